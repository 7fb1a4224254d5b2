#!/usr/bin/python3
"""§2.4's backwall (body 3, al-alloy, x = 201..208 mm, 0.875 mm lattice): its front and
rear faces by distance from the axis, and its craters.

Columns are 0.875 mm squares in (y, z) (z >= 0: the half model). A column's front is
its smallest x among backwall particles at x >= 201 mm - FRONT_MARGIN (0.3 mm: the
splash thrown back off the face is not wall) (minus half a spacing, so that an untouched
column reads 0), its rear the largest x (plus half a spacing, minus 208 mm). The far
wall's shift (the lower median front of the columns beyond 0.8 of the wall's
inscribed radius, 96 mm, as `hvsph measure` takes it) is subtracted from both.

Craters: columns whose front lies deeper than DEPTH mm below the median front of the
columns 1.5 to 3 mm around them (their own neighbourhood's bulged face), joined into
connected groups (8-neighbour, mirrored at z = 0: a group touching z = 0 is one
crater across the symmetry plane). For each group: its deepest column's depth below the
far wall and below its neighbourhood, its centre's distance from the axis, its width.

usage: ws_backwall.py particles_NNNNN.csv ...   (DEPTH, FRONT_MARGIN from env, mm)"""
import os
import sys
import numpy as np

DX = 0.875                      # backwall spacing, mm
X0, X1 = 201.0, 208.0           # backwall faces, mm
FRONT_MARGIN = float(os.environ.get('FRONT_MARGIN', '0.3'))   # mm before the original face


def load(fn):
    with open(fn) as f:
        t = float(f.readline().split(' time ')[1].split()[0])
        f.readline()
        names = f.readline().strip().split(',')
    col = {n: i for i, n in enumerate(names)}
    use = [col[k] for k in ('x', 'y', 'z', 'body', 'damage', 'p')]
    d = np.loadtxt(fn, delimiter=',', skiprows=3, usecols=use)
    return t, d


for fn in sys.argv[1:]:
    t, d = load(fn)
    w = d[:, 3] == 3
    x, y, z = d[w, 0] * 1e3, d[w, 1] * 1e3, d[w, 2] * 1e3
    keep = (x >= X0 - FRONT_MARGIN) & (x < X1 + 40)  # the wall, not the splash thrown back
    x, y, z = x[keep], y[keep], z[keep]
    ky = np.floor(y / DX).astype(int)
    kz = np.floor(z / DX).astype(int)
    key = ky * 100000 + kz
    order = np.argsort(key, kind='stable')
    ks, xs = key[order], x[order]
    uk, start = np.unique(ks, return_index=True)
    front = np.minimum.reduceat(xs, start) - X0 - DX / 2
    rear = np.maximum.reduceat(xs, start) - X1 + DX / 2
    cy = (uk // 100000).astype(int)
    cz = (uk % 100000).astype(int)
    yc, zc = (cy + 0.5) * DX, (cz + 0.5) * DX
    rr = np.hypot(yc, zc)
    far = rr >= 0.8 * 120
    shift = np.sort(front[far])[(far.sum() - 1) // 2]
    front -= shift
    rear -= shift
    print('%.1f us: far-wall shift %+.3f mm; deepest front %.2f mm at r = %.1f mm' %
          (t * 1e6, shift, front.max(), rr[np.argmax(front)]))
    row = []
    for r1, r2 in ((0, 5), (5, 10), (10, 20), (20, 30), (30, 50), (50, 75), (75, 100)):
        s = (rr >= r1) & (rr < r2)
        row.append('%g-%g: %+.2f / %+.2f (max %+.2f)' %
                   (r1, r2, np.median(front[s]), np.median(rear[s]), front[s].max()))
    print('  front / rear median (deepest front), mm: ' + ' | '.join(row))
