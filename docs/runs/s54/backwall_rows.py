#!/usr/bin/python3
"""Backwall rows of measurements.csv over time: crater_depth, crater_depth_local,
crater_local_ref, damage_radius (mm), perforated. usage: backwall_rows.py measurements.csv [t0_us]"""
import sys, collections
t0 = float(sys.argv[2]) if len(sys.argv) > 2 else 30.0
q = ['crater_depth', 'crater_depth_local', 'crater_local_ref', 'damage_radius', 'wall_shift', 'perforated']
rows = collections.defaultdict(dict)
for line in open(sys.argv[1]):
    if line.startswith('#') or line.startswith('time'):
        continue
    t, name, v, unit, obj = line.strip().split(',')[:5]
    if obj == 'backwall' and name in q:
        rows[float(t) * 1e6][name] = float(v)
print('t_us ' + ' '.join(q) + '   (mm; perforated 0/1)')
for t in sorted(rows):
    if t >= t0 - 1e-9:
        r = rows[t]
        print('%5.1f ' % t + ' '.join('%.3f' % (r.get(k, float('nan')) * (1 if k == 'perforated' else 1e3)) for k in q))
