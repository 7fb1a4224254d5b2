"""Reads a run's measurements.csv (docs/output-files.md) for the analysis scripts of
docs/runs: read(path, quantities) -> {time in us (rounded to 1e-3): {quantity: value x
scale}} for the rows whose quantity is one of `quantities` (scale 1e3: metres to mm).
A missing file gives {}."""
import csv
import os


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
