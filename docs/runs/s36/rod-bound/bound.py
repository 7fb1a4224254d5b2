#!/usr/bin/python3
"""Session 36: can Table 2's steel hold the experiments' cavities at all?

For each rod of Table 3 the rod's kinetic energy E = m v^2 / 2 (Table 1, as
tools/gen_paper_cases.py holds it) over the cavity's volume V = pi (D/2)^2 L, for the
experiment, for the paper's KERNEL and for hvsph at the paper's counts (L and D from
the rods' validation table, ../../s23/rods_validation.csv, the Status table's runs). Opening a cavity in an
elastic-perfectly plastic solid takes, per unit of the cavity's volume, its limit
pressure: k (1 + ln(G/k)), k = Y/sqrt(3), for a cylinder, (2Y/3)(1 + ln(2G/Y)) for a
sphere (incompressible; Hill 1950). With the share of E that the target takes (s =
0.9, measured for rod-5841 in session 35), the last columns give
  - the yield Y that would make the target's plastic work s E / V (cylinder, sphere);
  - the part of E that would have to go elsewhere than the target's plastic work for
    Table 2's steel (Y = 0.39 GPa, G = 95 GPa) to hold the experiment's cavity:
    s - p_sphere / (E / V).
A second table gives the target resistance R_t that Tate's balance needs for the
experiment's and for KERNEL's depth (solve_rt of ../../s26/tate/tate.py; 0.10 GPa is
its bisection's floor: the depth is past Tate's hydrodynamic limit).

Usage: bound.py   (prints the table; bound.txt here is its output)
"""
import csv
import math
import os
import sys

from scipy.optimize import brentq

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', '..', 's26', 'tate'))
ROOT = os.path.join(HERE, '..', '..', '..', '..')
sys.path.insert(0, os.path.join(ROOT, 'tools'))
_cwd = os.getcwd()
os.chdir(ROOT)                   # gen_paper_cases reads data/materials.yaml from the root
import gen_paper_cases  # noqa: E402
os.chdir(_cwd)
import tate  # noqa: E402

G, Y2, SHARE = 95.0, 0.39, 0.9          # GPa, GPa, target's share of E
VALIDATION = os.path.join(HERE, '..', '..', 's23', 'rods_validation.csv')


def cavities():
    """test -> {column: (L, D)} in mm for 'simulated' (hvsph), 'experiment' and
    'paper_simulation' (KERNEL), from the rods' validation table."""
    out = {}
    with open(VALIDATION) as f:
        for row in csv.DictReader(f):
            test = row['case'].removeprefix('rod-')
            i = {'penetration_depth:target': 0, 'cavity_diameter:target': 1}[row['quantity']]
            for col in ('simulated', 'experiment', 'paper_simulation'):
                out.setdefault(test, {}).setdefault(col, [0.0, 0.0])[i] = float(row[col])
    return out


def cylinder(y):
    k = y / math.sqrt(3.0)
    return k * (1.0 + math.log(G / k))


def sphere(y):
    return 2.0 * y / 3.0 * (1.0 + math.log(2.0 * G / y))


def per_volume(e, length, diameter):
    """E over the cavity's volume, GPa (e in J, lengths in mm)."""
    return e / (math.pi * (diameter / 2e3) ** 2 * length / 1e3) / 1e9


def main():
    print(f"Table 2's steel (Y = {Y2} GPa, G = {G:.0f} GPa): limit pressure"
          f" {cylinder(Y2):.2f} GPa (cylinder), {sphere(Y2):.2f} GPa (sphere)")
    print("test | v km/s | E kJ | E/V experiment | E/V KERNEL | E/V hvsph (GPa) |"
          f" Y for {SHARE} E/V, cylinder / sphere (GPa) | share of E to go elsewhere with Table 2")
    cav = cavities()
    for test, (v, _, _, m, _) in gen_paper_cases.RODS.items():
        e = 0.5 * m * 1e-3 * (v * 1e3) ** 2
        pe, pk, ph = (per_volume(e, *cav[test][c]) for c in ('experiment', 'paper_simulation',
                                                               'simulated'))
        yc = brentq(lambda y: cylinder(y) - SHARE * pe, 1e-3, 50.0)
        ys = brentq(lambda y: sphere(y) - SHARE * pe, 1e-3, 50.0)
        print(f"{test} | {v} | {e / 1e3:.1f} | {pe:.2f} | {pk:.2f} | {ph:.2f} | {yc:.2f} / {ys:.2f}"
              f" | {SHARE - sphere(Y2) / pe:.0%}")
    print()
    print("test | v km/s | R_t for the experiment's L | R_t for KERNEL's L (GPa)")
    for test in gen_paper_cases.RODS:
        v, length, l_exp, l_kernel = tate.RODS[test]      # SI units
        print(f"{test} | {v / 1e3} | {tate.solve_rt(v, length, l_exp) / 1e9:.2f} |"
              f" {tate.solve_rt(v, length, l_kernel) / 1e9:.2f}")


if __name__ == '__main__':
    main()
