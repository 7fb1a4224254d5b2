#!/usr/bin/env bash
# docs/validation.md, Table 4: the simulated flash radiograph of bumper-20 at t_x = 49.5 µs
# (areal density along z, mirrored across the symmetry plane), as validate's final.png.
# Made from the final snapshot of `hvsph validate --scale 1 --only bumper-20` (the paper's
# particle counts) by `hvsph render`.
#
# Environment: HVSPH (the hvsph binary, default build/hvsph), RUNS (the folder of
# `hvsph validate` run folders, default out/validation), OUT (default docs/img); relative
# paths are taken from the directory the script is started in. Writes $OUT/bumper-20-50us.png;
# without the run folder $RUNS/bumper-20, or with a run that has not reached the case's end, it
# says "skip: ..." and exits 0.
set -eu
abs() { case $1 in /*) printf '%s\n' "$1" ;; *) printf '%s\n' "$PWD/$1" ;; esac; }
root=$(cd "$(dirname "$0")/../.." && pwd)
HVSPH=$(abs "${HVSPH:-$root/build/hvsph}")
RUNS=$(abs "${RUNS:-$root/out/validation}")
OUT=$(abs "${OUT:-$root/docs/img}")
name=bumper-20-50us
case=bumper-20
run=$RUNS/$case
if [ ! -f "$run/run_segments.csv" ]; then
  echo "skip: $name needs $run (hvsph validate --scale 1 --only $case -o $RUNS)"
  exit 0
fi
if [ "$(tail -n 1 "$run/run_segments.csv" | cut -d, -f10)" != "done" ]; then
  echo "skip: $name needs $run run to its end (hvsph validate --resume --scale 1 --only $case -o $RUNS)"
  exit 0
fi
snaps=("$run"/particles_*.vtu)   # in time order: the names are numbered
snap=${snaps[${#snaps[@]} - 1]}
[ -f "$snap" ] || { echo "$name: no snapshot in $run" >&2; exit 1; }
mkdir -p "$OUT"
tmp=$OUT/.$name.tmp.png
trap 'rm -f "$tmp"' EXIT
"$HVSPH" render "$snap" -o "$tmp" --quiet --mode radiograph --axis z --size 900
mv "$tmp" "$OUT/$name.png"
echo "$OUT/$name.png from $snap"
