#!/usr/bin/python3
"""First cloud of W.P.3 (session 50's run): mass and axial momentum by angle from the
first bumper's rear centre, by body.  usage: cloud1.py particles_NNNNN.csv"""
import sys
import numpy as np

f = sys.argv[1]
d = np.genfromtxt(f, delimiter=',', skip_header=2, names=True)
x, y, z = d['x'] * 1e3, d['y'] * 1e3, d['z'] * 1e3
r = np.hypot(y, z)
m = d['m'] * 2 * 1e3
vx = d['vx']
body = d['body'].astype(int)
x_rear = 0.8
sel = (x > x_rear + 0.32) & (x < 60.8) & (body <= 2)
th = np.degrees(np.arctan2(r, x - x_rear))
print(open(f).readline().strip())
print('first cloud: %.4f g, p %.3f g km/s (projectile %.4f g)' % (m[sel].sum(), (m[sel] * vx[sel]).sum() / 1e3,
      m[sel & (body == 0)].sum()))
edges = [0, 5, 10, 15, 20, 25, 30, 40, 60, 90]
print(' angle     mass g  p g km/s  mean vx   proj.frac  r at x=60 (mm)')
for a, b in zip(edges[:-1], edges[1:]):
    s = sel & (th >= a) & (th < b)
    if not s.any():
        continue
    mm = m[s].sum()
    print('%4.0f-%4.0f  %7.4f  %7.4f  %7.0f  %5.2f  %5.1f-%5.1f' % (a, b, mm, (m[s] * vx[s]).sum() / 1e3,
          (m[s] * vx[s]).sum() / mm, m[s & (body == 0)].sum() / mm, 60 * np.tan(np.radians(a)), 60 * np.tan(np.radians(min(b, 89)))))
