#!/usr/bin/env python3
"""What individual (block) time steps could gain, read from snapshots' `dt` column.

For each particle snapshot given (a CSV written with output.csv: true), with dt_i each
particle's own limit and dt_min their minimum (the global step):
  - own:   N dt_min / sum(dt_min / dt_i) ... the work ratio if every particle took
           exactly its own step (force evaluations per unit time: sum 1/dt_i against
           N/dt_min);
  - block: the same with each step rounded down to dt_min 2^k, k <= 10 (a power-of-two
           hierarchy as block-step codes use);
  - the share of particles on the lowest level (within 2 dt_min).
  - the same two counting only the particles in motion (v != 0): sph.skip_resting already
    spares the cells at rest, so against today's code these are the gains.
Upper bounds: they leave out the overheads of such a scheme (drifting the inactive
particles, neighbour searches of the active ones) and the limiter that keeps
neighbouring steps within a small factor of each other, which moves particles down.
Usage: block_steps.py particles_NNNNN.csv ...
"""
import sys

import numpy as np

for path in sys.argv[1:]:
    d = np.genfromtxt(path, delimiter=",", names=True, skip_header=2)
    dt = d["dt"]
    n = dt.size
    dmin = dt.min()
    own = n / np.sum(dmin / dt)
    k = np.minimum(np.floor(np.log2(dt / dmin)), 10)
    block = n / np.sum(2.0 ** -k)
    low = np.mean(dt < 2 * dmin)
    bodies = ", ".join("body %d: median %.3g ns" % (b, 1e9 * np.median(dt[d["body"] == b]))
                       for b in np.unique(d["body"]).astype(int))
    moving = (d["vx"] != 0) | (d["vy"] != 0) | (d["vz"] != 0)
    m = np.count_nonzero(moving)
    own_m = m / np.sum(dmin / dt[moving])
    block_m = m / np.sum(2.0 ** -k[moving])
    print("%s: %d particles, step %.4g ns; own steps %.2fx, blocks %.2fx fewer force "
          "evaluations; %.1f %% on the lowest level; %s; %d moving (%.0f %%): own %.2fx, "
          "blocks %.2fx"
          % (path, n, 1e9 * dmin, own, block, 100 * low, bodies, m, 100.0 * m / n, own_m,
             block_m))
