#!/usr/bin/env bash
# docs/verification-solids.md §3: the colliding rubber rings (three runs: eps = 0.3,
# 0 and 0.6; the longest test of the set, two to three minutes). Runs the test
# verification.test_rings and draws its snapshots.
. "$(dirname "$0")/lib/common.sh"
fig_need_python
fig_fresh_work
fig_test rings
"$PY" tools/figures/plot_solids.py rings --tmp "$FIG_WORK" -o "$FIG_TMP"
fig_done
