#!/usr/bin/python3
"""The Johnson-Cook target steel with less artificial viscosity (session 31): rod-1929
(1.29 km/s), rod-5841 (2.37) and rod-5844 (4.46) at resolution 0.3 with a joined 1.0 mm
core (session 28's r29-jc / r41-jc / r44-jc set-ups in docs/runs/s28/rod-jc), run with
alpha = 0.2, beta = 0.4 and with the Cullen-Dehnen switch, beside session 28's runs with
the cases' alpha = 1, beta = 2 and with Table 2's steel (sessions 20 and 26): depth and
crater-floor speed, channel (cavity_diameter_wall_mean / cavity_diameter_wall /
cavity_diameter_mean) at 20 and 30 us, the floor speed Tate's balance gives with the
resistance R_t the experiment's final depth needs (docs/runs/s26/tate), and the depth
and diameter read onto the paper's counts (L scaled by u/(v - u) of the 10-30 us floors,
session 28's rule; D by the ratio of D_wall_mean at 30 us, where session 28 used D_wall
or D_mean; both against the Table-2-steel run at the same resolution and the
paper's-count result).

Usage: jcvisc.py   (in this folder)
docs/validation.md ("The Johnson-Cook steel with less viscosity").
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
S28 = os.path.join(RUNS_DIR, 's28', 'rod-jc')
# the reference run (Table 2's steel, alpha = 1) at resolution 0.3 and the case at the
# paper's counts (validation.md Status): depth, D (nearest particle), experiment L, D
REF = {'1929': (os.path.join(S26, 'case-c10'), 122.6, 20.8, 80.0, 12.5),
       '5841': (os.path.join(S26, 'r41-case-c10'), 148.0, 22.9, 165.2, 13.0),
       '5844': (os.path.join(S20, 'r44-core-remeasured'), 168.4, 33.3, 193.7, 27.2)}
RUNS = [('1929', os.path.join(S28, 'r29-jc'), 'JC, alpha 1 (s28)'),
        ('1929', os.path.join(HERE, 'r29-jc-a02'), 'JC, alpha 0.2'),
        ('1929', os.path.join(HERE, 'r29-jc-sw'), 'JC, switch'),
        ('5841', os.path.join(S28, 'r41-jc'), 'JC, alpha 1 (s28)'),
        ('5841', os.path.join(HERE, 'r41-jc-a02'), 'JC, alpha 0.2'),
        ('5841', os.path.join(HERE, 'r41-jc-sw'), 'JC, switch'),
        ('5844', os.path.join(S28, 'r44-jc'), 'JC, alpha 1 (s28)'),
        ('5844', os.path.join(HERE, 'r44-jc-a02'), 'JC, alpha 0.2'),
        ('5844', os.path.join(HERE, 'r44-jc-sw'), 'JC, switch')]


def fmt(d, t):
    return f"{d[t]:.2f}" if t in d else "-"


def floor_speed(folder):
    L = depths(folder, 'penetration_depth')
    return (L[30] - L[10]) / 20 if 30 in L and 10 in L else float('nan'), L


print("rod | run | L 30 us (mm) | u 10-30 | u 20-30 (km/s) | u Tate, R_t of the experiment"
      " (km/s) | D_wall_mean 20 / 30 | D_wall 20 / 30 | D_mean 20 / 30 (mm)"
      " | paper's counts, estimated: L (mm, vs exp.) | D (mm, vs exp.)")
for rod, folder, what in RUNS:
    if not os.path.isdir(folder):
        continue
    v, l, lexp, _ = tate.RODS[rod]
    rt = tate.solve_rt(v, l, lexp)
    u_exp = f"{tate.head_speed(v, rt) / 1e3:.3f}" if rt > 0.11e9 else "-"
    u1, L = floor_speed(folder)
    u2 = (L[30] - L[20]) / 10 if 30 in L and 20 in L else float('nan')
    M = depths(folder, 'cavity_diameter_wall_mean')
    W = depths(folder, 'cavity_diameter_wall')
    A = depths(folder, 'cavity_diameter_mean')
    ref, l_pc, d_pc, l_e, d_e = REF[rod]
    u_ref, _ = floor_speed(ref)
    M_ref = depths(ref, 'cavity_diameter_wall_mean')
    vk = v / 1e3
    l_est = l_pc * (u1 / (vk - u1)) / (u_ref / (vk - u_ref))
    d_est = d_pc * M[30] / M_ref[30] if 30 in M else float('nan')
    print(f"{rod} | {what} | {fmt(L, 30)} | {u1:.3f} | {u2:.3f} | {u_exp} |"
          f" {fmt(M, 20)} / {fmt(M, 30)} | {fmt(W, 20)} / {fmt(W, 30)} | {fmt(A, 20)} / {fmt(A, 30)}"
          f" | {l_est:.1f} ({100 * (l_est / l_e - 1):+.0f} %) | {d_est:.1f} ({100 * (d_est / d_e - 1):+.0f} %)")
