#!/bin/sh
# Session 42: session 15's free symmetric test at 4.46 km/s (tungsten into tungsten without
# strength) with the wide core at 0.5 mm; as a full model, on the cubic lattice and with
# rod and core on an hcp lattice; and with half the Courant number. 2 threads each, one
# after the other, from the repository root after `make build`. Compared with session
# 41's half models free446-a1 and free446-wide (docs/runs/s41/floor-free); full.py.
set -e
D=docs/runs/s42/floor-full
# First (it ran alone, before the others): session 41's +-20 mm core (the whole crater in
# the fine lattice) with rod and core at 0.5 mm instead of 0.7, 485 232 particles:
build/hvsph run docs/runs/s41/floor-free/symc-free-wide.yaml -o out/s42/free446-wide-h05 \
  --threads 2 --set 'bodies[0].spacing=0.5 mm' --set 'bodies[1].spacing=0.5 mm'
build/hvsph run $D/symc-free-full.yaml -o out/s42/full-cubic --threads 2
build/hvsph run $D/symc-free-full-hcp.yaml -o out/s42/full-hcp --threads 2
# Then the half model of session 41 (free446-a1: symc-free.yaml with a measure section)
# with half the Courant number, twice the steps:
S=docs/runs/s15/rod-symmetric-free/symc-free.yaml; M='measure.thick_target=[core, mid, outer]'
build/hvsph run $S -o out/s42/half-cfl015 --threads 2 --set "$M" --set output.csv=false \
  --set time.cfl=0.15
