#!/usr/bin/env bash
# docs/verification-solids.md §1: the planar shock in al-alloy against the
# Rankine-Hugoniot solution. Runs the test verification.test_hugoniot and draws its
# snapshots (tools/figures/plot_solids.py).
. "$(dirname "$0")/lib/common.sh"
fig_need_python
fig_fresh_work
fig_test hugoniot
"$PY" tools/figures/plot_solids.py hugoniot --tmp "$FIG_WORK" -o "$FIG_TMP"
fig_done
