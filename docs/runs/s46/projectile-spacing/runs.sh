#!/bin/sh
# Session 46: the projectile's lattice against the plate's refined disc. Session 33's
# short bumper cases (the sphere and the first plate, to 12 us, holes every us) with the
# projectile's particle count raised so that its spacing equals the disc's: section 2.4
# 0.355 -> 0.2 mm (1 000 -> 5 625 particles in the half model), W.P.3 0.203 -> 0.16 mm
# (2 000 -> 4 092). hvsph 9912acb, 1 thread each, two at a time.
# Usage: sh runs.sh LANE   (a: the two finer projectiles)
set -e
H=${HVSPH:-../../../../build/hvsph}
S33=../../s33
if [ "$1" = a ]; then
  $H run $S33/ws-bumper-fracture/ws-base.yaml -o ws-p02 --threads 1 --quiet \
     --set 'bodies[0].particles=5625' > ws-p02.log 2>&1 &
  $H run $S33/al-bumper-fracture/wp3-base.yaml -o wp3-p016 --threads 1 --quiet \
     --set 'bodies[0].particles=4092' > wp3-p016.log 2>&1 &
  wait
fi
# lane b: W.P.2's sphere and bumper (wp2-base.yaml) as it is and with the projectile at
# the disc's 0.4 mm (2 000 -> 4 091); lane c: finer still, W.P.1's projectile at 0.2 mm
# (2 000 -> 4 090; its disc is 0.3 mm) and section 2.4's at 0.16 mm (1 000 -> 10 990).
if [ "$1" = b ]; then
  $H run wp2-base.yaml -o wp2-base --threads 1 --quiet > wp2-base.log 2>&1 &
  $H run wp2-base.yaml -o wp2-p04 --threads 1 --quiet \
     --set 'bodies[0].particles=4091' > wp2-p04.log 2>&1 &
  wait
elif [ "$1" = c ]; then
  $H run $S33/al-bumper-fracture/wp1-base.yaml -o wp1-p02 --threads 1 --quiet \
     --set 'bodies[0].particles=4090' > wp1-p02.log 2>&1 &
  $H run $S33/ws-bumper-fracture/ws-base.yaml -o ws-p016 --threads 1 --quiet \
     --set 'bodies[0].particles=10990' > ws-p016.log 2>&1 &
  wait
fi
