#!/bin/sh
# Session 46: rod-1929 at the paper's counts with session 31's set (Johnson-Cook 4340
# target, alpha = 0.2, beta = 0.4), started in session 44 (../../s44/rod-pc/runs.sh's
# command with rod-1929.yaml, out/s44/pc1929jc, to 28.2 us) and continued from out/s44:
#   ../../build/hvsph restart pc1929jc --threads 2 > pc1929jc-restart45.log 2>&1
# stopped with SIGINT at 253.8 us (the floor still for 50 us); then
#   sh ../../docs/runs/s38/rod-jc/remeasure.sh pc1929jc     (cavity_min_count: 2)
# and, with a folder J holding links to ../../s44/rod-pc/pc5835jc-mc2,
# ../../s44/rod-pc/pc5839jc-mc2 and this folder's pc1929jc-mc2:
#   /usr/bin/python3 ../../s43/rod-pc/pc.py J > pc.txt
# pc1929jc/: the run's measurements.csv (min_count 1), summary.csv, run_segments.csv,
# used_parameters.yaml; pc1929jc-mc2/: measurements.csv and case.yaml of the re-reading.
# Continue it: ../../build/hvsph restart pc1929jc --threads 2 (in out/s44, if kept).
