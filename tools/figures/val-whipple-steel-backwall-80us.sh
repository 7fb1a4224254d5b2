#!/usr/bin/env bash
# docs/validation.md, §2.4: the aluminium backwall at the case's end, 80 µs, cut at
# z = 0 (a 1 mm slab; x from 190 to 215 mm, y within 60 mm of the axis), coloured by material.
# Made from the final snapshot of `hvsph validate --scale 1 --only whipple-steel` (the paper's
# particle counts) by `hvsph render`.
#
# Environment: HVSPH (the hvsph binary, default build/hvsph), RUNS (the folder of
# `hvsph validate` run folders, default out/validation), OUT (default docs/img); relative
# paths are taken from the directory the script is started in. Writes $OUT/whipple-steel-backwall-80us.png;
# without the run folder $RUNS/whipple-steel, or with a run that has not reached the case's end, it
# says "skip: ..." and exits 0.
. "$(dirname "$0")/lib/common.sh"
fig_render_last whipple-steel --mode particles --axis z --box 190mm,215mm,-60mm,60mm,0,1mm --size 1000
