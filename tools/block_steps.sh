#!/usr/bin/env bash
# The individual-time-step estimate of docs/performance.md: three paper cases (rod-5841,
# W.P.1, the steel Whipple shield) at resolution 0.3 to 20 us, snapshots (CSV) at 10 and
# 20 us, then tools/block_steps.py on each run. About 9 minutes on 2 cores.
# Usage: tools/block_steps.sh   (from anywhere; environment: HVSPH, the binary, default
#        build/hvsph; WORK, the runs' folder, default out/block-steps; THREADS, default 2)
set -euo pipefail
abs() { case $1 in /*) printf '%s\n' "$1" ;; *) printf '%s\n' "$PWD/$1" ;; esac; }
root=$(cd "$(dirname "$0")/.." && pwd)
hvsph=$(abs "${HVSPH:-$root/build/hvsph}")
work=$(abs "${WORK:-$root/out/block-steps}")
threads=${THREADS:-2}
cd "$root"
[ -x "$hvsph" ] || { echo "block_steps: $hvsph: no hvsph binary (make build, or set HVSPH)" >&2; exit 1; }
"$hvsph" --version
for c in rod-5841 wp1 whipple-steel; do
  echo "block_steps: $c at resolution 0.3 to 20 us -> $work/$c"
  "$hvsph" run "examples/paper/$c.yaml" -o "$work/$c" --threads "$threads" -q \
    --set resolution=0.3 --set time.end=20us --set output.every=10us \
    --set output.csv=true --set output.vtu=false
done
for c in rod-5841 wp1 whipple-steel; do
  /usr/bin/python3 tools/block_steps.py "$work/$c"
done
