#!/usr/bin/python3
"""What the Johnson-Cook target's strength is at the rod's head (session 28): in a
snapshot of a rod run with steel-target-jc, the target within 4 mm ahead of the crater
floor and 1.5 rod radii of the axis ("ahead"), and the target beside the head, 0-4 mm
behind the floor and within 3 mm outside the wall ("wall"; the wall is the smallest
radius of a target particle in that slab): mass-mean temperature T = 293.15 K + e/cv,
plastic strain, von Mises stress sqrt(3 J2) and the Johnson-Cook yield Y(eps_p, T) with
a strain rate of 1e5/s.

Usage: head_yield.py R0_MM particles_NNNNN.vtu [...]
docs/validation.md ("A Johnson-Cook target steel").
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', '..', '..', 'tools'))
from rod_floor import read_vtu  # noqa: E402

A, B, N, C, M, TM, TR, CV = 0.792e9, 0.510e9, 0.26, 0.014, 1.03, 1793.0, 293.15, 477.0
r0 = float(sys.argv[1]) * 1e-3


def jc(eps, T, rate=1e5):
    ts = np.clip((T - TR) / (TM - TR), 0.0, 1.0)
    return (A + B * np.power(np.maximum(eps, 0.0), N)) * (1 + C * np.log(rate)) * (1 - ts ** M)


print("snapshot | t (us) | region | n | T (K) | eps_p | sqrt(3 J2) (GPa) | JC yield (GPa)")
for f in sys.argv[2:]:
    v = read_vtu(f)
    x = v['x'].reshape(-1, 3)
    S = v['S'].reshape(-1, 6)
    m = v['m']
    tg = v['mat'] == 0          # material 0 is the target (st-jc) in these runs
    r = np.hypot(x[:, 1], x[:, 2])
    near = tg & (r < 2e-3) & (x[:, 0] > 1e-3)
    floor = x[near, 0].min()
    J2 = 0.5 * (S[:, 0] ** 2 + S[:, 1] ** 2 + S[:, 2] ** 2) + S[:, 3] ** 2 + S[:, 4] ** 2 + S[:, 5] ** 2
    seq = np.sqrt(3 * J2)
    T = TR + np.maximum(v['e'], 0) / CV
    eps = v['eps_p']
    slab = tg & (x[:, 0] > floor - 4e-3) & (x[:, 0] <= floor)
    wall = r[slab].min() if slab.any() else 0.0
    regions = [('ahead', tg & (x[:, 0] >= floor) & (x[:, 0] < floor + 4e-3) & (r < 1.5 * r0)),
               (f'wall (a = {wall * 1e3:.1f} mm)', slab & (r < wall + 3e-3))]
    for name, sel in regions:
        w = m[sel] / m[sel].sum()
        print(f"{os.path.basename(os.path.dirname(os.path.abspath(f)))}/{os.path.basename(f)} |"
              f" {v['TIME'] * 1e6:.0f} | {name} | {sel.sum()} | {np.sum(w * T[sel]):.0f} |"
              f" {np.sum(w * eps[sel]):.2f} | {np.sum(w * seq[sel]) / 1e9:.2f} |"
              f" {np.sum(w * jc(eps[sel], T[sel])) / 1e9:.2f}")
