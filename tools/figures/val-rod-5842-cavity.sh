#!/usr/bin/env bash
# docs/validation.md, rod-5842: the cavity at the case's end, 135 µs, cut through the
# symmetry plane (a 1.5 mm slab), coloured by material.
# Made from the final snapshot of `hvsph validate --scale 1 --only rod-5842` (the paper's
# particle counts) by `hvsph render`.
#
# Environment: HVSPH (the hvsph binary, default build/hvsph), RUNS (the folder of
# `hvsph validate` run folders, default out/validation), OUT (default docs/img); relative
# paths are taken from the directory the script is started in. Writes $OUT/rod-5842-cavity.png;
# without the run folder $RUNS/rod-5842, or with a run that has not reached the case's end, it
# says "skip: ..." and exits 0.
. "$(dirname "$0")/lib/common.sh"
fig_render_last rod-5842 --mode particles --axis z --box -70mm,230mm,-50mm,50mm,0,1.5mm
