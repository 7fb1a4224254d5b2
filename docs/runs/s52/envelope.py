#!/usr/bin/python3
"""W.P.3's second cloud: its radial extent (90 % mass quantile of r) in slices along x,
and the slope of that envelope, the half angle of a cloud seen from the side whatever
the width of its source.  usage: envelope.py particles.csv [x_rear_mm x_limit_mm]"""
import sys
import numpy as np

f = sys.argv[1]
X_REAR = float(sys.argv[2]) if len(sys.argv) > 2 else 61.3
X_LIM = float(sys.argv[3]) if len(sys.argv) > 3 else 121.3
d = np.genfromtxt(f, delimiter=',', skip_header=2, names=True)
x, r, m = d['x'] * 1e3 - X_REAR, np.hypot(d['y'], d['z']) * 1e3, d['m']
sel = (x > 1.0) & (x < X_LIM - X_REAR)


def q(v, w, p):
    o = np.argsort(v)
    c = np.cumsum(w[o])
    return v[o][np.searchsorted(c, p * c[-1])]


xl = q(x[sel], m[sel], 0.99)
print(open(f).readline().strip(), ' x_lead (99 %% of mass) %.1f mm' % xl)
xs, rs = [], []
for a in np.arange(0.5, 1.0, 0.1):
    s = sel & (x >= a * xl) & (x < (a + 0.1) * xl)
    if m[s].sum() == 0:
        continue
    xs.append((m[s] * x[s]).sum() / m[s].sum())
    rs.append(q(r[s], m[s], 0.9))
    print('  x %5.1f mm: r90 %5.1f mm (%d particles)' % (xs[-1], rs[-1], s.sum()))
k = np.polyfit(xs, rs, 1)
print('front half: r90 = %.1f mm + %.3f x: envelope half angle %.1f°' % (k[1], k[0], np.degrees(np.arctan(k[0]))))
