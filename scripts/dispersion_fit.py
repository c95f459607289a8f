#!/usr/bin/env python3
"""Fits render/dispersion.rs's SPECTRUM: 11 piecewise-linear knots per channel (red 0 to
violet 1), each channel averaging 1, whose bins match povray's measured dispersion colours
(scripts/dispersion_spectrum.sh: the 2- and 3-bin colours weighted 10, the noisier 10-bin
shares 1, plus a little smoothing). Needs numpy and scipy; prints the knots and the bins they
give."""
import numpy as np
from scipy.optimize import minimize
T=np.linspace(0,1,11)
t=(np.arange(1200)+0.5)/1200
meas={2:[[0.956,0.730,0.012],[0.039,0.270,0.982]],3:[[0.791,0.262,0],[0.159,0.737,0.301],[0.039,0.0015,0.693]]}
n10=np.array([[2.08,0,0],[2.50,0.16,0],[2.69,1.45,0],[1.89,2.34,0],[0.35,2.45,0.10],[0,2.80,1.67],[0,0.81,2.87],[0,0,2.14],[0.13,0,1.82],[0.36,0,1.41]])/10
def model(x):
  V=np.abs(x.reshape(11,3))
  S=np.stack([np.interp(t,T,V[:,c]) for c in range(3)],axis=1)
  S=S/S.mean(axis=0)
  return S
def bins(S,n):
  return np.array([S[(t>=i/n)&(t<(i+1)/n)].mean(axis=0)/n for i in range(n)])
def loss(x):
  S=model(x); e=0
  for n,m in meas.items(): e+=10*np.sum((bins(S,n)-np.array(m))**2)
  e+=np.sum((bins(S,10)-n10)**2)
  V=np.abs(x.reshape(11,3))
  e+=0.002*np.sum(np.diff(V,2,axis=0)**2)
  return e
x0=np.array([np.interp(T,[0,.15,.35,.45,.55,.65,.75,.85,1],k) for k in ([2.1,2.5,2.5,.3,0,0,0,.1,.35],[0,0,2,2.6,2.6,.8,0,0,0],[0,0,0,0,1.2,2.8,2.5,1.9,1.4])]).T.ravel()
r=minimize(loss,x0,method="L-BFGS-B",bounds=[(0,10)]*33)
V=np.abs(r.x.reshape(11,3)); V=V/V.mean(axis=0)
print(r.fun); print(np.round(V,3).tolist())
S=model(r.x)
for n in (2,3): print(np.round(bins(S,n),3))
print(np.round(bins(S,10)*10,2))
