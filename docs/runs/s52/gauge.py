#!/usr/bin/python3
"""W.P.3's backwall (bodies 4, 5): the centre pressure over gauges of several radii in the
front 1.6 mm, mass-weighted as measure_center_pressure does, and the largest particle
pressure within 5 and 20 mm.  usage: gauge.py particles.csv"""
import sys
import numpy as np

f = sys.argv[1]
d = np.genfromtxt(f, delimiter=',', skip_header=2, names=True)
x, r = d['x'] * 1e3, np.hypot(d['y'], d['z']) * 1e3
w = (d['body'] >= 4) & (x >= 121.3 - 1.6)
out = []
for r0 in (1.0, 2.5, 5.0, 10.0):
    s = w & (r < r0)
    xf = x[s].min()
    g = s & (x <= xf + 1.6)
    out.append('r0 %.1f mm: %.2f kbar (%d)' % (r0, (d['m'][g] * d['p'][g]).sum() / d['m'][g].sum() / 1e8, g.sum()))
for r0 in (5.0, 20.0):
    s = w & (r < r0)
    out.append('max within %.0f mm %.2f kbar' % (r0, d['p'][s].max() / 1e8))
print('%.1f us: ' % (float(open(f).readline().split(' time ')[1].split()[0]) * 1e6) + '; '.join(out))
