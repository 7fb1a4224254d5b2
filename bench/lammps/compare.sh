#!/bin/sh
# The sphere-on-plate impact in hvsph and in LAMMPS (MACHDYN ULSPH), one thread each,
# alternating, RUNS times; prints each run's wall time, simulated time and steps, and
# the medians of the wall time per simulated microsecond.
#   bench/lammps/compare.sh HVSPH LMP [RUNS] [TEND]
# HVSPH: an hvsph binary (Release); LMP: from bench/lammps/build-lammps.sh.
# RUNS default 3; TEND the simulated time in seconds, default 2e-6.
set -eu
hv=$1
lmp=$2
runs=${3:-3}
tend=${4:-2e-6}
here=$(cd "$(dirname "$0")" && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
for k in $(seq 1 "$runs"); do
  t0=$(date +%s.%N)
  OMP_NUM_THREADS=1 "$hv" run "$here/sphere_plate.yaml" -o "$scratch/hv$k" --threads 1 \
    --set time.end="$tend s" >"$scratch/hv$k.log" 2>&1
  t1=$(date +%s.%N)
  steps=$(tail -n 1 "$scratch/hv$k/run_segments.csv" | cut -d, -f7)
  echo "hvsph run $k: $(echo "$t1 - $t0" | bc) s wall, $steps steps"
  # MACHDYN prints its banner on stdout even with -screen none
  (cd "$scratch" && "$lmp" -in "$here/in.sphere_plate" -var tend "$tend" -log "lmp$k.log" \
    -screen none >"lmp$k.out" 2>&1) || true
  t2=$(date +%s.%N)
  lsteps=$(awk '/^Loop time/ {print $9}' "$scratch/lmp$k.log")
  echo "lammps run $k: $(echo "$t2 - $t1" | bc) s wall, $lsteps steps"
  echo "$k $(echo "$t1 - $t0" | bc) $(echo "$t2 - $t1" | bc)" >>"$scratch/times"
  rm -rf "$scratch/hv$k"
done
sort -k2 -n "$scratch/times" | awk -v n="$runs" -v te="$tend" \
  'NR == int((n + 1) / 2) {printf "median hvsph: %.1f s per simulated us\n", $2 / (te * 1e6)}'
sort -k3 -n "$scratch/times" | awk -v n="$runs" -v te="$tend" \
  'NR == int((n + 1) / 2) {printf "median LAMMPS: %.1f s per simulated us\n", $3 / (te * 1e6)}'
