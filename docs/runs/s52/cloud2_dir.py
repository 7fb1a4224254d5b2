#!/usr/bin/python3
"""W.P.3's second cloud: mass, axial and radial velocity and flight angle atan(v_r/v_x) by
radius, and the same for the front half of the cloud.  usage: cloud2_dir.py particles.csv"""
import sys
import numpy as np

f = sys.argv[1]
d = np.genfromtxt(f, delimiter=',', skip_header=2, names=True)
x, y, z = d['x'] * 1e3, d['y'] * 1e3, d['z'] * 1e3
r = np.hypot(y, z)
vr = (d['vy'] * y + d['vz'] * z) / np.maximum(r, 1e-9)
m = d['m'] * 2e3
vx = d['vx']
X_REAR = 61.3
sel = (x > X_REAR + 1.0) & (x < 121.3)
xl = np.quantile(x[sel] - X_REAR, 0.99)
front = sel & (x - X_REAR >= 0.5 * xl)
print(open(f).readline().strip(), ' x_lead (99 %% by count) %.1f mm' % xl)
print('| r (mm) | mass (g) | mean v_x, v_r (km/s) | flight angle | front half: mass (g), v_x, v_r, angle |')
print('|---|---|---|---|---|')
for r1, r2 in ((0, 5), (5, 10), (10, 15), (15, 20), (20, 30), (30, 40)):
    s = sel & (r >= r1) & (r < r2)
    t = front & (r >= r1) & (r < r2)
    if not s.any():
        continue
    mv = lambda q, v: (m[q] * v[q]).sum() / m[q].sum() / 1e3
    row = '| %g–%g | %.3f | %.2f, %.2f | %.0f° |' % (r1, r2, m[s].sum(), mv(s, vx), mv(s, vr),
                                                  np.degrees(np.arctan2(mv(s, vr), mv(s, vx))))
    if t.any():
        row += ' %.3f, %.2f, %.2f, %.0f° |' % (m[t].sum(), mv(t, vx), mv(t, vr),
                                              np.degrees(np.arctan2(mv(t, vr), mv(t, vx))))
    else:
        row += ' – |'
    print(row)


def quantile(v, w, q):
    o = np.argsort(v)
    c = np.cumsum(w[o])
    return v[o][np.searchsorted(c, q * c[-1])]


fl = np.degrees(np.arctan2(vr, vx))
pos = np.degrees(np.arctan2(r, x - X_REAR))
print('front half: 90 %% mass quantile of the angle seen from the rear centre %.1f°, of the flight '
      'angle atan(v_r/v_x) %.1f°; median %.1f° and %.1f°' % (quantile(pos[front], m[front], 0.9),
      quantile(fl[front], m[front], 0.9), quantile(pos[front], m[front], 0.5), quantile(fl[front], m[front], 0.5)))
