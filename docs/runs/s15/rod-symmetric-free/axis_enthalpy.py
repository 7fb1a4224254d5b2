#!/usr/bin/env python3
"""The symmetric rod test read along the axis (docs/validation.md, Still to do, the rods).

usage: /usr/bin/python3 axis_enthalpy.py RUNDIR V_IMPACT U_FLOOR
  RUNDIR     a run of symc-free.yaml, symc-free-long.yaml or
             ../../s14/rod-symmetric/symc-long.yaml (its particles_NNNNN.vtu)
  V_IMPACT   the rod's speed, m/s (4460)
  U_FLOOR    the floor speed that defines the tip's frame, m/s (the fit over 5-20 us)

Snapshots are read with tools/rod_floor.py's reader, the tip is its "tip" (the mean x
of the rod's five deepest particles). Per snapshot: the tip and its speed since the
last snapshot; the total enthalpy H = e + p/rho + w^2/2 (w = vx - U_FLOOR) on the axis
(r < 1.5 mm) of the rod 4-8 mm behind the tip and of the target 1-8 mm ahead of it (in
a steady adiabatic flow H is constant along a streamline: 0.5 (V - U)^2 for the rod,
0.5 U^2 for an undisturbed target); the target's pressure and axial velocity 15-25 mm
ahead within 8 mm of the axis; and the floor speed that Bernoulli's balance gives when
the target arrives with the measured H instead of 0.5 U^2 (equal materials):
0.5 (V - u)^2 = 0.5 u^2 + dH, u = V/2 - dH/V. Then the tip's speed fitted (least
squares) over 5-20, 20-35 and 35-50 us, where the run covers them.
"""
import glob
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../../tools"))
from rod_floor import body_index, read_vtu  # noqa: E402

run, v, u = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
rod_body = body_index(run, "rod")
ts, tips = [], []
print("  t us   tip mm  speed km/s | H rod 4-8 mm behind, target 1-8 mm ahead (MJ/kg) | "
      "target 15-25 mm ahead: p GPa, vx m/s | u = V/2 - dH/V km/s")
for f in sorted(glob.glob(os.path.join(run, "particles_*.vtu"))):
    d = read_vtu(f)
    t, x, vx = d["TIME"], d["x"], d["v"][:, 0]
    rod = d["body"] == rod_body
    tip = np.sort(x[rod, 0])[-5:].mean()
    speed = (tip - tips[-1]) / (t - ts[-1]) / 1e3 if ts else float("nan")
    ts.append(t)
    tips.append(tip)
    r = np.hypot(x[:, 1], x[:, 2])
    dx = x[:, 0] - tip
    H = d["e"] + d["p"] / d["rho"] + 0.5 * (vx - u) ** 2
    ax = r < 1.5e-3
    hr = H[ax & rod & (dx > -8e-3) & (dx < -4e-3)]
    ht = H[ax & ~rod & (dx > 1e-3) & (dx < 8e-3)]
    ahead = ~rod & (dx > 15e-3) & (dx < 25e-3) & (r < 8e-3)
    if len(ht) == 0 or len(hr) == 0 or not ahead.any():
        print("%6.1f %8.2f %8.3f" % (t * 1e6, tip * 1e3, speed))
        continue
    dH = ht.mean() - 0.5 * u * u
    print("%6.1f %8.2f %8.3f   | %6.3f %6.3f | %5.1f %5.0f | %6.3f" % (
        t * 1e6, tip * 1e3, speed, hr.mean() / 1e6, ht.mean() / 1e6,
        d["p"][ahead].mean() / 1e9, vx[ahead].mean(), (v / 2 - dH / v) / 1e3))
print("undisturbed: H rod %.3f, target %.3f MJ/kg; V/2 = %.3f km/s"
      % (0.5 * (v - u) ** 2 / 1e6, 0.5 * u * u / 1e6, v / 2e3))
ts, tips = np.array(ts), np.array(tips)
for a, b in ((5e-6, 20e-6), (20e-6, 35e-6), (35e-6, 50e-6)):
    m = (ts >= a - 1e-7) & (ts <= b + 1e-7)
    if ts[-1] >= b - 1e-7 and m.sum() > 2:
        print("fit %g-%g us: %.3f km/s" % (a * 1e6, b * 1e6, np.polyfit(ts[m], tips[m], 1)[0] / 1e3))
