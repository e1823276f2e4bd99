#!/usr/bin/env python3
"""diagrams.py - draws the slides' exact diagrams from their geometry (run from anywhere).

Writes into slides/figures/: sat-edge-normal.svg (two turned boxes whose AABBs overlap,
separated on an edge normal: the shadows are computed, not drawn by eye),
minkowski-rounded.svg (a circle cast against a box = its centre against the rounded box;
the first touch is solved from the quadratic), swept-false-positive.svg and
reflect-split.svg (v split into (v.n)n and the rest). Re-run after changing a number.
"""
import math
import os

os.chdir(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'figures'))
HEAD='<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 {w} {h}" font-family="DejaVu Sans, sans-serif" font-size="28">\n<rect width="{w}" height="{h}" fill="white"/>\n'
ARROW='<defs><marker id="ar" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="6" markerHeight="6" orient="auto-start-reverse"><path d="M0,0 L10,5 L0,10 z" fill="context-stroke"/></marker></defs>\n'
def line(a,b,c,w=4,dash=None,arrow=False):
    d=f' stroke-dasharray="{dash}"' if dash else ''
    m=' marker-end="url(#ar)"' if arrow else ''
    return f'<line x1="{a[0]:.1f}" y1="{a[1]:.1f}" x2="{b[0]:.1f}" y2="{b[1]:.1f}" stroke="{c}" stroke-width="{w}"{d}{m}/>\n'
def text(p,s,c="#222",extra=''):
    return f'<text x="{p[0]:.0f}" y="{p[1]:.0f}" fill="{c}"{extra}>{s}</text>\n'
def poly(pts,c,op=0.2,w=4,dash=None):
    d=f' stroke-dasharray="{dash}"' if dash else ''
    return f'<polygon points="{" ".join(f"{x:.1f},{y:.1f}" for x,y in pts)}" fill="{c}" fill-opacity="{op}" stroke="{c}" stroke-width="{w}"{d}/>\n'
def rect(cx,cy,w,h,ang):
    c,sn=math.cos(ang),math.sin(ang)
    return [(cx+c*x-sn*y,cy+sn*x+c*y) for x,y in [(-w/2,-h/2),(w/2,-h/2),(w/2,h/2),(-w/2,h/2)]]
def bbox(p):
    xs=[x for x,_ in p]; ys=[y for _,y in p]; return min(xs),min(ys),max(xs),max(ys)

# SAT
a=rect(200,170,230,60,math.radians(40))
b=rect(330,170,230,60,math.radians(40))
s=HEAD.format(w=620,h=560)+ARROW
s+='<!-- Two turned boxes whose AABBs overlap, separated on the normal of one of their edges. -->\n'
ba,bb=bbox(a),bbox(b)
ov=(max(ba[0],bb[0]),max(ba[1],bb[1]),min(ba[2],bb[2]),min(ba[3],bb[3]))
s+=f'<rect x="{ov[0]:.1f}" y="{ov[1]:.1f}" width="{ov[2]-ov[0]:.1f}" height="{ov[3]-ov[1]:.1f}" fill="#f1c40f" fill-opacity="0.35"/>\n'
for bx,c in [(ba,"#2f6fd0"),(bb,"#d07a1f")]:
    s+=f'<rect x="{bx[0]:.1f}" y="{bx[1]:.1f}" width="{bx[2]-bx[0]:.1f}" height="{bx[3]-bx[1]:.1f}" fill="none" stroke="{c}" stroke-width="2" stroke-dasharray="8 6"/>\n'
s+=poly(a,"#2f6fd0")+poly(b,"#d07a1f")
e=(a[1][0]-a[0][0],a[1][1]-a[0][1]); L=math.hypot(*e); n=(e[1]/L,-e[0]/L)
if n[0]<0: n=(-n[0],-n[1])
O=(330,420)
def proj(p): return (p[0]-O[0])*n[0]+(p[1]-O[1])*n[1]
def at(t): return (O[0]+n[0]*t,O[1]+n[1]*t)
pa=[proj(p) for p in a]; pb=[proj(p) for p in b]
tmin=min(pa+pb)-60; tmax=max(pa+pb)+60
s+=line(at(tmin),at(tmax),"#555",3,arrow=True)
s+=text((at(tmax)[0]+8,at(tmax)[1]+8),"axis","#555")
for vals,c,pts in [(pa,"#2f6fd0",a),(pb,"#d07a1f",b)]:
    s+=line(at(min(vals)),at(max(vals)),c,12)
    for p,t in zip(pts,vals):
        if t in (min(vals),max(vals)): s+=line(p,at(t),c,2,"6 6")
gap=max(min(pb)-max(pa),min(pa)-max(pb))
assert gap>0, gap
lo,hi=(max(pa),min(pb)) if min(pb)>max(pa) else (max(pb),min(pa))
m=at((lo+hi)/2)
s+=text((m[0]+14,m[1]+30),"gap","#c0392b",' font-weight="bold"')
s+=text((20,40),"yellow: the AABBs overlap")
s+=text((20,520),"on the normal of an edge the")
s+=text((20,552),"shadows have a gap: no hit")
s+='</svg>\n'
open('sat-edge-normal.svg','w').write(s)

# Minkowski rounded box
s=HEAD.format(w=620,h=520)+ARROW
s+='<!-- A moving circle against a box = its centre (a point) against the box grown by r: a rounded box. -->\n'
bx,by,bw,bh,r=260,170,220,140,60
s+=f'<rect x="{bx-r}" y="{by-r}" width="{bw+2*r}" height="{bh+2*r}" rx="{r}" ry="{r}" fill="#d07a1f" fill-opacity="0.12" stroke="#d07a1f" stroke-width="3" stroke-dasharray="10 6"/>\n'
s+=f'<rect x="{bx}" y="{by}" width="{bw}" height="{bh}" fill="#d07a1f" fill-opacity="0.3" stroke="#d07a1f" stroke-width="4"/>\n'
s+=line((bx+bw,by+bh),(bx+bw+r*math.cos(0.7),by+bh+r*math.sin(0.7)),"#555",3)
s+=text((bx+bw+30,by+bh+40),"r","#555",' font-weight="bold"')
cx,cy=bx,by+bh
target=(cx-r*math.cos(math.radians(50)),cy+r*math.sin(math.radians(50)))
start=(70,440)
d=(target[0]-start[0],target[1]-start[1]); Ld=math.hypot(*d); d=(d[0]/Ld,d[1]/Ld)
fx,fy=start[0]-cx,start[1]-cy
B_=fx*d[0]+fy*d[1]; C_=fx*fx+fy*fy-r*r
t=(-B_-math.sqrt(B_*B_-C_))
hit=(start[0]+d[0]*t,start[1]+d[1]*t)
s+=f'<circle cx="{start[0]}" cy="{start[1]}" r="{r}" fill="#2f6fd0" fill-opacity="0.15" stroke="#2f6fd0" stroke-width="3"/>\n'
s+=f'<circle cx="{start[0]}" cy="{start[1]}" r="6" fill="#2f6fd0"/>\n'
s+=line(start,(start[0]+d[0]*(t+90),start[1]+d[1]*(t+90)),"#2f6fd0",3,"10 6",arrow=True)
s+=f'<circle cx="{hit[0]:.1f}" cy="{hit[1]:.1f}" r="{r}" fill="none" stroke="#2f6fd0" stroke-width="3"/>\n'
s+=f'<circle cx="{hit[0]:.1f}" cy="{hit[1]:.1f}" r="8" fill="#c0392b"/>\n'
s+=text((hit[0]-40,hit[1]+95),"first touch: t","#c0392b")
s+=text((20,40),"the centre against the box grown by r:")
s+=text((20,75),"two slabs and four corner circles")
s+='</svg>\n'
open('minkowski-rounded.svg','w').write(s)

# Swept-volume false positive
s=HEAD.format(w=620,h=520)+ARROW
s+='<!-- The box around the start and end of a diagonal move covers a target the path never touches. -->\n'
s0=(60,330); e0=(420,90); w=70
s+=f'<rect x="{s0[0]}" y="{e0[1]}" width="{e0[0]-s0[0]+w}" height="{s0[1]-e0[1]+w}" fill="#c0392b" fill-opacity="0.08" stroke="#c0392b" stroke-width="3" stroke-dasharray="10 6"/>\n'
s+=poly([(s0[0],s0[1]),(e0[0],e0[1]),(e0[0]+w,e0[1]),(e0[0]+w,e0[1]+w),(s0[0]+w,s0[1]+w),(s0[0],s0[1]+w)],"#2f6fd0",0.12,2)
s+=f'<rect x="{s0[0]}" y="{s0[1]}" width="{w}" height="{w}" fill="#2f6fd0" fill-opacity="0.4" stroke="#2f6fd0" stroke-width="4"/>\n'
s+=f'<rect x="{e0[0]}" y="{e0[1]}" width="{w}" height="{w}" fill="none" stroke="#2f6fd0" stroke-width="4" stroke-dasharray="8 6"/>\n'
s+=line((s0[0]+w/2,s0[1]+w/2),(e0[0]+w/2-6,e0[1]+w/2+4),"#2f6fd0",3,arrow=True)
s+=f'<rect x="385" y="290" width="90" height="90" fill="#d07a1f" fill-opacity="0.4" stroke="#d07a1f" stroke-width="4"/>\n'
s+=text((385,430),"target","#b35900")
s+=text((20,45),"dashed red: the swept bounds","#c0392b")
s+=text((20,475),"the bounds overlap the target, the path")
s+=text((20,508),"does not: a false positive. Sweep next.")
s+='</svg>\n'
open('swept-false-positive.svg','w').write(s)

# Reflection as the (v.n)n split
s=HEAD.format(w=600,h=480)+ARROW
s+='<!-- Reflection: v splits into (v·n)n along the normal and the rest along the surface. -->\n'
P=(300,380); v=(170,200)
A=(P[0]-v[0],P[1]-v[1])
s+='<rect x="30" y="380" width="540" height="50" fill="#888" fill-opacity="0.3"/>\n'+line((30,380),(570,380),"#555")
s+=line(A,(P[0]-4,P[1]-4),"#2f6fd0",6,arrow=True)+text((150,320),"v","#2f6fd0",' font-size="36" font-weight="bold"')
s+=line(A,(A[0]+v[0],A[1]),"#1e8449",4,"10 6",arrow=True)+text((A[0]-20,A[1]-16),"v − (v·n)n: kept","#1e8449")
s+=line((A[0]+v[0],A[1]),(P[0],P[1]-6),"#c0392b",4,"10 6",arrow=True)
s+=text((P[0]+10,A[1]+40),"(v·n)n","#c0392b")
R=(P[0]+v[0],P[1]-v[1])
s+=line(P,R,"#8e44ad",6,arrow=True)+text((430,320),"v′","#8e44ad",' font-size="36" font-weight="bold"')
s+=line((530,380),(530,300),"#555",3,arrow=True)+text((545,320),"n","#555",' font-weight="bold"')
s+=text((20,465),"v′ = v − (1+e)(v·n)n")
s+='</svg>\n'
open('reflect-split.svg','w').write(s)
