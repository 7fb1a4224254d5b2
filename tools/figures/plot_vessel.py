#!/usr/bin/python3
"""The section-3 pressure vessel over time: the gas's density in the symmetry plane with
the debris on it, like the paper's Fig. 3, and a table of the shock front, the debris's
leading edge and the largest fragment at each output.

Usage:
    /usr/bin/python3 tools/figures/plot_vessel.py RUNDIR [-o FILE.png] [--times 10,20,30,40]
                                          [--gas nitrogen] [--slab 4] [--csv FILE]

RUNDIR is a run of examples/paper/vessel.yaml with `output.csv: true` (hvsph validate
sets it): particles_NNNNN.csv, fragments_NNNNN.csv and measurements.csv. Each panel
shows the gas particles within --slab mm of the symmetry plane z = 0, coloured by their
density over the initial gas density, and every condensed particle (projectile and
wall) projected onto that plane in black. --times picks the outputs nearest to these
times [us] (default: up to four, evenly spread). The table (stdout, and --csv) gives, at
every output, the shock front's axial and radial extent (measurements.csv,
docs/measurements.md), the debris's leading edge (the 99 % mass quantile of x over the
condensed material behind the wall) and the mass, x and vx of the largest fragment whose
centre is behind the wall.

Needs python3-numpy and python3-matplotlib (tools/install-deps.sh --docs).
"""
import argparse
import csv
import glob
import os
import re
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_snapshot(path):
    """(time [s], {material index: name}, structured array)"""
    with open(path) as f:
        head = [f.readline(), f.readline()]
    m = re.search(r"time ([0-9.eE+-]+) s", head[0])
    if not m:
        sys.exit("%s: not an hvsph particle snapshot (no time in its first line)" % path)
    mats = dict((int(k), v) for k, v in re.findall(r"(\d+)=(\S+)", head[1]))
    data = np.genfromtxt(path, delimiter=",", names=True, skip_header=2)
    return float(m.group(1)), mats, np.atleast_1d(data)


def read_measurements(path):
    """{(time rounded to 1 ns, quantity): value} for the gas rows"""
    out = {}
    if not os.path.exists(path):
        return out
    with open(path) as f:
        rows = [r for r in csv.reader(line for line in f if not line.startswith("#"))]
    for r in rows[1:]:
        try:
            out[(round(float(r[0]) * 1e9), r[1])] = float(r[2])
        except (ValueError, IndexError):
            continue
    return out


def largest_fragment(path, x_behind):
    """(mass [kg], x [m], vx [m/s]) of the largest fragment whose centre is beyond
    x_behind (the wall's rear face: the wall itself is the largest piece), or None"""
    if not os.path.exists(path):
        return None
    with open(path) as f:
        lines = [line for line in f if not line.startswith("#")]
    for r in csv.DictReader(lines):  # largest first
        if float(r["x"]) > x_behind:
            return float(r["mass"]), float(r["x"]), float(r["vx"])
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("rundir")
    ap.add_argument("-o", "--output", default=None, help="picture (PNG)")
    ap.add_argument("--times", default=None, help="comma-separated times [us]")
    ap.add_argument("--gas", default="nitrogen", help="the gas's material name")
    ap.add_argument("--slab", type=float, default=4.0, help="half-thickness [mm] of the gas slice")
    ap.add_argument("--csv", default=None, help="write the table here too")
    args = ap.parse_args()

    snaps = sorted(glob.glob(os.path.join(args.rundir, "particles_*.csv")))
    if not snaps:
        sys.exit("%s: no particles_NNNNN.csv (run with output.csv: true)" % args.rundir)
    meas = read_measurements(os.path.join(args.rundir, "measurements.csv"))
    t0, mats, d0 = read_snapshot(snaps[0])
    gas_ids = [k for k, v in mats.items() if v == args.gas]
    if not gas_ids:
        sys.exit("%s: no material named '%s' (materials: %s)" %
                 (snaps[0], args.gas, ", ".join(mats.values())))
    gid = gas_ids[0]
    rho1 = float(np.median(d0["rho"][d0["mat"] == gid]))
    wall_x = float(np.max(d0["x"][d0["mat"] != gid]))  # the wall's rear face at t = 0

    table = []
    cache = {}
    for path in snaps:
        t, _, d = read_snapshot(path)
        cache[path] = (t, d)
        cond = d["mat"] != gid
        behind = cond & (d["x"] > wall_x)
        lead = np.nan
        if behind.any():
            order = np.argsort(d["x"][behind])
            cm = np.cumsum(d["m"][behind][order])
            lead = d["x"][behind][order][np.searchsorted(cm, 0.99 * cm[-1])]
        k = os.path.basename(path)[len("particles_"):-len(".csv")]
        frag = largest_fragment(os.path.join(args.rundir, "fragments_%s.csv" % k), wall_x)
        key = round(t * 1e9)
        table.append((t, meas.get((key, "shock_front_axial"), np.nan),
                      meas.get((key, "shock_front_radial"), np.nan), lead,
                      float(np.sum(d["m"][behind])), frag))

    hdr = "t_us,shock_front_axial_mm,shock_front_radial_mm,debris_lead_mm,debris_mass_g," \
          "largest_fragment_g,largest_fragment_x_mm,largest_fragment_vx_m_s"
    lines = [hdr]
    for t, sa, sr, lead, mb, frag in table:
        fm, fx, fv = frag if frag else (np.nan, np.nan, np.nan)
        lines.append("%.3f,%.2f,%.2f,%.2f,%.4f,%.4f,%.2f,%.0f" %
                     (t * 1e6, sa * 1e3, sr * 1e3, lead * 1e3, mb * 1e3, fm * 1e3, fx * 1e3, fv))
    print("\n".join(lines))
    if args.csv:
        tmp = args.csv + ".tmp"
        with open(tmp, "w") as f:
            f.write("\n".join(lines) + "\n")
        os.replace(tmp, args.csv)

    if not args.output:
        return
    times = [cache[p][0] for p in snaps]
    if args.times:
        want = [float(x) * 1e-6 for x in args.times.split(",")]
        picks = sorted(set(int(np.argmin([abs(t - w) for t in times])) for w in want))
    else:
        later = [i for i, t in enumerate(times) if t > 0]
        n = min(4, len(later))
        picks = [later[int(round(j * (len(later) - 1) / max(n - 1, 1)))] for j in range(n)] if n else [0]
        picks = sorted(set(picks))
    fig, axes = plt.subplots(1, len(picks), figsize=(3.3 * len(picks) + 1.2, 4.2), squeeze=False,
                             constrained_layout=True)
    slab = args.slab * 1e-3
    sc = None
    for ax, i in zip(axes[0], picks):
        t, d = cache[snaps[i]]
        gas = (d["mat"] == gid) & (np.abs(d["z"]) < slab)
        cond = d["mat"] != gid
        sc = ax.scatter(d["x"][gas] * 1e3, d["y"][gas] * 1e3, c=d["rho"][gas] / rho1, s=4,
                        cmap="viridis", vmin=0.0, vmax=4.0, marker="s", linewidths=0)
        ax.scatter(d["x"][cond] * 1e3, d["y"][cond] * 1e3, s=0.3, c="k", linewidths=0)
        row = table[i]
        ax.set_title("t = %.0f us\nshock %.0f mm ahead, %.0f mm across" %
                     (t * 1e6, row[1] * 1e3, row[2] * 1e3), fontsize=9)
        ax.set_xlim(-10, 150)
        ax.set_ylim(-80, 80)
        ax.axvline(0, color="0.5", lw=0.5)
        ax.set_aspect("equal")
        ax.set_xlabel("x [mm]")
    axes[0][0].set_ylabel("y [mm]")
    fig.colorbar(sc, ax=axes[0].tolist(), shrink=0.8, label="gas density / initial (|z| < %g mm)"
                 % args.slab)
    fig.suptitle("Pressure vessel (section 3): debris (black, projected) and the gas in the "
                 "symmetry plane", fontsize=10)
    tmp = args.output + ".tmp.png"
    fig.savefig(tmp, dpi=110)
    os.replace(tmp, args.output)
    print("wrote %s" % args.output, file=sys.stderr)


if __name__ == "__main__":
    main()
