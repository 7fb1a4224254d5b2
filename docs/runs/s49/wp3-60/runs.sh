#!/bin/sh
# Session 49: W.P.3's second bumper to 60 us (the case's end) on session 47's cheaper
# W.P.3 (no backwall, first bumper's disc at 0.267 mm, second bumper one layer;
# docs/runs/s47/wp3-bumper2/one-layer.yaml), 1 thread each:
#   rule   the paper's rule (the current model), from the start to 60 us
#   ef     split: crack with crack_eps_f (2024-T351's d1..d3; docs/runs/s49/crack-ef),
#          continued from its 30 us run (out/s49/crack-ef/wp3) to 60 us
#   crack  split: crack alone (session 48's wp3b2-crack.yaml), from the start to 60 us
# Usage, from the repository root: sh docs/runs/s49/wp3-60/runs.sh LANE; HVSPH names
# the binary.
set -e
H=${HVSPH:-./build/hvsph}
O=out/s49/wp3-60
mkdir -p $O
case "$1" in
  rule) $H run docs/runs/s47/wp3-bumper2/one-layer.yaml -o $O/rule --threads 1 --quiet --set time.end="60 us" > $O/rule.log 2>&1 ;;
  ef) $H restart out/s49/crack-ef/wp3 --threads 1 --quiet --set time.end="60 us" > $O/ef.log 2>&1 ;;
  crack) (cd docs/runs/s48/crack && ../../../../$H run wp3b2-crack.yaml -o ../../../../$O/crack --threads 1 --quiet --set time.end="60 us") > $O/crack.log 2>&1 ;;
esac
