#!/usr/bin/python3
"""Where the cup's reversed flow loses its speed (session 35 study): from one CSV
snapshot of cup.yaml, the mass-mean speed |v|/v0 on a grid of
(x, r) cells of 1 mm outside the rod (r > 1.05 r0).  usage: path.py SNAPSHOT.csv"""
import os, sys, numpy as np
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "..", "tools"))
from rod_floor import read_csv  # noqa: E402
v0, r0 = 1100.0, 2.638
d = read_csv(sys.argv[1])[1]
x, r = d["x"] * 1e3, np.hypot(d["y"], d["z"]) * 1e3
sp = np.sqrt(d["vx"]**2 + d["vy"]**2 + d["vz"]**2) / v0
m = d["m"] * 4e3
print("# |v|/v0 per cell (x rows, r columns, 1 mm); '.' empty")
rb = np.arange(3, 10)
print("x\\r  " + " ".join("%5.1f" % (a + 0.5) for a in rb))
for xa in np.arange(0, 10):
    row = []
    for a in rb:
        s = (x >= xa) & (x < xa + 1) & (r >= a) & (r < a + 1) & (r > 1.05 * r0)
        row.append("%5.2f" % np.average(sp[s], weights=m[s]) if s.sum() else "    .")
    print("%4.1f " % (xa + 0.5) + " ".join(row))
