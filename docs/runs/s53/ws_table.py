#!/usr/bin/python3
"""§2.4's run: its measurements every 5 us (bumper hole, backwall crater and damage,
centre pressure) from measurements.csv files (later files override earlier ones for the
same time and quantity: the run's own first; a later file only adds what the earlier
lack, e.g. a remeasurement's crater_depth_local; its peak pressure, a running maximum
that a remeasurement cannot know, is never taken).
usage: ws_table.py measurements.csv [remeasured.csv ...]"""
import sys
import csv

val = {}
for fn in sys.argv[1:]:
    with open(fn) as f:
        rows = [r for r in f if not r.startswith('#')]
    for r in csv.DictReader(rows):
        t = round(float(r['time']) * 1e6, 1)
        val.setdefault((t, r['quantity'], r['object']), float(r['value']))
times = sorted({k[0] for k in val if abs(k[0] / 5 - round(k[0] / 5)) < 1e-6 and k[0] >= 35})
q = [('hole_diameter', 'bumper', 1e3, 'bumper hole (mm)'),
     ('crater_depth', 'backwall', 1e3, 'crater depth from the far wall (mm)'),
     ('crater_depth_local', 'backwall', 1e3, 'crater below its own surroundings (mm)'),
     ('crater_local_ref', 'backwall', 1e3, 'those surroundings behind the far wall (mm)'),
     ('wall_shift', 'backwall', 1e3, 'far wall moved, wall_shift (mm)'),
     ('damage_radius', 'backwall', 2e3, 'damaged-area diameter, 2 x damage_radius (mm)'),
     ('crater_radius', 'backwall', 1e3, 'cratered radius (mm)'),
     ('peak_pressure_center', 'backwall', 1e-9, 'peak pressure at the centre (GPa)')]
print('| µs | ' + ' | '.join('%g' % t for t in times) + ' |')
print('|---|' + '---|' * len(times))
for name, obj, f, label in q:
    print('| %s | ' % label + ' | '.join(
        '%.2f' % (val[(t, name, obj)] * f) if (t, name, obj) in val else '' for t in times) + ' |')
