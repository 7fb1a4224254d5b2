#!/usr/bin/env bash
# docs/validation.md, §2.4: the aluminium backwall at the case's end, 80 µs, cut at
# z = 0 (a 1 mm slab; x from 190 to 215 mm, y within 60 mm of the axis), coloured by material.
# Made from the final snapshot of `hvsph validate --scale 1 --only whipple-steel` (the paper's
# particle counts) by `hvsph render`.
#
# Environment: HVSPH (the hvsph binary, default build/hvsph), RUNS (the folder of
# `hvsph validate` run folders, default out/validation), OUT (default docs/img); relative
# paths are taken from the directory the script is started in. Writes $OUT/whipple-steel-backwall-80us.png;
# without the run folder $RUNS/whipple-steel, or with a run that has not reached the case's end, it
# says "skip: ..." and exits 0.
set -eu
abs() { case $1 in /*) printf '%s\n' "$1" ;; *) printf '%s\n' "$PWD/$1" ;; esac; }
root=$(cd "$(dirname "$0")/../.." && pwd)
HVSPH=$(abs "${HVSPH:-$root/build/hvsph}")
RUNS=$(abs "${RUNS:-$root/out/validation}")
OUT=$(abs "${OUT:-$root/docs/img}")
name=whipple-steel-backwall-80us
case=whipple-steel
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
"$HVSPH" render "$snap" -o "$tmp" --quiet --mode particles --axis z --box 190mm,215mm,-60mm,60mm,0,1mm --size 1000
mv "$tmp" "$OUT/$name.png"
echo "$OUT/$name.png from $snap"
