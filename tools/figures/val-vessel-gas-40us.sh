#!/usr/bin/env bash
# docs/validation.md, the gas-filled vessel (§3): the nitrogen's density in the symmetry
# plane with the debris on it at 10, 20, 30 and 40 µs, as the paper's Fig. 3. Made from
# the run of `hvsph validate --scale 1 --only vessel` (the paper's particle counts) by
# plot_vessel.py, which also prints the shock front's and the debris's table.
#
# Environment: HVSPH (unused here; for the same interface as the other figure scripts),
# RUNS (the folder of `hvsph validate` run folders, default out/validation), OUT
# (default docs/img), PY (the Python with matplotlib, default /usr/bin/python3:
# tools/install-deps.sh --docs); relative paths are taken from the directory the script
# is started in. Writes $OUT/vessel-gas-40us.png; without the run folder $RUNS/vessel, or
# with a run that has not reached the case's end, it says "skip: ..." and exits 0.
set -eu
abs() { case $1 in /*) printf '%s\n' "$1" ;; *) printf '%s\n' "$PWD/$1" ;; esac; }
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
RUNS=$(abs "${RUNS:-$root/out/validation}")
OUT=$(abs "${OUT:-$root/docs/img}")
PY=${PY:-/usr/bin/python3}
name=vessel-gas-40us
case=vessel
run=$RUNS/$case
if [ ! -f "$run/run_segments.csv" ]; then
  echo "skip: $name needs $run (hvsph validate --scale 1 --only $case -o $RUNS)"
  exit 0
fi
if [ "$(tail -n 1 "$run/run_segments.csv" | cut -d, -f10)" != "done" ]; then
  echo "skip: $name needs $run run to its end (hvsph validate --resume --scale 1 --only $case -o $RUNS)"
  exit 0
fi
plot=$here/plot_vessel.py   # where tools/figures keeps it; else its older place
[ -f "$plot" ] || plot=$root/tools/plot_vessel.py
mkdir -p "$OUT"
tmp=$OUT/.$name.tmp.png
trap 'rm -f "$tmp"' EXIT
"$PY" "$plot" "$run" -o "$tmp" --times 10,20,30,40
mv "$tmp" "$OUT/$name.png"
echo "$OUT/$name.png from $run"
