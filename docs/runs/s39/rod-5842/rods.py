#!/usr/bin/env python3
"""rod-5842 at resolution 0.3 to its end: the case (Table 2's steel, alpha = 1) beside
the Johnson-Cook steel with alpha = 0.2, beta = 0.4, read onto the paper's counts by the
ratio of the two at the end (the ratio x the case's result at the paper's counts), as
sessions 37 and 38 did for the other five rods; then the six rods' estimates together.
Session 39, docs/validation.md ("rod-5842 with the Johnson-Cook target; the six rods
(session 39)").  Run from this folder: /usr/bin/python3 rods.py

The case at the paper's counts: the final output of session 16's run
(../../s16/rod-5842), its D_wall from session 20's re-measurement
(../../s20/wall-remeasured); the experiment and KERNEL from ../../s23/rods_validation.csv.
The other five rods' estimates and errors are read from session 38's table
(../../s38/rod-jc/rods.txt, whose errors are of the unrounded estimates).
"""
import os
import re
import statistics
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "..", "tools"))
import meas_csv  # noqa: E402

Q, SHORT = meas_csv.CAVITY_Q, meas_csv.CAVITY_SHORT
RUNS = os.path.join("..", "..")
NAME, V, M = "rod-5842", 3.58, 46.02  # km/s, g (Table 1)
PAPER = [os.path.join(RUNS, "s16", "rod-5842", "measurements.csv"),
         os.path.join(RUNS, "s20", "wall-remeasured", "rod-5842_measurements.csv")]


def read(run):
    return meas_csv.read(os.path.join(run, "measurements.csv"), Q)


VAL = meas_csv.validation_table(os.path.join(RUNS, "s23", "rods_validation.csv"))
sL, eL, kL = VAL[NAME]["penetration_depth"]
sD, eD, kD = VAL[NAME]["cavity_diameter"]
tp, paper = meas_csv.final_of(PAPER, Q)
print(f"== {NAME} ({V} km/s); experiment L {eL} mm, D {eD} mm; the case at the paper's "
      f"counts at {tp:.0f} us: " + ", ".join(f"{SHORT[q]} {paper[q]:.1f}" for q in Q if q in paper))
b, d = read("c5842"), read("jc5842")
for run, x in (("c5842", b), ("jc5842", d)):
    meas_csv.print_history(run, x, Q, SHORT)
t, est = meas_csv.ratio_estimates(b, d, paper, eL, eD, SHORT, "jc5842 / c5842")
meas_csv.print_energy(0.5 * M * 1e-3 * (V * 1e3) ** 2, est, SHORT)
print()

# the six rods: session 38's table rows (five rods) and this one
rows = {}
with open(os.path.join(RUNS, "s38", "rod-jc", "rods.txt")) as f:
    for line in f:
        if re.match(r"rod-\d+ \|", line):
            c = [x.strip() for x in line.split("|")]
            pct = [float(x.rstrip(" %")) for x in (c[4], c[5], c[6], c[9], c[10], c[11])]
            rows[c[0]] = (line.rstrip("\n"), pct)
Dw = est.get("cavity_diameter_wall")
D = Dw if Dw is not None else est["cavity_diameter"]
pct = [(est["penetration_depth"] / eL - 1) * 100, (sL / eL - 1) * 100, (kL / eL - 1) * 100,
       (D / eD - 1) * 100, (sD / eD - 1) * 100, (kD / eD - 1) * 100]
dtxt = f"{est['cavity_diameter']:.1f} / " + (f"{Dw:.1f}" if Dw is not None else "-")
rows[NAME] = (f"{NAME} | {est['penetration_depth']:.1f} | {eL} | {kL} | {pct[0]:+.1f} % | {pct[1]:+.1f} % | "
              f"{pct[2]:+.1f} % | {dtxt} | {eD} | {pct[3]:+.1f} % | {pct[4]:+.1f} % | {pct[5]:+.1f} %", pct)
print("== the six rods: the Johnson-Cook target at alpha = 0.2, estimated at the paper's counts")
print("rod | L est | L exp | L KERNEL | err est | err case | err KERNEL | D est (D / D_wall) | D exp | err est | err case | err KERNEL")
for name in sorted(rows):
    print(rows[name][0])
for k, off in (("L", 0), ("D", 3)):
    a, c, kk = (statistics.mean(abs(rows[n][1][off + i]) for n in rows) for i in range(3))
    print(f"mean |error| of {k} over {len(rows)} rods: JC estimate {a:.1f} %, case {c:.1f} %, KERNEL {kk:.1f} %")
for k, off, lim in (("L", 0, 5.0), ("D", 3, 10.0)):
    ok = [n for n in sorted(rows) if abs(rows[n][1][off]) <= lim]
    print(f"{k} within the aim's {lim:.0f} %: {', '.join(ok) if ok else 'none'}")
print("(D est: D_wall where the paper-count run has it, else D; the case's D column is D)")
