#!/bin/sh
# Session 36: is the paper's agreement on the rods a viscosity's resistance that falls
# with speed? The standard (unreconstructed) viscosity with its linear term only
# (alpha = 1, beta = 0) and with the standard pair (alpha = 1, beta = 2), on the three
# resolution-0.3 rod cases with a 1.0 mm core (sessions 26, 32), to 30 us, 1 thread each,
# two at a time. Baselines (the cases' reconstruction, alpha = 1, beta = 2):
# ../../s26/rod-1929-floor/case-c10, ../../s32/rod-erode/base, ../../s32/rod-erode/b44.
set -e
H=${HVSPH:-hvsph}
E=../../s32/rod-erode
run() {  # name case alpha beta
  $H run $E/$2 -o $1 --threads 1 --set time.end=30us --set output.every=5us \
    --set sph.viscosity.reconstruct=false --set sph.viscosity.alpha=$3 --set sph.viscosity.beta=$4
}
run lin29 r29-case-c10.yaml 1 0 & run lin41 r41-case-c10.yaml 1 0; wait
run std29 r29-case-c10.yaml 1 2 & run std41 r41-case-c10.yaml 1 2; wait
run lin44 r44-core.yaml 1 0 & run std44 r44-core.yaml 1 2; wait
