#!/bin/sh
# Session 44: rod-5835 at the paper's counts with session 31's set (Johnson-Cook 4340
# target, alpha = 0.2, beta = 0.4), 2 threads, run from out/s44 (as session 43's rod-5839).
H=../../build/hvsph
$H run ../../examples/paper/rod-5835.yaml -o pc5835jc --threads 2 --quiet \
  --material steel-target=steel-target-jc \
  --set sph.viscosity.alpha=0.2 --set sph.viscosity.beta=0.4 > pc5835jc.log 2>&1
# continue: $H restart pc5835jc --threads 2 --quiet
# Then: sh ../../docs/runs/s38/rod-jc/remeasure.sh pc5835jc (cavity_min_count: 2)
# Ran 2026-12-05 01:27:55-02:50 (4 965 s, 5 346 steps to 197 us, 2 threads beside 1-thread
# studies). Remeasured with remeasure.sh; measurements.csv, summary.csv, run_segments.csv,
# used_parameters.yaml of pc5835jc and pc5835jc-mc2's measurements.csv and case.yaml copied
# here, with session 43's pc5839jc-mc2/measurements.csv; then
#   /usr/bin/python3 ../../s43/rod-pc/pc.py . > pc.txt   (in this folder)
