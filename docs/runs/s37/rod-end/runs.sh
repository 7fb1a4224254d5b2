#!/bin/sh
# Session 37: rod-5841, rod-1929 and rod-5844 at resolution 0.3 to their ends, 1 thread each, two at once
# on the 2-core machine (hvsph f5805f4).  Run from a scratch folder; then copy the small
# outputs (measurements.csv, summary.csv, used_parameters.yaml, the logs) here and run
# /usr/bin/python3 rods.py > rods.txt
H=../../build/hvsph
C=../../examples/paper/rod-5841.yaml
$H run $C -o case03 --set resolution=0.3 --set output.every=30us --threads 1 --quiet \
  > case03.log 2>&1 &
$H run $C -o jc02 --set resolution=0.3 --set output.every=30us --threads 1 --quiet \
  --set "materials.st={library: steel-target-jc}" --set 'bodies[1].material=st' \
  --set sph.viscosity.alpha=0.2 --set sph.viscosity.beta=0.4 > jc02.log 2>&1 &
wait
# rod-1929 to 260 us (its floor stops by 220 us), the same pair, output every 20 us
C=../../examples/paper/rod-1929.yaml
$H run $C -o c29case --set resolution=0.3 --set output.every=20us --set time.end=260us \
  --threads 1 --quiet > c29case.log 2>&1 &
$H run $C -o c29jc --set resolution=0.3 --set output.every=20us --set time.end=260us \
  --threads 1 --quiet --set "materials.st={library: steel-target-jc}" \
  --set 'bodies[1].material=st' --set sph.viscosity.alpha=0.2 --set sph.viscosity.beta=0.4 \
  > c29jc.log 2>&1 &
wait
# rod-5844: session 29's Johnson-Cook box file (docs/runs/s29/rod-box, copied here) at alpha = 0.2;
# its case and alpha = 1 runs are session 29's (r44-box, r44-box-jc there)
$H run r44-box-jc.yaml -o r44jc02 --threads 1 --quiet --set sph.viscosity.alpha=0.2 \
  --set sph.viscosity.beta=0.4 > r44jc02.log 2>&1
# then: copy measurements.csv, summary.csv, used_parameters.yaml, run_segments.csv and the
# logs of each run here; /usr/bin/python3 rods.py > rods.txt
# /usr/bin/python3 slices.py 1 case03/particles_00006.vtu > slices.txt, and 0 for
# jc02/particles_0000{5,6}.vtu and c29jc/particles_00013.vtu, 1 for c29case/particles_00013.vtu
