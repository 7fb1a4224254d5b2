#!/usr/bin/python3
"""How fast the eroded rod material leaves the head, against Bernoulli's v - u.

Usage: backflow.py particles_NNNNN.csv R0_MM V0_M_S U_M_S [mat|body]
  R0_MM the rod's radius, V0 its speed, U the floor's speed (from the run's depths);
  the last argument names the column that tells rod (0) from target (default mat;
  `body` for the symmetric test, where both are tungsten).
In 2 mm slabs behind the floor (smallest x of target within 2 mm of the axis): the rod
material outside r0 (count, axial velocity and its value relative to the floor, radial
velocity, pressure), the rod's core inside r0 (axial velocity) and the radius holding
95 % of the rod's material. Session 25, docs/validation.md.
"""
import numpy as np, sys
f=sys.argv[1]; r0=float(sys.argv[2])*1e-3; v0=float(sys.argv[3]); u=float(sys.argv[4]); rodkey=sys.argv[5] if len(sys.argv)>5 else 'mat'
with open(f) as fh:
    h=fh.readline(); fh.readline(); names=fh.readline().strip().split(',')
d=np.loadtxt(f,delimiter=',',skiprows=3); p={n:d[:,i] for i,n in enumerate(names)}
rod=p[rodkey]==0; tg=~rod
r=np.hypot(p['y'],p['z']); vr=(p['vy']*p['y']+p['vz']*p['z'])/np.maximum(r,1e-12)
floor=p['x'][tg&(r<2e-3)&(p['x']>1e-3)].min()
# floor speed: mean vx of target within 1.5mm of floor on axis
print(h.strip(), 'floor %.1f mm, u %.0f m/s, v-u %.0f, 2u-v %.0f'%(floor*1e3,u,v0-u,2*u-v0))
for k in range(8):
    s=(p['x']>floor-(k+1)*2e-3)&(p['x']<=floor-k*2e-3)
    o=s&rod&(r>r0)
    c=s&rod&(r<=r0)
    if o.sum()<2: continue
    rr=np.percentile(r[s&rod],95)
    print(f'{2*k:2d}-{2*k+2:2d} mm: rod outside r0 n {o.sum():4d} vx {p["vx"][o].mean():6.0f} (rel {p["vx"][o].mean()-u:6.0f}) vr {vr[o].mean():5.0f} p {p["p"][o].mean()/1e9:5.1f} GPa | core r<r0 n {c.sum():4d} vx {p["vx"][c].mean() if c.sum() else 0:6.0f} | rod r95 {rr/r0:4.2f} r0')
