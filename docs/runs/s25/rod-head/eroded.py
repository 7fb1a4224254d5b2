#!/usr/bin/python3
"""Where the eroded rod material goes at the head: in 2 mm slabs behind the crater floor,
the rod material's count and mean radial velocity, and for the part outside the rod's
original radius r0 its radial and axial velocity and pressure; beside it the radial
momentum of rod and target (r < 15 mm) in the slab (half model, kg m/s).

Usage: eroded.py particles_NNNNN.csv R0_MM   (a rod run's CSV snapshot)
Session 25, docs/validation.md ("How wide the head launches the channel").
"""
import sys
import numpy as np

f, r0 = sys.argv[1], float(sys.argv[2]) * 1e-3
with open(f) as fh:
    fh.readline()
    fh.readline()
    names = fh.readline().strip().split(',')
d = np.loadtxt(f, delimiter=',', skiprows=3)
p = {n: d[:, i] for i, n in enumerate(names)}
rod = p['mat'] == 0
tgt = ~rod
r = np.hypot(p['y'], p['z'])
vr = (p['vy'] * p['y'] + p['vz'] * p['z']) / np.maximum(r, 1e-12)
floor = p['x'][tgt & (r < 2e-3) & (p['x'] > 1e-3)].min()
print(f"{f}: floor at {floor*1e3:.1f} mm")
print("behind floor | rod n | rod vr | r>r0: n | vr | vx | p | radial momentum rod | target")
for k in range(6):
    s = (p['x'] > floor - (k + 1) * 2e-3) & (p['x'] <= floor - k * 2e-3)
    R, T = s & rod, s & tgt & (r < 15e-3)
    o = R & (r > r0)
    if not o.any():
        continue
    print(f"{2*k:2d}-{2*k+2:2d} mm | {R.sum():4d} | {vr[R].mean():5.0f} m/s | {o.sum():4d} |"
          f" {vr[o].mean():5.0f} m/s | {p['vx'][o].mean():5.0f} m/s | {p['p'][o].mean()/1e9:5.1f} GPa |"
          f" {(p['m']*vr)[R].sum():.3f} | {(p['m']*vr)[T].sum():.3f}")
