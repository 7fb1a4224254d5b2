#!/usr/bin/env bash
# docs/verification-solids.md §4: the copper Taylor bar's final shape. Runs the test
# verification.test_taylor and draws its snapshots.
. "$(dirname "$0")/lib/common.sh"
fig_need_python
fig_fresh_work
fig_test taylor
"$PY" tools/figures/plot_solids.py taylor --tmp "$FIG_WORK" -o "$FIG_TMP"
fig_done
