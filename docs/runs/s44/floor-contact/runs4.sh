#!/bin/sh
# Session 44: study.patch's density diffusion (HV_DDIFF=0.1, build-exp3) on the cases'
# short studies, in two lanes of 1 thread, from the repository root:
#  lane a: session 26's rod-5841 at resolution 0.3 with the 1.0 mm core to 30 us
#          (r41-case-c10.yaml; session 43's runs without it: r41 L 38.74 mm at 30 us),
#          then session 33's sec. 2.4 and W.P.1 bumper cases to 12 us (ws-base.yaml,
#          wp1-base.yaml; holes 12.60 and 11.14 mm without it);
#  lane b: free129-split.yaml (every body split from the start: the pressure's noise
#          clipped at 0 in every particle; committed build) to 30 us, then rod-1929 at
#          resolution 0.3 with the core (r29-case-c10.yaml) to 30 us.
S=docs/runs/s26/rod-1929-floor
H=build-exp3/hvsph
if [ "$1" = a ]; then
  while pgrep -f 'o out/s44/free-a1-dd01 ' > /dev/null; do sleep 15; done
  HV_DDIFF=0.1 $H run $S/r41-case-c10.yaml -o out/s44/r41-dd01 --threads 1 --quiet
  HV_DDIFF=0.1 $H run docs/runs/s33/ws-bumper-fracture/ws-base.yaml -o out/s44/ws-dd01 --threads 1 --quiet
  HV_DDIFF=0.1 $H run docs/runs/s33/al-bumper-fracture/wp1-base.yaml -o out/s44/wp1-dd01 --threads 1 --quiet
else
  while pgrep -f 'o out/s44/free-a1-norecon ' > /dev/null; do sleep 15; done
  build/hvsph run docs/runs/s44/floor-contact/free129-split.yaml -o out/s44/free-a1-split \
    --threads 1 --quiet --set time.end=30us
  HV_DDIFF=0.1 $H run $S/r29-case-c10.yaml -o out/s44/r29-dd01 --threads 1 --quiet
fi
# (after both lanes) W.P.3's first bumper to 12 us (wp3-base.yaml; 8.21 mm without it):
#   HV_DDIFF=0.1 build-exp3/hvsph run docs/runs/s33/al-bumper-fracture/wp3-base.yaml -o out/s44/wp3-dd01 --threads 1 --quiet
