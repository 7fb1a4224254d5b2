#!/bin/sh
# Session 54: session 53's ws-frag.sh with the two rules side by side (1 thread each).
# Does the crack model (fracture.split: crack) keep §2.4's projectile in bigger pieces
# than the paper's rule? §2.4 at resolution 0.3 to 10 us. From the repository root.
H=${HVSPH:-out/s54/hvsph}
$H validate --scale 0.3 --only whipple-steel --threads 1 -o out/s54/frag-rule \
  --set time.end=10us --set output.every=2.5us > out/s54/frag-rule.log 2>&1 &
$H validate --scale 0.3 --only whipple-steel --threads 1 -o out/s54/frag-crack \
  --set time.end=10us --set output.every=2.5us \
  --set 'materials.steel-bumper.library=steel-bumper' --set 'materials.steel-bumper.fracture.split=crack' \
  --set 'materials.steel-projectile.library=steel-projectile' --set 'materials.steel-projectile.fracture.split=crack' \
  > out/s54/frag-crack.log 2>&1 &
wait
