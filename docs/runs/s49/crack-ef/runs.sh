#!/bin/sh
# Session 49: split: crack with the cracked state's strain to failure (fracture.crack_eps_f,
# Johnson-Cook's 2024-T351 d1 = 0.13, d2 = 0.13, d3 = -1.5) for al-alloy, on session 48's
# short aluminium bumper cases (docs/runs/s48/crack), nothing else changed:
#   wp1  W.P.1's sphere and bumper to 12 us
#   wp2  W.P.2's sphere (4 091 particles) and bumper to 12 us
#   wp3a W.P.3's sphere (4 092 particles) and first bumper to 12 us
#   wp3  W.P.3 without backwall, first bumper's disc at 0.267 mm, second bumper one layer,
#        to 30 us
# Usage, from this folder: sh runs.sh LANE; HVSPH names the binary (a build of this
# session's source). 1 thread each.
set -e
H=${HVSPH:-../../../../build/hvsph}
O=${OUT:-../../../../out/s49/crack-ef}
mkdir -p $O
case "$1" in
  wp1) $H run wp1-ef.yaml -o $O/wp1 --threads 1 --quiet > $O/wp1.log 2>&1 ;;
  wp3a) $H run wp3-ef.yaml -o $O/wp3a --threads 1 --quiet --set 'bodies[0].particles=4092' > $O/wp3a.log 2>&1 ;;
  wp2) $H run wp2-ef.yaml -o $O/wp2 --threads 1 --quiet --set 'bodies[0].particles=4091' > $O/wp2.log 2>&1 ;;
  wp3) $H run wp3b2-ef.yaml -o $O/wp3 --threads 1 --quiet > $O/wp3.log 2>&1 ;;
esac
