#!/usr/bin/env python3
"""Light debris on a heavy backwall: how far apart may the particle masses of two bodies
be where they collide? (docs/validation.md, "Light debris on a heavy backwall")

A slab of light particles (2.1 mm thick, 2.08 mm in the slow set; 7 x 7 mm, rigid side walls, so the flow is
planar) strikes a block of heavier particles; for each pair of spacings the script runs
hvsph to 0.6 us (1.2 us for the 1 km/s set) and prints the slab's largest density over
the outputs against its material's reference density, the median of its shocked state
at 0.2 us (0.4 us) and the block's largest density. The exact planar impact has one
shocked state per side; a light particle squeezed between heavy ones shows as a
largest density far above the shocked median.

usage: python3 tools/mass_ratio_study.py [--hvsph build/hvsph] [-o out/mass-ratio]
       [--set steel|slow|all]
Needs python3-numpy. "all" (18 runs, one thread each) took 12 minutes on this project's
2-core machine with other simulations beside it.
"""
import argparse
import glob
import os
import subprocess

import numpy as np

RHO0 = {"steel-bumper": 7850.0, "al-alloy": 2780.0}

# (label, debris material, debris spacing mm, slab thickness mm, speed km/s, wall spacing
#  mm, side mm, end us)
STEEL = [("steel", "steel-bumper", ds, 2.1, 6.2, dw, 7.0, 0.6)
         for ds, dw in [(0.175, 0.175), (0.175, 0.35), (0.175, 0.7), (0.175, 0.875),
                        (0.175, 1.0), (0.175, 1.4), (0.175, 1.75), (0.2, 0.35), (0.2, 0.5),
                        (0.2, 0.7), (0.2, 0.875), (0.2, 1.0), (0.2, 1.4), (0.19, 1.0),
                        (0.21, 1.0)]]
SLOW = [("slow", "al-alloy", 0.16, 2.08, 1.0, dw, 6.4, 1.2) for dw in (0.4, 0.8, 1.6)]


def case(label, mat, ds, thick, v, dw, side, end):
    return f"""name: mr_{label}_{ds}_{dw}
domain:
  min: [-3 mm, 0, 0]
  max: [8 mm, {side} mm, {side} mm]
  boundary: {{x: open, y: wall, z: wall}}
bodies:
  - name: debris
    material: {mat}
    shape: {{type: box, min: [{-thick} mm, 0, 0], max: [0, {side} mm, {side} mm]}}
    spacing: {ds} mm
    velocity: [{v} km/s, 0, 0]
  - name: wall
    material: al-alloy
    shape: {{type: box, min: [0, 0, 0], max: [{side} mm, {side} mm, {side} mm]}}
    spacing: {dw} mm
sph:
  kernel: cubic-spline
  eta: 1.2
  viscosity: {{alpha: 1.0, beta: 2.0, reconstruct: true}}
time:
  end: {end} us
output:
  every: {end / 6:.3g} us
  csv: true
  vtu: false
"""


def read(f):
    return np.genfromtxt(f, delimiter=",", names=True, skip_header=2)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--hvsph", default="build/hvsph")
    ap.add_argument("-o", default="out/mass-ratio")
    ap.add_argument("--set", default="steel", choices=["steel", "slow", "all"])
    a = ap.parse_args()
    runs = (STEEL if a.set in ("steel", "all") else []) + (SLOW if a.set in ("slow", "all") else [])
    os.makedirs(a.o, exist_ok=True)
    print("| debris | speed | debris spacing | wall spacing | mass ratio | debris max rho/rho0 "
          "| debris shocked (median) | wall max rho/rho0 |")
    print("|---|---|---|---|---|---|---|---|")
    for label, mat, ds, thick, v, dw, side, end in runs:
        name = f"mr_{label}_{ds}_{dw}"
        path = os.path.join(a.o, name + ".yaml")
        with open(path, "w") as f:
            f.write(case(label, mat, ds, thick, v, dw, side, end))
        out = os.path.join(a.o, name)
        subprocess.run([a.hvsph, "run", path, "-o", out, "--overwrite", "--threads", "1",
                        "--quiet"], check=True)
        snaps = sorted(glob.glob(os.path.join(out, "particles_*.csv")))[1:]
        rd, rw = RHO0[mat], RHO0["al-alloy"]
        dmax = wmax = 0.0
        for s in snaps:
            d = read(s)
            dmax = max(dmax, (d["rho"][d["body"] == 0] / rd).max())
            wmax = max(wmax, (d["rho"][d["body"] == 1] / rw).max())
        d = read(snaps[1])
        deb = d["body"] == 0
        shocked = deb & (d["vx"] < d["vx"][deb].max() - 50.0)
        ratio = d["m"][d["body"] == 1][0] / d["m"][deb][0]
        print(f"| {mat} | {v} km/s | {ds} mm | {dw} mm | {ratio:.2g} | {dmax:.2f} | "
              f"{np.median(d['rho'][shocked]) / rd:.2f} | {wmax:.2f} |")


if __name__ == "__main__":
    main()
