#!/usr/bin/python3
"""W.P.3's second cloud (everything 1 mm or more behind the second bumper's rear face,
short of the backwall), by body: mass and axial momentum (full model).
Bodies: 0 projectile, 1 bumper1, 2 bumper1-core, 3 bumper2.  usage: cloud2_bodies.py particles.csv..."""
import sys
import numpy as np

for f in sys.argv[1:]:
    d = np.genfromtxt(f, delimiter=',', skip_header=2, names=True)
    x = d['x'] * 1e3
    m = d['m'] * 2e3
    p = m * d['vx'] / 1e3
    body = d['body'].astype(int)
    sel = (x > 61.3 + 1.0) & (x < 121.3)
    t = float(open(f).readline().split(' time ')[1].split()[0]) * 1e6
    parts = ['body %d %.4f g %.3f g km/s' % (b, m[sel & (body == b)].sum(), p[sel & (body == b)].sum())
             for b in sorted(set(body[sel]))]
    print('%.1f us: %.4f g, %.3f g km/s; ' % (t, m[sel].sum(), p[sel].sum()) + '; '.join(parts))
