import numpy as np
from qmodel import qmul
def orbit(p,c,mi,R,cube=False):
    h=np.array([p[0],p[1],p[2],0.]); dr=1.0; r=np.linalg.norm(h)
    if r>R: return False,np.log(r)/dr
    for k in range(mi-1):
        h=(qmul(h,qmul(h,h)) if cube else qmul(h,h))+c; dr*=(3*r*r if cube else 2*r); r=np.linalg.norm(h)
        if r>R: return False,np.log(r)/dr
    return True,0
def march(O,u,c,mi,prec,cube=False,bis=40):
    c=np.asarray(c,float); R=min(2,1+np.linalg.norm(c))
    b=(O*u).sum(); disc=b*b-(O@O-R*R)
    if disc<=0: return None
    ent=-b-np.sqrt(disc); ex=-b+np.sqrt(disc)
    t=max(0,ent); prev=None; state=None
    while t<=ex:
        ins,de=orbit(O+t*u,c,mi,R,cube)
        if state is not None and ins!=state:
            a,bb=prev,t
            for _ in range(bis):
                m=(a+bb)/2
                if orbit(O+m*u,c,mi,R,cube)[0]==state: a=m
                else: bb=m
            return (a+bb)/2
        state=ins; prev=t
        t+=max(de,1/prec) if not ins else 1/prec
    return None
