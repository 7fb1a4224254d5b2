#!/usr/bin/python3
"""The state on the axis around a rod's tip in one VTU snapshot: particles within R of
the x axis, in 0.5 mm bins from 8 mm behind the tip to 8 mm ahead of it (the tip: the
mean x of the three deepest rod particles within R), rod (body 0) and target (every
other body) apart: count, mean axial velocity, pressure, density, specific internal
energy.

Usage: /usr/bin/python3 axis.py SNAPSHOT.vtu [R_mm (0.5)]   (needs python3-numpy;
tools/install-deps.sh --docs). docs/validation.md, session 42.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', '..', '..', 'tools'))
import numpy as np  # noqa: E402
import rod_floor  # noqa: E402


def main():
    d = rod_floor.read_vtu(sys.argv[1])
    R = (float(sys.argv[2]) if len(sys.argv) > 2 else 0.5) * 1e-3
    x, v, b = d['x'], d['v'], d['body']
    near = np.hypot(x[:, 1], x[:, 2]) < R
    tip = np.sort(x[near & (b == 0), 0])[-3:].mean()
    print(f"t = {d['TIME'] * 1e6:.2f} us, tip at {tip * 1e3:.2f} mm; particles within {R * 1e3:.2f} mm of the axis")
    print(" x - tip (mm) | body | n | vx (km/s) | p (GPa) | rho (kg/m3) | e (MJ/kg)")
    edges = np.arange(tip - 8e-3, tip + 8e-3 + 1e-9, 0.5e-3)
    for lo, hi in zip(edges[:-1], edges[1:]):
        s = near & (x[:, 0] >= lo) & (x[:, 0] < hi)
        for name, sel in (('rod', s & (b == 0)), ('target', s & (b != 0))):
            if sel.any():
                print(f" {(0.5 * (lo + hi) - tip) * 1e3:6.2f} | {name} | {sel.sum()} | {v[sel, 0].mean() / 1e3:.3f}"
                      f" | {d['p'][sel].mean() / 1e9:.1f} | {d['rho'][sel].mean():.0f} | {d['e'][sel].mean() / 1e6:.3f}")


if __name__ == '__main__':
    main()
