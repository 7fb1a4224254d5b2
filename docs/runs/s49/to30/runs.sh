#!/bin/sh
# Session 49: W.P.1's and W.P.2's short cases (sphere and bumper, no backwall) on to
# 30 us, to see whether the holes' ratio between the paper's rule and the crack with
# crack_eps_f (docs/runs/s49/crack-ef) holds after 12 us:
#   rule-wp1  session 33's wp1-base.yaml (the paper's rule) from the start to 30 us
#   rule-wp2  session 46's wp2-base.yaml with 4 091 projectile particles (wp2-p04), to 30 us
#   ef-wp1, ef-wp2  the crack with crack_eps_f, continued from their 12 us runs
#             (out/s49/crack-ef/wp1, wp2) to 30 us
# Usage, from the repository root: sh docs/runs/s49/to30/runs.sh LANE; HVSPH names the
# binary. 1 thread each.
set -e
H=${HVSPH:-./build/hvsph}
O=out/s49/to30
mkdir -p $O
case "$1" in
  rule-wp1) $H run docs/runs/s33/al-bumper-fracture/wp1-base.yaml -o $O/rule-wp1 --threads 1 --quiet --set time.end="30 us" > $O/rule-wp1.log 2>&1 ;;
  rule-wp2) $H run docs/runs/s46/projectile-spacing/wp2-base.yaml -o $O/rule-wp2 --threads 1 --quiet --set 'bodies[0].particles=4091' --set time.end="30 us" > $O/rule-wp2.log 2>&1 ;;
  ef-wp1) $H restart out/s49/crack-ef/wp1 --threads 1 --quiet --set time.end="30 us" > $O/ef-wp1.log 2>&1 ;;
  ef-wp2) $H restart out/s49/crack-ef/wp2 --threads 1 --quiet --set time.end="30 us" > $O/ef-wp2.log 2>&1 ;;
esac
