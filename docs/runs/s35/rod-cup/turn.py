#!/usr/bin/python3
"""The rod's 180-degree turn in a rigid cup or slot (session 35 study), from a run's CSV
snapshots. Per time: the rod's rear end and speed, the mass outside the rod and the part
of it held near the bottom (x < X_hold, the 'mushroom'), and through planes x = X the
reversed sheet's axial mass flux against the rod's inflow, its mass-mean axial speed
against the impact speed v (Bernoulli: v), and where it is.
  cup  (cup.yaml, a quarter rod of radius a): outside the rod is r > 1.05 a; masses in
       g of the whole rod; the last column is the sheet's mass-mean r (mm).
  slot (slot.yaml, a slab of half-width a, periodic in z): outside is y > 1.05 a;
       masses in g per mm of z; the last column is the sheet's inner edge, the 5th
       percentile of its y (mm).
usage: turn.py cup|slot RUNDIR [a_mm] [v_m_s] [X_hold_mm]"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', '..', '..', 'tools'))
from rod_floor import csv_snapshots  # noqa: E402

mode, run = sys.argv[1], sys.argv[2]
a = float(sys.argv[3]) * 1e-3 if len(sys.argv) > 3 else 2.638e-3
v0 = float(sys.argv[4]) if len(sys.argv) > 4 else 1100.0
xh = float(sys.argv[5]) * 1e-3 if len(sys.argv) > 5 else 2 * a
cup = mode == "cup"
unit = "g" if cup else "g/mm"
print("# %s  %s = %.3f mm  v = %.0f m/s  hold: x < %.2f mm" % (run, "r0" if cup else "a", a * 1e3, v0, xh * 1e3))
print("# t_us  rear_mm  v_rear  out_%s  held_%s | per X/%s: flux/inflow  <vx>/v  %s"
      % (unit, unit, "r0" if cup else "a", "<r>_mm" if cup else "y_in_mm"))
rho0 = None
for t, d in csv_snapshots(run):
    x, vx, m = d["x"], d["vx"], d["m"]
    r = np.hypot(d["y"], d["z"]) if cup else d["y"]
    if t == 0:
        rho0 = np.median(d["rho"])
        if not cup:   # the periodic length: the lattice's z extent plus one spacing
            zs = np.unique(np.round(d["z"], 7))
            Lz = zs[-1] - zs[0] + (zs[-1] - zs[0]) / (len(zs) - 1)
        continue
    core = r < 1.05 * a
    if cup:
        rear = x[core].max()
        sel = core & (x > rear - 3e-3)
        inflow, scale = rho0 * np.pi * a ** 2 / 4, 4e3             # quarter model, g
    else:
        rear = np.percentile(x[core], 99.5)
        sel = core & (x > rear - 3e-3) & (x < rear)
        inflow, scale = rho0 * a * Lz, 1.0 / Lz                    # per mm of z, g/mm
    vrear = -np.average(vx[sel], weights=m[sel])
    inflow *= vrear
    line = "%6.1f %7.2f %6.0f %7.3f %7.3f |" % (t * 1e6, rear * 1e3, vrear, m[~core].sum() * scale,
                                               m[~core & (x < xh)].sum() * scale)
    for X in (2.0, 3.0, 4.0):
        dX = 0.25 * a
        sh = ~core & (x > X * a - dX) & (x < X * a + dX)
        if sh.sum() == 0:
            line += "   -     -     -   "
            continue
        where = np.average(r[sh], weights=m[sh]) if cup else np.percentile(r[sh], 5)
        line += " %5.2f %5.2f %5.2f " % ((m[sh] * vx[sh]).sum() / (2 * dX) / inflow,
                                       np.average(vx[sh], weights=m[sh]) / v0, where * 1e3)
    print(line)
