#!/usr/bin/python3
"""Session 48: a plate's hole quantities over time from a run's measurements.csv.
Usage: /usr/bin/python3 holes.py RUNDIR/measurements.csv OBJECT [EVERY_US]"""
import csv
import sys

path, obj = sys.argv[1], sys.argv[2]
every = float(sys.argv[3]) if len(sys.argv) > 3 else 2.0
want = ['hole_diameter', 'hole_diameter_equiv', 'hole_diameter_intact', 'hole_diameter_intact_equiv']
d = {}
with open(path) as f:
    for r in csv.reader(l for l in f if not l.startswith('#')):
        if len(r) < 5 or r[4] != obj or r[1] not in want:
            continue
        d.setdefault(float(r[0]), {})[r[1]] = float(r[2]) * 1e3
print('t [us]  ' + '  '.join(want) + '  [mm]')
for t in sorted(d):
    tu = t * 1e6
    if abs(tu / every - round(tu / every)) < 1e-3:
        print(f'{tu:6.1f}  ' + '  '.join(f'{d[t].get(k, float("nan")):7.2f}' for k in want))
