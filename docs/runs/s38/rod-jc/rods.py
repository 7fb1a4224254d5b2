#!/usr/bin/env python3
"""Rods 5835 and 5839 at resolution 0.3 to their ends: the case (Table 2's steel,
alpha = 1) beside the Johnson-Cook steel with alpha = 0.2, beta = 0.4, read onto the
paper's counts by the ratio of the two at the end (the ratio x the case's result at the
paper's counts), as session 37 did for rods 1929, 5841 and 5844 (../../s37/rod-end).
Session 38, docs/validation.md ("The Johnson-Cook target on rods 5835 and 5839").
Run from this folder: /usr/bin/python3 rods.py

The case at the paper's counts: the final output of its archived run (rod-5835
../../s24/rod-5835, rod-5839 ../../s23/rod-5839); the experiment
and KERNEL from the rods' validation table ../../s23/rods_validation.csv.  The last part
puts five rods' estimates (these two and session 37's three, from its rods.txt) beside
the experiment and KERNEL.
"""
import os
import re
import statistics
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "..", "tools"))
import meas_csv  # noqa: E402

Q, SHORT = meas_csv.CAVITY_Q, meas_csv.CAVITY_SHORT
RUNS = os.path.join("..", "..")
# rod, speed km/s, paper-count run(s) (later files fill what earlier ones lack), rod's m (g)
RODS = [
    ("rod-5835", 2.65, [os.path.join(RUNS, "s24", "rod-5835", "measurements.csv")], 96.96),
    ("rod-5839", 3.45, [os.path.join(RUNS, "s23", "rod-5839", "measurements.csv")], 96.73),
    # rod-5842: its pair ran in session 39 (../../s39/rod-5842, whose rods.py puts
    # the six rods together)
]


def read(run):
    return meas_csv.read(os.path.join(run, "measurements.csv"), Q)


VAL = meas_csv.validation_table(os.path.join(RUNS, "s23", "rods_validation.csv"))
EST = {}  # rod -> {quantity: estimate mm}
for name, v, paths, m in RODS:
    tp, paper = meas_csv.final_of(paths, Q)
    eL = VAL[name]["penetration_depth"][1]
    eD = VAL[name]["cavity_diameter"][1]
    base, other = "c" + name[4:], "jc" + name[4:]
    b = read(base)
    print(f"== {name} ({v} km/s); experiment L {eL} mm, D {eD} mm; the case at the paper's "
          f"counts at {tp:.0f} us: " + ", ".join(f"{SHORT[q]} {paper[q]:.1f}" for q in Q if q in paper))
    for run in (base, other):
        meas_csv.print_history(run, read(run), Q, SHORT)
    d = read(other)
    res = meas_csv.ratio_estimates(b, d, paper, eL, eD, SHORT, f"{other} / {base}")
    if res:
        EST[name] = res[1]
        # the rod's kinetic energy per unit volume of the estimated cavity (session 36's bound)
        meas_csv.print_energy(0.5 * m * 1e-3 * (v * 1e3) ** 2, EST[name], SHORT)
    print()

# session 37's three rods, from its printed estimates
PCT = {}  # rod -> {quantity: printed relative error} for session 37's rods
S37 = os.path.join(RUNS, "s37", "rod-end", "rods.txt")
rod = None
with open(S37) as f:
    for line in f:
        m = re.match(r"== (rod-\d+)", line)
        if m:
            rod = m.group(1)
        m = re.match(r"\s+(\w+): .* -> ([\d.]+) mm, ([+-][\d.]+) % of the experiment", line)
        if m and rod and "/" not in line:
            q = {v: k for k, v in SHORT.items()}[m.group(1)]
            # rod-5844: the alpha = 0.2 run (r44jc02) is the second estimate; keep the last.
            # The printed error (of the unrounded estimate) is kept beside the estimate
            EST.setdefault(rod, {})[q] = float(m.group(2))
            PCT.setdefault(rod, {})[q] = float(m.group(3)) / 100

print("== the rods run so far: the Johnson-Cook target at alpha = 0.2, estimated at the paper's counts")
print("rod | L est | L exp | L KERNEL | err est | err case | err KERNEL | D est (D / D_wall) | D exp | err est | err case | err KERNEL")
errs = {"L": [[], [], []], "D": [[], [], []]}
for name in sorted(EST):
    e = EST[name]
    sL, xL, kL = VAL[name]["penetration_depth"]
    sD, xD, kD = VAL[name]["cavity_diameter"]
    L = e["penetration_depth"]
    Dd, Dw = e.get("cavity_diameter"), e.get("cavity_diameter_wall")
    D = Dw if Dw is not None else Dd
    qD = "cavity_diameter_wall" if Dw is not None else "cavity_diameter"
    p = PCT.get(name, {})
    row = [p.get("penetration_depth", L / xL - 1), sL / xL - 1, kL / xL - 1]
    rowD = [p.get(qD, D / xD - 1), sD / xD - 1, kD / xD - 1]
    for i in range(3):
        errs["L"][i].append(abs(row[i]))
        errs["D"][i].append(abs(rowD[i]))
    dtxt = (f"{Dd:.1f} / {Dw:.1f}" if Dw is not None else f"{Dd:.1f} / -")
    print(f"{name} | {L:.1f} | {xL} | {kL} | {row[0]*100:+.1f} % | {row[1]*100:+.1f} % | "
          f"{row[2]*100:+.1f} % | {dtxt} | {xD} | {rowD[0]*100:+.1f} % | {rowD[1]*100:+.1f} % | "
          f"{rowD[2]*100:+.1f} %")
for k in ("L", "D"):
    a, c, kk = (statistics.mean(x) * 100 for x in errs[k])
    print(f"mean |error| of {k} over {len(errs[k][0])} rods: JC estimate {a:.1f} %, case {c:.1f} %, KERNEL {kk:.1f} %")
print("(D est: D_wall where the paper-count run has it, else D; the case's D column is D)")
