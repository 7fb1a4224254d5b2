#!/usr/bin/python3
"""Where §2.4's step goes once the debris reaches the backwall (session 31): in a snapshot
of the paper's-count run, every pair within the kernel's reach (r < h_i + h_j, the cubic
spline's 2 h_ij with h_ij the mean), counted per particle, and summed by body and by the
particle's h against its body's initial h. A particle is "quiet" when v, p and S are
exactly 0; one whose neighbours are all quiet as well is left out of the sums, as
sph.skip_resting skips it (an approximation: the solver skips whole cells). The symmetry
plane's ghosts are not counted.

Usage: pairs.py particles_NNNNN.csv   (output in pairs.txt)
docs/performance.md ("Particles at rest", the step once the debris arrives).
"""
import sys

import numpy as np
from scipy.spatial import cKDTree

f = sys.argv[1]
lines = open(f).readlines()[:3]
hdr = lines[2].strip().split(',')
d = np.loadtxt(f, delimiter=',', skiprows=3)
c = {k: i for i, k in enumerate(hdr)}
X = d[:, [c['x'], c['y'], c['z']]]
h = d[:, c['h']]
body = d[:, c['body']].astype(int)
quiet = ((d[:, [c['vx'], c['vy'], c['vz'], c['p'], c['S_xx'], c['S_yy'], c['S_zz'],
                c['S_xy'], c['S_yz'], c['S_xz']]] == 0).all(axis=1))
tree = cKDTree(X)
hmax = h.max()
n = len(h)
count = np.zeros(n, dtype=np.int64)
allquiet = np.ones(n, dtype=bool)
for i0 in range(0, n, 20000):
    idx = np.arange(i0, min(n, i0 + 20000))
    lists = tree.query_ball_point(X[idx], h[idx] + hmax)
    for k, i in enumerate(idx):
        js = np.asarray(lists[k], dtype=np.int64)
        js = js[js != i]
        r = np.linalg.norm(X[js] - X[i], axis=1)
        js = js[r < h[i] + h[js]]
        count[i] = len(js)
        allquiet[i] = quiet[i] and quiet[js].all()
active = ~allquiet
print(lines[0].strip())
print(f"particles {n}, active (not skipped, approx.) {active.sum()}, pairs counted from the"
      f" active particles {count[active].sum()}")
names = {b: f"body {b}" for b in np.unique(body)}
print("body | particles | active | h0 (mm, median of the body's smallest 10 %) |"
      " pairs of active particles | share | mean neighbours (active) | max")
h0 = {}
for b in np.unique(body):
    s = body == b
    h0[b] = np.percentile(h[s], 10)
    a = s & active
    print(f"{names[b]} | {s.sum()} | {a.sum()} | {h0[b] * 1e3:.3f} | {count[a].sum()} |"
          f" {count[a].sum() / count[active].sum():.3f} |"
          f" {count[a].mean() if a.any() else 0:.0f} | {count[a].max() if a.any() else 0}")
ratio = h / np.array([h0[b] for b in body])
print("h / h0 of the body | active particles | pairs | share")
for lo, hi in [(0, 1.5), (1.5, 2), (2, 3), (3, 5), (5, 1e9)]:
    a = active & (ratio >= lo) & (ratio < hi)
    print(f"{lo}-{hi if hi < 1e9 else 'inf'} | {a.sum()} | {count[a].sum()} |"
          f" {count[a].sum() / count[active].sum():.3f}")
