#!/usr/bin/python3
"""Floor speeds at 1.29 km/s without strength (session 41): tungsten into tungsten and steel
into steel, where the floor of an unbounded target moves at v/2 exactly, beside session 26's
tungsten into steel (Bernoulli u = v / (1 + sqrt(rho_t / rho_p))). The same case file
(../../s26/rod-1929-floor/r29-fluid-c10.yaml: rod 1.24 mm, a 1.0 mm core in a 2.5 mm block,
alpha = 1, reconstruction), materials swapped with --material. Mean speed of the
penetration depth L (measurements.csv, every 5 us) over 10-30 and 20-30 us.

Usage: floor.py   (in this folder; writes floor.txt)
docs/validation.md ("The floor without strength at 1.29 km/s, and what a floor's deficit
does to the depth").
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', '..', '..', '..', 'tools'))
import meas_csv  # noqa: E402

V = 1.29
RHO_W, RHO_S = 17.78, 7.81
RUNS = [  # folder, what, theory (km/s)
    ('ww', 'tungsten into tungsten', V / 2),
    ('ss', 'steel into steel', V / 2),
    (os.path.join('..', '..', 's26', 'rod-1929-floor', 'fluid-c10'),
     'tungsten into steel (session 26)', V / (1 + math.sqrt(RHO_S / RHO_W))),
]


def main():
    lines = ['pair | L at 10 / 20 / 30 us (mm) | u 10-30 | u 20-30 (km/s) | theory |'
             ' u 10-30 / theory - 1 | u 20-30 / theory - 1']
    for folder, what, theory in RUNS:
        L = meas_csv.series(os.path.join(HERE, folder, 'measurements.csv'), 'penetration_depth')
        u1 = (L[30] - L[10]) / 20.0
        u2 = (L[30] - L[20]) / 10.0
        lines.append(f"{what} | {L[10]:.2f} / {L[20]:.2f} / {L[30]:.2f} | {u1:.3f} | {u2:.3f} |"
                     f" {theory:.3f} | {100 * (u1 / theory - 1):+.1f}% | {100 * (u2 / theory - 1):+.1f}%")
    meas_csv.emit(os.path.join(HERE, 'floor.txt'), lines)


if __name__ == '__main__':
    main()
