#!/usr/bin/env bash
# docs/verification-solids.md §12: distended aluminium on a solid plate at 7 km/s, the
# plate's pressure and the momentum it gains against the porous Hugoniot (three runs).
# Runs the test verification.test_porous_impact and draws its snapshots.
. "$(dirname "$0")/lib/common.sh"
fig_need_python
fig_fresh_work
fig_test porous_impact
"$PY" tools/figures/plot_solids.py porous_impact --tmp "$FIG_WORK" -o "$FIG_TMP"
fig_done
