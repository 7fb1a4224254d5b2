#!/usr/bin/python3
"""Session 36: the rods' floor and channel with three forms of the artificial viscosity,
at 1.29, 2.37 and 4.46 km/s (resolution 0.3, a 1.0 mm core; runs.sh here). For each run:
depth, floor speed u over 10-30 us, the channel (the columns of session 26's floor.py),
and the target resistance R_t that Tate's head balance gives for that floor,
    R_t = 1/2 rho_p (v - u)^2 + Y_p - 1/2 rho_t u^2
(Table 2: rho_p = 17 780, rho_t = 7 810 kg/m3, Y_p = 0.983 GPa). Hill's cylinder for
Table 2's steel is 1.59 GPa; the experiments' depths read 6.08, 2.63 and < 0.1 GPa
(../../s26/tate/tate.txt), the paper's KERNEL depths 6.08, 3.0 and < 0.1 GPa.

Usage: visc.py   (in this folder, after runs.sh)
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', '..', 's26', 'rod-1929-floor'))
from floor import CHANNEL_HEADER, channel_row, depths  # noqa: E402

RHO_P, RHO_T, Y_P = 17780.0, 7810.0, 0.983e9
RUNS = [  # (folder, v km/s, viscosity)
    ('../../s26/rod-1929-floor/case-c10', 1.29, 'reconstruction, alpha 1, beta 2 (the cases)'),
    ('std29', 1.29, 'standard, alpha 1, beta 2'),
    ('lin29', 1.29, 'standard, alpha 1, beta 0'),
    ('../../s32/rod-erode/base', 2.37, 'reconstruction, alpha 1, beta 2 (the cases)'),
    ('std41', 2.37, 'standard, alpha 1, beta 2'),
    ('lin41', 2.37, 'standard, alpha 1, beta 0'),
    ('../../s32/rod-erode/b44', 4.46, 'reconstruction, alpha 1, beta 2 (the cases)'),
    ('std44', 4.46, 'standard, alpha 1, beta 2'),
    ('lin44', 4.46, 'standard, alpha 1, beta 0'),
]


def resistance(v, u):
    """Tate's R_t (GPa) for a head moving at u (km/s) under a rod at v (km/s)."""
    v, u = v * 1e3, u * 1e3
    return (0.5 * RHO_P * (v - u) ** 2 + Y_P - 0.5 * RHO_T * u ** 2) / 1e9


def main():
    print("v (km/s) | viscosity | " + CHANNEL_HEADER + " | R_t from the 10-30 us floor (GPa)")
    for folder, v, what in RUNS:
        path = os.path.join(HERE, folder)
        if not os.path.exists(os.path.join(path, 'measurements.csv')):
            print(f"{v} | {what} | (not run)")
            continue
        L = depths(path)
        if 30 not in L:
            print(f"{v} | {what} | (not finished)")
            continue
        u = (L[30] - L[10]) / 20
        print(f"{v} | {what} | {channel_row(path)} | {resistance(v, u):.2f}")


if __name__ == '__main__':
    main()
