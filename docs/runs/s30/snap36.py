#!/usr/bin/python3
"""§2.4 at 36 µs (session 30): the bumper particles that hold the step and their neighbours.
The snapshot: a copy of out/validation-s30/whipple-steel's checkpoint (35.93 µs) continued with
`hvsph restart COPY --set output.every=4.5us --set time.end=36us --threads 2` (34 steps).
Usage: snap36.py COPY/particles_00008.csv  (output in snap36.txt)"""
import sys
import numpy as np
f = sys.argv[1]
hdr = open(f).readlines()[2].strip().split(',')
d = np.loadtxt(f, delimiter=',', skiprows=3)
c = {k: i for i, k in enumerate(hdr)}
mat = d[:, c['mat']].astype(int)
r = d[:, c['rho']] / np.array([7850., 7850., 2780.])[mat]   # steel-projectile, steel-bumper, al-alloy
X = d[:, [c['x'], c['y'], c['z']]]
h = d[:, c['h']]
for m in (0, 1, 2):
    s = mat == m
    print(m, 'max rho/rho0 %.3f' % r[s].max(), '>1.5:', (r[s] > 1.5).sum())
def show(pid):
    k = np.where(d[:, c['id']] == pid)[0][0]
    print('id', pid, 'mat', mat[k], 'rho/rho0 %.3f' % r[k], 'x=%.2f mm' % (X[k, 0] * 1e3),
          'v=', np.round(d[k, [c['vx'], c['vy'], c['vz']]]), 'p=%.3g' % d[k, c['p']],
          'cs=%.3g' % d[k, c['cs']], 'h=%.3g' % h[k], 'dmg', d[k, c['damage']])
    dist = np.linalg.norm(X - X[k], axis=1)
    for j in np.where((dist < h + h[k]) & (dist > 0))[0]:
        print('   nb', int(d[j, c['id']]), 'mat', mat[j], 'body', int(d[j, c['body']]),
              'rho/rho0 %.3f' % r[j], 'r=%.3f mm' % (dist[j] * 1e3), 'h=%.3g' % h[j],
              'vx=%.0f' % d[j, c['vx']])
for pid in (57215, 58567):
    show(pid)
for k in np.argsort(-r)[:5]:
    print(int(d[k, c['id']]), mat[k], '%.3f' % r[k], 'x=%.2f' % (X[k, 0] * 1e3), 'p=%.3g' % d[k, c['p']])
