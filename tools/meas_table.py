#!/usr/bin/env python3
"""A run's measurements over time as a Markdown table: one row per measurement time, one
column per quantity (docs/measurements.md), lengths in mm, speeds in km/s, pressures in
GPa, angles in degrees as written.

usage: tools/meas_table.py RUN [QUANTITY[@OBJECT] ...] [--times 25,50,100] [--every 5]

RUN is a run folder (its measurements.csv) or a measurements.csv file. Each column is a
quantity, e.g. `penetration_depth` or `hole_diameter@bumper` (the object where several
objects measure the same quantity); without any, every quantity the file has (its
objects named where there are several). --times keeps the rows nearest to these times
[µs]; --every keeps the times that are multiples of that many µs. A value the file
lacks at a time is "–". Examples:

  tools/meas_table.py out/validation/rod-5842 penetration_depth cavity_diameter \\
      cavity_diameter_wall --every 25
  tools/meas_table.py out/validation/wp1 hole_diameter@bumper cloud_velocity_mean

Standard library only. Exit status 2 for a missing or unreadable file, or a quantity the
file does not have (named in the message).
"""
import argparse
import csv
import math
import os
import sys

# unit as written -> (factor, unit shown)
SHOWN = {"m": (1e3, "mm"), "m/s": (1e-3, "km/s"), "Pa": (1e-9, "GPa"), "m^2": (1e6, "mm²"),
         "m2": (1e6, "mm²")}


def fail(msg):
    print("meas_table: " + msg, file=sys.stderr)
    sys.exit(2)


def read(path):
    """[(time s, quantity, object, value, unit)] from measurements.csv, comments skipped."""
    rows = []
    try:
        with open(path, newline="") as f:
            lines = [(n, l) for n, l in enumerate(f, 1) if not l.startswith("#")]
    except OSError as e:
        fail("%s: %s" % (path, e.strerror))
    if not lines:
        fail("%s: no header line" % path)
    reader = csv.DictReader(l for _, l in lines)
    need = {"time", "quantity", "value", "unit", "object"}
    if not need <= set(reader.fieldnames or []):
        fail("%s: line %d: the header lacks %s" % (path, lines[0][0],
                                                   ", ".join(sorted(need - set(reader.fieldnames or [])))))
    for (n, _), r in zip(lines[1:], reader):
        try:
            rows.append((float(r["time"]), r["quantity"], r["object"], float(r["value"]), r["unit"]))
        except (TypeError, ValueError):
            fail("%s: line %d: not a measurement row" % (path, n))
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("run")
    ap.add_argument("quantities", nargs="*")
    ap.add_argument("--times", help="comma-separated times [us]: the rows nearest to them")
    ap.add_argument("--every", type=float, help="keep the times that are multiples of this [us]")
    a = ap.parse_args()
    path = os.path.join(a.run, "measurements.csv") if os.path.isdir(a.run) else a.run
    rows = read(path)

    objects = {}
    for _, q, o, _, _ in rows:
        objects.setdefault(q, set()).add(o)
    cols = []
    if a.quantities:
        for spec in a.quantities:
            q, _, o = spec.partition("@")
            if q not in objects or (o and o not in objects[q]):
                fail("%s: no quantity %s (it has: %s)" % (path, spec, ", ".join(
                    "%s@%s" % (k, ob) for k in sorted(objects) for ob in sorted(objects[k]))))
            if not o and len(objects[q]) > 1:
                fail("%s: %s is measured on %s: name one as %s@OBJECT"
                     % (path, q, ", ".join(sorted(objects[q])), q))
            cols.append((q, o or next(iter(objects[q]))))
    else:
        seen = set()
        for _, q, o, _, _ in rows:
            if (q, o) not in seen:
                seen.add((q, o))
                cols.append((q, o))

    value, unit = {}, {}
    for t, q, o, v, u in rows:
        key = round(t * 1e6, 6)          # µs; the file's times are the run's output times
        value[(key, q, o)] = v
        unit[(q, o)] = u
    times = sorted({k[0] for k in value})
    if a.every:
        times = [t for t in times if abs(t / a.every - round(t / a.every)) < 1e-6]
    if a.times:
        try:
            want = [float(x) for x in a.times.split(",")]
        except ValueError:
            fail("--times %s: not a list of numbers" % a.times)
        times = sorted({min(times, key=lambda t: abs(t - w)) for w in want}) if times else []

    def head(q, o):
        f, shown = SHOWN.get(unit[(q, o)], (1.0, unit[(q, o)]))
        name = q if sum(1 for c in cols if c[0] == q) == 1 else "%s@%s" % (q, o)
        return "%s [%s]" % (name, shown) if shown not in ("", "1", "-") else name

    def cell(t, q, o):
        v = value.get((t, q, o))
        if v is None or math.isnan(v):
            return "–"
        f, _ = SHOWN.get(unit[(q, o)], (1.0, ""))
        return "%.4g" % (v * f)

    print("| t [µs] | " + " | ".join(head(q, o) for q, o in cols) + " |")
    print("|---" * (len(cols) + 1) + "|")
    for t in times:
        print("| %g | " % t + " | ".join(cell(t, q, o) for q, o in cols) + " |")


if __name__ == "__main__":
    main()
