#!/bin/sh
# Session 47: W.P.3 at the paper's counts with session 46's projectile (PROJECTILE_MATCH:
# 4 092 particles, 204 550 in all), hvsph d04f054, 1 thread beside the 2.4 run; stopped
# by SIGINT at the session's end and continued later with
#   ./build/hvsph validate --resume --scale 1 --only wp3 --threads 2 -o out/s47/val-wp3
# From the repository root.
./build/hvsph validate --scale 1 --only wp3 --threads 1 -o out/s47/val-wp3
