#!/bin/sh
# Session 43: session 41's wide free tungsten target at 1.29 km/s (free129.yaml, one
# material without strength, so a steady floor moves at v/2 = 0.645 km/s), alpha = 1 as
# in the cases. From the repository root, 1 thread each, beside other runs.
set -e
Y=docs/runs/s41/floor-free/free129.yaml
# 1. The rod joined to the core (`part_of`: one piece, so no contact rule, and the
#    viscosity's reconstruction across the rod-target interface as inside a body);
#    built at 73a1396 with the lattice-cover warning uncommitted (73a1396-dirty):
build/hvsph run $Y -o out/s43/free-a1-joined --threads 1 --quiet --set 'bodies[0].part_of=core'
# 2. The bodies apart (the contact rule kept), the reconstruction for the pairs of the
#    two bodies too: study.patch's environment switch HV_RECON_ALL (the condition that
#    sph.viscosity.reconstruct_contact, c090c53, puts in the code), built in build-exp
#    at f717401 (run_segments.csv: f717401-dirty):
#      git apply docs/runs/s43/floor-joined/study.patch
#      cmake -S . -B build-exp -DCMAKE_BUILD_TYPE=Release && cmake --build build-exp --target hvsph
#      git checkout src/sph/sph_solid.c
HV_RECON_ALL=1 build-exp/hvsph run $Y -o out/s43/free-a1-reconall --threads 1 --quiet
#    (Run 2 was started twice into the same folder by mistake, 19 min apart, from the
#    same binary; the second was stopped at 20 us, and the first, which rewrites
#    measurements.csv and summary.csv whole at each output, went on to 50 us: its files
#    are the ones kept. Same binary and input, so the overwritten snapshots were the
#    same bits.)
# 3. study.patch's other two switches, to 30 us: HV_GRAD_ALL, each particle's velocity
#    gradient over the condensed neighbours of every body, not only its own piece's;
#    HV_DENS_ALL, the continuity sum without the contact rule's "a separating pair of
#    different bodies does not unload a particle below rho0" (a first 1-thread run was
#    stopped at 5 us; run again on 2 threads alone at the session's end):
HV_RECON_ALL=1 HV_GRAD_ALL=1 build-exp/hvsph run $Y -o out/s43/free-a1-recongrad --threads 1 --quiet --set time.end=30us
HV_DENS_ALL=1 build-exp/hvsph run $Y -o out/s43/free-a1-densall --threads 2 --quiet --set time.end=30us
# Then copy measurements.csv, summary.csv, run_segments.csv, used_parameters.yaml of each
# here and run /usr/bin/python3 floor.py (floor.txt).
