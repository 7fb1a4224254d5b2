#!/usr/bin/python3
"""Session 48: W.P.3's second bumper by rings around the axis (the session 47 study's runs,
docs/runs/s47/wp3-bumper2). For each snapshot: the second bumper's particles (body 3) in
rings of 5 mm radius: the share split (damage >= 1), the median and 90th percentile of the
axial displacement from the plate's mid-plane (61.05 mm), the mean axial velocity, and the
first cloud's mass (bodies 0-2) that has crossed the plate's plane within that ring, per
unit area, with its mean axial velocity at the crossing's time (taken at the snapshot).

Usage: /usr/bin/python3 rings.py RUNDIR/particles_NNNNN.vtu ...
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', '..', '..', 'tools'))
from rod_floor import read_vtu  # noqa: E402

MID = 61.05e-3


def rings(path):
    d = read_vtu(path)
    x, v, b, m = d['x'], d['v'], d['body'], d['m']
    dmg = d.get('damage', np.zeros(len(m)))
    r = np.hypot(x[:, 1], x[:, 2])
    print(f'{path}: t = {d["TIME"] * 1e6:.1f} us')
    print(' r [mm]  n   split  dx med / p90 [mm]  vx mean [m/s]  cloud past plane [kg/m^2]  its vx [km/s]')
    for lo in range(0, 60, 5):
        hi = lo + 5
        s = (b == 3) & (r >= lo * 1e-3) & (r < hi * 1e-3)
        c = (b < 3) & (r >= lo * 1e-3) & (r < hi * 1e-3) & (x[:, 0] > MID)
        area = np.pi * ((hi * 1e-3)**2 - (lo * 1e-3)**2) / 2  # half model
        dx = (x[s, 0] - MID) * 1e3
        mc = m[c].sum()
        vc = (m[c] * v[c, 0]).sum() / mc if mc > 0 else 0
        print(f'{lo:3d}-{hi:<3d} {s.sum():6d} {np.mean(dmg[s] >= 1) if s.any() else 0:5.2f} '
              f'{np.median(dx) if s.any() else 0:7.2f} / {np.percentile(dx, 90) if s.any() else 0:6.2f} '
              f'{np.mean(v[s, 0]) if s.any() else 0:10.0f} {mc / area:14.4f} {vc * 1e-3:12.2f}')


if __name__ == '__main__':
    for a in sys.argv[1:]:
        rings(a)
