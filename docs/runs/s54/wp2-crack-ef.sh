#!/bin/sh
# Session 54: W.P.2 at the paper's counts with session 49's aluminium set (split: crack and
# the 2024-T351 strain to failure d1 = d2 = 0.13, d3 = -1.5 for al-alloy), to 50 us, 1 thread:
# the projectile's pieces in the gap against session 53's reading of the paper's rule
# (out/s51 W.P.2 run; docs/runs/s53/wp2_gap_fragments.out). From the repository root.
H=${HVSPH:-out/s54/hvsph}
m=al-alloy
$H validate --scale 1 --only wp2 --threads 1 -o out/s54/wp2-crackef \
  --set time.end=50us --set output.every=10us \
  --set materials.$m.library=$m --set materials.$m.fracture.split=crack \
  --set materials.$m.fracture.crack_eps_f.d1=0.13 --set materials.$m.fracture.crack_eps_f.d2=0.13 \
  --set materials.$m.fracture.crack_eps_f.d3=-1.5 > out/s54/wp2-crackef.log 2>&1
