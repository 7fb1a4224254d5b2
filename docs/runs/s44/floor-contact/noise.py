#!/usr/bin/python3
"""Session 44: the pressure's particle-scale noise at the head of the free tests at 1.29 km/s
(free129.yaml and its variants; runs.sh, runs2.sh, runs3.sh, runs4.sh). For each snapshot
given: the particles of both bodies within 4 mm (along x) of the rod's tip (the mean x of its
five deepest particles) and 7 mm of the axis; for each, the kernel-smoothed pressure
<p>_i = sum_j W_ij V_j p_j / sum_j W_ij V_j over every particle within 2 h_i (the half model
mirrored across z = 0; cubic spline), and p_i - <p>_i. Prints the smoothed pressure's median
and 10/90 percentiles, the rms and 10/90 percentiles of p - <p>, the share of particles with
p < 0, and the mean of p and of max(p, 0).

Usage: /usr/bin/python3 noise.py RUNDIR/particles_NNNNN.vtu ... (needs python3-numpy and
python3-scipy). docs/validation.md, "The floor at 1.29 km/s: the contact's tension and the
head's pressure noise (session 44)".
"""
import os
import sys

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', '..', '..', 'tools'))
from rod_floor import read_vtu  # noqa: E402


def noise(path):
    d = read_vtu(path)
    x, b, p, rho, h, m = d['x'], d['body'], d['p'], d['rho'], d['h'], d['m']
    r = np.hypot(x[:, 1], x[:, 2])
    tip = np.sort(x[b == 0, 0])[-5:].mean()
    sel = np.where((np.abs(x[:, 0] - tip) < 4e-3) & (r < 7e-3))[0]
    xm = np.vstack([x, x * np.array([1, 1, -1])])
    pm = np.concatenate([p, p])
    vm = np.concatenate([m / rho, m / rho])
    tree = cKDTree(xm)
    dev = np.empty(len(sel))
    smooth = np.empty(len(sel))
    for k, i in enumerate(sel):
        idx = tree.query_ball_point(x[i], 2 * h[i])
        q = np.linalg.norm(xm[idx] - x[i], axis=1) / h[i]
        w = np.where(q < 1, 1 - 1.5 * q**2 + 0.75 * q**3, np.where(q < 2, 0.25 * (2 - q)**3, 0))
        smooth[k] = np.sum(w * vm[idx] * pm[idx]) / np.sum(w * vm[idx])
        dev[k] = p[i] - smooth[k]
    g = 1e-9
    return (f'{path}: t = {d["TIME"] * 1e6:.0f} us, {len(sel)} particles | smoothed p median '
            f'{np.median(smooth) * g:.2f} GPa (10/90 {np.percentile(smooth, 10) * g:.2f} / '
            f'{np.percentile(smooth, 90) * g:.2f}) | p - smoothed: rms {np.sqrt(np.mean(dev**2)) * g:.2f} '
            f'GPa (10/90 {np.percentile(dev, 10) * g:.2f} / {np.percentile(dev, 90) * g:.2f}) | '
            f'p < 0: {np.mean(p[sel] < 0):.2f} | mean p {np.mean(p[sel]) * g:.2f}, '
            f'mean max(p, 0) {np.mean(np.maximum(p[sel], 0)) * g:.2f} GPa')


if __name__ == '__main__':
    for a in sys.argv[1:]:
        print(noise(a))
