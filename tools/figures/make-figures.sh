#!/usr/bin/env bash
# `make figures`: makes the documentation's pictures by running every figure script
# tools/figures/*.sh but this one (or only those named: make-figures.sh sod-shock-tube
# taylor-bar ...), each with the environment HVSPH (the hvsph binary, default
# build/hvsph), RUNS (the folder of `hvsph validate` run folders, default
# out/validation) and OUT (default docs/img); each writes $OUT/<its name>.png (val-NAME.sh
# writes NAME.png), or prints
# "skip: ..." when its input runs are missing (tools/README.md, "Figures").
# Counts what was made, skipped and failed; exits 1 if any failed, 0 otherwise. A script
# counts as failed when it exits non-zero, and also when it exits 0 without a skip line
# and without having written its picture.
set -uo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
abs() { case $1 in /*) printf '%s\n' "$1" ;; *) printf '%s\n' "$PWD/$1" ;; esac; }
HVSPH=$(abs "${HVSPH:-$root/build/hvsph}")
RUNS=$(abs "${RUNS:-$root/out/validation}")
OUT=$(abs "${OUT:-$root/docs/img}")
export HVSPH RUNS OUT
cd "$root" || exit 1

scripts=()
if [ $# -gt 0 ]; then
  for name in "$@"; do
    s=tools/figures/${name%.sh}.sh
    if [ ! -f "$s" ] || [ "$s" = tools/figures/make-figures.sh ]; then
      echo "make-figures: $s: no such figure script" >&2
      exit 2
    fi
    scripts+=("$s")
  done
else
  for s in tools/figures/*.sh; do
    [ "$s" = tools/figures/make-figures.sh ] || scripts+=("$s")
  done
fi

mkdir -p "$OUT" || exit 1
stamp=$(mktemp) || exit 1
log=$(mktemp) || exit 1
trap 'rm -f "$stamp" "$log"' EXIT
made=0 skipped=0 failed=0 failures=""
echo "make-figures: ${#scripts[@]} scripts; HVSPH=$HVSPH RUNS=$RUNS OUT=$OUT"
for s in "${scripts[@]}"; do
  name=$(basename "$s" .sh)
  pic=$OUT/${name#val-}.png # lib/common.sh: val-NAME.sh draws NAME.png
  start=$(date +%s)
  touch "$stamp"
  # the script's lines as they come (a run can take minutes), and kept for the skip check
  bash "$s" 2>&1 | tee "$log" | sed -u 's/^/  /'
  rc=${PIPESTATUS[0]}
  took=$(( $(date +%s) - start ))
  if [ $rc -ne 0 ]; then
    failed=$((failed + 1)); failures="$failures $name"
    echo "FAILED  $name (exit status $rc, ${took} s)"
  elif grep -q '^skip: ' "$log"; then
    skipped=$((skipped + 1))
    echo "skipped $name"
  elif [ ! -f "$pic" ] || [ "$stamp" -nt "$pic" ]; then
    failed=$((failed + 1)); failures="$failures $name"
    echo "FAILED  $name (exit status 0, but it wrote no $pic)"
  else
    made=$((made + 1))
    echo "made    $(basename "$pic") (${took} s)"
  fi
done
echo "make-figures: $made made, $skipped skipped, $failed failed${failures:+ (failed:$failures)}"
[ $failed -eq 0 ]
