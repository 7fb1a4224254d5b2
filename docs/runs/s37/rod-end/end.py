#!/usr/bin/env python3
"""rod-5841 at resolution 0.3 to its end (179 us): the case (Table 2's steel, alpha = 1)
and the Johnson-Cook steel with alpha = 0.2, beta = 0.4; read onto the paper's counts by
the ratio of the two at the same time and resolution.  Session 37, docs/validation.md
("Session 31's estimate run to the end").  Run from this folder: /usr/bin/python3 end.py
"""
import csv, math, os, sys

RUNS = [("case03", "Table 2's steel, alpha = 1 (the case)"),
        ("jc02", "Johnson-Cook steel, alpha = 0.2, beta = 0.4")]
Q = ["penetration_depth", "cavity_diameter", "cavity_diameter_mean",
     "cavity_diameter_wall", "cavity_diameter_wall_mean"]
# the case at the paper's counts (sessions 22-23): L, D, D_wall (mm); experiment
PAPER = {"penetration_depth": 148.0, "cavity_diameter": 22.9, "cavity_diameter_mean": 19.0,
         "cavity_diameter_wall": 22.0, "cavity_diameter_wall_mean": 20.7}
EXP = {"penetration_depth": 165.2, "cavity_diameter": 13.0, "cavity_diameter_mean": 13.0,
       "cavity_diameter_wall": 13.0, "cavity_diameter_wall_mean": 13.0}
E_ROD = 0.5 * 46.20e-3 * 2370.0 ** 2          # J, Table 1's mass and speed


def read(run):
    out = {}
    with open(os.path.join(run, "measurements.csv")) as f:
        rows = [r for r in f if not r.startswith("#")]
    for r in csv.DictReader(rows):
        if r["quantity"] in Q:
            out.setdefault(float(r["time"]), {})[r["quantity"]] = float(r["value"]) * 1e3
    return out


data = {run: read(run) for run, _ in RUNS}
for run, label in RUNS:
    print(f"{run}: {label}")
    print("t us | " + " | ".join(Q) + " (mm) | E/V GPa (D, L)")
    for t in sorted(data[run]):
        m = data[run][t]
        L, D = m.get("penetration_depth", 0), m.get("cavity_diameter", 0)
        ev = E_ROD / (math.pi * (D / 2e3) ** 2 * L / 1e3) / 1e9 if L > 0 and D > 0 else float("nan")
        print(f"{t * 1e6:6.1f} | " + " | ".join(f"{m.get(q, float('nan')):.2f}" for q in Q)
              + f" | {ev:.2f}")
    print()

tb, tj = max(data["case03"]), max(data["jc02"])
print(f"ends: case03 {tb * 1e6:.1f} us, jc02 {tj * 1e6:.1f} us")
if abs(tb - tj) > 1e-9:
    print("the runs have not both ended; the ratios below are at the last common time")
common = sorted(set(data["case03"]) & set(data["jc02"]))
# the end, and the output before it (the largest diameter D is one slice's nearest
# particle: a single gap in the wall at one time moves it; D_wall reads filled volume)
for t in common[-2:]:
    print(f"read onto the paper's counts at t = {t * 1e6:.1f} us "
          "(jc02 / case03 x the case at the paper's counts at its end)")
    for q, pv in PAPER.items():
        b, j = data["case03"][t][q], data["jc02"][t][q]
        est = j / b * pv
        print(f"  {q}: case03 {b:.2f}, jc02 {j:.2f} mm, ratio {j / b:.3f} -> {est:.1f} mm "
              f"({(est / EXP[q] - 1) * 100:+.0f} % of the experiment's {EXP[q]:g})")
t = common[-1]
L = data["jc02"][t]["penetration_depth"] / data["case03"][t]["penetration_depth"] * PAPER["penetration_depth"]
for q in ("cavity_diameter_wall", "cavity_diameter_wall_mean"):
    D = data["jc02"][t][q] / data["case03"][t][q] * PAPER[q]
    print(f"E/V of the estimated cavity (L {L:.1f} mm, {q} {D:.1f} mm): "
          f"{E_ROD / (math.pi * (D / 2e3) ** 2 * L / 1e3) / 1e9:.2f} GPa")
