#!/usr/bin/env bash
# docs/validation.md, the rods: penetration depth and cavity diameter of the six long-rod
# tests (the paper's Tables 1-3) over impact speed, hvsph beside the experiments and
# KERNEL. Made from the six runs of `hvsph validate --scale 1 --only rod-1929 rod-5835
# rod-5839 rod-5841 rod-5842 rod-5844` (the paper's particle counts): `hvsph validate
# --no-run` tabulates them in the scratch folder $WORK/rods-depth (default
# out/figures/rods-depth) and plot_rods.py draws the table.
#
# Environment: HVSPH (the hvsph binary, default build/hvsph), RUNS (the folder of
# `hvsph validate` run folders, default out/validation), OUT (default docs/img), PY (the
# Python with matplotlib, default /usr/bin/python3: tools/install-deps.sh --docs);
# relative paths are taken from the directory the script is started in. Writes
# $OUT/rods-depth.png; with a rod's run folder missing or not run to its end it says
# "skip: ..." and exits 0.
. "$(dirname "$0")/lib/common.sh"
rods="rod-1929 rod-5835 rod-5839 rod-5841 rod-5842 rod-5844"
# shellcheck disable=SC2086  # $rods is a list of names
fig_need_done $rods
fig_need_hvsph
fig_need_python
plot=$ROOT/tools/figures/plot_rods.py
fig_fresh_work
# the rods' folders seen from the scratch folder, so that the table --no-run writes
# there leaves $RUNS/validation.md and .csv as they are
for case in $rods; do ln -s "$RUNS/$case" "$FIG_WORK/$case"; done
# shellcheck disable=SC2086
"$HVSPH" validate --no-run --only $rods -o "$FIG_WORK" > "$FIG_WORK/validate.log" 2>&1 ||
  { cat "$FIG_WORK/validate.log" >&2; exit 1; }
"$PY" "$plot" "$FIG_WORK/validation.csv" --label "hvsph (paper's counts)" -o "$FIG_TMP"
echo "$FIG_NAME: from $RUNS/{$(echo "$rods" | tr ' ' ,)}"
fig_done
