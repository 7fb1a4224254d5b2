#!/bin/sh
# Session 43: rod-5839 at the paper's counts with session 31's set (Johnson-Cook 4340
# target, alpha = 0.2, beta = 0.4), 2 threads, from out/s43.
H=../../build/hvsph
$H run ../../examples/paper/rod-5839.yaml -o pc5839jc --threads 2 --quiet \
  --material steel-target=steel-target-jc \
  --set sph.viscosity.alpha=0.2 --set sph.viscosity.beta=0.4 > pc5839jc.log 2>&1
# continue: $H restart pc5839jc --threads 2 --quiet
# Then the cavity read again with measure.cavity_min_count: 2 (a loose particle on the
# axis closed the cavity at 125-163 us with the default 1):
#   sh ../../docs/runs/s38/rod-jc/remeasure.sh pc5839jc
# and measurements.csv, summary.csv, run_segments.csv, used_parameters.yaml of pc5839jc
# and pc5839jc-mc2's measurements.csv and case.yaml copied here; /usr/bin/python3 pc.py > pc.txt
# (rods 5835 and 1929 were queued after it and dropped for the session's time).
