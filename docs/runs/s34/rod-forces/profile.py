#!/usr/bin/python3
"""Session 34: the cavity's profile at a rod's head from one VTU snapshot: per 1 mm of
xi = x - x_tip, the target's innermost particles (the mean r of the five nearest the
axis), the rod's outermost (the mean r of its five farthest), and the mass-mean radial
velocity of the target's innermost layer (within 1.5 mm of that radius).
usage: profile.py SNAPSHOT.vtu"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', '..', '..', 'tools'))
from rod_floor import read_vtu  # noqa: E402

d = read_vtu(sys.argv[1])
X, V, m, body = d['x'], d['v'], d['m'], d['body']
r = np.hypot(X[:, 1], X[:, 2])
vr = (X[:, 1] * V[:, 1] + X[:, 2] * V[:, 2]) / np.maximum(r, 1e-12)
rod = body == 0
tip = X[rod & (r < 1.3e-3), 0].max()
xi = X[:, 0] - tip
print("# %s: t = %.1f us, tip at %.2f mm" % (os.path.basename(sys.argv[1]), d['TIME'] * 1e6, tip * 1e3))
print("# xi (mm)   target inner r (mm)   its v_r (m/s)   rod outer r (mm)")
for a in np.arange(2.0, -20.0, -1.0):
    s = (xi >= (a - 1) * 1e-3) & (xi < a * 1e-3)
    t = s & ~rod & (r < 20e-3)
    line = "%5.1f..%5.1f" % (a - 1, a)
    if t.sum() >= 5:
        rin = np.sort(r[t])[:5].mean()
        lay = t & (r < rin + 1.5e-3)
        line += "   %8.2f   %8.0f" % (rin * 1e3, np.average(vr[lay], weights=m[lay]))
    else:
        line += "   %8s   %8s" % ("-", "-")
    w = s & rod
    line += "   %8.2f" % (np.sort(r[w])[-5:].mean() * 1e3) if w.sum() >= 5 else "   %8s" % "-"
    print(line)
