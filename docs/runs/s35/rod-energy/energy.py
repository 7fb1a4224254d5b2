#!/usr/bin/python3
"""Session 35: where a rod's energy goes, from a run's VTU snapshots. Per snapshot and
per body group (the rod: body 0; the target: every other body), the kinetic energy
sum(m v^2/2), the internal energy sum(m e) and the elastic shear energy
sum(m S:S/(4 G rho)), in kJ of the whole model (twice the half model's), and the rod's
loss of kinetic energy since t = 0. For the target also its plastic work as a perfectly
plastic von Mises solid, sum((m/rho) Y eps_p) with Table 2's Y = 0.39 GPa (eps_p the
equivalent plastic strain), part of its internal energy; the rest is heat from the
viscosity and shocks and the cold compression energy.
usage: energy.py RUNDIR [G_target_GPa] [G_rod_GPa] [Y_target_GPa]"""
import glob
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', '..', '..', 'tools'))
from rod_floor import read_vtu  # noqa: E402

run = sys.argv[1]
G = {False: float(sys.argv[2]) * 1e9 if len(sys.argv) > 2 else 95e9,       # Table 2's steel
     True: float(sys.argv[3]) * 1e9 if len(sys.argv) > 3 else 126.615e9}   # tungsten alloy
Yt = float(sys.argv[4]) * 1e9 if len(sys.argv) > 4 else 0.39e9
print("# %s: energies in kJ of the whole model (2 x the half model)" % run)
print("# t_us | rod: KE  IE  shear  lost_KE | target: KE  IE  shear  plastic_work | target share of the rod's lost KE (KE+IE+shear)")
ke0 = None
for f in sorted(glob.glob(os.path.join(run, "particles_*.vtu"))):
    d = read_vtu(f)
    m, v, e, rho, S = d["m"], d["v"], d["e"], d["rho"], d["S"]
    ke = 0.5 * m * (v ** 2).sum(axis=1)
    # S:S of the symmetric deviator, 6 components xx yy zz xy yz xz (particles.h)
    ss = (S[:, :3] ** 2).sum(axis=1) + 2 * (S[:, 3:] ** 2).sum(axis=1)
    rod = d["body"] == 0
    Gp = np.where(rod, G[True], G[False])
    sh = m * ss / (4 * Gp * rho)
    ie = m * e
    r = [2e-3 * a[rod].sum() for a in (ke, ie, sh)]
    t = [2e-3 * a[~rod].sum() for a in (ke, ie, sh)]
    if ke0 is None:
        ke0 = r[0]
    lost = ke0 - r[0]
    wp = 2e-3 * (m / rho * Yt * d["eps_p"])[~rod].sum()
    share = sum(t) / lost if lost > 0 else float("nan")
    print("%6.1f | %7.2f %6.2f %5.2f %7.2f | %6.2f %6.2f %5.2f %6.2f | %5.3f" %
          (d["TIME"] * 1e6, r[0], r[1], r[2], lost, t[0], t[1], t[2], wp, share))
