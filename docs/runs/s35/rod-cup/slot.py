#!/usr/bin/python3
"""The planar rod's 180-degree turn in a rigid slot (session 35 study; slot.yaml): per
time, the slab's rear end and speed, the mass held near the bottom outside the slab
(x < X_hold, y > 1.05 a), and through planes x = X the reversed sheet's axial mass
flux (y > 1.05 a) against the slab's inflow, its mass-mean axial speed against the
impact speed v (Bernoulli: v) and its mass-mean thickness W - <y> ... as the sheet's
inner edge: the smallest y of the sheet there.
usage: slot.py RUNDIR [a_mm] [v_m_s] [X_hold_mm]"""
import sys, glob, numpy as np
run = sys.argv[1]
a = float(sys.argv[2]) * 1e-3 if len(sys.argv) > 2 else 2.638e-3
v0 = float(sys.argv[3]) if len(sys.argv) > 3 else 1100.0
xh = float(sys.argv[4]) * 1e-3 if len(sys.argv) > 4 else 2 * a
X_list = [2.0, 3.0, 4.0]          # planes, in a
files = sorted(glob.glob(run + "/particles_*.csv"))
rho0 = None
print("# %s  a = %.3f mm  v = %.0f m/s  hold: x < %.2f mm" % (run, a * 1e3, v0, xh * 1e3))
print("# t_us  rear_mm  v_rear  out_g/mm  held_g/mm | per X/a: flux/inflow  <vx>/v  y_in_mm")
for f in files:
    with open(f) as fh:
        t = float(fh.readline().split()[6])
    d = np.genfromtxt(f, delimiter=",", names=True, skip_header=2)
    if t == 0:
        rho0 = np.median(d["rho"])
        Lz = d["z"].max() - d["z"].min() + (d["z"].max() - d["z"].min()) / (len(np.unique(np.round(d["z"], 7))) - 1)
        continue
    x, y = d["x"], d["y"]
    vx, m = d["vx"], d["m"]
    core = y < 1.05 * a
    rear = np.percentile(x[core], 99.5)
    sel = core & (x > rear - 3e-3) & (x < rear)
    vrear = -np.average(vx[sel], weights=m[sel])
    inflow = rho0 * a * Lz * vrear
    out = m[~core].sum() / Lz * 1e3 * 1e-3
    held = m[~core & (x < xh)].sum() / Lz * 1e3 * 1e-3
    line = "%6.1f %7.2f %6.0f %7.3f %7.3f |" % (t * 1e6, rear * 1e3, vrear, out, held)
    for X in X_list:
        dX = 0.25 * a
        sh = ~core & (x > X * a - dX) & (x < X * a + dX)
        if sh.sum() == 0:
            line += "   -     -     -   "
            continue
        flux = (m[sh] * vx[sh]).sum() / (2 * dX)
        line += " %5.2f %5.2f %5.2f " % (flux / inflow, np.average(vx[sh], weights=m[sh]) / v0,
                                       np.percentile(y[sh], 5) * 1e3)
    print(line)
