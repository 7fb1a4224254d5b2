#!/bin/sh
# Session 44, after the rho0/2 bound (badc9ee): W.P.3's first bumper, sec. 2.4's and W.P.1's
# bumper cases to 12 us with the committed sph.density_diffusion = 0.1, 1 thread each
# (runs4.sh's were the study build without the bound; W.P.3's failed there at 6 us).
# The sec. 2.4 and W.P.1 runs were stopped at once for the session's time (not run); only
# W.P.3's (below) ran.
H=build/hvsph
while pgrep -f 'o out/s44/free-a02-split ' > /dev/null; do sleep 10; done
$H run docs/runs/s33/ws-bumper-fracture/ws-base.yaml -o out/s44/ws-dd01g --threads 1 --quiet \
  --set sph.density_diffusion=0.1 &
$H run docs/runs/s33/al-bumper-fracture/wp1-base.yaml -o out/s44/wp1-dd01g --threads 1 --quiet \
  --set sph.density_diffusion=0.1
wait
# (wp3-dd01g was started by hand at 03:4x with the same build:
#  build/hvsph run docs/runs/s33/al-bumper-fracture/wp3-base.yaml -o out/s44/wp3-dd01g --threads 1 --quiet --set sph.density_diffusion=0.1)
# It stopped at 5.04 us (rho < 0, projectile). Then, with a 0.9 rho0 bound (a build not
# kept): build/hvsph run ... -o out/s44/wp3-dd01h --threads 2 --set sph.density_diffusion=0.1
# --set time.end=7us stopped at 5.70 us; without the option (wp3-nodd, --set time.end=6.5us,
# 2 threads) the case runs through. Measurements, segments and logs in wp3/.
