#!/usr/bin/python3
"""Plot hvsph verification profiles: SPH particles against the exact solution.

Usage:
    /usr/bin/python3 tools/figures/plot_verification.py -o FILE.png PROFILE.csv [PROFILE.csv ...]

Each PROFILE.csv is written by a verification test (tests/verification/test_*.c) into
its scratch folder, e.g. build/testtmp/test_sod/sod_profile.csv. Its first line is a
comment "# <problem> t=<time> n=<particles>: ...", then a header whose first column is
the coordinate (x or r) followed by pairs "q,q_exact", one row per particle. When the
same folder holds <problem>_exact.csv (coordinate and q_exact columns on a fine grid,
also written by the tests) the exact line is drawn from it, else from the particles'
own exact values. The profiles given must be of one problem (e.g. test_noh's two
resolutions, one colour each); they make one PNG, FILE.png, with one panel per pair: the
particles as small dots, the exact solution as a line. The vertical range covers the exact solution and 99.9 % of the particles; the
few beyond it (e.g. the hot particles at the centre of the Sedov blast) are counted in
the panel's corner.

Needs python3-numpy and python3-matplotlib (tools/install-deps.sh --docs). The figure
scripts tools/figures/{sod-shock-tube,noh-implosion,sedov-blast}.sh run the tests and call
this (tools/README.md, `make figures`).
"""
import argparse
import os
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

LABELS = {
    "x": "x [m]",
    "r": "r [m]",
    "rho": "density ρ [kg/m³]",
    "vx": "velocity vₓ [m/s]",
    "vr": "radial velocity v_r [m/s]",
    "p": "pressure p [Pa]",
}
# plotted coordinate range per problem (the region the tests compare, and a margin)
XRANGE = {"sod": (-0.5, 0.5), "noh": (0.0, 0.5), "sedov": (0.0, 0.45)}


def read_profile(path, pairs=True):
    with open(path) as f:
        first = f.readline()
        if not first.startswith("#"):
            sys.exit(f"{path}: the first line should be a '# problem ...' comment")
        comment = first[1:].strip()
        header = f.readline().strip().split(",")
        data = np.loadtxt(f, delimiter=",", ndmin=2)
    if data.shape[1] != len(header) or (pairs and (len(header) < 3 or len(header) % 2 == 0)):
        sys.exit(f"{path}: expected a coordinate column and pairs q,q_exact; got {header}")
    return comment, header, data


def exact_table(path, problem):
    """The fine-grid exact solution beside the profile, as {column: values}, or None."""
    ex = os.path.join(os.path.dirname(path), f"{problem}_exact.csv")
    if not os.path.exists(ex):
        return None
    _, header, data = read_profile(ex, pairs=False)
    return {name: data[:, k] for k, name in enumerate(header)}


COLOURS = ["tab:blue", "tab:orange", "tab:green", "tab:red"]


def run_label(comment):
    """'n=33512 spacing=0.025' from the comment's key=value words."""
    words = [w.rstrip(":") for w in comment.split() if w.startswith(("n=", "spacing="))]
    return " ".join(words) if words else "SPH particles"


def plot(paths, out):
    runs = [read_profile(p) for p in paths]
    comment, header, _ = runs[0]
    problem = comment.split()[0]
    fine = exact_table(paths[0], problem)
    npairs = (len(header) - 1) // 2
    fig, axes = plt.subplots(npairs, 1, figsize=(7.0, 2.6 * npairs), sharex=True, squeeze=False)
    for k in range(npairs):
        ax = axes[k, 0]
        lo, hi, off = np.inf, -np.inf, 0
        for r, (cm, hd, data) in enumerate(runs):
            coord, q, qe = data[:, 0], data[:, 1 + 2 * k], data[:, 2 + 2 * k]
            lab = "SPH particles" if len(runs) == 1 else run_label(cm)
            ax.plot(coord, q, ".", ms=1.0, alpha=0.35, color=COLOURS[r % len(COLOURS)],
                    rasterized=True, label=lab)
            lo = min(lo, np.nanpercentile(q, 0.05))
            hi = max(hi, np.nanpercentile(q, 99.95))
        name = header[2 + 2 * k]
        data = runs[0][2]
        if fine is not None and name in fine:
            xe, ye = fine[header[0]], fine[name]
        else:
            order = np.argsort(data[:, 0], kind="stable")
            xe, ye = data[order, 0], data[order, 2 + 2 * k]
        ax.plot(xe, ye, "-", lw=1.2, color="black", label="exact")
        lo, hi = min(np.nanmin(ye), lo), max(np.nanmax(ye), hi)
        pad = 0.06 * (hi - lo if hi > lo else 1.0)
        ax.set_ylim(lo - pad, hi + pad)
        for _, _, data in runs:
            q = data[:, 1 + 2 * k]
            off += int(np.sum((q < lo - pad) | (q > hi + pad)))
        if off:
            ax.text(0.99, 0.97, f"{off} particle{'s' if off > 1 else ''} off scale",
                    transform=ax.transAxes, ha="right", va="top", fontsize=7)
        ax.set_ylabel(LABELS.get(header[1 + 2 * k], header[1 + 2 * k]))
        ax.grid(alpha=0.3)
        if k == 0:
            ax.legend(loc="best", fontsize=8, markerscale=6)
    if problem in XRANGE:
        axes[0, 0].set_xlim(*XRANGE[problem])
    axes[-1, 0].set_xlabel(LABELS.get(header[0], header[0]))
    fig.suptitle("\n".join(cm for cm, _, _ in runs), fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110, format="png")
    plt.close(fig)
    print(f"{', '.join(paths)} -> {out}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("profiles", nargs="+", help="profile CSV files written by the tests")
    ap.add_argument("-o", "--output", required=True, help="the PNG file to write")
    args = ap.parse_args()
    problems = set()
    for p in args.profiles:
        try:
            with open(p) as f:
                problems.add((f.readline()[1:].split() or ["?"])[0])
        except OSError as e:
            sys.exit(f"{p}: {e.strerror}")
    if len(problems) != 1:
        sys.exit(f"the profiles are of {len(problems)} problems ({', '.join(sorted(problems))}); "
                 "one figure takes one problem")
    plot(args.profiles, args.output)


if __name__ == "__main__":
    main()
