#!/usr/bin/python3
"""rod-5841 variants of session 28 beside the case: resolution 0.3, a joined 1.0 mm core,
Table 2's materials, to 30 us, session 26's case file
(docs/runs/s26/rod-1929-floor/r41-case-c10.yaml) run with one change each: depth and
crater-floor speed, channel (cavity_diameter_wall_mean / _wall / _mean) at 20 and 30 us.
  kernel/r41-quad   `--set sph.kernel=quadratic`
  cond/r41-cond     `--set sph.conductivity.alpha=1`, built from cond/conductivity.patch
                    and cond/cond.h on hvsph 60e6fb8 (not committed)

Usage: variant.py RUNDIR LABEL [RUNDIR LABEL ...]   (folders relative to this one), e.g.
  variant.py kernel/r41-quad quadratic > kernel/kernel.txt
docs/validation.md ("A Johnson-Cook target steel", its last two paragraphs).
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
S26 = os.path.join(HERE, '..', 's26', 'rod-1929-floor')
sys.path.insert(0, S26)
from floor import depths  # noqa: E402  (the measurements.csv loader)

runs = [(os.path.join(S26, 'r41-case-c10'), 'the case (s26)')]
args = sys.argv[1:]
runs += [(os.path.join(HERE, args[k]), args[k + 1]) for k in range(0, len(args) - 1, 2)]
print("rod-5841 | L 30 us (mm) | u 10-30 | u 20-30 (km/s) | D_wall_mean 20 / 30 | D_wall 20 / 30 |"
      " D_mean 20 / 30 (mm)")
for folder, what in runs:
    L, M = depths(folder, 'penetration_depth'), depths(folder, 'cavity_diameter_wall_mean')
    W, A = depths(folder, 'cavity_diameter_wall'), depths(folder, 'cavity_diameter_mean')
    print(f"{what} | {L[30]:.2f} | {(L[30] - L[10]) / 20:.3f} | {(L[30] - L[20]) / 10:.3f} |"
          f" {M[20]:.2f} / {M[30]:.2f} | {W[20]:.2f} / {W[30]:.2f} | {A[20]:.2f} / {A[30]:.2f}")
