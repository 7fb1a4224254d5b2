#!/usr/bin/python3
"""How much of a body is split (damage >= 1) in a particle snapshot, and where its
unsplit particles are. usage: split_share.py BODY particles_NNNNN.csv ..."""
import sys
import numpy as np

body = int(sys.argv[1])
for fn in sys.argv[2:]:
    with open(fn) as f:
        t = float(f.readline().split(' time ')[1].split()[0])
    d = np.loadtxt(fn, delimiter=',', skiprows=3, usecols=(1, 2, 3, 13, 16))
    p = d[d[:, 3] == body]
    whole = p[p[:, 4] < 1]
    print('%s, %.1f us: body %d, %d particles, %d split (%.1f %%); unsplit ones at x %.1f..%.1f mm'
          % (fn, t * 1e6, body, len(p), len(p) - len(whole), 100 * (1 - len(whole) / len(p)),
             whole[:, 0].min() * 1e3 if len(whole) else np.nan,
             whole[:, 0].max() * 1e3 if len(whole) else np.nan))
