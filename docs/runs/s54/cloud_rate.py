#!/usr/bin/python3
"""The projectile's expansion rate in a debris cloud (§2.4, W.P.2; an input to Grady's fragment-size
estimates). Least-squares fit, mass-weighted, of v = v0 + A (x - x0) over the projectile's
particles (body 0), mirrored at z = 0 (half model). Prints the rates' eigenvalues
(1/s) and tr(A)/3, and the spread of v about the fit.
usage: cloud_rate.py particles_NNNNN.csv..."""
import sys
import numpy as np
for fn in sys.argv[1:]:
    t = float(open(fn).readline().split(' time ')[1].split()[0])
    d = np.loadtxt(fn, delimiter=',', skiprows=3, usecols=(1, 2, 3, 4, 5, 6, 7, 13))
    d = d[d[:, 7] == 0]
    m = np.concatenate([d[:, 6], d[:, 6]])
    x = np.concatenate([d[:, 0:3], d[:, 0:3] * [1, 1, -1]])
    v = np.concatenate([d[:, 3:6], d[:, 3:6] * [1, 1, -1]])
    x0 = (m[:, None] * x).sum(0) / m.sum()
    v0 = (m[:, None] * v).sum(0) / m.sum()
    X = x - x0
    V = v - v0
    W = m[:, None]
    A = np.linalg.solve((W * X).T @ X, (W * X).T @ V).T     # V ~ X A^T
    ev = np.linalg.eigvals(0.5 * (A + A.T))
    res = V - X @ A.T
    print('%5.1f us: projectile centre x %.2f mm, v %.3f km/s; rate eigenvalues %s 1/s, tr/3 %.3g 1/s; '
          'rms of v about the fit %.0f m/s, of v %.0f m/s' % (
              t * 1e6, x0[0] * 1e3, v0[0] * 1e-3, ' '.join('%.3g' % e for e in sorted(ev.real)),
              np.trace(A) / 3, np.sqrt((m * (res ** 2).sum(1)).sum() / m.sum()),
              np.sqrt((m * (V ** 2).sum(1)).sum() / m.sum())))
