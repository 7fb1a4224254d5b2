#!/bin/sh
# Session 48: section 2.4 at the paper's counts (session 46's projectile, 398 938
# particles) with fracture.split: crack for both steels, to the hole's time (35 us), beside
# session 47's run with the paper's rule (docs/runs/s47/whipple-steel.sh). 1 thread.
# HVSPH: a build of this session's source. From the repository root.
H=${HVSPH:-./build/hvsph}
$H validate --scale 1 --only whipple-steel --threads 1 -o out/s48/val-ws-crack \
  --set 'materials.steel-bumper.library=steel-bumper' --set 'materials.steel-bumper.fracture.split=crack' \
  --set 'materials.steel-projectile.library=steel-projectile' --set 'materials.steel-projectile.fracture.split=crack'
