#!/usr/bin/env python3
"""Crater-floor position and speed of a rod-penetration run, from its VTU snapshots.

    python3 tools/rod_floor.py [--rod BODY] [--axis-radius MM] RUNDIR...

For each snapshot RUNDIR/particles_NNNNN.vtu (hvsph's appended raw VTU) it prints
  tip    the mean x of the five deepest particles of the rod body (the eroding rod's
         front, which lines the crater floor);
  floor  the mean x of the three shallowest particles of every other body within
         --axis-radius of the x axis (the target material just ahead of the rod; "nan"
         where the target lattice has no particle that close to the axis);
and, between snapshots, the speeds of both in km/s. Works with any number of target
bodies (a target refined near its axis is two bodies of one material). Needs
python3-numpy.
"""
import argparse
import glob
import os
import re
import sys

import numpy as np

TYPES = {"Int64": np.int64, "Int32": np.int32, "UInt64": np.uint64, "Float64": np.float64,
         "Float32": np.float32, "UInt8": np.uint8}


def read_vtu(path):
    """The point arrays of one hvsph VTU file (appended raw, UInt64 block headers)."""
    with open(path, "rb") as f:
        data = f.read()
    start = data.index(b"<AppendedData")
    base = data.index(b"_", start) + 1
    head = data[:start].decode("latin-1")
    if 'header_type="UInt64"' not in head:
        sys.exit(f"{path}: not an hvsph VTU file (header_type UInt64 expected)")
    out = {"TIME": float(re.search(r'Name="TIME"[^>]*>([^<]*)<', head).group(1))}
    pat = (r'<DataArray type="(\w+)" Name="(\w+)"(?: NumberOfComponents="(\d+)")? '
           r'format="appended" offset="(\d+)"')
    for typ, name, comp, off in re.findall(pat, head):
        off, comp = base + int(off), int(comp or 1)
        nbytes = int(np.frombuffer(data[off:off + 8], np.uint64)[0])
        a = np.frombuffer(data[off + 8:off + 8 + nbytes], TYPES[typ])
        out[name] = a.reshape(-1, comp) if comp > 1 else a
    return out


def read_csv(path):
    """One hvsph CSV snapshot: its time (s, from the first header line) and its columns
    as a numpy structured array (docs/output-files.md)."""
    with open(path) as f:
        t = float(f.readline().split()[6])
    return t, np.genfromtxt(path, delimiter=",", names=True, skip_header=2)


def csv_snapshots(run):
    """(time, columns) of every RUNDIR/particles_NNNNN.csv, in order."""
    for path in sorted(glob.glob(os.path.join(run, "particles_*.csv"))):
        yield read_csv(path)


def body_index(path, name):
    """Index of body `name` from the run's used_parameters.yaml (bodies in order)."""
    names = []
    with open(os.path.join(path, "used_parameters.yaml")) as f:
        inside = False
        for line in f:
            if line.startswith("bodies:"):
                inside = True
            elif inside and line[:1].strip():
                break
            elif inside and re.match(r"\s*- name: ", line):
                names.append(line.split("name:", 1)[1].split("#")[0].strip().strip("\"'"))
    if name not in names:
        sys.exit(f"{path}: no body '{name}' (bodies: {', '.join(names)})")
    return names.index(name)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("rundir", nargs="+")
    ap.add_argument("--rod", default="rod", help="the rod's body name (default rod)")
    ap.add_argument("--axis-radius", type=float, default=1.3,
                    help="radius around the axis for the floor, mm (default 1.3)")
    a = ap.parse_args()
    for d in a.rundir:
        rod = body_index(d, a.rod)
        print(f"# {d}\n# t [us]  tip [mm]  floor [mm]  tip speed  floor speed [km/s]")
        prev = None
        for f in sorted(glob.glob(os.path.join(d, "particles_*.vtu"))):
            p = read_vtu(f)
            t, x = p["TIME"] * 1e6, p["x"] * 1e3
            is_rod = p["body"] == rod
            tip = np.sort(x[is_rod, 0])[-5:].mean()
            near = ~is_rod & (np.hypot(x[:, 1], x[:, 2]) < a.axis_radius)
            floor = np.sort(x[near, 0])[:3].mean() if near.sum() >= 3 else float("nan")
            line = f"{t:8.2f} {tip:9.2f} {floor:10.2f}"
            if prev is not None and t > prev[0]:
                dt = t - prev[0]
                line += f" {(tip - prev[1]) / dt:10.3f} {(floor - prev[2]) / dt:10.3f}"
            print(line)
            prev = (t, tip, floor)


if __name__ == "__main__":
    main()
