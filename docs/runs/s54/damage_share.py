#!/usr/bin/python3
"""The projectile's (body 0) mass share by damage state in a particle snapshot: 0 whole,
1 cracked once (split: crack) or split (the paper's rule), 2 split through after a crack;
with the mean equivalent plastic strain of each state. usage: damage_share.py particles_*.csv"""
import sys
import numpy as np
for fn in sys.argv[1:]:
    t = float(open(fn).readline().split(' time ')[1].split()[0])
    d = np.loadtxt(fn, delimiter=',', skiprows=3, usecols=(7, 13, 15, 16))
    p = d[d[:, 1] == 0]
    m = p[:, 0]
    out = []
    for D in (0, 1, 2):
        s = np.isclose(p[:, 3], D)
        out.append('damage %d: %.3f (eps_p %.2f)' % (D, m[s].sum() / m.sum(), p[s, 2].mean() if s.any() else float('nan')))
    print('%s %5.1f us: %s' % (fn, t * 1e6, '; '.join(out)))
