import numpy as np
np.seterr(all='ignore')
def qmul(p,q):
    a,b=p[...,0],p[...,1:]; c_,d=q[...,0],q[...,1:]
    return np.concatenate([(a*c_-(b*d).sum(-1))[...,None], a[...,None]*d+c_[...,None]*b+np.cross(b,d)],-1)
def qorbit(P,c,mi,cube=False):
    """returns inside flag, final |h|, |h'| product, number of iters done"""
    c=np.asarray(c,float); R=min(2,1+np.linalg.norm(c))
    h=np.concatenate([P,np.zeros(P.shape[:-1]+(1,))],-1)
    ok=np.sqrt((h*h).sum(-1))<=R
    dr=np.ones(P.shape[:-1]); n=np.zeros(P.shape[:-1],int)
    hh=h.copy(); alive=ok.copy()
    for k in range(mi-1):
        r=np.sqrt((hh*hh).sum(-1))
        nh=(qmul(hh,qmul(hh,hh)) if cube else qmul(hh,hh))+c
        ndr=dr*(3*r*r if cube else 2*r)
        hh=np.where(alive[...,None],nh,hh); dr=np.where(alive,ndr,dr); n=n+alive
        alive&=np.sqrt((hh*hh).sum(-1))<=R
    return alive, np.sqrt((hh*hh).sum(-1)), dr, n
def load_tr(f):
    a=np.loadtxt(f,delimiter=',')
    return a[:,0:3],a[:,3:6],a[:,6:9],a[:,9:12]
