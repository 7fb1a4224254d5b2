#!/usr/bin/env bash
# docs/verification-solids.md §2: the elastic wave in al-alloy and its speed. Runs the
# test verification.test_elastic_wave and draws its snapshots.
. "$(dirname "$0")/lib/common.sh"
fig_need_python
fig_fresh_work
fig_test elastic_wave
"$PY" tools/figures/plot_solids.py elastic_wave --tmp "$FIG_WORK" -o "$FIG_TMP"
fig_done
