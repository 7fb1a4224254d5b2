#!/bin/sh
# Session 47: Table 4's bumper-3 with session 46's projectile (PROJECTILE_MATCH: 9 873
# particles), hvsph d04f054, 1 thread beside the W.P.3 bumper study. From the repository
# root. (bumper-17, stopped at 7.06 us in session 46, is continued with
#   ./build/hvsph validate --resume --scale 1 --only bumper-17 --threads 1 -o out/s46/val-t4
# and was not in this session: 2.4 had the core.)
set -e
./build/hvsph validate --scale 1 --only bumper-3 --threads 1 -o out/s46/val-t4
