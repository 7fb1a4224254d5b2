#!/usr/bin/env python3
"""Session 33: the §2.4 bumper's plastic strain around the hole at 12 us.

For each run folder given, reads its last snapshot (particles_00001.vtu, 12 us) and
prints, for the bumper's particles still within 0.5 mm of the plate's mid-plane
(|x - 0.5 mm| < 0.5 mm) in 0.5 mm rings of the radius r = sqrt(y^2 + z^2), the
particle count, the median plastic strain and the fraction split (damage 1).
Usage: /usr/bin/python3 rim.py RUN...
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "..", "..", "tools"))
from rod_floor import read_vtu  # noqa: E402


def main():
    for run in sys.argv[1:]:
        d = read_vtu(os.path.join(run, "particles_00001.vtu"))
        x = d["x"]
        body = d["body"]
        sel = (body >= 1) & (np.abs(x[:, 0] - 0.5e-3) < 0.5e-3)
        r = np.hypot(x[sel, 1], x[sel, 2]) * 1e3
        ep = d["eps_p"][sel]
        dmg = d["damage"][sel] if "damage" in d else np.zeros_like(ep)
        print(f"{run}  t = {d['TIME'] * 1e6:.1f} us")
        print("  r (mm)     n   eps_p median   split")
        for a in np.arange(4.0, 9.01, 0.5):
            m = (r >= a) & (r < a + 0.5)
            if m.sum() == 0:
                print(f"  {a:4.1f}-{a + 0.5:4.1f}    0")
                continue
            print(f"  {a:4.1f}-{a + 0.5:4.1f} {m.sum():5d}   {np.median(ep[m]):8.3f}   "
                  f"{(dmg[m] >= 1).mean():6.2f}")


if __name__ == "__main__":
    main()
