#!/usr/bin/python3
"""The crater's nose and the rod's head, slab by slab behind the crater floor.

Usage: nose.py R0_MM particles_NNNNN.csv [...]
  Snapshots: CSV of a rod run (`output.csv: true`); material 0 the rod, 1 the target.

The floor is the smallest x of target particles within 2 mm of the axis, ahead of the
original face. In slabs 1 mm thick behind it (xi = floor - x), per slab:
  a      the target's wall: inner edge of the first 0.5 mm annulus more than half filled
         by target volume (m/rho; half model, so the annulus is a half ring);
  vr_w, vx_w, p_w  mass-mean radial and axial velocity and pressure of the target
         within 1 mm outside the wall;
  r_rod  the rod's outer edge: the 95th percentile of the radius of its particles
         in the slab (mass-weighted), and m_rod its mass per mm (whole model);
  vr_r, vx_r, p_r  mass-mean radial and axial velocity and pressure of the rod's
         particles outside 0.8 r0 (its head's flank; the whole slab if none);
  slope  da/dxi from the neighbouring slabs; in a flow steady in the floor's frame
         the wall moves along itself, so vr_w = slope * (u - vx_w) (u the floor's
         speed, from the floor's advance between the snapshots given).
Session 26, docs/validation.md ("The crater's nose").
"""
import sys
import numpy as np

DR, SLAB = 0.5e-3, 1e-3
r0 = float(sys.argv[1]) * 1e-3


def load(f):
    with open(f) as fh:
        head = fh.readline()
        fh.readline()
        names = fh.readline().strip().split(',')
    t = float(head.split(' time ')[1].split()[0])
    d = np.loadtxt(f, delimiter=',', comments='#', skiprows=3,
                   usecols=[names.index(n) for n in
                            ('x', 'y', 'z', 'vx', 'vy', 'vz', 'm', 'rho', 'p', 'mat', 'damage')])
    return t, dict(zip(('x', 'y', 'z', 'vx', 'vy', 'vz', 'm', 'rho', 'p', 'mat', 'damage'), d.T))


def floor_of(c):
    r = np.hypot(c['y'], c['z'])
    return c['x'][(c['mat'] == 1) & (r < 2e-3) & (c['x'] > 1e-3)].min()


snaps = [load(f) for f in sys.argv[2:]]
floors = [floor_of(c) for _, c in snaps]
print(f"rod radius r0 = {r0*1e3:.3f} mm")
for k, (t, c) in enumerate(snaps):
    if len(snaps) > 1:
        j = k + 1 if k + 1 < len(snaps) else k - 1
        u = (floors[j] - floors[k]) / (snaps[j][0] - t)
    else:
        u = float('nan')
    fl = floors[k]
    r = np.hypot(c['y'], c['z'])
    vr = (c['y'] * c['vy'] + c['z'] * c['vz']) / np.maximum(r, 1e-12)
    V = c['m'] / c['rho']
    tgt, rod = c['mat'] == 1, c['mat'] == 0
    print(f"\nt = {t*1e6:.0f} us, floor at {fl*1e3:.1f} mm, floor speed u = {u:.0f} m/s "
          f"(from the neighbouring snapshot)")
    print(" xi mm | a mm  a/r0 | vr_w  vx_w  m/s  p_w GPa | r_rod/r0 m_rod g/mm | vr_r  vx_r m/s  p_r GPa"
          " | slope | slope*(u-vx_w)")
    edges = np.arange(0.0, 30e-3, DR)
    ann = np.pi * (edges[1:]**2 - edges[:-1]**2) / 2 * SLAB
    rows = []
    for k0 in range(-1, 16):
        lo, hi = fl - (k0 + 1) * SLAB, fl - k0 * SLAB
        s = (c['x'] > lo) & (c['x'] <= hi)
        st = s & tgt
        fill = np.histogram(r[st], edges, weights=V[st])[0] / ann
        a = edges[np.argmax(fill > 0.5)] if (fill > 0.5).any() else np.nan
        near = st & (r >= a) & (r < a + 1e-3)
        sr = s & rod
        if near.sum() >= 3:
            w = c['m'][near]
            vrw, vxw, pw = (np.average(q[near], weights=w) for q in (vr, c['vx'], c['p']))
        else:
            vrw = vxw = pw = np.nan
        if sr.sum() >= 3:
            order = np.argsort(r[sr])
            cm = np.cumsum(c['m'][sr][order])
            rr = r[sr][order][np.searchsorted(cm, 0.95 * cm[-1])]
            mrod = 2 * cm[-1] / (SLAB * 1e3) * 1e3
            fl_ = sr & (r > 0.8 * r0)
            if fl_.sum() < 3:
                fl_ = sr
            w = c['m'][fl_]
            vrr, vxr, pr = (np.average(q[fl_], weights=w) for q in (vr, c['vx'], c['p']))
        else:
            rr = mrod = vrr = vxr = pr = np.nan
        rows.append([(k0 + 0.5) * SLAB, a, vrw, vxw, pw, rr, mrod, vrr, vxr, pr])
    rows = np.array(rows)
    slope = np.gradient(rows[:, 1], rows[:, 0])
    for q, sl in zip(rows, slope):
        xi, a, vrw, vxw, pw, rr, mrod, vrr, vxr, pr = q
        print(f"{xi*1e3:5.1f} | {a*1e3:5.2f} {a/r0:4.2f} | {vrw:5.0f} {vxw:5.0f} {pw/1e9:8.2f} |"
              f" {rr/r0:8.2f} {mrod:8.3f} | {vrr:5.0f} {vxr:5.0f} {pr/1e9:8.2f} | {sl:5.2f} |"
              f" {sl*(u-vxw):6.0f}")

    # The rod's head region: its split (damage = 1) share and the state of the split part.
    xi = fl - c['x']
    for lo, hi in ((2e-3, 4e-3), (4e-3, 6e-3), (6e-3, 8e-3)):
        s = rod & (xi >= lo) & (xi < hi) & (r > r0)
        if s.sum() < 3:
            continue
        sp = s & (c['damage'] >= 1.0) if 'damage' in c else s & False
        w, ws = c['m'][s], c['m'][sp]
        print(f"rod outside r0, {lo*1e3:.0f}-{hi*1e3:.0f} mm behind the floor: {2*w.sum()*1e3:.3f} g,"
              f" split {ws.sum()/w.sum()*100:.0f} %"
              + (f" (rho/rho0 {np.average(c['rho'][sp], weights=ws)/17780:.3f},"
                 f" p {np.average(c['p'][sp], weights=ws)/1e9:.2f} GPa,"
                 f" vr {np.average(vr[sp], weights=ws):.0f} m/s);"
                 if sp.sum() else ";")
              + (f" unsplit p {np.average(c['p'][s & ~sp], weights=c['m'][s & ~sp])/1e9:.2f} GPa,"
                 f" vr {np.average(vr[s & ~sp], weights=c['m'][s & ~sp]):.0f} m/s"
                 if (s & ~sp).sum() else ""))
