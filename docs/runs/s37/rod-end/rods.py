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
import math
import os
import statistics
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "..", "tools"))
import meas_csv  # noqa: E402

Q = ["penetration_depth", "cavity_diameter", "cavity_diameter_mean",
     "cavity_diameter_wall", "cavity_diameter_wall_mean"]
SHORT = {"penetration_depth": "L", "cavity_diameter": "D", "cavity_diameter_mean": "D_mean",
         "cavity_diameter_wall": "D_wall", "cavity_diameter_wall_mean": "D_wall_mean"}
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
        common = sorted(t for t in set(b) & set(d) if t > 0)
        if not common:
            continue
        t = common[-1]
        print(f"{run} / {os.path.basename(base)} at {t:.1f} us, x the case at the paper's counts:")
        for q, pv in paper.items():
            r = d[t][q] / b[t][q]
            e = eL if q == "penetration_depth" else eD
            # the last three common outputs: a single particle in the channel can close
            # the cavity (L) or a thin slice miss the wall (D) at one output
            rr = [d[s][q] / b[s][q] for s in common[-3:]]
            print(f"  {SHORT[q]}: {b[t][q]:.2f} -> {d[t][q]:.2f} mm, ratio {r:.3f} "
                  f"(last three outputs {', '.join(f'{x:.3f}' for x in rr)}; median "
                  f"{statistics.median(rr):.3f}) -> {r * pv:.1f} mm, "
                  f"{(r * pv / e - 1) * 100:+.1f} % of the experiment")
        # the rod's kinetic energy per unit volume of the estimated cavity (session 36's
        # bound: E/V against the steel's limit pressure), V = pi (D/2)^2 L
        if name in E_ROD:
            L = d[t]["penetration_depth"] / b[t]["penetration_depth"] * paper["penetration_depth"]
            for q in ("cavity_diameter_wall", "cavity_diameter_wall_mean"):
                if q in paper:
                    D = d[t][q] / b[t][q] * paper[q]
                    ev = E_ROD[name] / (math.pi * (D / 2e3) ** 2 * L / 1e3) / 1e9
                    print(f"  E/V of the estimated cavity (L {L:.1f} mm, {SHORT[q]} {D:.1f} mm): {ev:.2f} GPa")
    print()
