import numpy as np
np.seterr(all='ignore')
def F(fn):
    if fn.startswith('pwr'):
        x,y=map(float,fn[4:-1].split(',')); w=complex(x,y)
        return lambda z: np.where(z==0, 0, np.exp(w*np.log(z)))
    d={'sqr':lambda z:z*z,'cube':lambda z:z*z*z,'exp':np.exp,'reciprocal':lambda z:1/z,'sin':np.sin,'asin':np.arcsin,'sinh':np.sinh,'asinh':np.arcsinh,'cos':np.cos,'acos':np.arccos,'cosh':np.cosh,'acosh':np.arccosh,'tan':np.tan,'atan':np.arctan,'tanh':np.tanh,'atanh':np.arctanh,'ln':np.log}
    return d[fn]
def norm(h): return np.sqrt((h*h).sum(1))
FUNCS={}
def stepB(h,c,fn):
    a,b,cc,d=h.T
    z1=(a-d)+1j*(b+cc); z2=(a+d)+1j*(b-cc)
    if fn in('sqr','cube'): w1=z1*z1; w2=z2*z2
    elif fn=='reciprocal': w1=1/z1; w2=1/z2
    else: f=FUNCS.get(fn) or F(fn); w1=f(z1); w2=f(z2)
    p,q,r,s=w1.real,w1.imag,w2.real,w2.imag
    return np.column_stack([(p+r)/2,(q+s)/2,(q-s)/2,(r-p)/2])+c
def insideB(P,c,fn,mi,w=0.0):
    trans = fn not in ('sqr','cube','reciprocal')
    h=np.column_stack([P[:,0],P[:,1],P[:,1] if trans else P[:,2],np.full(len(P),w)])
    ok=~(norm(h)>4)
    for k in range(mi-1):
        h=stepB(h,c,fn); ok&=~(norm(h)>4)
    return ok
def load(i):
    line=open('hindex.txt').read().split('\n')[i]
    _,fn,cc,mi=line.split('|'); mi=int(mi)
    c=np.array(eval(cc.replace('<','[').replace('>',']')),float)
    a=np.loadtxt(f'h_{i}.txt',delimiter=','); P=a[:,:3]; ins=a[:,3]>.5
    return fn,c,mi,P,ins
