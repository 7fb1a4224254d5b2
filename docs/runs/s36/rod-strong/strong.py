#!/usr/bin/python3
"""Session 36: the three resolution-0.3 rod cases with the target's yield at 1.17 GPa,
unbroken or split at a plastic strain of 1 (runs.sh here; rod-5841 with the cases' viscosity is session 34's y3-41), read onto the
paper's counts by session 28's ratio rule (an estimate, not a run): the depth scaled
by u/(v - u) of the 10-30 us floor, D by D_wall_mean at 30 us, both against the
Table-2-steel run at the same resolution and that case's result at the paper's counts.

Usage: strong.py   (in this folder, after runs.sh)
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', '..', 's26', 'rod-1929-floor'))
from floor import CHANNEL_HEADER, channel_row, depths  # noqa: E402

# rod: v (km/s), baseline run (Table 2's steel, the cases' viscosity), paper-count L, D
# (mm), experiment L, D (mm)
RODS = {
    '1929': (1.29, '../../s26/rod-1929-floor/case-c10', 122.6, 20.8, 80.0, 12.5),
    '5841': (2.37, '../../s32/rod-erode/base', 148.0, 22.9, 165.2, 13.0),
    '5844': (4.46, '../../s32/rod-erode/b44', 168.4, 33.3, 193.7, 27.2),
}
RUNS = [  # rod, folder, what
    ('1929', 'y3-29', 'Y = 1.17 GPa, alpha 1, beta 2'),
    ('1929', 'y3a-29', 'Y = 1.17 GPa, alpha 0.2, beta 0.4'),
    ('5841', '../../s34/rod-forces/y3-41', 'Y = 1.17 GPa, alpha 1, beta 2 (session 34)'),
    ('5841', 'y3a-41', 'Y = 1.17 GPa, alpha 0.2, beta 0.4'),
    ('5844', 'y3-44', 'Y = 1.17 GPa, alpha 1, beta 2'),
    ('5844', 'y3a-44', 'Y = 1.17 GPa, alpha 0.2, beta 0.4'),
    ('1929', 'y3af-29', 'Y = 1.17 GPa, alpha 0.2, beta 0.4, split at plastic strain 1'),
    ('5841', 'y3af-41', 'Y = 1.17 GPa, alpha 0.2, beta 0.4, split at plastic strain 1'),
    ('5844', 'y3af-44', 'Y = 1.17 GPa, alpha 0.2, beta 0.4, split at plastic strain 1'),
]


def floor_ratio(path, v):
    L = depths(path)
    u = (L[30] - L[10]) / 20
    return u / (v - u)


def main():
    print("rod | run | " + CHANNEL_HEADER + " | estimated L, D at the paper's counts (mm; vs experiment)")
    for rod, folder, what in RUNS:
        v, base, lp, dp, le, de = RODS[rod]
        path = os.path.join(HERE, folder)
        if not os.path.exists(os.path.join(path, 'measurements.csv')) or 30 not in depths(path):
            print(f"{rod} | {what} | (not finished)")
            continue
        b = os.path.join(HERE, base)
        lest = lp * floor_ratio(path, v) / floor_ratio(b, v)
        dest = dp * (depths(path, 'cavity_diameter_wall_mean')[30]
                     / depths(b, 'cavity_diameter_wall_mean')[30])
        print(f"{rod} | {what} | {channel_row(path)} | {lest:.1f} ({lest / le - 1:+.0%}),"
              f" {dest:.1f} ({dest / de - 1:+.0%})")


if __name__ == '__main__':
    main()
