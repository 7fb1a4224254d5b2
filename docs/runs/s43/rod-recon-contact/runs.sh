#!/bin/sh
# Session 43: session 26's rod cases at resolution 0.3 with a 1.0 mm core joined to the
# block (Table 2's materials, alpha = 1, the reconstruction; r29-case-c10.yaml: rod-1929
# at 1.29 km/s, r41-case-c10.yaml: rod-5841 at 2.37 km/s), to 30 us, with
# sph.viscosity.reconstruct_contact (hvsph c090c53), 1 thread each beside other runs,
# from the repository root. The baselines are session 26's (docs/runs/s26/rod-1929-floor,
# floor.txt). rods.py -> rods.txt.
set -e
S=docs/runs/s26/rod-1929-floor
for c in r29 r41; do
  build/hvsph run $S/$c-case-c10.yaml -o out/s43/$c-rc --threads 1 --quiet \
    --set sph.viscosity.reconstruct_contact=true &
done
wait
