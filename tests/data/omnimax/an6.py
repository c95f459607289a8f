import numpy as np,sys
from rd import dirs
from scipy.optimize import least_squares
f=sys.argv[1]
v=dirs(f); H,W,_=v.shape
valid=np.linalg.norm(v,axis=2)<1.01
py,px=np.mgrid[0:H,0:W]
xs=(px+0.5)/W-0.5; ys=0.5-(py+0.5)/H
ph=np.arctan2(v[:,:,1],v[:,:,0]); th=np.arccos(np.clip(v[:,:,2],-1,1))
m=valid&(th>0.15)
def res(p):
    k,y0=p
    d=ph[m]-np.arctan2(k*(ys[m]-y0),xs[m])
    return (d+np.pi)%(2*np.pi)-np.pi
r=least_squares(res,[1.0,0.0]); print(f,'k=%.6f y0=%.6f'%tuple(r.x),'max resid deg',np.degrees(np.abs(r.fun).max()))
k,y0=r.x
rho=np.hypot(xs,k*(ys-y0))
for deg in [1,3,5]:
    p=np.polyfit(rho[valid],th[valid],deg); print('  poly',deg,np.degrees(np.abs(th[valid]-np.polyval(p,rho[valid])).max()).round(4), np.round(p,5))
