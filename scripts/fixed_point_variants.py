#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Independent, standard-library-only re-implementation of the fixed-point contract
# (docs/fixed_point.md) next to one proposed change, for the comparison in docs/core.md:
#   contract:   every section's output is rounded to D bits and stored so in the feedback history.
#   wide state: the feedback history keeps s = FeedbackShift more fractional bits (it then enters
#               the DSP48E1 A port unshifted, D + s <= 25 bits); only the section's output to the
#               next section is rounded to D bits.
# For each filter.json: SNR and largest error against the float SOS for a passband sine (fc / 4)
# at 0.5 and 0.05 of full scale, and the zero-input tail after a half-scale negative step.
#   python3 scripts/fixed_point_variants.py coeffs/vehicle_sos/filter.json [...]
# The "contract" rows must equal the C++ model (tests/model/iir_core_fidelity_test.cpp prints them).
import json
import math
import sys

def load(p):
    d=json.load(open(p)); q=d['quantized']
    return d,q
def run(q, xs, wide):
    w=q['words']; Fb=q['b_frac_bits']; s=q['feedback_shift']; K=q['sections']; M=q['section_order']; T=2*M+1; D=q['data_bits']
    lo,hi=-2**(D-1),2**(D-1)-1
    xh=[[0]*(M+1) for _ in range(K)]   # narrow inputs per section
    yh=[[0]*(M+1) for _ in range(K)]   # feedback state per section (wide or narrow<<s)
    out=[]
    for x in xs:
        v=x
        for k in range(K):
            xh[k].insert(0,xh[k].pop()); xh[k][0]=v
            yh[k].insert(0,yh[k].pop())
            acc=2**(Fb-1) if not wide else 0
            for i in range(M+1): acc+=w[k*T+i]*xh[k][i]
            for j in range(1,M+1): acc+=w[k*T+M+j]*yh[k][j]
            if wide:
                yw=(acc+2**(Fb-s-1))>>(Fb-s); yw=max(lo<<s,min((hi<<s)|((1<<s)-1),yw))
                yh[k][0]=yw
                v=max(lo,min(hi,(yw+2**(s-1))>>s)) if s>0 else yw
            else:
                y=max(lo,min(hi,acc>>Fb)); yh[k][0]=y<<s; v=y
        out.append(v)
    return out

def sosfilt(sos,xs):
    st=[[0.0]*4 for _ in sos]; out=[]
    for x in xs:
        v=x
        for k,(b0,b1,b2,a0,a1,a2) in enumerate(sos):
            x1,x2,y1,y2=st[k]; y=b0*v+b1*x1+b2*x2-a1*y1-a2*y2; st[k]=[v,x1,y,y1]; v=y
        out.append(v)
    return out
for p in sys.argv[1:]:
    d,q=load(p); fs=d['fs_hz']; fc=d['fc_hz']; S=2**(q['data_bits']-1)
    n=40000; sk=15000
    for level in (0.5,0.05):
        x=[round(level*math.sin(2*math.pi*fc/4*i/fs)*S) for i in range(n)]
        ref=[v*S for v in sosfilt(d['sos'],[v/S for v in x])]
        for wide in (False,True):
            y=run(q,x,wide)
            e=[a-b for a,b in zip(y[sk:],ref[sk:])]
            snr=10*math.log10(sum(r*r for r in ref[sk:])/sum(v*v for v in e))
            print(f"{p.split('/')[-2]:16s} level {level:4.2f} {'wide state' if wide else 'contract  '}: SNR {snr:6.1f} dB, max err {max(abs(v) for v in e):8.1f} LSB")
    for wide in (False,True):
        y=run(q,[-16384]*4000+[0]*30000,wide)
        print(f"{p.split('/')[-2]:16s} zero-input tail {'wide' if wide else 'contract'}: min {min(y[-3000:])} max {max(y[-3000:])}")
