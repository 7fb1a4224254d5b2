#!/usr/bin/python3
"""Where the target block of a rod run parts: per snapshot, the widest gap between
neighbouring target particles along x (100 < x < 200 mm) in rows 1.5 mm from the symmetry
plane at y = -45, -35, -25, 25, 35, 45 mm; the split share of the target between 120 and
160 mm; the target's mean axial velocity in front of 130 mm and behind 150 mm.

Usage: crack.py particles_NNNNN.csv [...]   (CSV snapshots of a rod run)
Session 26, docs/validation.md (rod-5841 at the paper's counts, the cut at 179 us).
"""
import sys
import numpy as np

for f in sys.argv[1:]:
    with open(f) as fh:
        head = fh.readline()
        fh.readline()
        names = fh.readline().strip().split(',')
    cols = ('x', 'y', 'z', 'mat', 'damage', 'vx')
    d = np.loadtxt(f, delimiter=',', comments='#', skiprows=3,
                   usecols=[names.index(n) for n in cols])
    c = dict(zip(cols, d.T))
    tg = c['mat'] == 1
    out = []
    for y0 in (-45, -35, -25, 25, 35, 45):
        s = tg & (np.abs(c['y'] - y0 * 1e-3) < 0.9e-3) & (c['z'] < 1.5e-3) \
            & (c['x'] > 100e-3) & (c['x'] < 200e-3)
        x = np.sort(c['x'][s])
        dx = np.diff(x)
        k = np.argmax(dx)
        out.append(f"y={y0:+d}: {dx[k]*1e3:.2f} mm at x={x[k]*1e3:.0f}")
    band = tg & (c['x'] > 120e-3) & (c['x'] < 160e-3)
    t = float(head.split(' time ')[1].split()[0])
    print(f"t = {t*1e6:5.1f} us | widest gap per row: {'; '.join(out)} | split share 120-160 mm "
          f"{c['damage'][band].mean():.2f} | target vx, x < 130 mm: "
          f"{c['vx'][tg & (c['x'] < 130e-3)].mean():.1f} m/s, x > 150 mm: "
          f"{c['vx'][tg & (c['x'] > 150e-3)].mean():.1f} m/s")
