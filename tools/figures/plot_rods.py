#!/usr/bin/python3
"""Penetration depth and cavity diameter of the six long-rod tests (the seed paper's
Tables 1-3) over impact velocity: hvsph beside the experiments and the paper's KERNEL
simulations.

Usage:
    /usr/bin/python3 tools/figures/plot_rods.py VALIDATION.csv -o FILE.png [--label TEXT]

VALIDATION.csv is the table `hvsph validate` writes (columns case, quantity,
simulated, experiment, paper_simulation, unit, rel_error; lengths in the unit column's
m, cm or mm). The impact
velocity of each case is read from the header of examples/paper/<case>.yaml ("... at
4.46 km/s ..."). Cases without a simulated value are drawn with the references only.

Needs python3-numpy and python3-matplotlib (tools/install-deps.sh --docs).
"""
import argparse
import csv
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# the repository root: this file is tools/figures/plot_rods.py
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def impact_velocity(case):
    """[km/s] from the case file's header comment."""
    path = os.path.join(ROOT, "examples", "paper", case + ".yaml")
    with open(path) as f:
        for line in f:
            if not line.startswith("#"):
                break
            m = re.search(r"at ([0-9.]+) km/s", line)
            if m:
                return float(m.group(1))
    raise SystemExit("%s: no impact velocity in the header" % path)


TO_CM = {"m": 100.0, "cm": 1.0, "mm": 0.1}   # the table's unit column


def number(s):
    try:
        v = float(s)
    except ValueError:
        return math.nan
    return v


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("table")
    ap.add_argument("-o", "--output", required=True, help="the PNG file to write")
    ap.add_argument("--label", default="hvsph")
    a = ap.parse_args()
    rows = {}
    with open(a.table) as f:
        for r in csv.DictReader(line for line in f if not line.startswith("#")):
            if not r["case"].startswith("rod-"):
                continue
            # "penetration_depth:target" -> "penetration_depth"
            rows.setdefault(r["case"], {})[r["quantity"].split(":")[0]] = r
    if not rows:
        sys.exit("%s: no rod cases" % a.table)
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.2))
    for ax, q, name in ((axes[0], "penetration_depth", "penetration depth L [cm]"),
                        (axes[1], "cavity_diameter", "cavity diameter D [cm]")):
        for case in sorted(rows, key=impact_velocity):
            r = rows[case].get(q)
            if r is None:
                continue
            v = impact_velocity(case)
            cm = TO_CM.get(r.get("unit", "m"))
            if cm is None:
                sys.exit("%s: %s %s: unknown unit '%s'" % (a.table, case, q, r.get("unit")))
            exp, pap, sim = (cm * number(r[k]) for k in ("experiment", "paper_simulation",
                                                          "simulated"))
            ax.plot(v, exp, "ks", ms=7, label="experiment")
            ax.plot(v, pap, "o", mfc="none", mec="tab:red", ms=8, label="paper (KERNEL)")
            if not math.isnan(sim):
                ax.plot(v, sim, "D", color="tab:blue", ms=6, label=a.label)
            ax.annotate(case[4:], (v, exp), textcoords="offset points", xytext=(6, -4),
                        fontsize=7, color="0.4")
        handles, labels = ax.get_legend_handles_labels()
        seen = {}
        for h, lab in zip(handles, labels):
            seen.setdefault(lab, h)
        ax.legend(seen.values(), seen.keys(), fontsize=8, loc="upper left")
        ax.set_xlabel("impact velocity [km/s]")
        ax.set_ylabel(name)
        ax.grid(alpha=0.3)
    fig.suptitle("Long rods into steel (seed paper, Tables 1-3)", fontsize=10)
    fig.tight_layout()
    fig.savefig(a.output, dpi=100, format="png")
    print("%s -> %s" % (a.table, a.output))


if __name__ == "__main__":
    main()
