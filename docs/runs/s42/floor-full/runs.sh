#!/bin/sh
# Session 42: session 15's free symmetric test at 4.46 km/s (tungsten into tungsten without
# strength) as a full model, on the cubic lattice and with rod and core on an hcp lattice;
# 2 threads each, one after the other, from the repository root after `make build`.
# The half model it is compared with is session 41's free446-a1 (docs/runs/s41/floor-free).
set -e
D=docs/runs/s42/floor-full
build/hvsph run $D/symc-free-full.yaml -o out/s42/full-cubic --threads 2
build/hvsph run $D/symc-free-full-hcp.yaml -o out/s42/full-hcp --threads 2
