#!/usr/bin/python3
"""W.P.2's backwall (body 3): its front face (x_f - 202 mm - half a spacing, from the
smallest x in 1.1 mm columns, particles at x >= 201 mm) and its rear face (largest x - 212
mm + half a spacing) by distance from the axis: the crater in the bulge.
usage: wp2_front.py particles.csv..."""
import sys
import numpy as np

H = 1.1111 / 2
for fn in sys.argv[1:]:
    d = np.genfromtxt(fn, delimiter=',', skip_header=2, names=True)
    t = float(open(fn).readline().split(' time ')[1].split()[0])
    w = (d['body'] == 3) & (d['x'] * 1e3 >= 201)
    x, y, z = d['x'][w] * 1e3, d['y'][w] * 1e3, d['z'][w] * 1e3
    ky = np.floor(y / 1.1111).astype(int)
    kz = np.floor(z / 1.1111).astype(int)
    cols = {}
    for a, b, xv in zip(ky, kz, x):
        lo, hi = cols.get((a, b), (1e9, -1e9))
        cols[(a, b)] = (min(lo, xv), max(hi, xv))
    rr = np.array([np.hypot((a + 0.5) * 1.1111, (b + 0.5) * 1.1111) for a, b in cols])
    fr = np.array([v[0] - 202 - H for v in cols.values()])
    re = np.array([v[1] - 212 + H for v in cols.values()])
    row = []
    for r1, r2 in ((0, 5), (5, 10), (10, 20), (20, 30), (30, 50), (50, 80)):
        s = (rr >= r1) & (rr < r2)
        row.append('%g-%g: %+.2f / %+.2f (max %+.2f)' % (r1, r2, np.median(fr[s]), np.median(re[s]), fr[s].max()))
    print('%5.1f us front / rear median (deepest front), mm: ' % (t * 1e6) + ' | '.join(row))
