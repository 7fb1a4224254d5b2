#!/usr/bin/python3
"""The rod's core (particles within 0.7 r0 of the axis) by distance behind the crater
floor: count, mean axial velocity, plastic strain, pressure and density ratio.

Usage: rod_core.py R0_MM particles_NNNNN.csv [...]   (CSV snapshots of a rod run)
Session 26, docs/validation.md ("How wide the head launches the channel").
"""
import sys
import numpy as np

r0 = float(sys.argv[1]) * 1e-3
BINS = [0, 1, 2, 3, 4, 5, 6, 8, 10, 12, 15, 20, 30, 40, 60, 120]
for f in sys.argv[2:]:
    with open(f) as fh:
        h = fh.readline()
        fh.readline()
        names = fh.readline().strip().split(',')
    t = float(h.split(' time ')[1].split()[0])
    cols = ('x', 'y', 'z', 'vx', 'rho', 'p', 'mat', 'eps_p')
    d = np.loadtxt(f, delimiter=',', comments='#', skiprows=3,
                   usecols=[names.index(n) for n in cols])
    c = dict(zip(cols, d.T))
    rod, tgt = c['mat'] == 0, c['mat'] == 1
    r = np.hypot(c['y'], c['z'])
    fl = c['x'][tgt & (r < 2e-3) & (c['x'] > 1e-3)].min()
    core = rod & (r < 0.7 * r0)
    print(f"t = {t*1e6:.0f} us, floor {fl*1e3:.1f} mm; rod particles within 0.7 r0 of the axis")
    print(" xi mm  |    n | vx m/s | eps_p | p GPa  | rho/rho0")
    for a, b in zip(BINS[:-1], BINS[1:]):
        s = core & (fl - c['x'] >= a * 1e-3) & (fl - c['x'] < b * 1e-3)
        if s.sum() == 0:
            continue
        print(f"{a:3d}-{b:3d} | {s.sum():4d} | {c['vx'][s].mean():6.0f} | {c['eps_p'][s].mean():5.2f} |"
              f" {c['p'][s].mean()/1e9:6.2f} | {c['rho'][s].mean()/17780:5.3f}")
