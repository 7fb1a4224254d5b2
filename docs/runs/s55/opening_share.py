#!/usr/bin/python3
"""Share of each body's particles split (damage >= 1) and opening (0 < damage < 1, a
fracture.energy particle part-way open) in particle snapshots, with the median damage of
the opening ones. usage: opening_share.py particles_*.csv"""
import sys
import numpy as np
names = {0: 'projectile', 1: 'bumper', 2: 'bumper-core'}
for f in sys.argv[1:]:
    t = float(open(f).readline().split('time ')[1].split()[0])
    d = np.loadtxt(f, delimiter=',', skiprows=3, usecols=(13, 16))
    for b in (0, 2, 1):
        D = d[d[:, 0] == b, 1]
        op = (D > 0) & (D < 1)
        print('%5.1f us %-11s n %6d: split %.3f, opening %.3f (median D of those %.3f)'
              % (t * 1e6, names[b], len(D), (D >= 1).mean(), op.mean(),
                 np.median(D[op]) if op.any() else 0.0))
