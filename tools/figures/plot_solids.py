#!/usr/bin/python3
"""Plots of the solid verification problems (docs/verification-solids.md).

Reads the particle snapshots (particles_NNNNN.csv) the verification tests leave in
their scratch folders and draws one problem's figure: hugoniot, elastic_wave, rings,
taylor, spall or porous_impact. Needs Debian's python3-numpy and python3-matplotlib
(/usr/bin/python3, tools/install-deps.sh --docs).

usage:
  tools/figures/plot_solids.py NAME -o FILE.png [--tmp BUILD/testtmp]
                               [--hugoniot DIR] [--elastic-wave DIR] [--rings DIR]
                               [--rings-eps0 DIR] [--rings-eps06 DIR] [--taylor DIR]
                               [--spall DIR] [--spall-low DIR]

By default the folders are those the tests make under --tmp (default build/testtmp,
ctest's): e.g. build/testtmp/test_hugoniot/hugoniot. Any folder can be given instead (a
run of `hvsph run examples/verification/X.yaml -o DIR` with output.csv on). The figure
scripts tools/figures/{hugoniot-planar-shock,elastic-wave,rubber-rings,taylor-bar,
spall-flyer-plate,porous-impact}.sh run the tests and call this (`make figures`).
"""
import argparse
import glob
import math
import os
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


# ---------------------------------------------------------------- reading

def load(path):
    """One snapshot: (time [s], dict column -> numpy array)."""
    t, hdr, rows = float("nan"), None, []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                if " time " in line:
                    t = float(line.split(" time ")[1].split()[0])
                continue
            if hdr is None:
                hdr = line.strip().split(",")
                continue
            rows.append(line)
    a = np.loadtxt(rows, delimiter=",", ndmin=2) if rows else np.zeros((0, len(hdr)))
    return t, {h: a[:, k] for k, h in enumerate(hdr)}


def snapshots(d):
    files = sorted(glob.glob(os.path.join(d, "particles_*.csv")))
    if not files:
        raise SystemExit("no particles_*.csv in %s" % d)
    return files


def by_id(a, key):
    """Column `key` ordered by particle id."""
    o = np.argsort(a["id"])
    return a[key][o]


def layers(a0, sel, tol):
    """Initial lattice layer (in x) of every id among sel; -1 elsewhere."""
    ids = a0["id"].astype(int)
    lay = -np.ones(ids.max() + 1, dtype=int)
    x = a0["x"][sel]
    xs = np.sort(x)
    lo = xs[np.r_[True, np.diff(xs) > tol]]
    lay[ids[sel]] = np.searchsorted(lo, x, side="right") - 1
    return lay, len(lo)


def layer_mean(a, lay, nl, key):
    l = lay[a["id"].astype(int)]
    s = l >= 0
    return np.bincount(l[s], weights=a[key][s], minlength=nl) / np.maximum(
        np.bincount(l[s], minlength=nl), 1)


def front(X, V, level, from_end):
    idx = range(len(X) - 1, -1, -1) if from_end else range(len(X))
    idx = list(idx)
    above0 = V[idx[0]] > level
    for a, b in zip(idx[:-1], idx[1:]):
        if (V[b] > level) != above0:
            f = (level - V[a]) / (V[b] - V[a])
            return X[a] + f * (X[b] - X[a])
    return float("nan")


# ---------------------------------------------------------------- references

def mg_pressure(r, E, rho0=2780.0, c0=5612.0, n=3.54, gam=1.176):
    """The paper's Mie-Grueneisen EOS with the Murnaghan cold curve (al-alloy)."""
    eta = r / rho0
    pc = rho0 * c0 ** 2 / n * (eta ** n - 1)
    Ec = c0 ** 2 / n * ((eta ** (n - 1) - 1) / (n - 1) - 1 + rho0 / r)
    return pc + gam * r * (E - Ec)


def rankine_hugoniot(up, rho0=2780.0, c0=5612.0, n=3.54, gam=1.176):
    def eos(r, E):
        return mg_pressure(r, E, rho0, c0, n, gam)

    def res(r1):
        p1 = rho0 * up ** 2 * r1 / (r1 - rho0)
        return eos(r1, 0.5 * p1 * (1 / rho0 - 1 / r1)) - p1

    a, b = rho0 * (1 + 1e-6), 3 * rho0
    for _ in range(200):
        m = 0.5 * (a + b)
        a, b = (a, m) if res(m) > 0 else (m, b)
    r1 = 0.5 * (a + b)
    us = up * r1 / (r1 - rho0)
    return r1, us, rho0 * us * up


# ---------------------------------------------------------------- plots

def plot_hugoniot(d, out):
    up = 1000.0
    r1, us, p1 = rankine_hugoniot(up)
    files = snapshots(d)
    _, a0 = load(files[0])
    sel = a0["body"] == 1
    lay, nl = layers(a0, sel, 0.2 * a0["h"][0])
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.2))
    ts, xf = [], []
    for k, f in enumerate(files[1:], 1):
        t, a = load(f)
        X, V, P = (layer_mean(a, lay, nl, c) for c in ("x", "vx", "p"))
        x = front(X, V, -0.5 * up, True)
        ts.append(t)
        xf.append(x)
        if k % 2 == 0 or k == len(files) - 1:
            ax[0].plot(X * 1e3, V, lw=1, label="%.1f µs" % (t * 1e6))
            ax[1].plot(X * 1e3, P * 1e-9, lw=1)
    ax[1].axhline(p1 * 1e-9, color="k", ls="--", lw=0.8,
                  label="Rankine–Hugoniot p₁ = %.2f GPa" % (p1 * 1e-9))
    ax[0].set(xlabel="x [mm]", ylabel="layer-mean $v_x$ [m/s]",
              title="right plate (hit at −1 km/s): velocity")
    ax[0].legend(fontsize=7)
    ax[1].set(xlabel="x [mm]", ylabel="pressure [GPa]", title="pressure")
    ax[1].legend(fontsize=8)
    ts, xf = np.array(ts), np.array(xf)
    m = ts >= 0.25e-6
    c = np.polyfit(ts[m], xf[m], 1)
    ax[2].plot(ts * 1e6, xf * 1e3, "o", label="front (half the velocity jump)")
    tt = np.linspace(0, ts.max(), 10)
    ax[2].plot(tt * 1e6, np.polyval(c, tt) * 1e3, "-",
               label="fit: Us = %.0f m/s" % (c[0] + up))
    ax[2].plot(tt * 1e6, (us - up) * tt * 1e3, "k--", lw=0.8,
               label="Rankine–Hugoniot: Us = %.0f m/s" % us)
    ax[2].set(xlabel="t [µs]", ylabel="front position [mm]",
              title="shock front (al-alloy, up = 1 km/s)")
    ax[2].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def plot_elastic_wave(d, out):
    up = 1.0
    K = 2780.0 * 5612.0 ** 2
    G = 3 * K * (1 - 2 * 0.362) / (2 * (1 + 0.362))
    cl = math.sqrt((K + 4 * G / 3) / 2780.0)
    files = snapshots(d)
    _, a0 = load(files[0])
    lay, nl = layers(a0, np.ones(len(a0["x"]), bool), 0.2 * a0["h"][0])
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    ts, xf = [], []
    for k, f in enumerate(files[1:], 1):
        t, a = load(f)
        X, V = layer_mean(a, lay, nl, "x"), layer_mean(a, lay, nl, "vx")
        ts.append(t)
        xf.append(front(X, V, -0.5 * up, True))
        if k % 2 == 0:
            ax[0].plot(X * 1e3, V, lw=1, label="%.1f µs" % (t * 1e6))
    ax[0].set(xlabel="x [mm] (wall at x = 0)", ylabel="layer-mean $v_x$ [m/s]",
              title="elastic wave in al-alloy (bar at −1 m/s onto a wall)")
    ax[0].legend(fontsize=7)
    ts, xf = np.array(ts), np.array(xf)
    m = ts >= 0.2e-6
    c = np.polyfit(ts[m], xf[m], 1)
    tt = np.linspace(0, ts.max(), 10)
    ax[1].plot(ts * 1e6, xf * 1e3, "o", label="front (v = −0.5 m/s)")
    ax[1].plot(tt * 1e6, np.polyval(c, tt) * 1e3, "-", label="fit: %.0f m/s" % (c[0] + up))
    ax[1].plot(tt * 1e6, cl * tt * 1e3, "k--", lw=0.8,
               label="√((K + 4G/3)/ρ₀) = %.0f m/s" % cl)
    ax[1].plot(tt * 1e6, 5612.0 * tt * 1e3, ":", color="gray", lw=0.8,
               label="bulk c₀ = 5612 m/s (no shear)")
    ax[1].set(xlabel="t [µs]", ylabel="front position [mm]", title="wave front")
    ax[1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def plot_rings(d, d0, d6, out):
    """Rows: ε = 0.3 (the case), ε = 0 and ε = 0.6 snapshots; centre-of-mass velocity."""
    fig = plt.figure(figsize=(16, 11))
    gs = fig.add_gridspec(3, 4, height_ratios=[1, 1, 0.9])

    def draw(axx, a, t, title):
        for b, col in ((0, "tab:blue"), (1, "tab:red")):
            s = (a["body"] == b) & (a["z"] < a["z"].min() + 0.3 * a["h"][0])  # one z layer
            for sgn in (1, -1):   # the simulated half y > 0 and its mirror image
                axx.scatter(a["x"][s], sgn * a["y"][s], s=2, color=col, lw=0,
                            alpha=1.0 if sgn > 0 else 0.45)
        axx.set_aspect("equal")
        axx.set(xlim=(-9, 9), ylim=(-6.5, 6.5), title=title % t)
        axx.tick_params(labelsize=7)

    def pick(dd, tw):
        files = snapshots(dd)
        times = np.array([load(f)[0] for f in files])
        return load(files[int(np.argmin(np.abs(times - tw)))])

    for j, tw in enumerate([0, 50, 90, 140]):
        t, a = pick(d, tw)
        draw(fig.add_subplot(gs[0, j]), a, t, "ε = 0.3 (default), t = %.0f")
    row2 = []
    if d0:
        row2 += [(d0, 60, "ε = 0, t = %.0f"), (d0, 100, "ε = 0, t = %.0f")]
    if d6:
        row2 += [(d6, 90, "ε = 0.6, t = %.0f"), (d6, 140, "ε = 0.6, t = %.0f")]
    for j, (dd, tw, title) in enumerate(row2):
        t, a = pick(dd, tw)
        draw(fig.add_subplot(gs[1, j]), a, t, title)
    axv = fig.add_subplot(gs[2, :])
    for dd, lab, st in ((d, "ε = 0.3 (default)", "-o"), (d0, "ε = 0", "--s"),
                        (d6, "ε = 0.6", "-.^")):
        if not dd:
            continue
        tv, vv = [], []
        for f in snapshots(dd):
            t, a = load(f)
            s = a["body"] == 0
            tv.append(t)
            vv.append(np.sum(a["m"][s] * a["vx"][s]) / np.sum(a["m"][s]))
        axv.plot(tv, vv, st, ms=3, label="left ring, " + lab)
    axv.axhline(0, color="k", lw=0.5)
    axv.set(xlabel="t (units of the paper: ρ₀ = c₀ = 1)", ylabel="centre-of-mass $v_x$ / c₀",
            title="left ring's velocity (the right ring's is its mirror image)")
    axv.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    plt.close(fig)


def plot_taylor(d, out):
    files = snapshots(d)
    t0, a0 = load(files[0])
    dx = (a0["m"][0] / a0["rho"][0]) ** (1 / 3)
    L_ref, R_ref = 21.45e-3, 7.05e-3
    fig, ax = plt.subplots(1, 2, figsize=(13, 4.6), gridspec_kw={"width_ratios": [2, 1]})
    t, a = load(files[-1])
    r = np.hypot(a["y"], a["z"])
    r0 = np.hypot(a0["y"], a0["z"])
    ax[0].scatter(a0["x"] * 1e3, r0 * 1e3, s=3, color="lightgray", lw=0, label="t = 0")
    sc = ax[0].scatter(a["x"] * 1e3, r * 1e3, s=4, c=a["eps_p"], cmap="viridis", lw=0)
    fig.colorbar(sc, ax=ax[0], label="equivalent plastic strain")
    ax[0].axvline(L_ref * 1e3, color="k", ls="--", lw=0.8, label="published L = 21.4–21.5 mm")
    ax[0].axhline(R_ref * 1e3, color="r", ls="--", lw=0.8, label="published R = 7.0–7.1 mm")
    ax[0].set(xlabel="x [mm] (wall at x = 0)", ylabel="r = √(y² + z²) [mm]",
              title="copper Taylor bar at %.0f µs (particles of the quarter model)" % (t * 1e6))
    ax[0].set_aspect("equal")
    ax[0].legend(fontsize=7, loc="upper right")
    ts, Ls, Rs = [], [], []
    face = a0["id"][a0["x"] < a0["x"].min() + 0.5 * dx].astype(int)  # the impact face
    for f in files:
        t, a = load(f)
        x = a["x"]
        ts.append(t)
        Ls.append(x.max() - x.min() + dx)
        inface = np.isin(a["id"].astype(int), face)
        Rs.append(np.hypot(a["y"], a["z"])[inface].max() + 0.5 * dx)
    ts = np.array(ts) * 1e6
    ax[1].plot(ts, np.array(Ls) * 1e3, "-o", ms=3, label="length L")
    ax[1].plot(ts, np.array(Rs) * 1e3 * 3, "-s", ms=3, label="face radius R × 3")
    ax[1].axhline(L_ref * 1e3, color="k", ls="--", lw=0.8)
    ax[1].axhline(R_ref * 1e3 * 3, color="r", ls="--", lw=0.8)
    ax[1].set(xlabel="t [µs]", ylabel="[mm]", title="length and impact-face radius")
    ax[1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def plot_spall(d, dlow, out):
    files = snapshots(d)
    _, a0 = load(files[0])
    x0 = dict(zip(a0["id"].astype(int), a0["x"]))
    sel = a0["body"] == 1
    lay, nl = layers(a0, sel, 0.2 * a0["h"][0])
    fig, ax = plt.subplots(1, 3, figsize=(16, 4.3))
    for f in files:
        t, a = load(f)
        if not (0.75e-6 < t < 1.05e-6):
            continue
        X = layer_mean(a, lay, nl, "x")
        sxx = layer_mean(a, lay, nl, "S_xx") - layer_mean(a, lay, nl, "p")
        ax[0].plot(X * 1e3, sxx * 1e-9, lw=1, label="%.2f µs" % (t * 1e6))
    ax[0].axhline(0.59, color="r", ls="--", lw=0.8, label="|σ_c| = 0.59 GPa")
    ax[0].axvline(2.0, color="k", ls=":", lw=0.8, label="expected plane (t from the rear)")
    ax[0].set(xlabel="x [mm] (target: 0–4 mm)", ylabel="layer-mean σ_xx [GPa] (tension > 0)",
              title="target, 100 m/s: the release waves meet")
    ax[0].legend(fontsize=7)
    t, a = load(files[-1])
    dmg = a["damage"] >= 1
    ax[1].scatter(a["x"][~dmg] * 1e3, a["y"][~dmg] * 1e3, s=3, color="lightgray", lw=0)
    ax[1].scatter(a["x"][dmg] * 1e3, a["y"][dmg] * 1e3, s=5, color="r", lw=0, label="split")
    ax[1].set(xlabel="x [mm]", ylabel="y [mm]",
              title="100 m/s at %.1f µs: split particles" % (t * 1e6))
    ax[1].legend(fontsize=8)
    xs = np.array([x0[i] for i in a["id"][dmg].astype(int)]) * 1e3
    bins = np.arange(-2.0, 4.01, 0.1) - 1e-9
    ax[2].hist(xs, bins=bins, color="r", alpha=0.7, label="100 m/s")
    if dlow:
        tl, al = load(snapshots(dlow)[-1])
        x0l = dict(zip(load(snapshots(dlow)[0])[1]["id"].astype(int),
                       load(snapshots(dlow)[0])[1]["x"]))
        dl = al["damage"] >= 1
        xl = np.array([x0l[i] for i in al["id"][dl].astype(int)]) * 1e3
        ax[2].hist(xl, bins=bins, color="b", alpha=0.5, label="50 m/s")
    dx = (a0["m"][0] / a0["rho"][0]) ** (1 / 3) * 1e3
    ax[2].axvspan(2.0 - 4 * dx, 2.0 + 4 * dx, color="g", alpha=0.15,
                  label="test band ±4 spacings")
    ax[2].axvspan(-2 * dx, 2 * dx, color="gray", alpha=0.2, label="contact layers (excluded)")
    ax[2].set(xlabel="initial x of split particles [mm]", ylabel="count",
              title="where particles split")
    ax[2].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def porous_match(f, V=7000.0, rho0=2780.0):
    """Distended al-alloy debris (f rho0, E = 0, p = 0; pressure cut at 0) on the solid
    plate at V: the plate's particle speed u and pressure p (test_porous_impact.c)."""
    def debris_p(w):
        r00 = f * rho0
        a, b = r00 * (1 + 1e-9), 4 * rho0
        for _ in range(200):
            r = 0.5 * (a + b)
            pj = r00 * w * w * r / (r - r00)
            a, b = (a, r) if max(mg_pressure(r, 0.5 * w * w), 0.0) - pj > 0 else (r, b)
        r = 0.5 * (a + b)
        return r00 * w * w * r / (r - r00)

    lo, hi = 0.0, V
    for _ in range(100):
        u = 0.5 * (lo + hi)
        lo, hi = (lo, u) if rankine_hugoniot(u)[2] > debris_p(V - u) else (u, hi)
    u = 0.5 * (lo + hi)
    return u, rankine_hugoniot(u)[2]


def plot_porous_impact(dirs, out, area=1.8e-3 ** 2):
    fig, ax = plt.subplots(1, 2, figsize=(12, 4.2))
    for (f, d), col in zip(dirs, ("C0", "C1", "C2")):
        u, p = porous_match(f)
        files = snapshots(d)
        _, a0 = load(files[0])
        sel = a0["body"] == 1
        lay, nl = layers(a0, sel, 0.2 * a0["h"][0])
        ts, mom = [], []
        for fl in files:
            t, a = load(fl)
            s = a["body"] == 1
            ts.append(t)
            mom.append(np.sum(a["m"][s] * a["vx"][s]))
        X, P = (layer_mean(a, lay, nl, c) for c in ("x", "p"))
        ax[0].plot(X * 1e3, P * 1e-9, color=col, lw=1,
                   label="f = %g, %.1f µs" % (f, t * 1e6))
        ax[0].axhline(p * 1e-9, color=col, ls="--", lw=0.8)
        ts, mom = np.array(ts), np.array(mom)
        ax[1].plot(ts * 1e6, (mom - mom[0]) * 1e3, "o", color=col, ms=4,
                   label="f = %g" % f)
        ax[1].plot(ts * 1e6, p * area * (ts - ts[0]) * 1e3, "--", color=col, lw=0.8)
    ax[0].set(xlabel="x [mm] (contact at 0)", ylabel="plate layer-mean pressure [GPa]",
              title="debris at f ρ₀ on aluminium at 7 km/s (dashed: porous Hugoniot)",
              ylim=(0, 45))   # f = 0.3's squeezed contact layer is off the scale
    ax[0].legend(fontsize=8)
    ax[1].set(xlabel="t [µs]", ylabel="plate momentum gained [g m/s]",
              title="momentum handed to the plate (dashed: p A t)")
    ax[1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("name", choices=["hugoniot", "elastic_wave", "rings", "taylor", "spall",
                                     "porous_impact"])
    ap.add_argument("-o", "--output", required=True, help="the PNG file to write")
    ap.add_argument("--tmp", default="build/testtmp", help="the tests' scratch root")
    for k in ("hugoniot", "elastic-wave", "rings", "rings-eps0", "rings-eps06", "taylor", "spall",
              "spall-low"):
        ap.add_argument("--" + k)
    o = ap.parse_args()
    T = o.tmp
    dirs = {
        "hugoniot": o.hugoniot or os.path.join(T, "test_hugoniot", "hugoniot"),
        "elastic_wave": o.elastic_wave or os.path.join(T, "test_elastic_wave", "elastic_wave"),
        "rings": o.rings or os.path.join(T, "test_rings", "rings"),
        "rings_eps0": o.rings_eps0 or os.path.join(T, "test_rings", "rings_eps0"),
        "rings_eps06": o.rings_eps06 or os.path.join(T, "test_rings", "rings_eps06"),
        "taylor": o.taylor or os.path.join(T, "test_taylor", "taylor_bar"),
        "spall": o.spall or os.path.join(T, "test_spall", "spall"),
        "spall_low": o.spall_low or os.path.join(T, "test_spall", "spall_low"),
    }
    porous = [(f, os.path.join(T, "test_porous_impact", "porous_impact_%02d" % round(100 * f)))
              for f in (0.3, 0.1, 0.03)]
    jobs = {
        "hugoniot": lambda p: plot_hugoniot(dirs["hugoniot"], p),
        "elastic_wave": lambda p: plot_elastic_wave(dirs["elastic_wave"], p),
        "rings": lambda p: plot_rings(
            dirs["rings"],
            dirs["rings_eps0"] if os.path.isdir(dirs["rings_eps0"]) else None,
            dirs["rings_eps06"] if os.path.isdir(dirs["rings_eps06"]) else None, p),
        "taylor": lambda p: plot_taylor(dirs["taylor"], p),
        "spall": lambda p: plot_spall(dirs["spall"], dirs["spall_low"]
                                      if os.path.isdir(dirs["spall_low"]) else None, p),
        "porous_impact": lambda p: plot_porous_impact(porous, p),
    }
    jobs[o.name](o.output)   # a missing folder ends it with SystemExit and its message
    print("wrote", o.output)


if __name__ == "__main__":
    sys.exit(main())
