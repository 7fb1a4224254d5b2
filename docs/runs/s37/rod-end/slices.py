#!/usr/bin/python3
"""The cavity's nearest-particle radius by slice (session 37): for a snapshot, the target
particles (material index TARGET_MAT of the field `mat`) binned in axial slices from the
block's surface x = 0; per slice the distance from the axis of the nearest particle.
Prints the three widest slices for slices 0.5, 1 and 2 mm thick (the measurement's D
uses half the target spacing, here 1.25 mm at resolution 0.3, and the nearest particle
less half a spacing), then the profile in 5 mm slices (nearest, 3rd and 10th nearest).
It shows why the largest diameter D of jc02 at 179 us (35.4 mm) is one thin slice with a
gap in the wall, not the channel's width. docs/validation.md ("Session 31's estimate run
to the end").  Usage: slices.py TARGET_MAT particles_NNNNN.vtu [...]
(TARGET_MAT: 1 for the cases, 0 for the Johnson-Cook runs, whose steel is defined first)
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', '..', '..', 'tools'))
from rod_floor import read_vtu  # noqa: E402

tmat = int(sys.argv[1])
for f in sys.argv[2:]:
    v = read_vtu(f)
    x = v['x'].reshape(-1, 3)
    tg = v['mat'] == tmat
    r = np.hypot(x[:, 1], x[:, 2])
    xmax = x[tg, 0].max()
    print(f"# {f}: t = {v['TIME'] * 1e6:.1f} us")
    for dx in (0.5e-3, 1e-3, 2e-3):
        best = []
        for lo in np.arange(0.0, 118e-3, dx):
            s = tg & (x[:, 0] >= lo) & (x[:, 0] < lo + dx)
            if s.sum():
                best.append((r[s].min(), lo))
        best.sort()
        print(f"slices {dx * 1e3:.1f} mm: widest nearest radius "
              + ", ".join(f"{a * 1e3:.2f} mm at x = {b * 1e3:.1f}" for a, b in best[-3:]))
    for lo in np.arange(0.0, min(xmax, 135e-3), 5e-3):
        s = tg & (x[:, 0] >= lo) & (x[:, 0] < lo + 5e-3)
        if s.sum() < 10:
            continue
        rr = np.sort(r[s])
        print(f"x {lo * 1e3:5.1f}-{(lo + 5e-3) * 1e3:5.1f} mm: n {s.sum():5d}, nearest {rr[0] * 1e3:6.2f}, "
              f"3rd {rr[2] * 1e3:6.2f}, 10th {rr[9] * 1e3:6.2f} mm")
