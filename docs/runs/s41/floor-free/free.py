#!/usr/bin/python3
"""The wide free symmetric test (session 41): tungsten into tungsten without strength,
where the floor of a steady penetration moves at v/2 exactly; at 1.29 km/s
(free129.yaml, L every 5 us) and at session 15's 4.46 km/s (its symc-free.yaml with a
measure section, L every 2.5 us). Mean floor speed (penetration depth L of
measurements.csv) over the intervals below, for each run whose outputs reach them: the
difference of L at the two ends, then the least-squares slope over every output within
the interval (at least three).

Usage: free.py   (in this folder; writes free.txt). docs/validation.md, session 41.
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', '..', '..', '..', 'tools'))
import meas_csv  # noqa: E402

RUNS = [  # folder, v (km/s), what
    ('free-a1', 1.29, 'alpha = 1, beta = 2 (the cases), 0.7 mm'),
    ('free-a02', 1.29, 'alpha = 0.2, beta = 0.4, 0.7 mm'),
    ('free-cd', 1.29, 'the switch (cullen-dehnen, alpha_min = 0.1), 0.7 mm'),
    ('free-a0', 1.29, 'no artificial viscosity, 0.7 mm (lent machine, stopped at 23.6 us)'),
    ('free-h05', 1.29, 'alpha = 1, rod and core 0.5 mm (lent machine, stopped at 17.6 us)'),
    ('free446-a1', 4.46, '4.46 km/s, alpha = 1, beta = 2, 0.7 mm'),
    ('free446-a02', 4.46, '4.46 km/s, alpha = 0.2, beta = 0.4, 0.7 mm'),
    ('free446-h05', 4.46, '4.46 km/s, alpha = 1, beta = 2, rod and core 0.5 mm'),
    ('free446-j07', 4.46, '4.46 km/s, alpha = 1, 0.7 mm, the blocks joined to the core'),
    ('free446-j05', 4.46, '4.46 km/s, alpha = 1, rod and core 0.5 mm, the blocks joined'),
    ('free446-wide', 4.46, '4.46 km/s, alpha = 1, 0.7 mm, the core +-20 mm (symc-free-wide.yaml)'),
]
SPANS = [(5, 15), (5, 20), (10, 20), (10, 30), (20, 30), (30, 50), (40, 50), (40, 60), (30, 60)]


def fit(L, a, b):
    """Least-squares slope of L over the outputs with a <= t <= b; None unless the run
    has outputs at a and b and at least three in all."""
    if a not in L or b not in L:
        return None
    pts = [(t, x) for t, x in L.items() if a - 1e-6 <= t <= b + 1e-6]
    if len(pts) < 3:
        return None
    mt = sum(t for t, _ in pts) / len(pts)
    mx = sum(x for _, x in pts) / len(pts)
    return (sum((t - mt) * (x - mx) for t, x in pts) /
            sum((t - mt) ** 2 for t, _ in pts))


def cell(u, v):
    """A speed u (km/s) and its deficit against v/2, for the tables; '-' for None."""
    return '-' if u is None else f'{u:.3f} ({100 * (u / (v / 2) - 1):+.1f}%)'


def speed_tables(runs, spans, times):
    """The two tables of a set of runs: for each (folder, v km/s, what) of runs whose
    measurements.csv has L, a row of L at `times` and the end-point speeds over `spans`,
    and a row of the least-squares slopes over them; returns (header and rows, header
    and rows of the slopes)."""
    head = ' | '.join(f'u {a}-{b} us' for a, b in spans)
    at = ' / '.join(f'{t:g}' for t in times)
    lines = [f'run | L at {at} us (mm) | {head} (km/s; in brackets u / (v/2) - 1)']
    fits = [f'least-squares slopes | {head}']
    for folder, v, what in runs:
        L = meas_csv.series(os.path.join(folder, 'measurements.csv'), 'penetration_depth')
        if not L:
            continue
        ends = [(L[b] - L[a]) / (b - a) if a in L and b in L else None for a, b in spans]
        ls = ' / '.join(f'{L[t]:.2f}' if t in L else '-' for t in times)
        lines.append(f'{what} | {ls} | ' + ' | '.join(cell(u, v) for u in ends))
        fits.append(f'{what} | ' + ' | '.join(cell(fit(L, a, b), v) for a, b in spans))
    return lines, fits


def main():
    lines, fits = speed_tables([(os.path.join(HERE, f), v, w) for f, v, w in RUNS], SPANS,
                               (10, 20, 30, 50))
    meas_csv.emit(os.path.join(HERE, 'free.txt'), lines + [''] + fits)


if __name__ == '__main__':
    main()
