#!/bin/sh
# Session 43: session 26's rod cases at resolution 0.3 with a 1.0 mm core joined to the
# block (Table 2's materials, alpha = 1, the reconstruction; r29-case-c10.yaml: rod-1929
# at 1.29 km/s, r41-case-c10.yaml: rod-5841 at 2.37 km/s) with
# sph.viscosity.reconstruct_contact (hvsph c090c53), 1 thread each beside other runs,
# from the repository root; rod-1929's case without it run again to 60 us. Then copy
# measurements.csv, summary.csv, run_segments.csv, used_parameters.yaml of each here and
# /usr/bin/python3 docs/runs/s43/rod-recon-contact/rods.py > rods.txt (it also reads
# r29-rc's snapshots in out/s43 for the split share at the head).
S=docs/runs/s26/rod-1929-floor
build/hvsph run $S/r29-case-c10.yaml -o out/s43/r29-rc --threads 1 --quiet \
  --set sph.viscosity.reconstruct_contact=true            # to 30 us, then:
build/hvsph restart out/s43/r29-rc --threads 1 --quiet --set time.end=60us
build/hvsph run $S/r41-case-c10.yaml -o out/s43/r41-rc --threads 1 --quiet \
  --set sph.viscosity.reconstruct_contact=true
build/hvsph run $S/r29-case-c10.yaml -o out/s43/r29-base60 --threads 1 --quiet --set time.end=60us
