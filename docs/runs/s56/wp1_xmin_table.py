#!/usr/bin/python3
"""W.P.1 with the face in front of the bumper a wall or absorbing (wp1-xmin.sh): the bumper
hole (largest free circle, mm) every 5 us in both runs, and what the absorbing face took
(half model: mass x2, g). usage: wp1_xmin_table.py WALLDIR ABSDIR"""
import sys, csv
def holes(d):
    h = {}
    for r in csv.reader(l for l in open(d + '/measurements.csv') if not l.startswith('#')):
        if len(r) >= 5 and r[1] == 'hole_diameter' and r[4] == 'bumper':
            h[round(float(r[0]) * 1e6, 3)] = float(r[2]) * 1e3
    return h
def absorbed(d):
    a = {}
    rows = [l for l in open(d + '/summary.csv') if not l.startswith('#')]
    hdr = rows[0].strip().split(',')
    for l in rows[1:]:
        f = dict(zip(hdr, l.strip().split(',')))
        a[round(float(f['time']) * 1e6, 3)] = 2e3 * float(f['absorbed_mass'])
    return a
w, b, ab = holes(sys.argv[1]), holes(sys.argv[2]), absorbed(sys.argv[2])
print('t_us  hole_wall  hole_absorbing  diff_%  absorbed_g')
for t in sorted(set(w) & set(b)):
    if abs(t - round(t / 5) * 5) < 1e-6:
        print('%5.0f  %9.3f  %14.3f  %6.2f  %s' % (t, w[t], b[t], 100 * (b[t] / w[t] - 1) if w[t] else 0,
              '%.4f' % ab[t] if t in ab else ''))
