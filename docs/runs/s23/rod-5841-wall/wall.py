#!/usr/bin/python3
"""Where the rod's channel wall is, and how fast it moves, along the channel.

Usage: wall.py particles_NNNNN.csv ...   (the CSV snapshots of a rod run, `output.csv: true`)

For slabs 3 mm thick every 6 mm along x (the rod's axis), the wall is the inner edge of
the first 0.5 mm annulus (of the half model) whose volume is more than half filled by
target particles (volume m/rho); printed beside it: the mean radial velocity, pressure
and damage of the target within 2 mm outside the wall, the fraction of the channel's
cross-section inside the wall filled by rod material (material 0) and that material's
mean pressure. Session 23, docs/validation.md ("rod-5841 at the paper's counts").
"""
import sys
import numpy as np

DR, SLAB, STEP = 0.5e-3, 3e-3, 6e-3

for f in sys.argv[1:]:
    with open(f) as fh:
        t = float(fh.readline().split('time')[1].split()[0])
        fh.readline()
        names = fh.readline().strip().split(',')
    d = np.loadtxt(f, delimiter=',', comments='#', skiprows=3)
    col = {n: d[:, names.index(n)] for n in
           ('x', 'y', 'z', 'vy', 'vz', 'm', 'rho', 'p', 'mat', 'damage')}
    x, y, z, m, rho, p = col['x'], col['y'], col['z'], col['m'], col['rho'], col['p']
    mat, dmg = col['mat'], col['damage']
    r = np.hypot(y, z)
    vr = (y * col['vy'] + z * col['vz']) / np.maximum(r, 1e-9)
    V = m / rho
    tip = x[mat == 0].max()
    print(f"t = {t*1e6:.0f} us, deepest rod material at x = {tip*1e3:.1f} mm")
    print("  x mm | r_wall mm | vr (wall..+2mm) m/s | p GPa | dmg | W fill inside wall | W p GPa")
    edges = np.arange(0, 20e-3, DR)
    ann = np.pi * (edges[1:]**2 - edges[:-1]**2) / 2 * SLAB   # half model
    for x0 in np.arange(4.5e-3, tip + STEP, STEP):
        s = np.abs(x - x0) < SLAB / 2
        ft = np.histogram(r[s & (mat == 1)], edges, weights=V[s & (mat == 1)])[0] / ann
        k = np.argmax(ft > 0.5)
        rw = edges[k]
        a = s & (mat == 1) & (r >= rw) & (r < rw + 2e-3)
        wi = s & (mat == 0) & (r < rw + DR)
        wv = V[wi].sum() / (np.pi * rw**2 / 2 * SLAB) if rw > 0 else 0.0
        pw = p[wi].mean() / 1e9 if wi.any() else 0.0
        print(f"{x0*1e3:6.1f} | {rw*1e3:5.1f} | {vr[a].mean():7.1f} | {p[a].mean()/1e9:6.2f} | "
              f"{dmg[a].mean():.2f} | {wv:5.3f} | {pw:6.2f}")
