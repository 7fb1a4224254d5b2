#!/bin/sh
# Session 34: session 32's rod-5841 case again to 20 us (hvsph 7fd365b, 1 thread), then
# the pair forces on the mushroom and on the wall beside it (forces.txt).
set -e
hvsph run ../../s32/rod-erode/r41-case-c10.yaml -o base41 --threads 1 --set time.end=20us
F=base41/particles_00004.vtu
{ /usr/bin/python3 forces.py $F -5 -1 2.638
  /usr/bin/python3 forces.py $F -4 -1 4 7 1
  FORCES_NO_RECON=1 /usr/bin/python3 forces.py $F -4 -1 4 7 1; } > forces.txt
F=base41/particles_00004.vtu; /usr/bin/python3 profile.py $F > profile.txt
