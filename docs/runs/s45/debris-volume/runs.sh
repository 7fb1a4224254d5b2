#!/bin/sh
# Session 45: session 33's short bumper studies (sec. 2.4, W.P.1, W.P.3's first bumper,
# each to 12 us) with the solids' continuity rate bounding every condensed neighbour's
# volume at 2 m_j/rho0_j and the density integrated as rho^n exp(dt Drho/rho^n),
# without and with sph.density_diffusion = 0.1; two lanes of 1 thread, from the
# repository root (W.P.3 with the option ran first, on 2 threads: out/s45/wp3-dd01-cap).
W=docs/runs/s33
H=build/hvsph
if [ "$1" = a ]; then
  $H run $W/ws-bumper-fracture/ws-base.yaml -o out/s45/ws-nodd --threads 1 --quiet
  $H run $W/ws-bumper-fracture/ws-base.yaml -o out/s45/ws-dd01 --threads 1 --quiet \
    --set sph.density_diffusion=0.1
elif [ "$1" = b ]; then
  $H run $W/al-bumper-fracture/wp1-base.yaml -o out/s45/wp1-nodd --threads 1 --quiet
  $H run $W/al-bumper-fracture/wp1-base.yaml -o out/s45/wp1-dd01 --threads 1 --quiet \
    --set sph.density_diffusion=0.1
  $H run $W/al-bumper-fracture/wp3-base.yaml -o out/s45/wp3-nodd --threads 1 --quiet
fi
# then (lane c, after lane b): session 26's rod-5841 at resolution 0.3 with the 1.0 mm
# core to 30 us without the option (session 43: L 38.74 mm at 30 us):
if [ "$1" = c ]; then
  $H run docs/runs/s26/rod-1929-floor/r41-case-c10.yaml -o out/s45/r41 --threads 1 --quiet
fi
