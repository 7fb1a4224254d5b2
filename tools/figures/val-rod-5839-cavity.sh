#!/usr/bin/env bash
# docs/validation.md, rod-5839: the cavity at the case's end, 163 µs, cut through the
# symmetry plane (a 1.5 mm slab), coloured by material.
# Made from the final snapshot of `hvsph validate --scale 1 --only rod-5839` (the paper's
# particle counts) by `hvsph render`.
#
# Environment: HVSPH (the hvsph binary, default build/hvsph), RUNS (the folder of
# `hvsph validate` run folders, default out/validation), OUT (default docs/img); relative
# paths are taken from the directory the script is started in. Writes $OUT/rod-5839-cavity.png;
# without the run folder $RUNS/rod-5839, or with a run that has not reached the case's end, it
# says "skip: ..." and exits 0.
set -eu
abs() { case $1 in /*) printf '%s\n' "$1" ;; *) printf '%s\n' "$PWD/$1" ;; esac; }
root=$(cd "$(dirname "$0")/../.." && pwd)
HVSPH=$(abs "${HVSPH:-$root/build/hvsph}")
RUNS=$(abs "${RUNS:-$root/out/validation}")
OUT=$(abs "${OUT:-$root/docs/img}")
name=rod-5839-cavity
case=rod-5839
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
"$HVSPH" render "$snap" -o "$tmp" --quiet --mode particles --axis z --box -70mm,280mm,-50mm,50mm,0,1.5mm
mv "$tmp" "$OUT/$name.png"
echo "$OUT/$name.png from $snap"
