#!/usr/bin/python3
"""Where a rod run's energy ends up: internal energy of the rod and of the target, and
the target's internal energy, plastic strain and split fraction by distance from the
rod's axis (over 20 < x < 120 mm) and by depth.

Usage: energy.py particles_NNNNN.csv   (a CSV snapshot of a rod run, `output.csv: true`)
Session 24, docs/validation.md ("rod-5841 at the paper's counts", "Where the energy goes").
"""
import sys
import numpy as np

f = sys.argv[1]
with open(f) as fh:
    fh.readline()
    fh.readline()
    names = fh.readline().strip().split(',')
d = np.loadtxt(f, delimiter=',', comments='#', skiprows=3)
c = {n: d[:, names.index(n)] for n in ('x', 'y', 'z', 'mat', 'e', 'm', 'eps_p', 'damage')}
x, m, e, mat, eps, dmg = c['x'], c['m'], c['e'], c['mat'], c['eps_p'], c['damage']
r = np.hypot(c['y'], c['z'])
rod, tgt = mat == 0, mat == 1
print(f"internal energy (half model): rod {(m*e)[rod].sum()/1e3:.1f} kJ, "
      f"target {(m*e)[tgt].sum()/1e3:.1f} kJ")
print("target, 20 < x < 120 mm, by radius: particles, internal energy, mean e, "
      "plastic strain (mean, max), split fraction")
s0 = tgt & (x > 20e-3) & (x < 120e-3)
for r0, r1 in [(0, 11), (11, 15), (15, 20), (20, 25), (25, 30), (30, 40), (40, 50), (50, 80)]:
    s = s0 & (r >= r0 * 1e-3) & (r < r1 * 1e-3)
    if s.any():
        print(f"r {r0:2d}-{r1:2d} mm  n = {s.sum():6d}  E_int = {(m*e)[s].sum()/1e3:6.2f} kJ  "
              f"e = {e[s].mean()/1e3:6.1f} kJ/kg  eps_p = {eps[s].mean():.3f} (max {eps[s].max():.2f})"
              f"  split {np.mean(dmg[s] >= 1.0):.2f}")
print("target internal energy by depth:")
for x0 in range(-10, 200, 20):
    s = tgt & (x >= x0 * 1e-3) & (x < (x0 + 20) * 1e-3)
    if s.any():
        print(f"x {x0:4d} .. {x0+20:4d} mm  E_int = {(m*e)[s].sum()/1e3:6.2f} kJ")
