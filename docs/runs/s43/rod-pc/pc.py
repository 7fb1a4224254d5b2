#!/usr/bin/env python3
"""Rods 5839, 5835 and 1929 at the paper's counts with session 31's set (the
Johnson-Cook target, alpha = 0.2, beta = 0.4) beside the case at the paper's counts
(Table 2's steel, alpha = 1), output by output, and the same ratio at resolution 0.3
(sessions 37-38).  Session 43, docs/validation.md ("The set at the paper's counts to
the end: rods 5839, 5835 and 1929 (session 43)").  Run from this folder:
/usr/bin/python3 pc.py [JC_RUNS_DIR] > pc.txt

JC runs: pc5839jc-mc2, pc5835jc-mc2, pc1929jc-mc2 (this session; JC_RUNS_DIR, default this
folder): each run's snapshots measured again with measure.cavity_min_count: 2
(../../s38/rod-jc/remeasure.sh), so that a loose particle on the axis does not close
the cavity (pc5839jc's own measurements.csv, min_count 1, puts L at 144.5 mm at 125 us
where the floor is at 199.2).
The case at the paper's counts: ../../s23/rod-5839, ../../s24/rod-5835,
../../s25/rod-1929.  Resolution 0.3 pairs: ../../s38/rod-jc/{c5839,jc5839}-mc2 and
{c5835,jc5835}-mc2, ../../s37/rod-end/{c29case,c29jc}.  Experiment and KERNEL:
../../s23/rods_validation.csv.
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "..", "tools"))
import meas_csv  # noqa: E402

Q = meas_csv.CAVITY_Q
RUNS = os.path.join(HERE, "..", "..")
JC = sys.argv[1] if len(sys.argv) > 1 else HERE


def read(*parts):
    return meas_csv.read(os.path.join(*parts, "measurements.csv"), Q)


RODS = [
    ("rod-5839", 3.45, read(RUNS, "s23", "rod-5839"), read(JC, "pc5839jc-mc2"),
     read(RUNS, "s38", "rod-jc", "c5839-mc2"), read(RUNS, "s38", "rod-jc", "jc5839-mc2")),
    ("rod-5835", 2.65, read(RUNS, "s24", "rod-5835"), read(JC, "pc5835jc-mc2"),
     read(RUNS, "s38", "rod-jc", "c5835-mc2"), read(RUNS, "s38", "rod-jc", "jc5835-mc2")),
    ("rod-1929", 1.29, read(RUNS, "s25", "rod-1929"), read(JC, "pc1929jc-mc2"),
     read(RUNS, "s37", "rod-end", "c29case"), read(RUNS, "s37", "rod-end", "c29jc")),
]
VAL = meas_csv.validation_table(os.path.join(RUNS, "s23", "rods_validation.csv"))


at, f = meas_csv.at, meas_csv.fmt_or_dash


def err(x, e):
    return f"{(x / e - 1) * 100:+.1f} %"


for name, v, case, jc, c03, j03 in RODS:
    ref = meas_csv.rod_heading(name, v, VAL, jc)
    if ref is None:
        continue
    eL, kL, eD, kD = ref
    print("   t us | L case | L JC | JC/case | same at res 0.3 | D_wall case | D_wall JC | D case | D JC (mm)"
          "  (linear between outputs where a run has none at t)")
    for t, Lc, L, r, r03 in meas_csv.jc_rows(case, jc, c03, j03):
        print(f"  {t:6.1f} | {f(Lc)} | {f(L)} | {f(r, '7.3f')} | {f(r03, '7.3f')} | "
              f"{f(at(case, t, 'cavity_diameter_wall'))} | {f(jc[t].get('cavity_diameter_wall'))} | "
              f"{f(at(case, t, 'cavity_diameter'))} | {f(jc[t].get('cavity_diameter'))}")
    for label, d in (("JC", jc), ("case", case)):
        t = max(d)
        L, Dw, D = (d[t].get(q) for q in ("penetration_depth", "cavity_diameter_wall", "cavity_diameter"))
        print(f"  {label} last output {t:.1f} us: L {L:.1f} mm ({err(L, eL)}; KERNEL {err(kL, eL)}), "
              f"D_wall {f(Dw)} mm ({err(Dw, eD) if Dw else '-'}), D {D:.1f} mm ({err(D, eD)}; "
              f"KERNEL {err(kD, eD)})")
    print()
