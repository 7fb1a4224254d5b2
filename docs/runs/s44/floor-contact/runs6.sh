#!/bin/sh
# Session 44, after the rho0/2 bound (badc9ee): W.P.3's first bumper, sec. 2.4's and W.P.1's
# bumper cases to 12 us with the committed sph.density_diffusion = 0.1, 1 thread each
# (runs4.sh's were the study build without the bound; W.P.3's failed there at 6 us).
H=build/hvsph
while pgrep -f 'o out/s44/free-a02-split ' > /dev/null; do sleep 10; done
$H run docs/runs/s33/ws-bumper-fracture/ws-base.yaml -o out/s44/ws-dd01g --threads 1 --quiet \
  --set sph.density_diffusion=0.1 &
$H run docs/runs/s33/al-bumper-fracture/wp1-base.yaml -o out/s44/wp1-dd01g --threads 1 --quiet \
  --set sph.density_diffusion=0.1
wait
# (wp3-dd01g was started by hand at 03:4x with the same build:
#  build/hvsph run docs/runs/s33/al-bumper-fracture/wp3-base.yaml -o out/s44/wp3-dd01g --threads 1 --quiet --set sph.density_diffusion=0.1)
