#!/bin/sh
# Session 55: §2.4 at resolution 0.3 with a time to failure on the projectile's steel only
# (fracture.model: cumulative, tau, at Table 5's sigma_c; the bumper and backwall keep the
# paper's rule), tau = 0.3 and 1 us, to 40 us, 1 thread each. A probe: does a delay before
# the split (as a crack's growth or a fracture energy would give) keep the projectile in
# pieces between the paper's rule's (0.5-0.7 mm) and the crack model's (2.7-3.4 mm)?
# From the repository root.
H=${HVSPH:-out/s55/hvsph}
for tau in 0.3 1; do
  $H validate --scale 0.3 --only whipple-steel --threads 1 -o out/s55/tau-$tau \
    --set time.end=40us --set output.every=5us \
    --set materials.steel-projectile.library=steel-projectile \
    --set materials.steel-projectile.fracture.model=cumulative \
    --set materials.steel-projectile.fracture.tau=${tau}us > out/s55/tau-$tau.log 2>&1 &
done
wait
