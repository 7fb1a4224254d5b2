#!/usr/bin/env bash
# docs/validation.md, Table 4: the simulated flash radiograph of bumper-20 at t_x = 49.5 µs
# (areal density along z, mirrored across the symmetry plane), as validate's final.png.
# Made from the final snapshot of `hvsph validate --scale 1 --only bumper-20` (the paper's
# particle counts) by `hvsph render`.
#
# Environment: HVSPH (the hvsph binary, default build/hvsph), RUNS (the folder of
# `hvsph validate` run folders, default out/validation), OUT (default docs/img); relative
# paths are taken from the directory the script is started in. Writes $OUT/bumper-20-50us.png;
# without the run folder $RUNS/bumper-20, or with a run that has not reached the case's end, it
# says "skip: ..." and exits 0.
. "$(dirname "$0")/lib/common.sh"
fig_render_last bumper-20 --mode radiograph --axis z --size 900
