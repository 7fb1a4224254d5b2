#!/bin/sh
# Session 48: the smeared crack (fracture.split: crack) on session 33's and 47's short
# bumper cases, beside the runs of the current model they repeat:
#   ws   section 2.4's sphere (5 625 particles, session 46's spacing) and bumper to 12 us
#        (docs/runs/s46/projectile-spacing/ws-p02: 12.13 mm at 12 us)
#   wp1  W.P.1's sphere and bumper to 12 us (docs/runs/s33/al-bumper-fracture: 11.14 mm)
#   wp3a W.P.3's sphere (4 092 particles, session 46's spacing) and first bumper to 12 us
#        (docs/runs/s46/projectile-spacing/wp3-p016)
#   wp2  W.P.2's sphere (4 091 particles, session 46's spacing) and bumper to 12 us
#        (docs/runs/s46/projectile-spacing/wp2-p04)
#   wp3  W.P.3 without backwall, first bumper's disc at 0.267 mm, second bumper one layer,
#        to 30 us (docs/runs/s47/wp3-bumper2/one: 42.10 mm)
# Usage, from this folder: sh runs.sh LANE; HVSPH names the binary (a build of this
# session's source). 1 thread each.
set -e
H=${HVSPH:-../../../../build/hvsph}
O=${OUT:-../../../../out/s48/crack}
mkdir -p $O
case "$1" in
  ws)  $H run ws-crack.yaml -o $O/ws --threads 1 --quiet --set 'bodies[0].particles=5625' > $O/ws.log 2>&1 ;;
  wp1) $H run wp1-crack.yaml -o $O/wp1 --threads 1 --quiet > $O/wp1.log 2>&1 ;;
  wp3a) $H run wp3-crack.yaml -o $O/wp3a --threads 1 --quiet --set 'bodies[0].particles=4092' > $O/wp3a.log 2>&1 ;;
  wp2) $H run wp2-crack.yaml -o $O/wp2 --threads 1 --quiet --set 'bodies[0].particles=4091' > $O/wp2.log 2>&1 ;;
  wp3) $H run wp3b2-crack.yaml -o $O/wp3 --threads 1 --quiet > $O/wp3.log 2>&1 ;;
esac
