#!/usr/bin/python3
"""The convergence study in RZ (issue 74): rod-5841's and rod-5844's penetration depth
and cavity diameter and W.P.1's bumper hole against particles per projectile radius,
for each material set, beside the experiment and the paper's KERNEL value, with the
Richardson-extrapolated value.

Usage:
    /usr/bin/python3 tools/figures/plot_rz_convergence.py CONVERGENCE.csv -o FILE.png
    /usr/bin/python3 tools/figures/plot_rz_convergence.py CONVERGENCE.csv --table

CONVERGENCE.csv is what tools/rz-convergence.sh writes (columns case, set, resolution,
per_radius, particles, steps, wall_s, status, time, depth, diameter, hole; lengths in
m). Only points with status ok are used. The references are data/paper_results.yaml's
(penetration_depth and cavity_diameter of the target, hole_diameter of the bumper).

Richardson extrapolation, with N particles per radius doubling from point to point
(spacing h halved): from the finest three values f1, f2, f3 (N, 2N, 4N) the observed
order is p = log2((f1 - f2) / (f2 - f3)), taken when the differences have one sign
(monotone convergence) and 0.5 <= p <= 4; then f_inf = f3 + (f3 - f2) / (2^p - 1).
Otherwise (two points, or no monotone convergence) the order is assumed p = 1 (the
first order of SPH across shocks and free surfaces) and f_inf = 2 f_last - f_previous,
marked "p=1 assumed". --table prints each extrapolation as a Markdown table.

Needs python3-numpy and python3-matplotlib (tools/install-deps.sh --docs).
"""
import argparse
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import yaml  # noqa: E402

# the repository root: this file is tools/figures/plot_rz_convergence.py
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

# (case, column of the csv, quantity and object in data/paper_results.yaml, title)
PANELS = [
    ("rod-5841", "depth", "penetration_depth", "target", "rod-5841: depth L [cm]"),
    ("rod-5841", "diameter", "cavity_diameter", "target", "rod-5841: cavity diameter D [cm]"),
    ("rod-5844", "depth", "penetration_depth", "target", "rod-5844: depth L [cm]"),
    ("rod-5844", "diameter", "cavity_diameter", "target", "rod-5844: cavity diameter D [cm]"),
    ("wp1", "hole", "hole_diameter", "bumper", "W.P.1: bumper hole [cm]"),
]
AIM = {"depth": 0.05, "diameter": 0.10, "hole": 0.10}   # issue 74's aims, relative
STYLE = {"table2": ("C0", "o", "Table 2's set"), "sourced": ("C3", "s", "sourced set")}
UNITS = {"m": 1.0, "cm": 1e-2, "mm": 1e-3}


def length(s):
    """[m] from '16.52 cm'."""
    v, u = str(s).split()
    return float(v) * UNITS[u]


def references():
    with open(os.path.join(ROOT, "data", "paper_results.yaml")) as f:
        data = yaml.safe_load(f)
    wanted = {(c, q, o) for c, _, q, o, _ in PANELS}
    ref = {}
    for case, rows in data.items():
        for r in rows or []:
            if (case, r["quantity"], r.get("object")) in wanted:
                ref[(case, r["quantity"], r.get("object"))] = (
                    length(r["experiment"]) if "experiment" in r else math.nan,
                    length(r["paper"]) if "paper" in r else math.nan)
    return ref


def richardson(ns, fs):
    """(f_inf, p, observed) from values fs at particles per radius ns (ascending, each
    twice the one before), or None with fewer than two."""
    if len(fs) < 2:
        return None
    if len(fs) >= 3:
        f1, f2, f3 = fs[-3:]
        d1, d2 = f1 - f2, f2 - f3
        if d1 * d2 > 0:
            p = math.log2(d1 / d2)
            if 0.5 <= p <= 4:
                return f3 + (f3 - f2) / (2 ** p - 1), p, True
    return 2 * fs[-1] - fs[-2], 1.0, False


def series(rows, case, column, kind):
    pts = sorted((float(r["per_radius"]), float(r[column])) for r in rows
                 if r["case"] == case and r["set"] == kind and r["status"] == "ok"
                 and r[column] not in ("", "nan"))
    # only runs of doubled resolution form the Richardson sequence
    ns = [n for n, _ in pts]
    fs = [f for _, f in pts]
    return ns, fs


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("csvfile", metavar="CONVERGENCE.csv")
    ap.add_argument("-o", "--output", help="the PNG file to write")
    ap.add_argument("--table", action="store_true",
                    help="print the extrapolated values as Markdown instead")
    a = ap.parse_args()
    with open(a.csvfile) as f:
        rows = list(csv.DictReader(f))
    ref = references()

    if a.table:
        print("| case | set | quantity | points (per radius) | extrapolated | order | experiment |")
        print("|---|---|---|---|---|---|---|")
        for case, col, q, obj, _ in PANELS:
            for kind in STYLE:
                ns, fs = series(rows, case, col, kind)
                r = richardson(ns, fs)
                if r is None:
                    continue
                exp = ref.get((case, q, obj), (math.nan, math.nan))[0]
                print("| %s | %s | %s | %s | %.2f cm (%+.0f %%) | %s | %.2f cm |" % (
                    case, kind, col, ", ".join("%g" % n for n in ns), r[0] * 100,
                    (r[0] / exp - 1) * 100, "%.2f observed" % r[1] if r[2] else "1 assumed",
                    exp * 100))
        return 0
    if not a.output:
        ap.error("-o FILE.png or --table")

    fig, axes = plt.subplots(2, 3, figsize=(11, 6.2))
    axes = axes.ravel()
    drawn = 0
    for ax, (case, col, q, obj, title) in zip(axes, PANELS):
        exp, paper = ref.get((case, q, obj), (math.nan, math.nan))
        if not math.isnan(exp):
            ax.axhspan(exp * (1 - AIM[col]) * 100, exp * (1 + AIM[col]) * 100,
                       color="0.9", zorder=0)
            ax.axhline(exp * 100, color="k", lw=1.2, label="experiment (±%d %%)" % (AIM[col] * 100))
        if not math.isnan(paper):
            ax.axhline(paper * 100, color="0.4", lw=1, ls="--", label="KERNEL (paper)")
        here = 0
        for kind, (color, marker, label) in STYLE.items():
            ns, fs = series(rows, case, col, kind)
            if not ns:
                continue
            drawn += 1
            here += 1
            ax.plot(ns, [f * 100 for f in fs], color=color, marker=marker, label=label)
            r = richardson(ns, fs)
            if r is not None:
                ax.axhline(r[0] * 100, color=color, lw=1, ls=":",
                           label="extrapolated, p = %s" % (
                               "%.2g observed" % r[1] if r[2] else "1 assumed"))
        if not here:
            ax.text(0.5, 0.3, "no run finished", transform=ax.transAxes, ha="center",
                    va="center", color="0.4")
        ax.set_xscale("log", base=2)
        ax.set_xticks([4, 8, 16, 32])
        ax.set_xticklabels(["4", "8", "16", "32"])
        ax.set_xlim(3.4, 38)
        ax.set_title(title, fontsize=10)
        ax.set_xlabel("particles per projectile radius", fontsize=9)
        ax.legend(fontsize=6.5, loc="best")
        ax.grid(alpha=0.3)
    # the sixth panel: wall time
    ax = axes[5]
    for case, marker in (("rod-5841", "o"), ("rod-5844", "^"), ("wp1", "D")):
        for kind, (color, _, label) in STYLE.items():
            pts = sorted((float(r["per_radius"]), float(r["wall_s"]) / 3600) for r in rows
                         if r["case"] == case and r["set"] == kind and r["status"] == "ok")
            if pts:
                ax.plot([p[0] for p in pts], [p[1] for p in pts], color=color, marker=marker,
                        label="%s, %s" % (case, label), lw=1)
    ax.set_xscale("log", base=2)
    ax.set_yscale("log")
    ax.set_xticks([4, 8, 16, 32])
    ax.set_xticklabels(["4", "8", "16", "32"])
    ax.set_xlim(3.4, 38)
    ax.set_title("wall time [h], as run (shared machine)", fontsize=10)
    ax.set_xlabel("particles per projectile radius", fontsize=9)
    ax.legend(fontsize=6.5, loc="best")
    ax.grid(alpha=0.3, which="both")
    if drawn == 0:
        print("plot_rz_convergence: %s: no finished point" % a.csvfile, file=sys.stderr)
        return 1
    fig.tight_layout()
    fig.savefig(a.output, dpi=80)
    return 0


if __name__ == "__main__":
    sys.exit(main())
