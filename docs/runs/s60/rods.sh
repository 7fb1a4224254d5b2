#!/bin/sh
# The rods' table behind docs/img/val_rods.png (session 60): docs/runs/s23's table with
# the rows of the rods run again at the paper's counts with today's code — rod-5844
# (session 58), rod-5842 (session 59) and rod-5839 (session 60) — then the plot.
# Run from the repository root: sh docs/runs/s60/rods.sh
set -eu
out=docs/runs/s60/rods_validation.csv
{
  head -n 1 docs/runs/s23/rods_validation.csv
  grep -v -e '^case,' -e '^rod-5844,' -e '^rod-5842,' -e '^rod-5839,' docs/runs/s23/rods_validation.csv
  grep -h -e '^rod-5844,penetration_depth' -e '^rod-5844,cavity_diameter:' docs/runs/s58/rod-5844-pc/validation.csv
  grep -h -e '^rod-5842,penetration_depth' -e '^rod-5842,cavity_diameter:' docs/runs/s59/rod-5842-pc/validation.csv
  grep -h -e '^rod-5839,penetration_depth' -e '^rod-5839,cavity_diameter:' docs/runs/s60/rod-5839-pc/validation.csv
} > "$out"
/usr/bin/python3 tools/plot_rods.py "$out" --label "hvsph (paper's counts)" -o docs/img/val_rods.png
