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
# rod-1929 and rod-5844 at 20 us, for their profiles
hvsph run ../../s32/rod-erode/r29-case-c10.yaml -o base29 --threads 1 --set time.end=20us
hvsph run ../../s32/rod-erode/r44-core.yaml -o base44 --threads 1 --set time.end=20us --set output.every=5us
/usr/bin/python3 profile.py base29/particles_00004.vtu > profile29.txt
/usr/bin/python3 profile.py base44/particles_00004.vtu > profile44.txt
