#!/usr/bin/python3
"""How much of a rod's cross-section its cubic lattice covers: N columns of a lattice
centred on the rod's axis (points at (i + 1/2) d, (j + 1/2) d) lie inside its radius r,
and the ratio is N d^2 / (pi r^2) (the particles' masses are rho0 times the exact volume
over their number, so a ratio above 1 means particles lighter than rho0 d^3). For the
free symmetric test's rods (r = 2.615 mm) and the six paper-count rods, whose spacings
were read from a t = 0 snapshot (`hvsph run examples/paper/rod-N.yaml --set 'time.end=0
s'`: 5 018 particles in each half rod, 26 columns).

Usage: cover.py   (in this folder; writes cover.txt). docs/validation.md, session 42.
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', '..', '..', 'tools'))
import meas_csv  # noqa: E402

RODS = [('free test, rod 1.0 mm', 2.615, 1.0), ('free test, rod 0.7 mm', 2.615, 0.7),
        ('free test, rod 0.68 mm', 2.615, 0.68), ('free test, rod 0.62 mm', 2.615, 0.62),
        ('free test, rod 0.5 mm', 2.615, 0.5), ('free test, rod 0.35 mm', 2.615, 0.35),
        ('rod-1929', 3.433, 0.8091), ('rod-5835', 3.380, 0.8091), ('rod-5839', 3.376, 0.8091),
        ('rod-5841', 2.638, 0.6327), ('rod-5842', 2.633, 0.6327), ('rod-5844', 2.615, 0.6327)]


def columns(r, d):
    """Lattice columns inside radius r (whole cross-section)."""
    k = int(r / d) + 2
    return sum(1 for i in range(-k, k) for j in range(-k, k)
               if ((i + 0.5) * d) ** 2 + ((j + 0.5) * d) ** 2 <= r * r)


def main():
    lines = ['rod | r (mm) | spacing (mm) | r / spacing | columns | N d^2 / (pi r^2)']
    for what, r, d in RODS:
        n = columns(r, d)
        lines.append(f'{what} | {r} | {d} | {r / d:.2f} | {n} | {n * d * d / (math.pi * r * r):.3f}')
    meas_csv.emit(os.path.join(os.path.dirname(os.path.abspath(__file__)), 'cover.txt'), lines)


if __name__ == '__main__':
    main()
