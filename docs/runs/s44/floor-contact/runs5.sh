#!/bin/sh
# Session 44, at its end: the split free test (free129-split.yaml: every body split from
# the start, the standard viscosity everywhere, -19.5 % over 10-30 us) with density
# diffusion (sph.density_diffusion = 0.1, the committed option, 000984d) and with
# alpha = 0.2, beta = 0.4; to 30 us, 1 thread each, from the repository root.
Y=docs/runs/s44/floor-contact/free129-split.yaml
build/hvsph run $Y -o out/s44/free-a1-split-dd01 --threads 1 --quiet --set time.end=30us \
  --set sph.density_diffusion=0.1
while pgrep -f 'o out/s44/wp3-dd01 ' > /dev/null; do sleep 10; done
build/hvsph run $Y -o out/s44/free-a02-split --threads 1 --quiet --set time.end=30us \
  --set sph.viscosity.alpha=0.2 --set sph.viscosity.beta=0.4
