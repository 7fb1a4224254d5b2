#!/bin/sh
# Session 44: session 41's wide free tungsten target at 1.29 km/s (free129.yaml, one
# material without strength: a steady floor moves at v/2 = 0.645 km/s), alpha = 1 as in
# the cases, with session 43's reconstruction across the contact
# (sph.viscosity.reconstruct_contact) and study.patch's switch HV_CT: the pairs of two
# bodies exchange their whole pressures, tension included (the contact rule passes
# max(p, 0) only). To 30 us, 1 thread beside the rod-5835 run. From the repository root;
# build-exp built at bfc9be7 with study.patch applied:
#   git apply docs/runs/s44/floor-contact/study.patch
#   cmake -S . -B build-exp -DCMAKE_BUILD_TYPE=Release && cmake --build build-exp --target hvsph
#   git checkout src/sph/sph_solid.c
Y=docs/runs/s41/floor-free/free129.yaml
HV_CT=1 build-exp/hvsph run $Y -o out/s44/free-a1-ct --threads 1 --quiet \
  --set sph.viscosity.reconstruct_contact=true --set time.end=30us
