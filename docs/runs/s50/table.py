#!/usr/bin/python3
"""Session 50: hole quantities of a run's plates over time, from its measurements.csv.
Usage: table.py RUN/measurements.csv [OBJECT ...]; TIMES="5 10 20" picks the times (us),
QUANTITIES="hole_diameter hole_diameter_intact" the rows. Values in mm (lengths) as
written, others as written."""
import csv, os, sys

path = sys.argv[1]
objects = sys.argv[2:] or ["bumper1", "bumper2"]
TIMES = [float(t) for t in os.environ.get("TIMES", "5 10 15 20 30 40 50 60").split()]
QS = os.environ.get("QUANTITIES", "hole_diameter hole_diameter_intact").split()
vals, units = {}, {}
with open(path) as f:
    for r in csv.DictReader(l for l in f if not l.startswith("#")):
        t = round(float(r["time"]) * 1e6, 3)
        v = float(r["value"])
        if r["unit"] == "m":
            v *= 1e3
        vals[(r["object"], r["quantity"], t)] = v
print("| quantity | " + " | ".join(f"{t:g} µs" for t in TIMES) + " |")
print("|---|" + "---|" * len(TIMES))
for o in objects:
    for q in QS:
        cells = [f"{vals[(o, q, t)]:.2f}" if (o, q, t) in vals else "–" for t in TIMES]
        print(f"| {o}: {q} | " + " | ".join(cells) + " |")
