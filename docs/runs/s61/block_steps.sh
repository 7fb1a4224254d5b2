#!/bin/sh
# Session 61: what individual (block) time steps could gain, read from the snapshots' new
# per-particle dt. Three paper cases at resolution 0.3 to 20 us (snapshots at 10 and 20 us,
# CSV), then block_steps.py on them. Run from the repository root; about 9 min on 2 threads.
# Output as committed: docs/runs/s61/block_steps.out
set -eu
B=${B:-build/hvsph}
OUT=${OUT:-/tmp/s61-block}
for c in rod-5841 wp1 whipple-steel; do
  "$B" run examples/paper/$c.yaml --set resolution=0.3 --set time.end=20us \
    --set output.every=10us --set output.csv=true --set output.vtu=false --threads 2 -q \
    -o "$OUT/$c"
done
for c in rod-5841 wp1 whipple-steel; do
  /usr/bin/python3 docs/runs/s61/block_steps.py "$OUT/$c/particles_00001.csv" \
    "$OUT/$c/particles_00002.csv"
done
