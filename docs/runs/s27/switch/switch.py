#!/usr/bin/python3
"""The viscosity switch (sph.viscosity.switch: cullen-dehnen) on the rods at resolution 0.3
with a joined 1.0 mm core (session 27), beside session 26's runs of the same cases with
alpha = 1 and alpha = 0.2 (docs/runs/s26/rod-1929-floor): crater-floor speed over 10-30 us
and 20-30 us against Tate (Table 2's Y_p = 0.983 GPa, R_t = 1.59 GPa), the channel
(cavity_diameter_wall_mean, cavity_diameter_wall) at 30 us and the steps taken; then
session 26's §2.4 bumper without the backwall at 12 us with the switch (ws-cd) beside its
alpha = 1 and alpha = 0.2 runs: the hole.

Usage: switch.py   (in this folder)
docs/validation.md ("The viscosity switch").
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', '..', 's26', 'rod-1929-floor'))
from floor import depths  # noqa: E402  (the measurements.csv loader)
S26 = os.path.join(HERE, '..', '..', 's26', 'rod-1929-floor')
RUNS = [  # folder, what, Tate floor speed (km/s)
    (os.path.join(S26, 'case-c10'), 'rod-1929, alpha = 1 (s26)', 0.736),
    (os.path.join(S26, 'case-c10-a02'), 'rod-1929, alpha = 0.2, beta = 0.4 (s26)', 0.736),
    (os.path.join(HERE, 'r29-case-c10-cd'), 'rod-1929, switch', 0.736),
    (os.path.join(S26, 'r41-case-c10'), 'rod-5841, alpha = 1 (s26)', 1.404),
    (os.path.join(S26, 'r41-case-c10-a02'), 'rod-5841, alpha = 0.2, beta = 0.4 (s26)', 1.404),
    (os.path.join(HERE, 'r41-case-c10-cd'), 'rod-5841, switch', 1.404),
]


def series(folder, q):
    """{time in us: value in mm} of measurement q (session 26's loader, floor.py)."""
    return depths(folder, q)


print("run | L at 10 / 20 / 30 us (mm) | u 10-30 | u 20-30 (km/s) | u 10-30 / Tate |"
      " D_wall_mean / D_wall at 30 us (mm) | steps")
for folder, what, th in RUNS:
    if not os.path.exists(os.path.join(folder, 'measurements.csv')):
        print(f"{what} | (not run)")
        continue
    L = series(folder, 'penetration_depth')
    M = series(folder, 'cavity_diameter_wall_mean')
    W = series(folder, 'cavity_diameter_wall')
    u1 = (L[30] - L[10]) / 20
    u2 = (L[30] - L[20]) / 10
    seg = open(os.path.join(folder, 'run_segments.csv')).read().strip().split('\n')[-1]
    print(f"{what} | {L[10]:.2f} / {L[20]:.2f} / {L[30]:.2f} | {u1:.3f} | {u2:.3f} |"
          f" {u1 / th - 1:+.1%} | {M[30]:.2f} / {W[30]:.2f} | {seg.split(',')[6]}")

# §2.4's bumper without the backwall to 12 us (session 26's set-up)
WS26 = os.path.join(HERE, '..', '..', 's26', 'ws-bumper-viscosity')
print("\n§2.4 bumper at 12 us | hole_diameter / _equiv / _intact (mm) | steps")
for folder, what in [(os.path.join(WS26, 'a1'), 'alpha = 1 (s26)'),
                     (os.path.join(WS26, 'a02'), 'alpha = 0.2, beta = 0.4 (s26)'),
                     (os.path.join(HERE, 'ws-cd'), 'switch')]:
    d = {q: series(folder, q)[12] for q in ('hole_diameter', 'hole_diameter_equiv',
                                          'hole_diameter_intact')}
    seg = open(os.path.join(folder, 'run_segments.csv')).read().strip().split('\n')[-1]
    print(f"{what} | {d['hole_diameter']:.2f} / {d['hole_diameter_equiv']:.2f} /"
          f" {d['hole_diameter_intact']:.2f} | {seg.split(',')[6]}")
