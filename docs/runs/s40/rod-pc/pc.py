#!/usr/bin/env python3
"""The rods at the paper's counts with session 31's set (the Johnson-Cook target,
alpha = 0.2, beta = 0.4) beside the case at the paper's counts (Table 2's steel,
alpha = 1), output by output, and the same ratio at resolution 0.3 (the ratio rule of
sessions 37-39): does the set's gain at resolution 0.3 hold at the paper's counts?
Session 40, docs/validation.md ("The set at the paper's counts: rods 5841, 5842 and 5844
(session 40)").  Run from this folder: /usr/bin/python3 pc.py [JC_RUNS_DIR]

JC runs: pc5841jc, pc5842jc (this session; JC_RUNS_DIR, default this folder) and
../../s39/rod-5844-pc.  The case at the paper's counts: ../../s22/rod-5841,
../../s16/rod-5842 (its D_wall from ../../s20/wall-remeasured), rod-5844's session-7 run
(its depths as docs/validation.md quotes them: no measurements file was kept).
Resolution 0.3 pairs: ../../s37/rod-end/{case03,jc02} (rod-5841),
../../s39/rod-5842/{c5842,jc5842}, ../../s29/rod-box/r44-box and ../../s37/rod-end/r44jc02
(rod-5844).  Experiment and KERNEL: ../../s23/rods_validation.csv.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "..", "tools"))
import meas_csv  # noqa: E402

Q, SHORT = meas_csv.CAVITY_Q, meas_csv.CAVITY_SHORT
RUNS = os.path.join("..", "..")
JC = sys.argv[1] if len(sys.argv) > 1 else "."


def read(*parts):
    return meas_csv.read(os.path.join(*parts, "measurements.csv"), Q)


def merged(*dicts):
    """The union of read()'s dicts, the first holding a quantity at a time winning."""
    out = {}
    for d in dicts:
        for t, row in d.items():
            for q, v in row.items():
                out.setdefault(t, {}).setdefault(q, v)
    return out


# rod-5844's case at the paper's counts (session 7): L only, at its outputs
C5844 = {25.0: {"penetration_depth": 62.3}, 50.0: {"penetration_depth": 126.6},
         75.0: {"penetration_depth": 173.0}, 100.0: {"penetration_depth": 173.0},
         119.0: {"penetration_depth": 168.4, "cavity_diameter": 33.3}}
RODS = [
    ("rod-5841", 2.37, read(RUNS, "s22", "rod-5841"), read(JC, "pc5841jc"),
     read(RUNS, "s37", "rod-end", "case03"), read(RUNS, "s37", "rod-end", "jc02")),
    ("rod-5842", 3.58, merged(read(RUNS, "s16", "rod-5842"),
                              meas_csv.read(os.path.join(RUNS, "s20", "wall-remeasured",
                                                         "rod-5842_measurements.csv"), Q)),
     read(JC, "pc5842jc"), read(RUNS, "s39", "rod-5842", "c5842"),
     read(RUNS, "s39", "rod-5842", "jc5842")),
    ("rod-5844", 4.46, C5844, read(RUNS, "s39", "rod-5844-pc"),
     read(RUNS, "s29", "rod-box", "r44-box"), read(RUNS, "s37", "rod-end", "r44jc02")),
]
VAL = meas_csv.validation_table(os.path.join(RUNS, "s23", "rods_validation.csv"))


at, f = meas_csv.at, meas_csv.fmt_or_dash


for name, v, case, jc, c03, j03 in RODS:
    ref = meas_csv.rod_heading(name, v, VAL, jc)
    if ref is None:
        continue
    eL, kL, eD, kD = ref
    print("   t us | L case | L JC | JC/case | same at res 0.3 | D_wall case | D_wall JC | D JC (mm)"
          "  (L case and res 0.3: linear between their outputs where they have none at t)")
    for t, Lc, L, r, r03 in meas_csv.jc_rows(case, jc, c03, j03):
        print(f"  {t:6.1f} | {f(Lc)} | {f(L)} | {f(r, '7.3f')} | {f(r03, '7.3f')} | "
              f"{f(case.get(t, {}).get('cavity_diameter_wall'))} | "
              f"{f(jc[t].get('cavity_diameter_wall'))} | {f(jc[t].get('cavity_diameter'))}")
    t = max(jc)
    L, Dw, D = (jc[t].get(q) for q in ("penetration_depth", "cavity_diameter_wall", "cavity_diameter"))
    print(f"  last output {t:.1f} us: L {L:.1f} mm ({(L / eL - 1) * 100:+.1f} % of the experiment; "
          f"KERNEL {(kL / eL - 1) * 100:+.1f} %), D_wall {Dw:.1f} mm ({(Dw / eD - 1) * 100:+.1f} %), "
          f"D {D:.1f} mm ({(D / eD - 1) * 100:+.1f} %; KERNEL {(kD / eD - 1) * 100:+.1f} %)")
    tc = max(case)
    Lc = case[tc]["penetration_depth"]
    print(f"  the case's last output {tc:.1f} us: L {Lc:.1f} mm ({(Lc / eL - 1) * 100:+.1f} %)\n")
