#!/bin/sh
# Session 44, after runs.sh, each to 30 us on 1 thread beside the rod runs (from the
# repository root):
# 1. study.patch's HV_CT=2: the contact pair's two pressures summed and the sum clipped
#    at 0 (a pair of two bodies may not pull as a whole; one particle's tension offsets
#    the other's compression), with the reconstruction across the contact; build-exp2
#    built at bfc9be7 with study.patch (its HV_CT=1 is build-exp's);
# 2. the standard viscosity everywhere (reconstruct: false), and 3. the same with every
#    body split from the start (free129-split.yaml: pressure clipped at 0 in every
#    particle): what clipping the pressure's noise costs the floor, with the committed
#    build;
# 4. HV_CT=2 without the reconstruction across the contact (the cases' viscosity).
Y=docs/runs/s41/floor-free/free129.yaml
while pgrep -f 'free129.yaml -o out/s44/free-a1-ct ' > /dev/null; do sleep 20; done
HV_CT=2 build-exp2/hvsph run $Y -o out/s44/free-a1-ct2 --threads 1 --quiet \
  --set sph.viscosity.reconstruct_contact=true --set time.end=30us
build/hvsph run $Y -o out/s44/free-a1-norecon --threads 1 --quiet \
  --set sph.viscosity.reconstruct=false --set time.end=30us
build/hvsph run docs/runs/s44/floor-contact/free129-split.yaml -o out/s44/free-a1-split \
  --threads 1 --quiet --set time.end=30us
HV_CT=2 build-exp2/hvsph run $Y -o out/s44/free-a1-ct2-norc --threads 1 --quiet \
  --set time.end=30us
