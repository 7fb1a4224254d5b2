#!/usr/bin/env python3
"""Three rods at resolution 0.3 to (or near) their ends: the case (Table 2's steel,
alpha = 1) beside the Johnson-Cook steel with alpha = 0.2, beta = 0.4, read onto the
paper's counts by the ratio of the two at the same time (the ratio x the case's result
at the paper's counts).  Session 37, docs/validation.md ("Session 31's estimate run to
the end").  Run from this folder: /usr/bin/python3 rods.py
rod-5841: case03, jc02 (this folder); rod-1929: c29case, c29jc (to 260 us of the
case's 353: the paper-count run's floor stops by 250 us); rod-5844: session 29's
r44-box (the case) and r44-box-jc (JC steel, alpha = 1) in ../../s29/rod-box, and
r44jc02 (JC steel, alpha = 0.2) here.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "..", "tools"))
import meas_csv  # noqa: E402

Q, SHORT = meas_csv.CAVITY_Q, meas_csv.CAVITY_SHORT
# 1/2 m v^2 of the rod (Table 1's mass and speed), for the estimated cavities' E/V
E_ROD = {"rod-5841": 0.5 * 46.20e-3 * 2370.0 ** 2}
S29 = os.path.join("..", "..", "s29", "rod-box")
# case at the paper's counts (docs/validation.md: sessions 25-27, 22-23, 7), experiment (L, D)
RODS = [
    ("rod-1929", 1.29, "c29case", ["c29jc"],
     {"penetration_depth": 122.6, "cavity_diameter": 20.8, "cavity_diameter_mean": 16.4,
      "cavity_diameter_wall": 19.4, "cavity_diameter_wall_mean": 18.0}, (80.0, 12.5)),
    ("rod-5841", 2.37, "case03", ["jc02"],
     {"penetration_depth": 148.0, "cavity_diameter": 22.9, "cavity_diameter_mean": 19.0,
      "cavity_diameter_wall": 22.0, "cavity_diameter_wall_mean": 20.7}, (165.2, 13.0)),
    ("rod-5844", 4.46, os.path.join(S29, "r44-box"), [os.path.join(S29, "r44-box-jc"), "r44jc02"],
     {"penetration_depth": 168.4, "cavity_diameter": 33.3}, (193.7, 27.2)),
]


def read(run):
    return meas_csv.read(os.path.join(run, "measurements.csv"), Q)


for name, v, base, others, paper, (eL, eD) in RODS:
    b = read(base)
    print(f"== {name} ({v} km/s); experiment L {eL} mm, D {eD} mm")
    for run in [base] + others:
        meas_csv.print_history(run, read(run), Q, SHORT)
    for run in others:
        d = read(run)
        res = meas_csv.ratio_estimates(b, d, paper, eL, eD, SHORT, f"{run} / {os.path.basename(base)}")
        if res and name in E_ROD:
            t, est = res
            meas_csv.print_energy(E_ROD[name], est, SHORT)
    print()
