#!/usr/bin/python3
"""Session 36: can Table 2's steel hold the experiments' cavities at all?

For each rod of Table 3 the rod's kinetic energy E = m v^2 / 2 (Table 1) over the
cavity's volume V = pi (D/2)^2 L, for the experiment, for the paper's KERNEL and for
hvsph at the paper's counts (docs/validation.md, Status). Opening a cavity in an
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
import math
import os
import sys

from scipy.optimize import brentq

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 's26',
                                'tate'))
import tate  # noqa: E402

G, Y2, SHARE = 95.0, 0.39, 0.9          # GPa, GPa, target's share of E
# test: v (km/s), m (g), L, D experiment, L, D KERNEL, L, D hvsph (mm)
RODS = {
    '1929': (1.29, 100.0, 80.0, 12.5, 80.0, 12.1, 122.6, 20.8),
    '5835': (2.65, 96.96, 228.5, 19.2, 221.0, 18.0, 199.7, 28.2),
    '5839': (3.45, 96.73, 241.5, 26.0, 241.0, 25.0, 211.3, 34.2),
    '5841': (2.37, 46.20, 165.2, 13.0, 161.0, 12.5, 148.0, 22.9),
    '5842': (3.58, 46.02, 188.6, 20.1, 181.0, 20.0, 167.9, 28.9),
    '5844': (4.46, 45.41, 193.7, 27.2, 191.0, 26.0, 168.4, 33.3),
}


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
    for test, (v, m, le, de, lk, dk, lh, dh) in RODS.items():
        e = 0.5 * m * 1e-3 * (v * 1e3) ** 2
        pe, pk, ph = per_volume(e, le, de), per_volume(e, lk, dk), per_volume(e, lh, dh)
        yc = brentq(lambda y: cylinder(y) - SHARE * pe, 1e-3, 50.0)
        ys = brentq(lambda y: sphere(y) - SHARE * pe, 1e-3, 50.0)
        print(f"{test} | {v} | {e / 1e3:.1f} | {pe:.2f} | {pk:.2f} | {ph:.2f} | {yc:.2f} / {ys:.2f}"
              f" | {SHARE - sphere(Y2) / pe:.0%}")
    print()
    print("test | v km/s | R_t for the experiment's L | R_t for KERNEL's L (GPa)")
    for test in RODS:
        v, length, l_exp, l_kernel = tate.RODS[test]      # SI units
        print(f"{test} | {v / 1e3} | {tate.solve_rt(v, length, l_exp) / 1e9:.2f} |"
              f" {tate.solve_rt(v, length, l_kernel) / 1e9:.2f}")


if __name__ == '__main__':
    main()
