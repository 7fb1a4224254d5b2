#!/bin/sh
# Session 46, lane e: W.P.2's bumper disc at 7 layers (0.286 mm) with the projectile at
# the same spacing (2 000 -> 11 226), to 12 us: lane d's question for W.P.2.
# hvsph 9912acb, 1 thread.
set -e
H=${HVSPH:-../../../../build/hvsph}
$H run wp2-base.yaml -o wp2-l7p0286 --threads 1 --quiet \
   --set 'bodies[0].particles=11226' --set 'bodies[2].particles=67360' > wp2-l7p0286.log 2>&1
