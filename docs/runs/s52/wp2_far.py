#!/usr/bin/python3
"""W.P.2's backwall: how far the wall far from the impact has moved (the mean x
displacement, by particle id against the first snapshot, of the wall's first and last
particle layers at 60-90 mm from the axis), beside the crater depth of measurements.csv
at the same time.  usage: wp2_far.py measurements.csv particles_00000.csv particles.csv..."""
import sys
import numpy as np

crater = {}
for line in open(sys.argv[1]):
    f = line.split(',')
    if len(f) > 2 and f[1] == 'crater_depth':
        crater[round(float(f[0]) * 1e7)] = float(f[2]) * 1e3


def load(fn):
    d = np.genfromtxt(fn, delimiter=',', skip_header=2, names=True)
    t = float(open(fn).readline().split(' time ')[1].split()[0])
    o = np.argsort(d['id'])
    return t, d[o]


t0, d0 = load(sys.argv[2])
x0 = d0['x'] * 1e3
r0 = np.hypot(d0['y'], d0['z']) * 1e3
wall = (d0['body'] == 3) & (r0 >= 60) & (r0 < 90)
front = wall & (x0 < x0[d0['body'] == 3].min() + 0.1)
rear = wall & (x0 > x0[d0['body'] == 3].max() - 0.1)
print('far wall: %d front-layer and %d rear-layer particles' % (front.sum(), rear.sum()))
for fn in sys.argv[3:]:
    t, d = load(fn)
    assert (d['id'] == d0['id']).all()
    dx = d['x'] * 1e3 - x0
    c = crater.get(round(t * 1e7), float('nan'))
    print('%5.1f us: far wall moved: front %+.3f, rear %+.3f mm; crater_depth %.3f mm, less the front\'s move %.3f mm'
          % (t * 1e6, dx[front].mean(), dx[rear].mean(), c, c - dx[front].mean()))
