#!/bin/sh
# Session 42: variants of session 41's half-model free test at 4.46 km/s (free446-a1:
# symc-free.yaml with a measure section); 2 threads each, one after the other. First the
# Grueneisen coefficient set to 0: p = p_c(rho), a barotropic (cold) tungsten, so that
# heat (the impact's shock heating, wall heating at the contact) carries no pressure; a
# steady floor still moves at v/2 exactly.
set -e
S=docs/runs/s15/rod-symmetric-free/symc-free.yaml; M='measure.thick_target=[core, mid, outer]'
build/hvsph run $S -o out/s42/half-g0 --threads 2 --set "$M" --set output.csv=false \
  --set materials.w0.gamma=0
# (The same at 0.5 mm was stopped after its first minutes: at 0.7 mm the cold tungsten's
# floor was the case's to 0.1 mm at every output.)
# Then the rod and the core at different spacings: which of the two makes 0.5 mm slower?
build/hvsph run $S -o out/s42/half-r05-c07 --threads 2 --set "$M" --set output.csv=false \
  --set 'bodies[0].spacing=0.5 mm'
build/hvsph run $S -o out/s42/half-r07-c05 --threads 2 --set "$M" --set output.csv=false \
  --set 'bodies[1].spacing=0.5 mm'
# The rod's spacing alone, in the 0.7 mm core: 1.0 and 0.35 mm.
build/hvsph run $S -o out/s42/half-r10-c07 --threads 2 --set "$M" --set output.csv=false \
  --set 'bodies[0].spacing=1.0 mm'
build/hvsph run $S -o out/s42/half-r035-c07 --threads 2 --set "$M" --set output.csv=false \
  --set 'bodies[0].spacing=0.35 mm'
# Last, a test of the cross-section order: two rod spacings near 0.7 mm whose lattices
# cover 0.93 and 1.119 times the rod's cross-section (0.62 and 0.68 mm), 1 thread each,
# both at once:
build/hvsph run $S -o out/s42/half-r062-c07 --threads 1 --set "$M" --set output.csv=false \
  --set 'bodies[0].spacing=0.62 mm' &
build/hvsph run $S -o out/s42/half-r068-c07 --threads 1 --set "$M" --set output.csv=false \
  --set 'bodies[0].spacing=0.68 mm' &
wait
