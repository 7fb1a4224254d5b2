#!/bin/sh
# Session 48: W.P.2 at the paper's counts with session 46's projectile (PROJECTILE_MATCH),
# 1 thread beside the W.P.3 run (wp3-resume.sh); to be continued with
#   ./build/hvsph validate --resume --scale 1 --only wp2 --threads 2 -o out/s48/val-wp2
# From the repository root.
./build/hvsph validate --scale 1 --only wp2 --threads 1 -o out/s48/val-wp2
