#!/bin/sh
# Prepared in session 53, not yet run (about 40 min per rule on 1 thread, an estimate from
# its first 100 steps): does the crack model (fracture.split: crack) keep §2.4's projectile in
# bigger pieces than the paper's rule? §2.4 at resolution 0.3 to 10 us, both rules,
# 1 thread each. From the repository root.
H=${HVSPH:-./build/hvsph}
$H validate --scale 0.3 --only whipple-steel --threads 1 -o out/s53/frag-rule \
  --set time.end=10us --set output.every=2.5us
$H validate --scale 0.3 --only whipple-steel --threads 1 -o out/s53/frag-crack \
  --set time.end=10us --set output.every=2.5us \
  --set 'materials.steel-bumper.library=steel-bumper' --set 'materials.steel-bumper.fracture.split=crack' \
  --set 'materials.steel-projectile.library=steel-projectile' --set 'materials.steel-projectile.fracture.split=crack'
