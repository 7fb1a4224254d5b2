"""Reads a run's measurements.csv (docs/output-files.md) for the analysis scripts of
docs/runs: read(path, quantities) -> {time in us (rounded to 1e-3): {quantity: value x
scale}} for the rows whose quantity is one of `quantities` (scale 1e3: metres to mm).
A missing file gives {}.  series(path, quantity): one quantity, {time in us: value x
scale}.  emit(path, lines): writes a report's lines to path and prints them.  Also:
print_history (one run's table), final_of (a run's last
output), validation_table (a validation.csv), and the rods' ratio rule of sessions 37-39,
ratio_estimates and print_energy; at (a quantity between outputs) and jc_rows / rod_heading
(sessions 40 and 43: a material set beside the case, output by output)."""
import csv
import math
import os
import statistics

# the thick target's cavity quantities (docs/measurements.md) and their short names
CAVITY_Q = ["penetration_depth", "cavity_diameter", "cavity_diameter_mean",
            "cavity_diameter_wall", "cavity_diameter_wall_mean"]
CAVITY_SHORT = {"penetration_depth": "L", "cavity_diameter": "D", "cavity_diameter_mean": "D_mean",
                "cavity_diameter_wall": "D_wall", "cavity_diameter_wall_mean": "D_wall_mean"}


def read(path, quantities, scale=1e3):
    out = {}
    if not os.path.exists(path):
        return out
    with open(path) as f:
        rows = [r for r in f if not r.startswith("#")]
    for r in csv.DictReader(rows):
        if r["quantity"] in quantities:
            out.setdefault(round(float(r["time"]) * 1e6, 3), {})[r["quantity"]] = float(r["value"]) * scale
    return out


def series(path, quantity, scale=1e3):
    """read() for one quantity: {time in us (rounded to 1e-3): value x scale}."""
    return {t: q[quantity] for t, q in read(path, (quantity,), scale).items()}


def emit(path, lines):
    """Writes lines (a report, one string each) to path and prints them."""
    text = "\n".join(lines) + "\n"
    with open(path, "w") as f:
        f.write(text)
    print(text, end="")


def print_history(run, d, quantities, short):
    """Prints the table of read()'s d for run: one row per output (t > 0); of more than
    14 outputs only those at whole multiples of 20 us and the last."""
    if not d:
        print(f"{run}: no measurements")
        return
    ts = sorted(d)
    print(f"{run}: outputs to {ts[-1]:.1f} us")
    print("   t us | " + " | ".join(short[q] for q in quantities) + " (mm)")
    for t in ts:
        if t == 0 or (len(ts) > 14 and round(t) % 20 and t != ts[-1]):
            continue
        print(f"  {t:6.1f} | " + " | ".join(f"{d[t].get(q, float('nan')):6.2f}" for q in quantities))


def ratio_estimates(b, d, paper, exp_L, exp_D, short, title):
    """Session 37's ratio rule: the run d (read()'s dict) over the run b at their last
    common output t > 0, times paper (the b model's result at the paper's counts,
    {quantity: mm}), for each quantity of paper.  Prints one line per quantity (the
    ratio, those of the last three common outputs and their median: a single particle
    in the channel can close the cavity (L) or a thin slice miss the wall (D) at one
    output) after a heading "TITLE at T us, ...", and returns (t, {quantity: estimate
    mm}); None, printing nothing, without a common output."""
    common = sorted(t for t in set(b) & set(d) if t > 0)
    if not common:
        return None
    t = common[-1]
    print(f"{title} at {t:.1f} us, x the case at the paper's counts:")
    est = {}
    for q, pv in paper.items():
        r = d[t][q] / b[t][q]
        e = exp_L if q == "penetration_depth" else exp_D
        rr = [d[s][q] / b[s][q] for s in common[-3:]]
        est[q] = r * pv
        print(f"  {short[q]}: {b[t][q]:.2f} -> {d[t][q]:.2f} mm, ratio {r:.3f} "
              f"(last three outputs {', '.join(f'{x:.3f}' for x in rr)}; median "
              f"{statistics.median(rr):.3f}) -> {r * pv:.1f} mm, "
              f"{(r * pv / e - 1) * 100:+.1f} % of the experiment")
    return t, est


def print_energy(e_rod, est, short):
    """Session 36's bound: the rod's kinetic energy e_rod (J) per unit volume of the
    cavity V = pi (D/2)^2 L, for est's L and each of D_wall and D_wall_mean it has (mm)."""
    L = est["penetration_depth"]
    for q in ("cavity_diameter_wall", "cavity_diameter_wall_mean"):
        if q in est:
            D = est[q]
            ev = e_rod / (math.pi * (D / 2e3) ** 2 * L / 1e3) / 1e9
            print(f"  E/V of the estimated cavity (L {L:.1f} mm, {short[q]} {D:.1f} mm): {ev:.2f} GPa")


def final_of(paths, quantities):
    """The final output of a run read from one or more measurements files: (time in us,
    {quantity: mm}), each quantity from the first file that has it at that file's last
    output (a re-measurement can fill what the run's own file lacks)."""
    res, t = {}, None
    for p in paths:
        d = read(p, quantities)
        t = max(d)
        for q, v in d[t].items():
            res.setdefault(q, v)
    return t, res


def validation_table(path):
    """A validation.csv (hvsph validate) as {case: {quantity: (simulated, experiment,
    paper_simulation)}}, the quantity's name without its ':object' suffix."""
    out = {}
    with open(path) as f:
        for r in csv.DictReader(line for line in f if not line.startswith("#")):
            q = r["quantity"].split(":")[0]
            out.setdefault(r["case"], {})[q] = (float(r["simulated"]), float(r["experiment"]),
                                                float(r["paper_simulation"]))
    return out


def at(d, t, q="penetration_depth"):
    """read()'s d's q at t, linear between the two outputs around t when d has none at t
    (runs that wrote every 20 or 30 us, or stopped between outputs), None outside d's
    outputs."""
    if q in d.get(t, {}):
        return d[t][q]
    ts = sorted(s for s in d if q in d[s])
    for a, b in zip(ts, ts[1:]):
        if a < t < b:
            return d[a][q] + (d[b][q] - d[a][q]) * (t - a) / (b - a)
    return None


def fmt_or_dash(x, fmt="6.1f"):
    """x formatted, or a dash for None (the tables' empty cells)."""
    return format(x, fmt) if x is not None else "     -"


def rod_heading(name, v, val, jc):
    """Prints a rod's heading line from validation_table()'s val and returns (experiment
    L, KERNEL L, experiment D, KERNEL D) in mm; without the run jc (read()'s dict, empty)
    says so and returns None."""
    _, eL, kL = val[name]["penetration_depth"]
    _, eD, kD = val[name]["cavity_diameter"]
    print(f"== {name} ({v} km/s): experiment L {eL} mm, D {eD} mm; KERNEL L {kL}, D {kD}")
    if not jc:
        print("  no JC run at the paper's counts\n")
        return None
    return eL, kL, eD, kD


def jc_rows(case, jc, c03, j03):
    """For each output t > 0 of jc (read()'s dict of a run with another material set)
    yields (t, L of the case at t, L of jc, their ratio, the same ratio of the pair c03,
    j03 at resolution 0.3); case and the pair linear between their outputs (at)."""
    for t in sorted(jc):
        if t == 0:
            continue
        L = jc[t].get("penetration_depth")
        Lc = at(case, t)
        a, b = at(c03, t), at(j03, t)
        yield t, Lc, L, (L / Lc if L and Lc else None), (b / a if a and b else None)
