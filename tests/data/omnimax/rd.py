import numpy as np
def readppm(f):
    d=open(f,'rb').read()
    parts=[]; i=0
    while len(parts)<4:
        while d[i:i+1].isspace(): i+=1
        if d[i:i+1]==b'#':
            while d[i:i+1]!=b'\n': i+=1
            continue
        j=i
        while not d[j:j+1].isspace(): j+=1
        parts.append(d[i:j]); i=j
    i+=1
    w,h,mx=int(parts[1]),int(parts[2]),int(parts[3])
    a=np.frombuffer(d[i:i+w*h*6],dtype='>u2').reshape(h,w,3).astype(float)/mx
    return a
def dirs(f):
    a=readppm(f); v=a*2-1
    return v
