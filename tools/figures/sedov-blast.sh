#!/usr/bin/env bash
# docs/verification.md, Sedov: the point blast at t = 0.05, density, radial velocity
# and pressure against the exact solution. Runs the test verification.test_sedov (its CI
# resolution, 27 000 particles) and draws its profile.
. "$(dirname "$0")/lib/common.sh"
fig_need_python
fig_fresh_work
fig_test sedov
"$PY" tools/figures/plot_verification.py -o "$FIG_TMP" "$FIG_WORK/test_sedov/sedov_profile.csv"
fig_done
