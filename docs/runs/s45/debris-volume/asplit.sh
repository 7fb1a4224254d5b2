#!/bin/sh
# Session 45, at its end: the split material's viscosity as the lever (Still to do, the
# floor's deficit): asplit.patch's HV_ASPLIT = a gives the pairs of two split particles
# alpha = a, beta = 2a (other pairs keep alpha = 1, beta = 2; a ghost counts as split when
# its partner is). build-exp built at 7744ec1 with asplit.patch. Two lanes of 1 thread,
# from the repository root: sec. 2.4's bumper to 12 us (hole 12.60 mm with the cases'
# viscosity) and rod-5841 at resolution 0.3 with the core to 30 us (L 38.89 mm).
if [ "$1" = a ]; then
  HV_ASPLIT=0.2 build-exp/hvsph run docs/runs/s33/ws-bumper-fracture/ws-base.yaml -o out/s45/ws-as02 --threads 1 --quiet
else
  HV_ASPLIT=0.2 build-exp/hvsph run docs/runs/s26/rod-1929-floor/r41-case-c10.yaml -o out/s45/r41-as02 --threads 1 --quiet
fi
