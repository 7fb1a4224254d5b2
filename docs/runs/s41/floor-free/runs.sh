#!/bin/sh
# Session 41: the wide free tungsten target at 1.29 km/s (free129.yaml), the standard
# viscosity of the cases (alpha = 1, beta = 2, reconstruction) and alpha = 0.2, beta = 0.4.
# 1 thread each, both at once, from the repository root after `make build`.
set -e
Y=docs/runs/s41/floor-free/free129.yaml
build/hvsph run $Y -o out/s41/free-a1 --threads 1 &
build/hvsph run $Y -o out/s41/free-a02 --threads 1 --set sph.viscosity.alpha=0.2 --set sph.viscosity.beta=0.4 &
wait
# Then: the switch at 1.29 km/s, and session 15's 4.46 km/s free test with alpha = 0.2 and
# alpha = 1 (its measure section added), one after another beside each other:
#   build/hvsph run docs/runs/s41/floor-free/free129.yaml -o out/s41/free-cd --threads 1 \
#     --set sph.viscosity.switch=cullen-dehnen --set sph.viscosity.alpha_min=0.1 --set sph.skip_resting=false
#   S=docs/runs/s15/rod-symmetric-free/symc-free.yaml; M='measure.thick_target=[core, mid, outer]'
#   build/hvsph run $S -o out/s41/free446-a02 --threads 1 --set "$M" --set output.csv=false \
#     --set sph.viscosity.alpha=0.2 --set sph.viscosity.beta=0.4
#   build/hvsph run $S -o out/s41/free446-a1 --threads 1 --set "$M" --set output.csv=false
