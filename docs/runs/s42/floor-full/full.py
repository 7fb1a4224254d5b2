#!/usr/bin/python3
"""Session 42: the floor of the free symmetric test at 4.46 km/s (tungsten into tungsten
without strength; a steady floor moves at v/2 = 2.23 km/s exactly) in eleven more runs,
beside session 41's half models: the whole crater in the lattice at 0.5 mm (the +-20 mm
core of symc-free-wide.yaml); the +-8 mm core as a full model, on the cubic lattice and
with rod and core on an hcp lattice; the half model with half the Courant number, and
with a cold tungsten (Grueneisen coefficient 0: heat carries no pressure); and the rod
and the core at different spacings (the rod at 0.35, 0.5, 0.62, 0.68 and 1.0 mm in the
0.7 mm core, and at 0.7 mm in a 0.5 mm core). Speeds from the penetration depth L of
each run's
measurements.csv, by session 41's free.py (its speed_tables); then Bernoulli with the
target's measured enthalpy from each FOLDER_axis.txt beside the run's slope.

Usage: full.py   (in this folder; writes full.txt). docs/validation.md, session 42.
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
S41 = os.path.join(HERE, '..', '..', 's41', 'floor-free')
sys.path.insert(0, os.path.join(HERE, '..', '..', '..', '..', 'tools'))
sys.path.insert(0, S41)
import meas_csv  # noqa: E402
from free import cell, fit, speed_tables  # noqa: E402

V = 4.46
RUNS = [  # folder, what
    (os.path.join(S41, 'free446-a1'), 'half model, +-8 mm core, 0.7 mm (session 41)'),
    (os.path.join(S41, 'free446-h05'), 'half model, +-8 mm core, 0.5 mm (session 41)'),
    (os.path.join(S41, 'free446-wide'), 'half model, +-20 mm core, 0.7 mm (session 41)'),
    (os.path.join(HERE, 'free446-wide-h05'), 'half model, +-20 mm core, 0.5 mm'),
    (os.path.join(HERE, 'full-cubic'), 'full model, +-8 mm core, 0.7 mm cubic'),
    (os.path.join(HERE, 'full-hcp'), 'full model, +-8 mm core, rod and core hcp (0.7^3 mm^3 each)'),
    (os.path.join(HERE, 'half-cfl015'), 'half model, +-8 mm core, 0.7 mm, Courant number 0.15 (0.3)'),
    (os.path.join(HERE, 'half-g0'), 'half model, +-8 mm core, 0.7 mm, Grueneisen 0 (cold tungsten)'),
    (os.path.join(HERE, 'half-r05-c07'), 'half model, +-8 mm core, rod 0.5 mm, core 0.7 mm'),
    (os.path.join(HERE, 'half-r07-c05'), 'half model, +-8 mm core, rod 0.7 mm, core 0.5 mm'),
    (os.path.join(HERE, 'half-r10-c07'), 'half model, +-8 mm core, rod 1.0 mm, core 0.7 mm'),
    (os.path.join(HERE, 'half-r035-c07'), 'half model, +-8 mm core, rod 0.35 mm, core 0.7 mm'),
    (os.path.join(HERE, 'half-r062-c07'), 'half model, +-8 mm core, rod 0.62 mm, core 0.7 mm'),
    (os.path.join(HERE, 'half-r068-c07'), 'half model, +-8 mm core, rod 0.68 mm, core 0.7 mm'),
]
SPANS = [(5, 10), (10, 15), (15, 20), (5, 20), (10, 20)]


def main():
    lines, fits = speed_tables([(f, V, w) for f, w in RUNS], SPANS, (5, 10, 15, 20))
    lines += [''] + fits
    lines += ['', 'Bernoulli with the target\'s measured enthalpy (FOLDER_axis.txt, session 15\'s',
              'axis_enthalpy.py: u = V/2 - dH/V, its mean over the outputs at 10-20 us) against the',
              'least-squares slope of L over 10-20 us: what the pressure pulse ahead of the floor',
              'explains, and what is left (the run under the estimate)',
              'run | estimate (km/s, against v/2) | L slope 10-20 us | run against the estimate']
    for folder, what in RUNS:
        est = axis_estimate(folder + '_axis.txt')
        L = meas_csv.series(os.path.join(folder, 'measurements.csv'), 'penetration_depth')
        u = fit(L, 10, 20) if L else None
        if est is None or u is None:
            continue
        lines.append(f'{what} | {cell(est, V)} | {cell(u, V)} | {100 * (u / est - 1):+.1f}%')
    meas_csv.emit(os.path.join(HERE, 'full.txt'), lines)


def axis_estimate(path):
    """Mean of axis_enthalpy.py's last column (u = V/2 - dH/V, km/s) over its rows at
    10 <= t <= 20 us; None without the file (session 41's runs have none)."""
    if not os.path.exists(path):
        return None
    us = []
    with open(path) as f:
        for line in f:
            cols = line.split()
            if len(cols) > 8 and cols[0].replace('.', '', 1).isdigit() and 10 <= float(cols[0]) <= 20:
                us.append(float(cols[-1]))
    return sum(us) / len(us) if us else None


if __name__ == '__main__':
    main()
