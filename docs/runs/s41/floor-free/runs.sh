#!/bin/sh
# Session 41: the wide free tungsten target at 1.29 km/s (free129.yaml), the standard
# viscosity of the cases (alpha = 1, beta = 2, reconstruction) and alpha = 0.2, beta = 0.4.
# 1 thread each, both at once, from the repository root after `make build`.
set -e
Y=docs/runs/s41/floor-free/free129.yaml
build/hvsph run $Y -o out/s41/free-a1 --threads 1 &
build/hvsph run $Y -o out/s41/free-a02 --threads 1 --set sph.viscosity.alpha=0.2 --set sph.viscosity.beta=0.4 &
wait
# Then, two at a time on the two cores (1 thread each unless said):
#   hvsph restart out/s41/free-a1 --set time.end="60 us"      (and the same for free-a02)
#   build/hvsph run docs/runs/s41/floor-free/free129.yaml -o out/s41/free-cd --threads 1 \
#     --set sph.viscosity.switch=cullen-dehnen --set sph.viscosity.alpha_min=0.1 --set sph.skip_resting=false
# and session 15's 4.46 km/s free test with a measure section:
#   S=docs/runs/s15/rod-symmetric-free/symc-free.yaml; M='measure.thick_target=[core, mid, outer]'
#   build/hvsph run $S -o out/s41/free446-a02 --threads 1 --set "$M" --set output.csv=false \
#     --set sph.viscosity.alpha=0.2 --set sph.viscosity.beta=0.4
#   build/hvsph run $S -o out/s41/free446-a1 --threads 1 --set "$M" --set output.csv=false
#   build/hvsph run $S -o out/s41/free446-h05 --threads 2 --set "$M" --set output.csv=false \
#     --set 'bodies[0].spacing=0.5 mm' --set 'bodies[1].spacing=0.5 mm'
# (free446-h05 ran its first 152 steps on 1 thread, then `hvsph restart` on 2.)
# The same two with the blocks joined to the core (tension and shear across the seams):
#   J="--set bodies[2].part_of=core --set bodies[3].part_of=core"
#   build/hvsph run $S -o out/s41/free446-j07 --threads 1 --set "$M" --set output.csv=false $J
#   build/hvsph run $S -o out/s41/free446-j05 --threads 1 --set "$M" --set output.csv=false $J \
#     --set 'bodies[0].spacing=0.5 mm' --set 'bodies[1].spacing=0.5 mm'
# (free446-j05: 853 steps on 1 thread, then `hvsph restart` on 2.)
# The alpha = 0 and 0.5 mm runs at 1.29 km/s are device.sh's.
# And the core widened to +-20 mm (wider than the crater), 2 threads:
#   build/hvsph run docs/runs/s41/floor-free/symc-free-wide.yaml -o out/s41/free446-wide --threads 2
