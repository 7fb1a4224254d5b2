#!/usr/bin/env bash
# docs/validation.md, the rods: penetration depth and cavity diameter of the six long-rod
# tests (the paper's Tables 1-3) over impact speed, hvsph beside the experiments and
# KERNEL. Made from the six runs of `hvsph validate --scale 1 --only rod-1929 rod-5835
# rod-5839 rod-5841 rod-5842 rod-5844` (the paper's particle counts): `hvsph validate
# --no-run` tabulates them in a scratch folder and plot_rods.py draws the table.
#
# Environment: HVSPH (the hvsph binary, default build/hvsph), RUNS (the folder of
# `hvsph validate` run folders, default out/validation), OUT (default docs/img), PY (the
# Python with matplotlib, default /usr/bin/python3: tools/install-deps.sh --docs);
# relative paths are taken from the directory the script is started in. Writes
# $OUT/rods-depth.png; with a rod's run folder missing or not run to its end it says
# "skip: ..." and exits 0.
set -eu
abs() { case $1 in /*) printf '%s\n' "$1" ;; *) printf '%s\n' "$PWD/$1" ;; esac; }
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
HVSPH=$(abs "${HVSPH:-$root/build/hvsph}")
RUNS=$(abs "${RUNS:-$root/out/validation}")
OUT=$(abs "${OUT:-$root/docs/img}")
PY=${PY:-/usr/bin/python3}
name="rods-depth"
rods="rod-1929 rod-5835 rod-5839 rod-5841 rod-5842 rod-5844"
for case in $rods; do
  run=$RUNS/$case
  if [ ! -f "$run/run_segments.csv" ]; then
    echo "skip: $name needs $run (hvsph validate --scale 1 --only $case -o $RUNS)"
    exit 0
  fi
  if [ "$(tail -n 1 "$run/run_segments.csv" | cut -d, -f10)" != "done" ]; then
    echo "skip: $name needs $run run to its end (hvsph validate --resume --scale 1 --only $case -o $RUNS)"
    exit 0
  fi
done
plot=$here/plot_rods.py   # where tools/figures keeps it; else its older place
[ -f "$plot" ] || plot=$root/tools/plot_rods.py
work=$(mktemp -d)
tmp=$OUT/.$name.tmp.png
trap 'rm -rf "$work" "$tmp"' EXIT
# the rods' folders seen from a scratch folder, so that the table --no-run writes
# there leaves $RUNS/validation.md and .csv as they are
for case in $rods; do ln -s "$RUNS/$case" "$work/$case"; done
# shellcheck disable=SC2086  # $rods is a list of names
"$HVSPH" validate --no-run --only $rods -o "$work" > "$work/validate.log" 2>&1 ||
  { cat "$work/validate.log" >&2; exit 1; }
mkdir -p "$OUT"
"$PY" "$plot" "$work/validation.csv" --label "hvsph (paper's counts)" -o "$tmp"
mv "$tmp" "$OUT/$name.png"
echo "$OUT/$name.png from $RUNS/{$(echo "$rods" | tr ' ' ,)}"
