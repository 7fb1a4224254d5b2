#!/usr/bin/python3
"""Session 35: rod-5841's head at three refinements (r41-zones.yaml): from each run's
measurements.csv, at 8, 12 and 16 us, L, the floor's speed over the last 4 us, D_wall,
D_wall_mean and D_mean.  usage: compare.py RUNDIR..."""
import sys, csv
for run in sys.argv[1:]:
    q = {}
    for row in csv.reader(l for l in open(run + "/measurements.csv") if not l.startswith("#")):
        if row[0] == "time":
            continue
        q[(round(float(row[0]) * 1e6), row[1])] = float(row[2])
    print("# %s" % run)
    print("# t_us   L_mm  floor_km/s  D_wall  D_wall_mean  D_mean (mm)")
    for t in (8, 12, 16, 20):
        if (t, "penetration_depth") not in q:
            continue
        L = q[(t, "penetration_depth")]
        u = (L - q[(t - 4, "penetration_depth")]) / 4e-6 / 1e3
        print("%5d %7.2f %8.3f %9.2f %9.2f %9.2f" % (t, L * 1e3, u, q[(t, "cavity_diameter_wall")] * 1e3,
              q[(t, "cavity_diameter_wall_mean")] * 1e3, q[(t, "cavity_diameter_mean")] * 1e3))
