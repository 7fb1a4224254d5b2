#!/usr/bin/env bash
# docs/validation.md, the gas-filled vessel (§3): the nitrogen's density in the symmetry
# plane with the debris on it at 10, 20, 30 and 40 µs, as the paper's Fig. 3. Made from
# the run of `hvsph validate --scale 1 --only vessel` (the paper's particle counts) by
# plot_vessel.py, which also prints the shock front's and the debris's table.
#
# Environment: HVSPH (unused here; for the same interface as the other figure scripts),
# RUNS (the folder of `hvsph validate` run folders, default out/validation), OUT
# (default docs/img), PY (the Python with matplotlib, default /usr/bin/python3:
# tools/install-deps.sh --docs); relative paths are taken from the directory the script
# is started in. Writes $OUT/vessel-gas-40us.png; without the run folder $RUNS/vessel, or
# with a run that has not reached the case's end, it says "skip: ..." and exits 0.
. "$(dirname "$0")/lib/common.sh"
fig_need_done vessel
fig_need_python
"$PY" "$ROOT/tools/figures/plot_vessel.py" "$RUNS/vessel" -o "$FIG_TMP" --times 10,20,30,40
echo "$FIG_NAME: from $RUNS/vessel"
fig_done
