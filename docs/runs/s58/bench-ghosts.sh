#!/bin/sh
# Session 58: the parallel ghosts and cand_any's own cell first, against the session's
# start (dceef86), on rod-5841 at resolution 0.3 (97 524 particles, half model: a
# symmetry plane at z = 0, walls on four faces), 200 steps from t = 0, no snapshots.
# Alternating pairs; the run's own wall time (run_segments.csv, wall_s).
# BASE: hvsph of dceef86 built Release; NEW: this tree's.
BASE=${BASE:-/tmp/build-base/hvsph}
NEW=${NEW:-build/hvsph}
OUT=${OUT:-/tmp/s58-bench}
for threads in 2 1; do
  for pair in 1 2 3; do
    for b in base new; do
      bin=$BASE; [ $b = new ] && bin=$NEW
      rm -rf "$OUT/$b"
      "$bin" run examples/paper/rod-5841.yaml --set resolution=0.3 --threads $threads --quiet \
        -o "$OUT/$b" --set time.max_steps=200 --set output.every=1s --set output.vtu=false \
        --set output.checkpoint=false >/dev/null 2>&1
      printf '%s threads=%s pair=%s wall_s=%s\n' $b $threads $pair \
        "$(tail -1 "$OUT/$b/run_segments.csv" | cut -d, -f9)"
    done
  done
done
