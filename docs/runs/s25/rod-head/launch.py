#!/usr/bin/python3
"""How wide the rod's channel would grow from the state behind the rod's head, if the
target resisted its expansion with Hill's quasi-static cylindrical-cavity pressure.

Usage: launch.py R0_MM EXP_RADIUS_MM particles_NNNNN.csv ...
  R0_MM: the rod's radius; EXP_RADIUS_MM: the experiment's final channel radius (D/2).
  Snapshots: CSV of a rod run (`output.csv: true`).

The floor is the smallest x of target particles within 2 mm of the axis (ahead of the
original face). In slabs 2 mm thick behind it, the wall a is the inner edge of the first
0.5 mm annulus more than half filled by target volume (m/rho; half model), and its speed
da/dt the mean radial velocity of the target within 1 mm outside the wall.

Estimate: an incompressible target between the wall a and an outer radius b (the box's
rigid wall, 50 mm) moving radially (v = a da/dt / r) has kinetic energy
pi rho_t (a da/dt)^2 ln(b/a) per unit length (the half model's share is half of it, as
is the work); resisted by a constant pressure R at the wall it stops at
    a_f^2 = a^2 + rho_t (a da/dt)^2 ln(b/a) / R,
and the launch speed that would stop it at the experiment's radius a_x instead is
    da/dt = sqrt(R (a_x^2 - a^2) / (rho_t ln(b/a))) / a.
R = k (1 + ln(G/k)), k = Y/sqrt(3) (Hill; steel-target Y = 0.39 GPa, G = 95 GPa: 1.6 GPa).
Compressibility (waves) takes energy away, so a_f over-estimates. Session 25,
docs/validation.md ("How wide the head launches the channel").
"""
import sys
import numpy as np

RHO_T, Y, G, B = 7810.0, 0.39e9, 95e9, 50e-3
K = Y / np.sqrt(3.0)
R = K * (1.0 + np.log(G / K))
DR, SLAB = 0.5e-3, 2e-3

r0, a_x = float(sys.argv[1]) * 1e-3, float(sys.argv[2]) * 1e-3
print(f"Hill's R = {R/1e9:.2f} GPa; rod radius {r0*1e3:.3f} mm; the experiment's channel radius "
      f"{a_x*1e3:.2f} mm")
for f in sys.argv[3:]:
    with open(f) as fh:
        head = fh.readline()
        fh.readline()
        names = fh.readline().strip().split(',')
    t = float(head.split(' time ')[1].split()[0])
    d = np.loadtxt(f, delimiter=',', comments='#', skiprows=3)
    c = {n: d[:, names.index(n)] for n in ('x', 'y', 'z', 'vy', 'vz', 'm', 'rho', 'mat')}
    tgt = c['mat'] == 1
    r = np.hypot(c['y'], c['z'])
    vr = (c['y'] * c['vy'] + c['z'] * c['vz']) / np.maximum(r, 1e-12)
    V = c['m'] / c['rho']
    floor = c['x'][tgt & (r < 2e-3) & (c['x'] > 1e-3)].min()
    print(f"\nt = {t*1e6:.0f} us, floor at {floor*1e3:.1f} mm")
    print("behind floor | wall a | a/r0 | da/dt  | a_f (Hill R) | da/dt to stop at a_x")
    edges = np.arange(0.0, 30e-3, DR)
    ann = np.pi * (edges[1:]**2 - edges[:-1]**2) / 2 * SLAB
    for k0 in range(0, 12):
        lo, hi = floor - (k0 + 1) * SLAB, floor - k0 * SLAB
        s = tgt & (c['x'] > lo) & (c['x'] <= hi)
        fill = np.histogram(r[s], edges, weights=V[s])[0] / ann
        if not (fill > 0.5).any():
            continue
        a = edges[np.argmax(fill > 0.5)]
        near = s & (r >= a) & (r < a + 1e-3)
        if a <= 0 or near.sum() < 3:
            continue
        adot = vr[near].mean()
        q = a * adot
        lnb = np.log(B / a)
        af = np.sqrt(a * a + RHO_T * q * q * lnb / R) if adot > 0 else a
        need = (np.sqrt(R * (a_x**2 - a * a) / (RHO_T * lnb)) / a) if a_x > a else 0.0
        print(f"{k0*2:2d}-{k0*2+2:2d} mm     | {a*1e3:5.2f} mm | {a/r0:4.2f} | {adot:5.0f} m/s"
              f" | {af*1e3:6.2f} mm     | {need:5.0f} m/s")
