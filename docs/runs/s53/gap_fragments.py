#!/usr/bin/python3
"""The largest pieces flying in a shield's gap, from `hvsph validate`'s fragment tables
(friends-of-friends pieces, half model; a piece on the axis plane counts once, with
its multiplicity in the full picture): their masses (mg: a piece of the full picture, docs/measurements.md) and equivalent
sphere diameters, for pieces between X0 and X1 (m) along the axis.
usage: gap_fragments.py X0 X1 RHO fragments_*.csv   (RHO: density for the diameters)"""
import sys
import numpy as np

x0, x1, rho = float(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3])
for fn in sys.argv[4:]:
    with open(fn) as f:
        f.readline()
        t = float(f.readline().split('time ')[1].split()[0])
    d = np.genfromtxt(fn, delimiter=',', skip_header=2, names=True)
    s = (d['x'] > x0) & (d['x'] < x1)
    m = d['mass'][s]
    o = np.argsort(-m)[:6]
    dia = (6 * m[o] / (np.pi * rho)) ** (1 / 3) * 1e3
    print('%5.1f us: largest pieces in the gap (mg) %s; equivalent diameters (mm) %s; total %.1f mg'
          % (t * 1e6, ' '.join('%.1f' % (x * 1e6) for x in m[o]),
             ' '.join('%.2f' % x for x in dia), (m * d['multiplicity'][s]).sum() * 1e6))
