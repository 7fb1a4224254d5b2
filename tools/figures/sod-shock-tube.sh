#!/usr/bin/env bash
# docs/verification.md, Sod: the shock tube at t = 0.2, particles against the exact
# solution (density, velocity, pressure). Runs the test verification.test_sod (its CI
# resolution, 28 800 particles; well under a minute on 2 threads) and draws its profile.
. "$(dirname "$0")/lib/common.sh"
fig_need_python
fig_fresh_work
fig_test sod
"$PY" tools/figures/plot_verification.py -o "$FIG_TMP" "$FIG_WORK/test_sod/sod_profile.csv"
fig_done
