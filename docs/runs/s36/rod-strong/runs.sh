#!/bin/sh
# Session 36: the three resolution-0.3 rod cases (1.0 mm core; sessions 26, 32) with the
# target's yield at 1.17 GPa (3 x Table 2's, no fracture, as session 34's y3-41 at
# 2.37 km/s), with the cases' viscosity and with alpha = 0.2, beta = 0.4; to 30 us,
# 1 thread each, two at a time. Does a steel strong enough for the experiments'
# cavities (bound.txt: Y ~ 0.8-2.6 GPa) give hvsph their depths and widths?
set -e
H=${HVSPH:-hvsph}
E=../../s32/rod-erode
run() {  # name case alpha beta
  $H run $E/$2 -o $1 --threads 1 --set time.end=30us --set output.every=5us \
    --set "materials.st={library: steel-target, strength: {yield: 1.17 GPa}, fracture: {model: none}}" \
    --set 'bodies[1].material=st' --set 'bodies[2].material=st' \
    --set sph.viscosity.alpha=$3 --set sph.viscosity.beta=$4
}
run y3-29 r29-case-c10.yaml 1 2 & run y3a-29 r29-case-c10.yaml 0.2 0.4; wait
run y3a-41 r41-case-c10.yaml 0.2 0.4 & run y3-44 r44-core.yaml 1 2; wait
run y3a-44 r44-core.yaml 0.2 0.4
# ... and with the stronger steel failing on its plastic strain (the paper's
# "deformation criterion", session 33's cumulative model with eps_f = 1, no tensile
# criterion) instead of never, alpha = 0.2
runf() {  # name case
  $H run $E/$2 -o $1 --threads 1 --set time.end=30us --set output.every=5us \
    --set "materials.st={library: steel-target, strength: {yield: 1.17 GPa}, fracture: {model: cumulative, sigma_c: 0, eps_f: 1}}" \
    --set 'bodies[1].material=st' --set 'bodies[2].material=st' \
    --set sph.viscosity.alpha=0.2 --set sph.viscosity.beta=0.4
}
runf y3af-29 r29-case-c10.yaml & runf y3af-41 r41-case-c10.yaml; wait
runf y3af-44 r44-core.yaml
