#!/usr/bin/python3
"""The target without fracture (session 27): rod-1929 (1.29 km/s) and rod-5841 (2.37 km/s) at
resolution 0.3 with a joined 1.0 mm core, Table 2's materials but the steel target's
Tresca splitting off (`st-nofrac`), to 30 us, beside session 26's runs of the same cases
with it (docs/runs/s26/rod-1929-floor): crater-floor speed over 10-30 and 20-30 us, the
channel (cavity_diameter_wall_mean, cavity_diameter_wall, cavity_diameter_mean) at 20
and 30 us.

Usage: nofrac.py   (in this folder)
docs/validation.md ("The target's fracture at low speed").
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', '..', 's26', 'rod-1929-floor'))
from floor import depths  # noqa: E402  (the measurements.csv loader)
S26 = os.path.join(HERE, '..', '..', 's26', 'rod-1929-floor')
RUNS = [(os.path.join(S26, 'case-c10'), 'rod-1929, the case (s26)'),
        (os.path.join(HERE, 'r29-case-c10-nofrac'), 'rod-1929, target without fracture'),
        (os.path.join(S26, 'r41-case-c10'), 'rod-5841, the case (s26)'),
        (os.path.join(HERE, 'r41-case-c10-nofrac'), 'rod-5841, target without fracture')]


def series(folder, q):
    """{time in us: value in mm} of measurement q (session 26's loader, floor.py)."""
    return depths(folder, q)


print("run | L at 30 us (mm) | u 10-30 | u 20-30 (km/s) | D_wall_mean 20 / 30 us |"
      " D_wall 20 / 30 us | D_mean 20 / 30 us (mm)")
for folder, what in RUNS:
    L = series(folder, 'penetration_depth')
    M = series(folder, 'cavity_diameter_wall_mean')
    W = series(folder, 'cavity_diameter_wall')
    A = series(folder, 'cavity_diameter_mean')
    print(f"{what} | {L[30]:.2f} | {(L[30] - L[10]) / 20:.3f} | {(L[30] - L[20]) / 10:.3f} |"
          f" {M[20]:.2f} / {M[30]:.2f} | {W[20]:.2f} / {W[30]:.2f} | {A[20]:.2f} / {A[30]:.2f}")
