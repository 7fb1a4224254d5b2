#!/usr/bin/python3
"""The kernel's width on rod-5841's channel (session 31): session 26's r41-case-c10 (rod-5841
at resolution 0.3, a 1.0 mm core joined to the 2.5 mm block, Table 2's steel, alpha = 1)
with h = eta (m/rho)^(1/3) at eta = 1.0, 1.2 (the default; run again in this session,
../rod-stress/r41-base) and 1.5: depth at 10 / 20 / 30 us, floor speed, and the channel
(cavity_diameter_wall_mean, cavity_diameter_wall, cavity_diameter_mean) at 20 and 30 us.

Usage: eta.py   (in this folder)
docs/validation.md ("The Johnson-Cook steel with less viscosity", the kernel's width).
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', '..', 's26', 'rod-1929-floor'))
from floor import depths  # noqa: E402

RUNS = [('1.0', os.path.join(HERE, 'r41-eta10')),
        ('1.2', os.path.join(HERE, '..', 'rod-stress', 'r41-base')),
        ('1.5', os.path.join(HERE, 'r41-eta15'))]
print("eta | L 10 / 20 / 30 us (mm) | floor 10-30 / 20-30 (km/s) | D_wall_mean 20 / 30 |"
      " D_wall 20 / 30 | D_mean 20 / 30 (mm)")
for eta, f in RUNS:
    L = depths(f, 'penetration_depth')
    M = depths(f, 'cavity_diameter_wall_mean')
    W = depths(f, 'cavity_diameter_wall')
    A = depths(f, 'cavity_diameter_mean')
    print(f"{eta} | {L[10]:.2f} / {L[20]:.2f} / {L[30]:.2f} | {(L[30] - L[10]) / 20:.3f} /"
          f" {(L[30] - L[20]) / 10:.3f} | {M[20]:.2f} / {M[30]:.2f} | {W[20]:.2f} / {W[30]:.2f} |"
          f" {A[20]:.2f} / {A[30]:.2f}")
