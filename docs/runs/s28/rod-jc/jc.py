#!/usr/bin/python3
"""A Johnson-Cook target steel (session 28): rod-1929 (1.29 km/s), rod-5841 (2.37) and
rod-5844 (4.46) at resolution 0.3 with a joined 1.0 mm core, the steel target's strength
replaced by Johnson & Cook's (1983) 4340 steel (A 0.792 GPa, B 0.510 GPa, N 0.26, C 0.014,
M 1.03, T_melt 1793 K, cv 477 J/kg/K; Tresca splitting at -A) on Table 2's EOS and G,
against the same cases with Table 2's steel (sessions 20 and 26): penetration depth and
crater-floor speed, channel (cavity_diameter_wall_mean / cavity_diameter_wall /
cavity_diameter_mean) at 20 and 30 us, and the floor speed Tate's balance gives with the
resistance R_t that the experiment's final depth needs (docs/runs/s26/tate).

Usage: jc.py   (in this folder)
docs/validation.md ("A Johnson-Cook target steel").
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
RUNS_DIR = os.path.join(HERE, '..', '..')
sys.path.insert(0, os.path.join(RUNS_DIR, 's26', 'rod-1929-floor'))
sys.path.insert(0, os.path.join(RUNS_DIR, 's26', 'tate'))
from floor import depths  # noqa: E402  (the measurements.csv loader)
import tate  # noqa: E402

S26 = os.path.join(RUNS_DIR, 's26', 'rod-1929-floor')
S20 = os.path.join(RUNS_DIR, 's20', 'rod-5844-rod-spacing')
RUNS = [('1929', os.path.join(S26, 'case-c10'), "Table 2's steel (s26)"),
        ('1929', os.path.join(HERE, 'r29-jc'), 'Johnson-Cook steel'),
        ('5841', os.path.join(S26, 'r41-case-c10'), "Table 2's steel (s26)"),
        ('5841', os.path.join(HERE, 'r41-jc'), 'Johnson-Cook steel'),
        ('5841', os.path.join(HERE, 'r41-jc-nofrac'), 'Johnson-Cook steel without fracture'),
        ('5844', os.path.join(S20, 'r44-core-remeasured'), "Table 2's steel (s20)"),
        ('5844', os.path.join(HERE, 'r44-jc'), 'Johnson-Cook steel')]


def fmt(d, t):
    return f"{d[t]:.2f}" if t in d else "-"


print("rod | target | L 30 us (mm) | u 10-30 | u 20-30 (km/s) | u Tate, R_t of the experiment"
      " (km/s) | D_wall_mean 20 / 30 | D_wall 20 / 30 | D_mean 20 / 30 (mm)")
for rod, folder, what in RUNS:
    if not os.path.isdir(folder):
        continue
    v, l, lexp, _ = tate.RODS[rod]
    rt = tate.solve_rt(v, l, lexp)
    u_exp = f"{tate.head_speed(v, rt) / 1e3:.3f}" if rt > 0.11e9 else "-"
    L = depths(folder, 'penetration_depth')
    M = depths(folder, 'cavity_diameter_wall_mean')
    W = depths(folder, 'cavity_diameter_wall')
    A = depths(folder, 'cavity_diameter_mean')
    u1 = (L[30] - L[10]) / 20 if 30 in L else float('nan')
    u2 = (L[30] - L[20]) / 10 if 30 in L else float('nan')
    print(f"{rod} | {what} | {fmt(L, 30)} | {u1:.3f} | {u2:.3f} | {u_exp} |"
          f" {fmt(M, 20)} / {fmt(M, 30)} | {fmt(W, 20)} / {fmt(W, 30)} | {fmt(A, 20)} / {fmt(A, 30)}")
