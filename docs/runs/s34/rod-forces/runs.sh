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
# rod-5841's case with the target's yield at 3 x Table 2's (1.17 GPa) and at 1 kPa, both
# without fracture, to 20 us, then continued to 30 us
for v in "y3-41 1.17 GPa" "y0-41 1 kPa"; do set -- $v
  hvsph run ../../s32/rod-erode/r41-case-c10.yaml -o $1 --threads 1 --set time.end=20us \
    --set "materials.st={library: steel-target, strength: {yield: $2 $3}, fracture: {model: none}}" \
    --set 'bodies[1].material=st' --set 'bodies[2].material=st'
  hvsph restart $1 --threads 1 --set time.end=30us
done
/usr/bin/python3 profile.py y3-41/particles_00004.vtu > profile-y3.txt
/usr/bin/python3 profile.py y0-41/particles_00004.vtu > profile-y0.txt
/usr/bin/python3 ../../s32/rod-erode/erode.py y3-41 y0-41 ../../s32/rod-erode/base > strength.txt
# rod-5841's case with a finer rod (15 000 and 40 000 particles at resolution 0.3:
# 0.654 and 0.477 mm against the case's 0.956 mm), to 20 us
hvsph run ../../s32/rod-erode/r41-case-c10.yaml -o rod15k --threads 1 --set time.end=20us --set 'bodies[0].particles=15000'
hvsph run ../../s32/rod-erode/r41-case-c10.yaml -o rod40k --threads 1 --set time.end=20us --set 'bodies[0].particles=40000'
/usr/bin/python3 profile.py rod15k/particles_00004.vtu > profile-rod15k.txt
/usr/bin/python3 profile.py rod40k/particles_00004.vtu > profile-rod40k.txt
# rod-5841's case with the rod unbroken and with its split material keeping its
# compression and shear (fracture.split: no-tension), to 20 us
hvsph run ../../s32/rod-erode/r41-case-c10.yaml -o wnofrac --threads 1 --set time.end=20us \
  --set 'materials.w={library: tungsten-alloy, fracture: {model: none}}' --set 'bodies[0].material=w'
hvsph run ../../s32/rod-erode/r41-case-c10.yaml -o wnt --threads 1 --set time.end=20us \
  --set 'materials.w={library: tungsten-alloy, fracture: {split: no-tension}}' --set 'bodies[0].material=w'
/usr/bin/python3 profile.py wnofrac/particles_00004.vtu > profile-wnofrac.txt
/usr/bin/python3 profile.py wnt/particles_00004.vtu > profile-wnt.txt
# the contact allowed to stretch a particle below rho0 in the density rate (a study
# build: hvsph 7fd365b with contact-stretch.patch), 2 threads (bit for bit as 1)
HVSPH_CONTACT_STRETCH=1 hvsph-stretch run ../../s32/rod-erode/r41-case-c10.yaml -o stretch --threads 2 --set time.end=20us
/usr/bin/python3 profile.py stretch/particles_00004.vtu > profile-stretch.txt
