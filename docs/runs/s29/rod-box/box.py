#!/usr/bin/python3
"""The rod target's box and its steel (session 29): rod-5844 (4.46 km/s) at resolution 0.3
(no core: the case's 2.5 mm block), to the case's end (119 us), in the paper's box (rigid
walls at y = +-50, z = 50 mm) with Table 2's steel and with Johnson & Cook's 4340
(steel-target-jc), and with a shell of the same steel at twice the spacing out to +-150 mm
(`part_of: target`, rigid walls there) with steel-target-jc (session 10's shell run with
Table 2's steel is quoted in docs/validation.md, not rerun). Penetration depth at 30, 55,
70, 85, 100 and 119 us, floor speed 10-30 and 30-55 us, cavity diameters at the end
(measurements.csv).

Usage: box.py   (in this folder)
docs/validation.md ("The target's box with the Johnson-Cook steel").
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', '..', 's26', 'rod-1929-floor'))
from floor import depths  # noqa: E402  (the measurements.csv loader)

RUNS = [('r44-box', "paper's box, Table 2's steel"),
        ('r44-box-jc', "paper's box, Johnson-Cook steel"),
        ('r44-shell-jc', "shell to 150 mm, Johnson-Cook steel")]
TIMES = [30, 55, 70, 85, 100, 119]


def at(d, t):
    return f"{d[t]:.1f}" if t in d else "-"


print("run | " + " | ".join(f"L {t} us" for t in TIMES) +
      " | u 10-30 | u 30-55 (km/s) | D | D_mean | D_wall | D_wall_mean at the end (mm)")
for folder, what in RUNS:
    path = os.path.join(HERE, folder)
    if not os.path.isdir(path):
        continue
    L = depths(path, 'penetration_depth')
    end = max(L)
    ds = [depths(path, q) for q in ('cavity_diameter', 'cavity_diameter_mean',
                                    'cavity_diameter_wall', 'cavity_diameter_wall_mean')]
    u1 = (L[30] - L[10]) / 20 if 30 in L else float('nan')
    u2 = (L[55] - L[30]) / 25 if 55 in L else float('nan')
    print(f"{what} (t_end {end:g} us) | " + " | ".join(at(L, t) for t in TIMES) +
          f" | {u1:.3f} | {u2:.3f} | " + " | ".join(at(d, end) for d in ds))
