#!/bin/sh
# Session 46, lane d: section 2.4's bumper disc at 7 layers (0.143 mm) with the projectile
# at the same spacing (1 000 -> 15 434), to 12 us: does the hole converge when both are
# refined together? hvsph 9912acb, 1 thread.
set -e
H=${HVSPH:-../../../../build/hvsph}
$H run ../../s33/ws-bumper-fracture/ws-base.yaml -o ws-l7p0143 --threads 1 --quiet \
   --set 'bodies[0].particles=15434' --set 'bodies[2].particles=83290' > ws-l7p0143.log 2>&1
