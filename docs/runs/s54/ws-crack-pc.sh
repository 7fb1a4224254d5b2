#!/bin/sh
# Session 54: §2.4 at the paper's counts with the crack model on Table 5's steels, to 10 us
# (the projectile's pieces against session 52's run with the paper's rule, out/s52/val-ws).
# From the repository root; THREADS=1 or 2.
H=${HVSPH:-out/s54/hvsph}
$H validate --scale 1 --only whipple-steel --threads ${THREADS:-1} -o out/s54/pc-crack \
  --set time.end=10us --set output.every=2.5us \
  --set 'materials.steel-bumper.library=steel-bumper' --set 'materials.steel-bumper.fracture.split=crack' \
  --set 'materials.steel-projectile.library=steel-projectile' --set 'materials.steel-projectile.fracture.split=crack' \
  > out/s54/pc-crack.log 2>&1
