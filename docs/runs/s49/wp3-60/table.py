#!/usr/bin/python3
"""Session 49: W.P.3's second bumper over time, from each lane's measurements.csv:
hole_diameter and hole_diameter_intact of bumper2 (mm) at 12, 20, 30, 40, 50, 60 us.
Usage: table.py NAME=RUN/measurements.csv ...; TIMES="60 70 80 90" table.py ... for other
times."""
import csv, os, sys

TIMES = [float(t) for t in os.environ.get("TIMES", "12 20 30 40 50 60").split()]
print("| lane | quantity | " + " | ".join(f"{t:g} µs" for t in TIMES) + " |")
print("|---|---|" + "---|" * len(TIMES))
for arg in sys.argv[1:]:
    name, path = arg.split("=", 1)
    vals = {}
    with open(path) as f:
        for r in csv.DictReader(l for l in f if not l.startswith("#")):
            if r["object"] != "bumper2":
                continue
            t = round(float(r["time"]) * 1e6, 3)
            vals[(r["quantity"], t)] = float(r["value"]) * 1e3
    for q in ("hole_diameter", "hole_diameter_intact"):
        cells = [f"{vals[(q, t)]:.2f}" if (q, t) in vals else "–" for t in TIMES]
        print(f"| {name} | {q} | " + " | ".join(cells) + " |")
