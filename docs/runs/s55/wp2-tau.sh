#!/bin/sh
# Session 55: W.P.2 at resolution 0.3 to 120 us, 1 thread each: the paper's rule, and a
# time to failure of 0.3 us on the projectile's aluminium only (a copy of al-alloy,
# "al-proj", given to the projectile body: a probe, not one material set per table).
# Does the delay that doubled §2.4's steel pieces keep W.P.2's projectile in bigger pieces
# and deepen its backwall crater (experiment 6 mm)? From the repository root.
H=${HVSPH:-out/s55/hvsph}
$H validate --scale 0.3 --only wp2 --threads 1 -o out/s55/wp2-rule \
  --set time.end=120us --set output.every=10us > out/s55/wp2-rule.log 2>&1 &
$H validate --scale 0.3 --only wp2 --threads 1 -o out/s55/wp2-tau-0.3 \
  --set time.end=120us --set output.every=10us \
  --set materials.al-proj.library=al-alloy --set materials.al-proj.fracture.model=cumulative \
  --set materials.al-proj.fracture.tau=0.3us --set 'bodies[0].material=al-proj' \
  > out/s55/wp2-tau-0.3.log 2>&1 &
wait
