#!/usr/bin/python3
"""Line-of-sight gaps through a backwall in a particle snapshot, under three rules.

usage: tools/backwall_gaps.py SNAPSHOT.csv --bodies B:SPACING_MM[,B:SPACING_MM...]
                              --x0 MM --thickness MM [--window MM]

The backwall's particles (the listed body indices, each with its lattice spacing; those
with x > x0 - thickness) are projected along x; each covers a disc of its own spacing in
radius (as hvsph's measure does, docs/measurements.md). Reported for three choices of
which particles count as wall:
  slab            x < x0 + 2 thickness: the slab that `perforated` (measure_plate) takes;
  any material    every backwall particle, however far behind (spall included);
  attached only   the largest friends-of-friends group (link 1.5 x the mean spacing of
                  the pair): the wall a recovered target would show.
For each: the open area (full plane, mirrored half model), the open area of the hole at
the impact point (the empty region within one finest spacing of the axis) and its
equivalent diameter, and the open share within 10, 20 and 40 mm of the axis.
Needs python3-numpy and python3-scipy (tools/install-deps.sh --docs).
Used for W.P.1's backwall in docs/validation.md (session 12).
"""
import argparse
import numpy as np
from scipy import ndimage
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree

ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
ap.add_argument("snapshot")
ap.add_argument("--bodies", required=True, help="B:SPACING_MM,... (body index: lattice spacing)")
ap.add_argument("--x0", type=float, required=True, help="the backwall's front face [mm]")
ap.add_argument("--thickness", type=float, required=True, help="[mm]")
ap.add_argument("--window", type=float, default=60.0, help="half-width of the map [mm]")
ap.add_argument("--cell", type=float, default=0.1, help="map cell [mm]")
a = ap.parse_args()

spacing = {int(b): float(s) * 1e-3 for b, s in (e.split(":") for e in a.bodies.split(","))}
x0, t, W, c = a.x0 * 1e-3, a.thickness * 1e-3, a.window * 1e-3, a.cell * 1e-3
d = np.genfromtxt(a.snapshot, delimiter=",", names=True, skip_header=2)
with open(a.snapshot) as f:
    t_us = float(f.readline().split(" time ")[1].split()[0]) * 1e6
body = d["body"].astype(int)
wall = np.isin(body, list(spacing)) & (d["x"] > x0 - t)
sp = np.array([spacing[b] for b in body[wall]])
X = np.c_[d["x"][wall], d["y"][wall], d["z"][wall]]
n = len(X)
tree = cKDTree(X)
pairs = tree.query_pairs(1.5 * max(spacing.values()), output_type="ndarray")
dist = np.linalg.norm(X[pairs[:, 0]] - X[pairs[:, 1]], axis=1)
pairs = pairs[dist <= 0.75 * (sp[pairs[:, 0]] + sp[pairs[:, 1]])]
ng, lab = connected_components(coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])),
                                          shape=(n, n)), directed=False)
big = lab == np.bincount(lab).argmax()
ny, nz = int(round(2 * W / c)), int(round(W / c))
yy = (np.arange(ny) + 0.5) * c - W
zz = (np.arange(nz) + 0.5) * c
R = np.hypot(*np.meshgrid(yy, zz))
seed = min(spacing.values())


def gaps(sel):
    cov = np.zeros((nz, ny), bool)
    for (_, yi, zi), si in zip(X[sel], sp[sel]):
        a0, a1 = max(int((yi - si + W) / c), 0), min(int((yi + si + W) / c) + 1, ny)
        b0, b1 = max(int((zi - si) / c), 0), min(int((zi + si) / c) + 1, nz)
        if a0 >= a1 or b0 >= b1:
            continue
        Y, Z = np.meshgrid(yy[a0:a1], zz[b0:b1])
        cov[b0:b1, a0:a1] |= (Y - yi) ** 2 + (Z - zi) ** 2 <= si * si
    labels, _ = ndimage.label(~cov)
    ids = np.unique(labels[~cov & (R < seed)])
    hole = 2 * np.isin(labels, ids[ids > 0]).sum() * c * c
    return (2 * (~cov).sum() * c * c, hole, [100 * (~cov[R < r * 1e-3]).mean() for r in (10, 20, 40)])


print("t = %.0f us: %d backwall particles, %.1f %% split, %d pieces (largest %.1f %%), "
      "rear-most x %.2f mm" % (t_us, n, 100 * (d["damage"][wall] >= 1).mean(), ng,
                               100 * big.mean(), 1e3 * X[:, 0].max()))
for name, sel in (("slab", X[:, 0] < x0 + 2 * t), ("any material", np.ones(n, bool)),
                  ("attached only", big)):
    area, hole, share = gaps(sel)
    print("  %-14s open %8.2f mm2; hole at the impact point %6.2f mm2 (d_eq %.2f mm); "
          "open within 10/20/40 mm: %.2f/%.2f/%.2f %%"
          % (name, area * 1e6, hole * 1e6, 2 * np.sqrt(hole / np.pi) * 1e3, *share))
