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
from floor import CHANNEL_HEADER, channel_row  # noqa: E402

RUNS = [('1.0', os.path.join(HERE, 'r41-eta10')),
        ('1.2', os.path.join(HERE, '..', 'rod-stress', 'r41-base')),
        ('1.5', os.path.join(HERE, 'r41-eta15'))]
print("eta | " + CHANNEL_HEADER)
for eta, f in RUNS:
    print(f"{eta} | {channel_row(f)}")
