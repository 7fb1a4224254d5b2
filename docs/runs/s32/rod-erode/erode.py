#!/usr/bin/python3
"""Session 32: is the eroded tungsten in the channel what drives rod-5841's wall out?
Session 26's r41-case-c10 (rod-5841, resolution 0.3, 1.0 mm core joined to the 2.5 mm
block) with rod particles removed once they are slower than vcut along x and more than
dbehind behind the rod's foremost particle (study.patch, HVSPH_ERODE=vcut,dbehind; not
committed), stops their outward motion instead (r25, r01: ecap = -2), cools them instead, scales the rod-rod viscosity, or (nc41, nc29: rod-1929's
r29-case-c10.yaml against session 26's case-c10) makes the contact force normal-only.
e29b / e29: rod-1929 with the eroded rod taken out 2.5 / 1.0 mm behind the tip.
b44 / e44: rod-5844 (session 19's r44-core.yaml to 30 us), the case and the eroded rod
taken out 1 mm behind the tip. Prints depth, floor speed and the channel, as session
31's eta.py.

Usage: erode.py [RUN ...]   (run folders; default: the runs kept here)
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', '..', 's26', 'rod-1929-floor'))
from floor import CHANNEL_HEADER, channel_row  # noqa: E402

RUNS = ['base', 'e53', 'e10', 'e25', 'e01', 'r25', 'r01', 'c01', 'k01', 'c00', 'k00', 'rv02', 'nc41',
        '../../s26/rod-1929-floor/case-c10', 'nc29', 'e29b', 'e29', 'r29', 'b44', 'e44', 'r44']
print("run | " + CHANNEL_HEADER)
for f in sys.argv[1:] or [os.path.join(HERE, r) for r in RUNS]:
    print(f"{os.path.basename(f.rstrip('/'))} | {channel_row(f)}")
