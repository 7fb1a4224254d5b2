#!/usr/bin/python3
"""W.P.2's backwall: the mean x displacement (by particle id against the first snapshot)
of its rear particle layer in bands of distance from the axis, and of the particles
next to the rigid side walls (|y| or z within 2 mm of 100 mm).
usage: wp2_disp.py particles_00000.csv particles.csv..."""
import sys
import numpy as np


def load(fn):
    d = np.genfromtxt(fn, delimiter=',', skip_header=2, names=True)
    t = float(open(fn).readline().split(' time ')[1].split()[0])
    return t, d[np.argsort(d['id'])]


t0, d0 = load(sys.argv[1])
x0 = d0['x'] * 1e3
y0, z0 = d0['y'] * 1e3, d0['z'] * 1e3
r0 = np.hypot(y0, z0)
wall = d0['body'] == 3
rear = wall & (x0 > x0[wall].max() - 0.1)
edge = rear & ((np.abs(y0) > 98) | (z0 > 98))
bands = ((20, 40), (40, 60), (60, 80), (80, 90), (90, 100), (100, 142))
print('rear layer, mean dx (mm) at ρ (mm): ' + ' '.join('%d-%d' % b for b in bands) + ' | at the side walls')
for fn in sys.argv[2:]:
    t, d = load(fn)
    dx = d['x'] * 1e3 - x0
    row = ['%+.3f' % dx[rear & (r0 >= a) & (r0 < b)].mean() for a, b in bands]
    print('%5.1f us: ' % (t * 1e6) + ' '.join(row) + ' | %+.3f' % dx[edge].mean())
