#!/bin/sh
# Session 41: the 1.29 km/s stagnation flow without strength, with one material on both
# sides (tungsten into tungsten, steel into steel), beside session 26's tungsten into
# steel (../../s26/rod-1929-floor/fluid-c10, the same case file). hvsph 5dca9aa,
# 1 thread each, both at once. Run from the repository root after `make build`.
set -e
Y=docs/runs/s26/rod-1929-floor/r29-fluid-c10.yaml
build/hvsph run $Y -o out/s41/ww --material st0=w0 --threads 1 &
build/hvsph run $Y -o out/s41/ss --material w0=st0 --threads 1 &
wait
