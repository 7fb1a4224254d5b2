#!/usr/bin/python3
"""The rod's 180-degree turn in a rigid cup (session 35 study): from a run's CSV
snapshots, per time: the rod's rear end and speed, the mass held near the bottom outside
the rod (x < X_hold, r > 1.05 r0: the 'mushroom'), and through planes x = X the axial
mass flux of the reversed sheet (r > 1.05 r0) against the rod's inflow, with its
mass-mean axial speed against the impact speed v (Bernoulli: v), and the sheet's
mass-mean distance from the axis.
usage: cup.py RUNDIR [r0_mm] [v_m_s] [X_hold_mm]"""
import sys, glob, numpy as np
run = sys.argv[1]
r0 = float(sys.argv[2]) * 1e-3 if len(sys.argv) > 2 else 2.638e-3
v0 = float(sys.argv[3]) if len(sys.argv) > 3 else 1100.0
xh = float(sys.argv[4]) * 1e-3 if len(sys.argv) > 4 else 2 * r0
X_list = [2.0, 3.0, 4.0]          # planes, in r0
files = sorted(glob.glob(run + "/particles_*.csv"))
rho0 = None
print("# %s  r0 = %.3f mm  v = %.0f m/s  hold: x < %.2f mm" % (run, r0 * 1e3, v0, xh * 1e3))
print("# t_us  rear_mm  v_rear  out_g  held_g | per X/r0: flux/inflow  <vx>/v  <r>_mm")
for f in files:
    with open(f) as fh:
        t = float(fh.readline().split()[6])
    d = np.genfromtxt(f, delimiter=",", names=True, skip_header=2)
    if t == 0:
        rho0 = np.median(d["rho"])
        continue
    x, y, z = d["x"], d["y"], d["z"]
    vx, m = d["vx"], d["m"]
    r = np.hypot(y, z)
    core = r < 1.05 * r0
    rear = x[core].max()
    sel = core & (x > rear - 3e-3)
    vrear = -np.average(vx[sel], weights=m[sel])
    inflow = rho0 * np.pi * r0 ** 2 / 4 * vrear
    out = m[~core].sum()
    held = m[~core & (x < xh)].sum()
    line = "%6.1f %7.2f %6.0f %7.3f %7.3f |" % (t * 1e6, rear * 1e3, vrear, out * 4e3, held * 4e3)
    for X in X_list:
        dX = 0.25 * r0
        sh = ~core & (x > X * r0 - dX) & (x < X * r0 + dX)
        if sh.sum() == 0:
            line += "   -     -     -   "
            continue
        flux = (m[sh] * vx[sh]).sum() / (2 * dX)
        line += " %5.2f %5.2f %5.2f " % (flux / inflow, np.average(vx[sh], weights=m[sh]) / v0,
                                       np.average(r[sh], weights=m[sh]) * 1e3)
    print(line)
