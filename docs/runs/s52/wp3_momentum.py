#!/usr/bin/python3
"""W.P.3 (session 50's run at the paper's counts): does the second cloud's axial speed at
each radius follow the first cloud's momentum that crosses the second bumper there?
Reads the first cloud at T1 (before it strikes) and the second cloud at T2.
usage: wp3_momentum.py first.csv second.csv"""
import sys
import numpy as np


def load(f):
    d = np.genfromtxt(f, delimiter=',', skip_header=2, names=True)
    t = float(open(f).readline().split(' time ')[1].split()[0])
    return t, d


t1, a = load(sys.argv[1])
t2, b = load(sys.argv[2])
RHO, H, X1, X2 = 2.78, 0.05, 0.8, 60.8      # g/cm3, cm; first bumper rear, second front (mm)
# first cloud: projectile and first bumper (bodies 0-2) behind the first bumper
xa = a['x'] * 1e3
ra = np.hypot(a['y'], a['z']) * 1e3
ma = a['m'] * 2e3
sa = (xa > X1 + 0.32) & (xa < X2) & (a['body'] <= 2)
# where each first-cloud particle crosses the second bumper on a straight ray from the impact point
r_hit = ra * (X2 - X1) / np.maximum(xa - X1, 1e-9)
pa = ma * a['vx'] / 1e3                     # g km/s
# second cloud: everything behind the second bumper's rear face + 1 mm
xb = b['x'] * 1e3
rb = np.hypot(b['y'], b['z']) * 1e3
mb = b['m'] * 2e3
sb = (xb > X2 + 0.5 + 1.0) & (xb < 121.3)
print('first cloud at %.1f us: %.4f g, %.3f g km/s; second cloud at %.1f us: %.4f g, %.3f g km/s'
      % (t1 * 1e6, ma[sa].sum(), pa[sa].sum(), t2 * 1e6, mb[sb].sum(), (mb[sb] * b['vx'][sb]).sum() / 1e3))
print('| r at the second bumper (mm) | first cloud: momentum (g km/s), share | plate + cloud mass (g) | p/m (km/s) | second cloud at %.0f µs: mass (g), mean v_x (km/s) |' % (t2 * 1e6))
print('|---|---|---|---|---|')
tot = pa[sa].sum()
for r1, r2 in ((0, 5), (5, 10), (10, 15), (15, 20), (20, 30), (30, 40)):
    s = sa & (r_hit >= r1) & (r_hit < r2)
    p = pa[s].sum()
    mplate = np.pi * ((r2 / 10) ** 2 - (r1 / 10) ** 2) * H * RHO
    mc = ma[s].sum()
    t = sb & (rb >= r1) & (rb < r2)
    m2 = mb[t].sum()
    v2 = (mb[t] * b['vx'][t]).sum() / m2 / 1e3 if m2 > 0 else float('nan')
    print('| %g–%g | %.3f, %.0f %% | %.3f | %.2f | %.3f, %.2f |' % (r1, r2, p, 100 * p / tot, mplate + mc,
          p / (mplate + mc), m2, v2))
