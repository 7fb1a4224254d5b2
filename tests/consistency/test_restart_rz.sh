#!/usr/bin/env bash
# test_restart_rz.sh — an axisymmetric (RZ) run continued from its checkpoint writes the
# same files, bit for bit, as a run that was never stopped, and the checkpoint records
# the geometry.
#
# Case: examples/verification/taylor_bar_rz.yaml at spacing 0.54 mm (360 rings of copper
# with strength, the axis ghosts and a wall), to 4 us with outputs every 1 us. The
# reference runs straight through on 2 threads; the other stops after 100 steps
# (time.max_steps, between outputs) and `hvsph restart` continues it on 1 thread: every
# file (snapshots, summary.csv, run.pvd, the final checkpoint) must be identical, and
# the continued snapshots must still be axisymmetric (z = 0 for every ring).
set -u
BIN=${HVSPH_BIN:-build/hvsph}
SRC=${HVSPH_SOURCE_DIR:-.}
T=${HVSPH_TMP:-/tmp/hvsph_test_restart_rz}
rm -rf "$T" && mkdir -p "$T"
CASE=$SRC/examples/verification/taylor_bar_rz.yaml
SETS=(--set 'bodies[0].spacing=0.54 mm' --set time.end=4us --set output.every=1us
      --set output.vtu=true)
pass=0 fail=0
check() {  # check CONDITION-STATUS MESSAGE
  if [ "$1" -eq 0 ]; then pass=$((pass + 1)); echo "PASS: $2"; else fail=$((fail + 1)); echo "FAIL: $2"; fi
}
"$BIN" run "$CASE" -o "$T/ref" "${SETS[@]}" --threads 2 --quiet 2> "$T/ref.log"
check $? "reference RZ run to 4 us"
steps=$(tail -1 "$T/ref/summary.csv" | cut -d, -f1)
[ "$steps" -gt 130 ]
check $? "the reference takes more than 130 steps ($steps), so step 100 is mid-run"
"$BIN" run "$CASE" -o "$T/a" "${SETS[@]}" --set time.max_steps=100 --threads 2 --quiet 2> "$T/a1.log"
check $? "RZ run stopped by time.max_steps = 100"
"$BIN" restart "$T/a" --set time.max_steps=0 --threads 1 --quiet 2> "$T/a2.log"
check $? "hvsph restart continues it (1 thread)"
n=0 bad=0
for f in "$T/ref"/*; do
  b=$(basename "$f")
  [ "$b" = used_parameters.yaml ] || [ "$b" = run_segments.csv ] && continue
  n=$((n + 1))
  if ! cmp -s "$f" "$T/a/$b"; then echo "  differs: $b"; bad=1; fi
done
echo "  compared $n files"
[ $bad -eq 0 ] && [ $n -ge 10 ]
check $? "continued RZ run: every file identical to the reference"
last=$(ls "$T/a"/particles_*.csv | tail -1)
awk -F, '!/^#/ && !/^id,/ && $4 != 0 { bad = 1 } END { exit bad }' "$last"
check $? "the continued run's rings stay in the half-plane (z = 0)"
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
