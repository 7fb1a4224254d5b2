#!/usr/bin/python3
"""W.P.2's backwall (body 3, front face 202 mm, rear 212 mm): the front face (smallest x)
and the rear face (largest x) by radius, to split the measured crater depth into the
wall's bulge and the crater in it.  usage: wp2_bulge.py particles.csv..."""
import sys
import numpy as np

for f in sys.argv[1:]:
    d = np.genfromtxt(f, delimiter=',', skip_header=2, names=True)
    w = d['body'] == 3
    x, r = d['x'][w] * 1e3, np.hypot(d['y'][w], d['z'][w]) * 1e3
    vx = d['vx'][w]
    t = float(open(f).readline().split(' time ')[1].split()[0]) * 1e6
    row = []
    for r1, r2 in ((0, 3), (3, 6), (6, 10), (10, 20), (20, 40), (60, 90)):
        s = (r >= r1) & (r < r2) & (x > 195) & (x < 225)
        row.append('%g-%g: front %+.2f rear %+.2f v %.0f' % (r1, r2, x[s].min() - 202, x[s].max() - 212,
                   vx[s].mean()))
    print('%.0f us | ' % t + ' | '.join(row))
