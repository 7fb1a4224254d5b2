#!/usr/bin/python3
"""Session 34: which forces act on the rod's mushroom. From one VTU snapshot of a rod
run, the SPH pair forces on the rod particles in a region behind the tip (default: 1-5
mm behind the rod's foremost particle near the axis, outside the rod's radius r0),
recomputed from the snapshot's fields as src/sph/sph_solid.c forms them (cubic spline,
h_ij = (h_i + h_j)/2; within a body sigma_i/rho_i^2 + sigma_j/rho_j^2 with sigma = -pI + S,
split particles p >= 0 and S = 0; between bodies max(p, 0) only; the Monaghan-Gingold
viscosity with alpha = 1, beta = 2, eps = 0.01 on the pair-mean sound speed and density,
with the reconstruction for pairs of one piece (the corrected gradient of intact
particles, van Leer's limiter; FORCES_NO_RECON=1 leaves it out); the artificial stress
is left out), split by partner: the rod's core (r < r0), the
rod's sheath (r >= r0) and the target, and by term (stress, viscosity). Printed: the
region's total mass, mean velocity, and the force per unit mass of the region (m/s^2),
axial (x, the rod's direction) and radial (outward).

usage: forces.py SNAPSHOT.vtu [xi_min_mm xi_max_mm [r_min_mm [r_max_mm [body]]]]
(body 0: the rod, the default; 1: the target's particles (every other body) in the region instead)
"""
import os
import sys

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', '..', '..', 'tools'))
from rod_floor import read_vtu  # noqa: E402

R0 = 2.638e-3
f = sys.argv[1]
xi0 = float(sys.argv[2]) * 1e-3 if len(sys.argv) > 3 else -5e-3
xi1 = float(sys.argv[3]) * 1e-3 if len(sys.argv) > 3 else -1e-3
rmin = float(sys.argv[4]) * 1e-3 if len(sys.argv) > 4 else R0
rmax = float(sys.argv[5]) * 1e-3 if len(sys.argv) > 5 else 1.0
BODY = int(sys.argv[6]) if len(sys.argv) > 6 else 0
d = read_vtu(f)
X, V, m, rho, p, h, cs = d['x'], d['v'], d['m'], d['rho'], d['p'], d['h'], d['cs']
S6 = d['S'] if 'S' in d else np.zeros((len(m), 6))
body, dmg = d['body'], d['damage']
r = np.hypot(X[:, 1], X[:, 2])
rod = body == 0
tip = X[rod & (r < 0.5 * R0), 0].max()
split = dmg >= 1.0
P = np.where(split, np.maximum(p, 0.0), p)
S = np.where(split[:, None], 0.0, S6)   # xx yy zz xy yz xz (VTK order)


def sig(k):
    s = np.empty((len(k), 3, 3))
    s[:, 0, 0] = S[k, 0] - P[k]; s[:, 1, 1] = S[k, 1] - P[k]; s[:, 2, 2] = S[k, 2] - P[k]
    s[:, 0, 1] = s[:, 1, 0] = S[k, 3]; s[:, 1, 2] = s[:, 2, 1] = S[k, 4]; s[:, 0, 2] = s[:, 2, 0] = S[k, 5]
    return s


sel = np.where(((body == 0) if BODY == 0 else (body != 0)) & (X[:, 0] - tip >= xi0) & (X[:, 0] - tip < xi1) & (r >= rmin) & (r < rmax))[0]
# mirror ghosts across z = 0 (the half model's symmetry plane): position and v_z flipped
Xg = X.copy(); Xg[:, 2] *= -1
Vg = V.copy(); Vg[:, 2] *= -1
Sg = S.copy(); Sg[:, 4] *= -1; Sg[:, 5] *= -1        # yz, xz flip
XA = np.vstack([X, Xg]); VA = np.vstack([V, Vg])
idx = np.concatenate([np.arange(len(m)), np.arange(len(m))])
tree = cKDTree(XA)
hmax = h.max()
intact = ~split
piece = (body != 0).astype(int)
Gcache = {}


def grad(k):
    """Corrected velocity gradient G = L A^-1 of real particle k over its own piece's
    neighbours (mirror ghosts included), as the reconstruction takes it: 0 when split."""
    if k in Gcache:
        return Gcache[k]
    G = np.zeros((3, 3))
    if intact[k]:
        nb = np.array([q for q in tree.query_ball_point(X[k], h[k] + hmax) if q != k])
        jj = idx[nb]
        dx = X[k] - XA[nb]
        rr = np.linalg.norm(dx, axis=1)
        hh = 0.5 * (h[k] + h[jj])
        ok = (rr < 2 * hh) & (rr > 0) & (piece[jj] == piece[k])
        nb, jj, dx, rr, hh = nb[ok], jj[ok], dx[ok], rr[ok], hh[ok]
        q = rr / hh
        fq = np.where(q < 1, -3 * q + 2.25 * q * q, -0.75 * (2 - q) ** 2) / (np.pi * hh ** 4)
        gW = dx / rr[:, None] * fq[:, None]
        w = (m[jj] / rho[jj])[:, None, None]
        L = (w * np.einsum('ka,kb->kab', VA[nb] - V[k], gW)).sum(axis=0)
        A = (w * np.einsum('ka,kb->kab', -dx, gW)).sum(axis=0)
        if abs(np.linalg.det(A)) > 1e-3:
            G = L @ np.linalg.inv(A)
        else:
            G = L
    Gcache[k] = G
    return G


MZ = np.diag([1.0, 1.0, -1.0])
RECON = os.environ.get("FORCES_NO_RECON") is None
cats = ('rod core', 'rod sheath', 'target')
acc = {(c, t): np.zeros(3) for c in cats for t in ('stress', 'visc')}
Mtot = m[sel].sum()
for i in sel:
    nb = tree.query_ball_point(X[i], h[i] + hmax)
    nb = np.array([k for k in nb if not (k == i)])
    j = idx[nb]
    dx = X[i] - XA[nb]
    rr = np.linalg.norm(dx, axis=1)
    hij = 0.5 * (h[i] + h[j])
    ok = (rr < 2 * hij) & (rr > 0)
    nb, j, dx, rr, hij = nb[ok], j[ok], dx[ok], rr[ok], hij[ok]
    q = rr / hij
    fq = np.where(q < 1, -3 * q + 2.25 * q * q, -0.75 * (2 - q) ** 2)
    dW = fq / (np.pi * hij ** 4)
    gW = dx / rr[:, None] * dW[:, None]                 # grad_i W_ij
    dv = V[i] - VA[nb]
    vdx = np.einsum('ij,ij->i', dv, dx)
    same = (body[j] == 0) == (body[i] == 0)   # the core is part_of the target: one piece
    vap = vdx.copy()
    if RECON:
        Gi = grad(i)
        for k in np.where(same & (vdx < 0))[0]:
            Gj = grad(j[k])
            if nb[k] >= len(m):
                Gj = MZ @ Gj @ MZ
            gi = dx[k] @ Gi @ dx[k]
            gj = dx[k] @ Gj @ dx[k]
            phi = 4 * gi * gj / (gi + gj) ** 2 if gi * gj > 0 else 0.0
            a = vdx[k] - 0.5 * phi * (gi + gj)
            vap[k] = min(max(a, vdx[k]), 0.0)
    mu = hij * vap / (rr * rr + 0.01 * hij * hij)
    cb = 0.5 * (cs[i] + cs[j]); rb = 0.5 * (rho[i] + rho[j])
    Pi = np.where(vdx < 0, (-1.0 * cb * mu + 2.0 * mu * mu) / rb, 0.0)
    ghost = nb >= len(m)
    si = sig(np.array([i]))[0] / rho[i] ** 2
    sj = sig(j)
    if ghost.any():   # mirrored stress of ghosts: S_yz, S_xz flip sign
        for k in np.where(ghost)[0]:
            jj = j[k]
            s = np.array([[Sg[jj, 0] - P[jj], Sg[jj, 3], Sg[jj, 5]],
                          [Sg[jj, 3], Sg[jj, 1] - P[jj], Sg[jj, 4]],
                          [Sg[jj, 5], Sg[jj, 4], Sg[jj, 2] - P[jj]]])
            sj[k] = s
    sj = sj / (rho[j] ** 2)[:, None, None]
    T = si[None] + sj
    a_st = np.where(same[:, None], np.einsum('kab,kb->ka', T, gW), 0.0)
    pc = (max(P[i], 0) / rho[i] ** 2 + np.maximum(P[j], 0) / rho[j] ** 2)
    a_st += np.where(same[:, None], 0.0, -pc[:, None] * gW)
    a_vi = -Pi[:, None] * gW
    a_st *= m[j][:, None]; a_vi *= m[j][:, None]
    cat = np.where(body[j] != 0, 2, np.where(np.hypot(XA[nb, 1], XA[nb, 2]) < R0, 0, 1))
    # axial and radial (outward at i) components
    er = np.array([0, X[i, 1], X[i, 2]]) / max(r[i], 1e-12)
    for c in range(3):
        k = cat == c
        for t, a in (('stress', a_st), ('visc', a_vi)):
            F = (a[k].sum(axis=0)) * m[i]
            acc[(cats[c], t)] += np.array([F[0], F @ er, 0.0])
vr = (X[sel, 1] * V[sel, 1] + X[sel, 2] * V[sel, 2]) / r[sel]
print("%s: t = %.1f us, tip at %.2f mm; region x - tip in [%.1f, %.1f) mm, r in [%.2f, %.2f) mm: "
      "%d %s particles, %.2f g (half model), mean v_x %.0f m/s, v_r %.0f m/s, split %.0f %%"
      % (os.path.basename(f), d['TIME'] * 1e6, tip * 1e3, xi0 * 1e3, xi1 * 1e3, rmin * 1e3,
         min(rmax, 1) * 1e3, len(sel), ('rod', 'target')[BODY],
         Mtot * 1e3, np.average(V[sel, 0], weights=m[sel]), np.average(vr, weights=m[sel]),
         100 * np.average(split[sel], weights=m[sel])))
print("force per unit mass of the region [1e6 m/s^2]: axial (+ = forward) / radial (+ = outward)")
tot = np.zeros(3)
for c in cats:
    for t in ('stress', 'visc'):
        a = acc[(c, t)] / Mtot
        tot += a
        print("  from %-10s %-6s  %+9.2f  %+9.2f" % (c, t, a[0] / 1e6, a[1] / 1e6))
print("  total                    %+9.2f  %+9.2f" % (tot[0] / 1e6, tot[1] / 1e6))
