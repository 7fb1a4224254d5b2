#!/usr/bin/env bash
# docs/verification-solids.md §5: spall in an al-alloy flyer-plate impact (100 and
# 50 m/s). Runs the test verification.test_spall and draws its snapshots.
. "$(dirname "$0")/lib/common.sh"
fig_need_python
fig_fresh_work
fig_test spall
"$PY" tools/figures/plot_solids.py spall --tmp "$FIG_WORK" -o "$FIG_TMP"
fig_done
