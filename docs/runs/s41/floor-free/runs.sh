#!/bin/sh
# Session 41: the wide free tungsten target at 1.29 km/s (free129.yaml), the standard
# viscosity of the cases (alpha = 1, beta = 2, reconstruction) and alpha = 0.2, beta = 0.4.
# 1 thread each, both at once, from the repository root after `make build`.
set -e
Y=docs/runs/s41/floor-free/free129.yaml
build/hvsph run $Y -o out/s41/free-a1 --threads 1 &
build/hvsph run $Y -o out/s41/free-a02 --threads 1 --set sph.viscosity.alpha=0.2 --set sph.viscosity.beta=0.4 &
wait
