#!/bin/sh
# Session 56: W.P.1 with the face in front of the bumper (x = -50 mm) a rigid wall (the
# case) and absorbing, at resolution 0.2 to 50 us, 1 thread each, side by side: does the
# back-splash coming back off the wall move the bumper hole?
H=${HVSPH:-out/s56/hvsph}
$H run examples/paper/wp1.yaml -o out/s56/wp1-wall --set resolution=0.2 --set time.end=50us \
  --set output.every=5us --threads 1 --quiet > out/s56/wp1-wall.log 2>&1 &
$H run examples/paper/wp1.yaml -o out/s56/wp1-abs --set resolution=0.2 --set time.end=50us \
  --set output.every=5us --set domain.boundary.x_min=absorbing --threads 1 --quiet > out/s56/wp1-abs.log 2>&1 &
wait
