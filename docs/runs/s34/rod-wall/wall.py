#!/usr/bin/python3
"""Turning flow of a rod on a rigid wall (session 34 study): from a run's CSV snapshots,
per time: the rod's rear end and speed, the eroded mass (particles outside 1.05 r0), the
radial mass flux through cylinders r = R (shell R +- dR) against the rod's incoming flux,
and the mass-mean radial speed there against the impact speed v (Bernoulli: v).
usage: wall.py RUNDIR [r0_mm] [v_m_s]"""
import os, sys, numpy as np
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "..", "tools"))
from rod_floor import csv_snapshots  # noqa: E402
run = sys.argv[1]
r0 = float(sys.argv[2]) * 1e-3 if len(sys.argv) > 2 else 2.638e-3
v0 = float(sys.argv[3]) if len(sys.argv) > 3 else 1100.0
R_list = [1.5, 2.0, 3.0, 4.0]
rho0 = None
print("# %s  r0 = %.3f mm  v = %.0f m/s" % (run, r0 * 1e3, v0))
print("# t_us  rear_mm  v_rear  eroded_g  inflow_g/us | per R/r0: flux/inflow  <v_r>/v  <|v|>/v  mass_in_shell_g")
for t, d in csv_snapshots(run):
    if t == 0:
        rho0 = np.median(d["rho"])
        continue
    x, y, z = d["x"], d["y"], d["z"]
    vx, vy, vz, m = d["vx"], d["vy"], d["vz"], d["m"]
    r = np.hypot(y, z)
    vr = (y * vy + z * vz) / np.maximum(r, 1e-12)
    core = r < 1.05 * r0
    rear = x[core].max()
    sel = core & (x > rear - 3 * 0.001)
    vrear = -np.average(vx[sel], weights=m[sel])
    er = m[~core].sum()
    # incoming flux of the rod into the turning region, quarter model
    inflow = rho0 * np.pi * r0 ** 2 / 4 * vrear
    line = "%6.1f %7.2f %6.0f %7.3f %7.4f |" % (t * 1e6, rear * 1e3, vrear, er * 1e3 * 4,
                                               inflow * 1e-6 * 1e3 * 4)
    for R in R_list:
        dR = 0.25 * r0
        sh = (r > R * r0 - dR) & (r < R * r0 + dR)
        if sh.sum() == 0:
            line += "   -     -     -      -   "
            continue
        flux = (m[sh] * vr[sh]).sum() / (2 * dR)
        line += " %5.2f %5.2f %5.2f %6.3f " % (flux / inflow, np.average(vr[sh], weights=m[sh]) / v0,
                                             np.average(np.sqrt(vx[sh]**2 + vy[sh]**2 + vz[sh]**2), weights=m[sh]) / v0,
                                             m[sh].sum() * 1e3 * 4)
    print(line)
