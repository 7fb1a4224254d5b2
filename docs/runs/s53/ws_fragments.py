#!/usr/bin/python3
"""§2.4: how the steel projectile breaks up, from `hvsph validate`'s fragment tables
(fragments_NNNNN.csv: friends-of-friends pieces, half model, with each piece's mass
of each material and its multiplicity in the full picture).
Prints, per table: the five largest pieces' projectile mass (mg: a piece of the full picture, docs/measurements.md), their
equivalent sphere diameters (steel, 7850 kg/m3), and the share of the projectile's
mass (full picture) in pieces of at most 3 particles.
usage: ws_fragments.py fragments_*.csv"""
import sys
import numpy as np

for fn in sys.argv[1:]:
    with open(fn) as f:
        f.readline()
        t = float(f.readline().split('time ')[1].split()[0])
    d = np.genfromtxt(fn, delimiter=',', skip_header=2, names=True)
    p = d['m_steelprojectile']
    only = d['mass'] - p < 1e-3 * d['mass']      # pieces of projectile steel alone
    o = np.argsort(-np.where(only, p, 0))
    big = p[o[:5]]
    dia = (6 * big / (np.pi * 7850)) ** (1 / 3) * 1e3
    tot = (p * d['multiplicity']).sum()
    small = (p * d['multiplicity'])[d['count'] <= 3].sum()
    print('%5.1f us: largest projectile-only pieces %s mg (%s mm); in pieces of <= 3 particles %.0f %% of %.3f g'
          % (t * 1e6, ' '.join('%.2f' % (b * 1e6) for b in big),
             ' '.join('%.2f' % x for x in dia), 100 * small / tot, tot * 1e3))
