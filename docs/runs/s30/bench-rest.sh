#!/bin/sh
# The cost of a step of examples/paper/whipple-steel.yaml (394 366 particles) from its
# initial state, with sph.skip_resting true and false, alternating, PAIRS pairs:
# docs/performance.md, "Particles at rest". Run from the repository root after a build;
# prints one line per run: skip, steps, seconds of stepping (the run's own "elapsed").
PAIRS=${PAIRS:-3}; STEPS=${STEPS:-10}; THREADS=${THREADS:-2}
CASE=${CASE:-examples/paper/whipple-steel.yaml}
OUT=${TMPDIR:-/tmp}/hvsph-bench-rest
for k in $(seq "$PAIRS"); do
  for skip in true false; do
    rm -rf "$OUT"
    build/hvsph run "$CASE" -o "$OUT" --threads "$THREADS" --set time.max_steps="$STEPS" \
      --set output.vtu=false --set sph.skip_resting=$skip "$@" 2>&1 |
      sed -n 's/.*step \([0-9]*\) .*elapsed \([0-9.]*\) s.*/\1 \2/p' | tail -1 |
      { read -r st el; echo "skip_resting=$skip steps=$st elapsed_s=$el"; }
  done
done
rm -rf "$OUT"
