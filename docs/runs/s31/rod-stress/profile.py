#!/usr/bin/python3
"""The target's stress around a rod's channel (session 31): in a snapshot, the target
particles of a slab X1 < x < X2 mm (behind the head) binned by their distance r from the
axis (1 mm bins to 30 mm, 2 mm bins to 50 mm); per bin the mass-mean radial and hoop
total stress sigma_rr, sigma_tt (sigma = -p I + S; compression negative), the
von Mises stress, the radial velocity v_r, rho/rho0, plastic strain and the split
fraction. Beside it the quasi-static elastic-plastic cylinder (Hill, plane strain,
von Mises k = Y/sqrt(3)) for the measured wall radius a: in the plastic zone
sigma_rr = -P + 2k ln(r/a), with the elastic-plastic boundary c = a sqrt(G/k) (the
incompressible limit) and P = k(1 + 2 ln(c/a)) = k(1 + ln(G/k)); in the elastic zone
sigma_rr = -k c^2/r^2.

Usage: profile.py X1_MM X2_MM Y_GPA G_GPA RHO0 TARGET_MAT particles_NNNNN.vtu [...]
(TARGET_MAT: the target's material index, the field `mat` of the snapshot)
docs/validation.md ("The Johnson-Cook steel with less viscosity", the target's stress).
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', '..', '..', 'tools'))
from rod_floor import read_vtu  # noqa: E402

x1, x2 = float(sys.argv[1]) * 1e-3, float(sys.argv[2]) * 1e-3
Y, G, rho0 = float(sys.argv[3]) * 1e9, float(sys.argv[4]) * 1e9, float(sys.argv[5])
mat = int(sys.argv[6])
k = Y / np.sqrt(3)
edges = np.concatenate([np.arange(0, 30.01, 1.0), np.arange(32, 50.01, 2.0)]) * 1e-3

for f in sys.argv[7:]:
    v = read_vtu(f)
    x = v['x'].reshape(-1, 3)
    S = v['S'].reshape(-1, 6)          # xx, yy, zz, xy, yz, xz
    vel = v['v'].reshape(-1, 3)
    m, p = v['m'], v['p']
    tg = v['mat'] == mat
    r = np.hypot(x[:, 1], x[:, 2])
    sel = tg & (x[:, 0] > x1) & (x[:, 0] < x2)
    ny = np.where(r > 0, x[:, 1] / np.maximum(r, 1e-12), 1.0)
    nz = np.where(r > 0, x[:, 2] / np.maximum(r, 1e-12), 0.0)
    syy, szz, syz = S[:, 1] - p, S[:, 2] - p, S[:, 4]
    srr = syy * ny ** 2 + szz * nz ** 2 + 2 * syz * ny * nz
    stt = syy * nz ** 2 + szz * ny ** 2 - 2 * syz * ny * nz
    J2 = 0.5 * (S[:, 0] ** 2 + S[:, 1] ** 2 + S[:, 2] ** 2) + S[:, 3] ** 2 + S[:, 4] ** 2 + S[:, 5] ** 2
    seq = np.sqrt(3 * J2)
    vr = vel[:, 1] * ny + vel[:, 2] * nz
    # the wall: the smallest r at which the target fills half of an annulus (by volume)
    vol = m / v['rho']
    a = None
    for lo, hi in zip(np.arange(0, 30e-3, 0.5e-3), np.arange(0.5e-3, 30.5e-3, 0.5e-3)):
        inb = sel & (r >= lo) & (r < hi)
        ann = np.pi * (hi * hi - lo * lo) / 2 * (x2 - x1)   # half model: z >= 0
        if vol[inb].sum() > 0.5 * ann:
            a = lo
            break
    c = a * np.sqrt(G / k) if a else float('nan')
    P = k * (1 + 2 * np.log(c / a)) if a else float('nan')
    print(f"# {f}: t = {v['TIME'] * 1e6:.1f} us, slab {x1 * 1e3:.0f}-{x2 * 1e3:.0f} mm, wall a = "
          f"{a * 1e3 if a else float('nan'):.1f} mm, Hill: c = {c * 1e3:.0f} mm, P = {P / 1e9:.2f} GPa")
    print("r (mm) | n | sigma_rr | sigma_tt (GPa) | Hill sigma_rr | von Mises (GPa) | v_r (m/s) |"
          " rho/rho0 | eps_p | split")
    for lo, hi in zip(edges[:-1], edges[1:]):
        inb = sel & (r >= lo) & (r < hi)
        if inb.sum() == 0:
            continue
        w = m[inb] / m[inb].sum()
        rc = 0.5 * (lo + hi)
        if a and rc >= a:
            hill = -P + 2 * k * np.log(rc / a) if rc < c else -k * c * c / (rc * rc)
            hs = f"{hill / 1e9:+.2f}"
        else:
            hs = "-"
        print(f"{lo * 1e3:.0f}-{hi * 1e3:.0f} | {inb.sum()} | {np.sum(w * srr[inb]) / 1e9:+.2f} |"
              f" {np.sum(w * stt[inb]) / 1e9:+.2f} | {hs} | {np.sum(w * seq[inb]) / 1e9:.2f} |"
              f" {np.sum(w * vr[inb]):+.0f} | {np.sum(w * v['rho'][inb]) / rho0:.3f} |"
              f" {np.sum(w * v['eps_p'][inb]):.2f} | {np.mean(v['damage'][inb] >= 1):.2f}")
