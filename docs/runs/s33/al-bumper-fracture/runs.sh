#!/bin/sh
# Session 33: W.P.1's and W.P.3's sphere and first bumper (the paper's cases without the
# later plates), to 12 us, hole every us; the al-alloy as Table 8 (base) and with a
# plastic-strain criterion instead of the tensile one (ef10: cumulative, sigma_c: 0,
# eps_f: 1, for projectile and bumper alike). hvsph e31c8e7, 1 thread each.
set -e
for c in wp1-base wp1-ef10 wp3-base wp3-ef10; do hvsph run $c.yaml -o $c --threads 1; done
{ ../ws-bumper-fracture/holes.sh wp1-base wp1-ef10
  OBJ=bumper1 ../ws-bumper-fracture/holes.sh wp3-base wp3-ef10; } > holes.txt
