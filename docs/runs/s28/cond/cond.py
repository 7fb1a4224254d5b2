#!/usr/bin/python3
"""The artificial conductivity on rod-5841 (session 28): resolution 0.3, a joined 1.0 mm core,
Table 2's materials, to 30 us, `--set sph.conductivity.alpha=1` on session 26's case file
(docs/runs/s26/rod-1929-floor/r41-case-c10.yaml), beside that case without it:
depth and crater-floor speed, channel (cavity_diameter_wall_mean / _wall / _mean) at 20
and 30 us.

The build: hvsph 60e6fb8 with conductivity.patch and cond.h (this folder) applied, not
committed (session 28).
Usage: cond.py   (in this folder)
docs/validation.md ("A Johnson-Cook target steel", the last paragraph).
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
S26 = os.path.join(HERE, '..', '..', 's26', 'rod-1929-floor')
sys.path.insert(0, S26)
from floor import depths  # noqa: E402  (the measurements.csv loader)

print("rod-5841 | L 30 us (mm) | u 10-30 | u 20-30 (km/s) | D_wall_mean 20 / 30 | D_wall 20 / 30 |"
      " D_mean 20 / 30 (mm)")
for folder, what in [(os.path.join(S26, 'r41-case-c10'), 'the case (s26)'),
                     (os.path.join(HERE, 'r41-cond'), 'conductivity alpha_u = 1')]:
    L, M = depths(folder, 'penetration_depth'), depths(folder, 'cavity_diameter_wall_mean')
    W, A = depths(folder, 'cavity_diameter_wall'), depths(folder, 'cavity_diameter_mean')
    print(f"{what} | {L[30]:.2f} | {(L[30] - L[10]) / 20:.3f} | {(L[30] - L[20]) / 10:.3f} |"
          f" {M[20]:.2f} / {M[30]:.2f} | {W[20]:.2f} / {W[30]:.2f} | {A[20]:.2f} / {A[30]:.2f}")
