#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The bit-exact prototype of fixed-point contract v2 (docs/fixed_point.md), written before the C++
and kept as a second source for docs/benchmarks_core.md: it designs with scipy.signal.butter (not
the generator), splits the coefficients, feeds the rounding error back and passes y_ext between
sections, then prints the SNR of a passband sine (fc/4, -1 dBFS) against scipy's sosfilt.
  /usr/bin/python3 bench/contract_v2_prototype.py FINE EF ORDERS RATIOS
  e.g. bench/contract_v2_prototype.py 1 1 1,2,4,7,8,12 0.001,0.0026,0.01,0.05,0.1,0.2,0.4
FINE = 1 splits every coefficient (35 bits), 0 keeps one 18-bit word; EF = 1 feeds the rounding
error back through E = round(-a), 0 does not. Needs python3-scipy (scripts/setup.sh --bench).
"""
import numpy as np, sys
from scipy import signal
D=16; C=18; P=48; LO=C-1
def fbits(vals, c):
    m=max(np.abs(np.asarray(vals)).max(),1e-30); f=c-1-int(np.ceil(np.log2(m)))
    if np.abs(np.round(np.asarray(vals)*2.0**f)).max()>2**(c-1)-1: f-=1
    return f
def design(order, ratio, fine=True, ef=True):
    sos=signal.butter(order,2*ratio,output='sos')
    for row in sos: row[:3]*=np.sum(row[3:])/np.sum(row[:3])
    M=2; K=len(sos)
    Fa=fbits(np.concatenate([-r[4:6] for r in sos]),C)
    Fa=min(Fa,fbits(np.concatenate([r[:3] for r in sos]),C)); Fb=Fa; s=25-D
    secs=[]
    for r in sos:
        na=-r[4:6]
        if fine:
            t=na*2.0**Fa; hi=np.floor(t); lo=np.round((t-hi)*2**LO)
            over=lo>=2**LO; hi[over]+=1; lo[over]=0
            aq=(hi+lo/2**LO)/2**Fa
        else:
            hi=np.round(na*2.0**Fa); lo=np.zeros(2); aq=hi/2**Fa
        tb=r[:3]*2.0**Fb; Bh=np.floor(tb); Bl=np.round((tb-Bh)*2**LO); ov=Bl>=2**LO; Bh[ov]+=1; Bl[ov]=0
        if not fine: Bh=np.round(tb); Bl=np.zeros(3)
        B=Bh
        E=np.round(na) if ef else np.zeros(2)
        secs.append(dict(B=B.astype(np.int64),BL=Bl.astype(np.int64),A=hi.astype(np.int64),L=lo.astype(np.int64),E=E.astype(np.int64)))
    return sos,secs,Fa,Fb,s
def run(secs,Fa,s,x):
    K=len(secs); yh=[[0,0] for _ in range(K)]; eh=[[0,0] for _ in range(K)]; xh=[[0,0,0] for _ in range(K)]
    emin=-(1<<(D-1+s)); emax=(1<<(D-1+s))-1; half=(1<<(s-1)) if s>0 else 0
    out=np.zeros(len(x),dtype=np.int64)
    for n,xv in enumerate(x):
        v=int(xv)<<s
        for k,sc in enumerate(secs):
            xk=xh[k]; xk[2]=xk[1]; xk[1]=xk[0]; xk[0]=v
            yy=yh[k]; ee=eh[k]
            acc0=(1<<(Fa-1+LO)) + sum(int(sc['BL'][i])*xk[i] for i in range(3)) + int(sc['L'][0])*yy[0]+int(sc['L'][1])*yy[1]
            acc=(acc0>>LO) + sum(int(sc['B'][i])*xk[i] for i in range(3)) + int(sc['A'][0])*yy[0]+int(sc['A'][1])*yy[1] + int(sc['E'][0])*ee[0]+int(sc['E'][1])*ee[1]
            ye=min(max(acc>>Fa,emin),emax); e=(acc & ((1<<Fa)-1)) - (1<<(Fa-1))
            yy[1]=yy[0]; yy[0]=ye; ee[1]=ee[0]; ee[0]=e
            v=ye
        out[n]=min((v+half)>>s,(1<<(D-1))-1)
    return out
def snr(order,ratio,fine,ef,N=None):
    sos,secs,Fa,Fb,s=design(order,ratio,fine,ef)
    f=ratio/4; N=N or int(max(40000, 12/f)); settle=int(max(15000, 4/f))
    x=np.round(10**(-1/20)*(2**(D-1)-1)*np.sin(2*np.pi*f*np.arange(N))).astype(np.int64)
    ref=signal.sosfilt(sos,x.astype(float))
    y=run(secs,Fa,s,x)
    err=(y-ref)[settle:]; return 10*np.log10(np.mean(ref[settle:]**2)/np.mean(err**2))
if __name__=='__main__':
    fine=sys.argv[1]=='1'; ef=sys.argv[2]=='1'
    orders=[int(o) for o in sys.argv[3].split(',')]; ratios=[float(r) for r in sys.argv[4].split(',')]
    for o in orders:
        print(o, ' '.join(f'{snr(o,r,fine,ef):6.1f}' for r in ratios), flush=True)
