#!/usr/bin/python3
"""What individual (block) time steps could gain, an upper bound read from particle
snapshots' `dt` column (docs/performance.md, "Individual time steps").

usage: tools/block_steps.py SNAPSHOT.csv|RUNDIR ...

Each argument is a particle snapshot written with `output.csv: true`, or a run folder
(every particles_NNNNN.csv in it but the initial state, particles_00000.csv, where every
particle is at rest). Every particle takes the global step dt_min, the smallest
particle's own limit dt_i; for each snapshot it prints
  - own:   N dt_min / sum(dt_min / dt_i), the ratio of force evaluations per unit time
           if every particle took exactly its own step;
  - block: the same with each step rounded down to dt_min 2^k, k <= 10 (the power-of-two
           hierarchy of block-step codes);
  - the share of particles on the lowest level (dt_i < 2 dt_min) and each body's median
    dt_i;
  - own and block counting only the particles in motion (v != 0): sph.skip_resting already
    spares the cells at rest, so against today's code these are the gains.
Upper bounds: they leave out the overheads of such a scheme (drifting the inactive
particles, the neighbour searches of the active ones) and the limiter that keeps
neighbouring steps within a small factor of each other. tools/block_steps.sh makes the
runs docs/performance.md quotes and calls this. Needs python3-numpy.
"""
import glob
import os
import sys

import numpy as np


def snapshots(arg):
    if os.path.isdir(arg):
        files = sorted(f for f in glob.glob(os.path.join(arg, "particles_*.csv"))
                       if not f.endswith("particles_00000.csv"))
        if not files:
            sys.exit("block_steps: %s: no particles_NNNNN.csv after the initial state "
                     "(run with --set output.csv=true)" % arg)
        return files
    if not os.path.isfile(arg):
        sys.exit("block_steps: %s: no such file or folder" % arg)
    return [arg]


def report(path):
    d = np.genfromtxt(path, delimiter=",", names=True, skip_header=2)
    for col in ("dt", "body", "vx", "vy", "vz"):
        if d.dtype.names is None or col not in d.dtype.names:
            sys.exit("block_steps: %s: no column '%s' (a particle snapshot of hvsph, with dt, "
                     "is needed)" % (path, col))
    dt = np.atleast_1d(d["dt"])
    n = dt.size
    dmin = dt.min()
    own = n / np.sum(dmin / dt)
    k = np.minimum(np.floor(np.log2(dt / dmin)), 10)
    block = n / np.sum(2.0 ** -k)
    low = np.mean(dt < 2 * dmin)
    body = np.atleast_1d(d["body"])
    bodies = ", ".join("body %d: median %.3g ns" % (b, 1e9 * np.median(dt[body == b]))
                       for b in np.unique(body).astype(int))
    moving = (d["vx"] != 0) | (d["vy"] != 0) | (d["vz"] != 0)
    m = np.count_nonzero(moving)
    own_m = m / np.sum(dmin / dt[moving]) if m else float("nan")
    block_m = m / np.sum(2.0 ** -k[moving]) if m else float("nan")
    print("%s: %d particles, step %.4g ns; own steps %.2fx, blocks %.2fx fewer force "
          "evaluations; %.1f %% on the lowest level; %s; %d moving (%.0f %%): own %.2fx, "
          "blocks %.2fx"
          % (path, n, 1e9 * dmin, own, block, 100 * low, bodies, m, 100.0 * m / n, own_m,
             block_m))


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__.split("\n\n")[1])
    for arg in sys.argv[1:]:
        for path in snapshots(arg):
            report(path)


if __name__ == "__main__":
    main()
