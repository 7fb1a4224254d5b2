#!/bin/sh
# Session 48: continue session 47's W.P.3 run at the paper's counts (session 46's
# projectile, 204 550 particles; stopped at 18.66 us) towards 60 us, 1 thread beside
# the W.P.2 run (wp2.sh). From the repository root.
./build/hvsph validate --resume --scale 1 --only wp3 --threads 1 -o out/s47/val-wp3
