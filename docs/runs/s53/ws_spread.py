#!/usr/bin/python3
"""§2.4: where the projectile's steel flies, from a particle snapshot (body 0): its mass
share and axial speed by distance from the axis.
usage: ws_spread.py particles_NNNNN.csv"""
import sys
import numpy as np

for fn in sys.argv[1:]:
    with open(fn) as f:
        t = float(f.readline().split(' time ')[1].split()[0])
    d = np.loadtxt(fn, delimiter=',', skiprows=3, usecols=(1, 2, 3, 4, 7, 13))
    p = d[d[:, 5] == 0]
    r = np.hypot(p[:, 1], p[:, 2]) * 1e3
    vx = p[:, 3] / 1e3
    print('%.1f us, projectile steel (axial position median %.1f mm):' % (t * 1e6, np.median(p[:, 0]) * 1e3))
    for lo, hi in ((0, 5), (5, 10), (10, 20), (20, 40), (40, 200)):
        s = (r >= lo) & (r < hi)
        if s.sum():
            print('  r %g-%g mm: %4.1f %% of its mass, vx median %.2f km/s (10-90 %%: %.2f-%.2f)'
                  % (lo, hi, 100 * p[s, 4].sum() / p[:, 4].sum(), np.median(vx[s]),
                     np.percentile(vx[s], 10), np.percentile(vx[s], 90)))
