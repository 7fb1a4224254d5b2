#!/usr/bin/env python3
"""The symmetric rod test read along the axis (docs/validation.md, Still to do, the rods).

usage: /usr/bin/python3 axis_enthalpy.py RUNDIR V_IMPACT U_FLOOR
  RUNDIR     a run of symc-free.yaml or ../../s14/rod-symmetric/symc-long.yaml with csv snapshots
  V_IMPACT   the rod's speed, m/s (4460)
  U_FLOOR    the floor speed that defines the tip's frame, m/s (the fit over 5-20 us)

Per snapshot: the rod's tip (mean x of its five deepest particles) and the speed since
the last snapshot; the total enthalpy H = e + p/rho + w^2/2 (w = vx - U_FLOOR) on the
axis (r < 1.5 mm) of the rod 4-8 mm behind the tip and of the target 1-8 mm ahead of it
(in a steady adiabatic flow H is constant along a streamline: 0.5 (V - U)^2 for the
rod, 0.5 U^2 for an undisturbed target); the target's pressure and axial velocity
15-25 mm ahead within 8 mm of the axis; and the floor speed that Bernoulli's balance
gives when the target arrives with the measured H instead of 0.5 U^2 (equal materials):
0.5 (V - u)^2 = 0.5 u^2 + dH, u = V/2 - dH/V.
"""
import glob
import re
import sys

import numpy as np

run, v, u = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
prev = None
print("  t us   tip mm  speed km/s | H rod 4-8 mm behind, target 1-8 mm ahead (MJ/kg) | "
      "target 15-25 mm ahead: p GPa, vx m/s | u = V/2 - dH/V km/s")
for f in sorted(glob.glob(run + "/particles_*.csv")):
    t = float(re.search(r"time ([0-9.eE+-]+) s", open(f).readline()).group(1))
    d = np.genfromtxt(f, delimiter=",", names=True, skip_header=2)
    rod = d["body"] == 0
    tip = np.sort(d["x"][rod])[-5:].mean()
    speed = (tip - prev[1]) / (t - prev[0]) / 1e3 if prev else float("nan")
    prev = (t, tip)
    r = np.hypot(d["y"], d["z"])
    dx = d["x"] - tip
    H = d["e"] + d["p"] / d["rho"] + 0.5 * (d["vx"] - u) ** 2
    ax = r < 1.5e-3
    hr = H[ax & rod & (dx > -8e-3) & (dx < -4e-3)]
    ht = H[ax & ~rod & (dx > 1e-3) & (dx < 8e-3)]
    ahead = ~rod & (dx > 15e-3) & (dx < 25e-3) & (r < 8e-3)
    if len(ht) == 0 or len(hr) == 0:
        print("%6.1f %8.2f %8.3f" % (t * 1e6, tip * 1e3, speed))
        continue
    dH = ht.mean() - 0.5 * u * u
    print("%6.1f %8.2f %8.3f   | %6.3f %6.3f | %5.1f %5.0f | %6.3f" % (
        t * 1e6, tip * 1e3, speed, hr.mean() / 1e6, ht.mean() / 1e6,
        d["p"][ahead].mean() / 1e9 if ahead.any() else float("nan"),
        d["vx"][ahead].mean() if ahead.any() else float("nan"), (v / 2 - dH / v) / 1e3))
print("undisturbed: H rod %.3f, target %.3f MJ/kg; V/2 = %.3f km/s"
      % (0.5 * (v - u) ** 2 / 1e6, 0.5 * u * u / 1e6, v / 2e3))
