#!/usr/bin/env python3
"""Per-particle CFL step of a snapshot, dt_i = cfl h_i / (2.2 c_i) (the v_sig of a particle
whose neighbours do not approach it: c + 1.2 alpha c with alpha = 1), against the
smallest; the particles per power-of-two level (dt_min 2^k) and the work of a block
time step scheme relative to one global step (sum over levels of n_k / 2^k, no overhead)."""
import sys
import numpy as np
sys.path.insert(0, "/work/main/tools")
from rod_floor import read_vtu
for f in sys.argv[1:]:
    d = read_vtu(f)
    dt = 0.3 * d["h"] / (2.2 * d["cs"])
    m = dt.min()
    lev = np.floor(np.log2(dt / m)).clip(0, 6).astype(int)
    counts = [int((lev == k).sum()) for k in range(7)]
    work = sum(c / 2**k for k, c in enumerate(counts)) / len(dt)
    print(f"{f} t = {d['TIME']*1e6:.1f} us: dt_min = {m:.3g} s; particles per level "
          f"(dt_min x 1, 2, 4, ...): {counts}; work ratio {work:.3f}")
    for b in (0, 1):
        s = d["body"] == b
        print(f"  body {b}: dt/dt_min 1st/50th/99th percentile "
              f"{np.round(np.percentile(dt[s] / m, [1, 50, 99]), 2).tolist()}")
