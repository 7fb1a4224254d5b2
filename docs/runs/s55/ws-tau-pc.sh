#!/bin/sh
# Session 55: §2.4 at the paper's counts (resolution 1, 398 938 particles) with ws-tau.sh's
# time to failure of 0.3 us on the projectile's steel, to 20 us, 1 thread: is the piece
# the delay keeps at 10 us (res 0.3: 291 mg) and its break-up by 20 us (pieces of 1.1-2.3
# mm) the lattice's or the delay's? From the repository root.
H=${HVSPH:-out/s55/hvsph}
$H validate --scale 1 --only whipple-steel --threads 1 -o out/s55/tau-0.3-pc \
  --set time.end=20us --set output.every=5us \
  --set materials.steel-projectile.library=steel-projectile \
  --set materials.steel-projectile.fracture.model=cumulative \
  --set materials.steel-projectile.fracture.tau=0.3us > out/s55/tau-0.3-pc.log 2>&1
