#!/usr/bin/env bash
# docs/validation.md, W.P.2: the simulated flash radiograph at the case's end, 250 µs
# (areal density along z, mirrored across the symmetry plane), as validate's final.png.
# Made from the final snapshot of `hvsph validate --scale 1 --only wp2` (the paper's
# particle counts) by `hvsph render`.
#
# Environment: HVSPH (the hvsph binary, default build/hvsph), RUNS (the folder of
# `hvsph validate` run folders, default out/validation), OUT (default docs/img); relative
# paths are taken from the directory the script is started in. Writes $OUT/wp2-250us.png;
# without the run folder $RUNS/wp2, or with a run that has not reached the case's end, it
# says "skip: ..." and exits 0.
. "$(dirname "$0")/lib/common.sh"
fig_render_last wp2 --mode radiograph --axis z --size 900
