#!/usr/bin/env bash
# docs/verification.md, Noh: the spherical implosion at t = 0.6 at the test's two
# spacings (0.025 and 0.02), density and radial velocity against the exact solution.
# Runs the test verification.test_noh (about a minute on 2 threads) and draws its two
# profiles.
. "$(dirname "$0")/lib/common.sh"
fig_need_python
fig_fresh_work
fig_test noh
"$PY" tools/figures/plot_verification.py -o "$FIG_TMP" \
  "$FIG_WORK/test_noh/noh_profile.csv" "$FIG_WORK/test_noh/noh_fine_profile.csv"
fig_done
