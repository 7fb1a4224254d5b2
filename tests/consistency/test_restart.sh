#!/usr/bin/env bash
# test_restart.sh — a run continued from its checkpoint writes the same files, bit for
# bit, as a run that was never stopped; a bad checkpoint is refused without harm.
#
# Case: examples/paper/bumper-1.yaml at resolution 0.04 (2 444 particles: a steel
# sphere through a steel plate at 3.08 km/s, the plate in two bodies (a finer disc
# around the impact point), half model with a symmetry plane, absorbing faces,
# elastic-plastic with fracture, measurements and fragments), to 12 us with
# outputs every 3 us and measurements every 1 us (measure.every); the far face is moved
# to x = 15 mm, so that particles are absorbed (removed) from 5 us on, before the stop. The reference run goes straight through. Then:
#  1. stopped by time.max_steps after 300 steps (between output times: it writes an
#     extra snapshot there), continued by `hvsph restart` on 1 thread (the reference
#     used 2): every file of the reference — snapshots .vtu/.csv, fragments, summary.csv,
#     run.pvd, measurements.csv, the final checkpoint — is identical;
#  2. killed with SIGKILL while writing a checkpoint every step (output.checkpoint_wall
#     1 us), then continued: identical again (the checkpoint on disk is always whole);
#  3. the finished reference carried on to 15 us (--set time.end=15us) equals a run
#     made to 15 us at once (so the final checkpoint holds the final state);
#  4. a finished run restarted again does nothing (exit 0); a damaged checkpoint (one
#     byte changed), a truncated one, a missing one and one from another resolution
#     end with exit status 2 and a message naming the file, and leave every file of
#     the folder as it was;
#     a new run in a folder holding an earlier run is refused (exit 2, every file as it
#     was) and, with --overwrite, replaces it (its checkpoint and snapshots removed);
#  5. `hvsph validate --resume` continues a validation run stopped by SIGINT, and its
#     validation.csv and measurements.csv equal those of a straight run;
#  6. 1. again with split material without tension (fracture.split: no-tension);
#  7. 1. again with the viscosity switch (sph.viscosity.switch: cullen-dehnen), whose
#     per-particle alpha and last velocity divergence are state; a run made without it
#     refuses to take it up when continued (exit 2, its files untouched);
#  8. 1. again with split along a crack (fracture.split: crack, and crack_eps_f for the
#     plate), whose crack normals and opening strains are state; a run made without it
#     refuses to take it up when continued (exit 2, its files untouched);
#  9. 8. continued from its checkpoint with the record p.fstate dropped (a checkpoint
#     from before the fracture state was a field): identical again;
# 10. individual time steps (time.individual): stopped after 25 blocks (of 55; each of
#     up to 64 of its finest steps) and continued on 1 thread, every file identical to
#     the straight run's on 2 threads — the per-particle last step, own limit, density
#     rate and velocity gradient are state; a run made without them refuses to take
#     them up when continued, and one made with them to drop them (exit 2, its files
#     untouched).
set -u
BIN=${HVSPH_BIN:-build/hvsph}
SRC=${HVSPH_SOURCE_DIR:-.}
T=${HVSPH_TMP:-/tmp/hvsph_test_restart}
rm -rf "$T" && mkdir -p "$T"
CASE=$SRC/examples/paper/bumper-1.yaml
# the far face at x = 15 mm (not 100) so that debris leaves through it from 5 us on
SETS=(--set resolution=0.04 --set time.end=12us --set output.every=3us --set output.csv=true
      --set 'domain.max=[15 mm, 50 mm, 50 mm]' --set measure.every=1us)
pass=0 fail=0
check() {  # check CONDITION-STATUS MESSAGE
  if [ "$1" -eq 0 ]; then pass=$((pass + 1)); echo "PASS: $2"; else fail=$((fail + 1)); echo "FAIL: $2"; fi
}
# every file of folder $1 (but used_parameters.yaml and run_segments.csv, which records
# wall times and thread counts) is in $2 with the same bytes
same_files() {
  local n=0 bad=0
  for f in "$1"/*; do
    b=$(basename "$f")
    [ "$b" = used_parameters.yaml ] || [ "$b" = run_segments.csv ] && continue
    n=$((n + 1))
    if ! cmp -s "$f" "$2/$b"; then echo "  differs: $b"; bad=1; fi
  done
  echo "  compared $n files"
  [ $bad -eq 0 ] && [ $n -ge 15 ]
}

"$BIN" run "$CASE" -o "$T/ref" "${SETS[@]}" --threads 2 --quiet 2> "$T/ref.log"
check $? "reference run to 12 us"
steps=$(tail -1 "$T/ref/summary.csv" | cut -d, -f1)
absorbed=$(tail -1 "$T/ref/summary.csv" | cut -d, -f12)
echo "  reference: $steps steps, $absorbed particles absorbed, $(ls "$T/ref" | wc -l) files"
mtimes=$(grep -v '^#' "$T/ref/measurements.csv" | tail -n +2 | cut -d, -f1 | sort -u | wc -l)
[ "$mtimes" -eq 13 ] && [ "$(grep -c '^[0-9]' "$T/ref/summary.csv")" -eq 5 ]
check $? "measure.every = 1 us: measurements at $mtimes times (0, 1, ..., 12 us), outputs at 5"
# 358 steps since e8a2b2f (the longer step of docs/models.md, "Why this signal speed"),
# 484 at 20f0a24: step 300 is still before the end, after the absorption began
[ "$steps" -gt 330 ] && [ "$absorbed" -gt 100 ]
check $? "the reference takes more than 330 steps ($steps), so step 300 is mid-run; over 100 particles absorbed ($absorbed)"

# 1. stopped between outputs, continued on another thread count
"$BIN" run "$CASE" -o "$T/a" "${SETS[@]}" --set time.max_steps=300 --threads 2 --quiet 2> "$T/a1.log"
check $? "run stopped by time.max_steps = 300"
stop_absorbed=$(tail -1 "$T/a/summary.csv" | cut -d, -f12)
[ -f "$T/a/checkpoint.hvc" ] && [ -f "$T/a/particles_00003.vtu" ] && [ "$stop_absorbed" -gt 0 ]
check $? "it left a checkpoint and an extra snapshot (particles_00003) at step 300, with $stop_absorbed particles absorbed by then"
"$BIN" restart "$T/a" --set time.max_steps=0 --threads 1 --quiet 2> "$T/a2.log"
check $? "hvsph restart continues it (1 thread)"
same_files "$T/ref" "$T/a"
check $? "continued run: every file identical to the reference"
seg=$(grep -c '^[0-9]' "$T/a/run_segments.csv")
grep -q '^0,.*,2,.*,0,0,300,.*,stopped (max_steps)$' "$T/a/run_segments.csv" &&
  grep -q '^1,.*,1,.*,300,.*,done$' "$T/a/run_segments.csv"
check $((seg - 2 + $?)) "run_segments.csv: two rows, 2 threads steps 0-300 stopped, 1 thread from 300 done"

# 2. killed (SIGKILL) while checkpointing every step, then continued
"$BIN" run "$CASE" -o "$T/k" "${SETS[@]}" --set output.checkpoint_wall=1us --threads 2 --quiet \
  2> "$T/k1.log" &
pid=$!
for _ in $(seq 1 2000); do   # until the run is past its first output and a few steps on
  [ -f "$T/k/checkpoint.hvc" ] && [ "$(grep -c '^[0-9]' "$T/k/summary.csv" 2>/dev/null)" -ge 2 ] && break
  sleep 0.01
done
kill -KILL $pid 2> /dev/null
wait $pid 2> /dev/null
ls -a "$T/k" | grep -q '\.tmp\.' && echo "  (a temporary file of the killed write is left: $(ls -a "$T/k" | grep '\.tmp\.'))"
rows=$(grep -c '^[0-9]' "$T/k/summary.csv")
echo "  killed with $rows summary rows"
"$BIN" restart "$T/k" --threads 2 --quiet 2> "$T/k2.log"
check $? "restart after SIGKILL"
grep -o "from its checkpoint at t = [^)]*)" "$T/k2.log" | head -1
same_files "$T/ref" "$T/k"
check $? "killed and continued run: every file identical to the reference"

# 3. a finished run carried further equals a longer run
"$BIN" run "$CASE" -o "$T/long" "${SETS[@]}" --set time.end=15us --threads 2 --quiet 2> /dev/null
check $? "reference run to 15 us"
cp -r "$T/ref" "$T/ext"
"$BIN" restart "$T/ext" --set time.end=15us --threads 2 --quiet 2> "$T/ext.log"
check $? "the 12 us run carried on to 15 us"
same_files "$T/long" "$T/ext"
check $? "carried-on run: every file identical to the 15 us run"

# 4. nothing to do; bad checkpoints
"$BIN" restart "$T/ref" --threads 2 2> "$T/done.log"
st=$?
grep -q "nothing to do" "$T/done.log"
check $((st + $?)) "restarting a finished run does nothing, exit 0 (status $st)"
bad_case() {  # bad_case NAME SETUP-COMMAND EXPECTED-MESSAGE [restart args]
  local d="$T/bad_$1"
  cp -r "$T/ref" "$d"
  eval "$2"
  (cd "$d" && md5sum * > "$T/before_$1.md5")
  "$BIN" restart "$d" "${@:4}" --threads 2 2> "$T/bad_$1.log"
  local st=$?
  echo "  $1: exit $st: $(tail -1 "$T/bad_$1.log")"
  [ $st -eq 2 ] && grep -q "$3" "$T/bad_$1.log" && grep -q "$d/checkpoint.hvc" "$T/bad_$1.log"
  check $? "$1 checkpoint: exit 2, message names the file and says '$3'"
  (cd "$d" && md5sum -c --quiet "$T/before_$1.md5") && [ -z "$(ls -a "$d" | grep '\.tmp\.')" ]
  check $? "$1 checkpoint: every file of the folder left as it was"
}
bad_case damaged "python3 -c 'import sys; p=sys.argv[1]; d=bytearray(open(p,\"rb\").read()); d[5000]^=0x10; open(p,\"wb\").write(bytes(d))' \$d/checkpoint.hvc" \
  "checksum does not match"
bad_case truncated "truncate -s 20000 \$d/checkpoint.hvc" "not a usable hvsph checkpoint"
bad_case missing "rm \$d/checkpoint.hvc" "no checkpoint to restart from"
bad_case other_resolution ":" "does not belong to this case" --set resolution=0.1

# a new run in a folder that holds an earlier run is refused, the folder untouched (it
# once removed the checkpoint: a "quick check" to t = 0 into the default out/<name> lost
# a finished run's); with --overwrite it replaces that run: its checkpoint and its
# snapshots beyond this run's go (killed before its own first checkpoint, `hvsph restart`
# would otherwise continue the old state under the new used_parameters.yaml)
cp -r "$T/ref" "$T/reuse"
(cd "$T/reuse" && md5sum * > "$T/before_reuse.md5")
"$BIN" run "$CASE" -o "$T/reuse" "${SETS[@]}" --set time.end=0 --threads 2 --quiet 2> "$T/reuse.log"
st=$?
[ $st -eq 2 ] && grep -q "holds an earlier run (checkpoint.hvc" "$T/reuse.log" &&
  (cd "$T/reuse" && md5sum -c --quiet "$T/before_reuse.md5") && [ -z "$(ls -A "$T/reuse" | grep '^\.')" ]
check $? "a new run (to t = 0) in a folder holding an earlier run: exit 2 ($st), every file as it was: $(tail -1 "$T/reuse.log" | cut -c1-120)"
"$BIN" run "$CASE" -o "$T/reuse" "${SETS[@]}" --set time.end=0 --overwrite --threads 2 2> "$T/reuse2.log"
st=$?
[ $st -eq 0 ] && [ ! -e "$T/reuse/checkpoint.hvc" ] && [ ! -e "$T/reuse/particles_00001.vtu" ] &&
  [ -e "$T/reuse/particles_00000.vtu" ] && grep -q "overwrite: removed the earlier run's" "$T/reuse2.log"
check $? "... with --overwrite it replaces it: no checkpoint, only the new snapshot (status $st)"

# a checkpoint of another hvsph version: continued, with a warning (the version record
# rewritten in place and the CRC-32 made good again)
cp -r "$T/ref" "$T/ver"
python3 - "$T/ver/checkpoint.hvc" <<'PY'
import struct, sys, zlib
p = sys.argv[1]; d = bytearray(open(p, 'rb').read()); pos = 16
while True:
    name = bytes(d[pos:pos + 56]).rstrip(b'\0'); t, _, n = struct.unpack('<IIQ', d[pos + 56:pos + 72])
    if name == b'version':
        d[pos + 72:pos + 72 + n] = b'v' * n; break
    pos += 72 + n * {1: 1, 2: 4, 3: 8, 4: 8}[t]
d[-4:] = struct.pack('<I', zlib.crc32(bytes(d[:-4])) & 0xffffffff)
open(p, 'wb').write(bytes(d))
PY
"$BIN" restart "$T/ver" --set time.end=13us --threads 2 2> "$T/ver.log"
st=$?
grep -q "was written by hvsph vvv" "$T/ver.log"
check $((st + $?)) "another version's checkpoint is continued with a warning (exit $st): $(grep -o 'warning: .\{0,60\}' "$T/ver.log")"

# output.checkpoint: false writes none, and a restart then says so
"$BIN" run "$CASE" -o "$T/nock" "${SETS[@]}" --set output.checkpoint=false \
  --set time.max_steps=50 --threads 2 --quiet 2> /dev/null
[ ! -e "$T/nock/checkpoint.hvc" ] && [ -f "$T/nock/summary.csv" ]
check $? "output.checkpoint: false writes no checkpoint"
"$BIN" restart "$T/nock" --threads 2 2> "$T/nock.log"
[ $? -eq 2 ] && grep -q "no checkpoint to restart from" "$T/nock.log"
check $? "... and hvsph restart then ends with exit 2: $(tail -1 "$T/nock.log")"

# 5. hvsph validate --resume continues an interrupted validation run
VSETS=(--scale 0.04 --only bumper-1 --threads 2)
"$BIN" validate "${VSETS[@]}" -o "$T/val_ref" > "$T/val_ref.log" 2>&1
check $? "validate bumper-1 at scale 0.04 straight through"
"$BIN" validate "${VSETS[@]}" -o "$T/val" > "$T/val1.log" 2>&1 &
pid=$!
for _ in $(seq 1 2000); do
  [ "$(grep -c '^[0-9]' "$T/val/bumper-1/summary.csv" 2>/dev/null)" -ge 2 ] && break
  sleep 0.01
done
kill -INT $pid 2> /dev/null
wait $pid
st=$?
echo "  validate interrupted: exit $st, $(grep -c '^[0-9]' "$T/val/bumper-1/summary.csv") summary rows"
"$BIN" validate --resume "${VSETS[@]}" -o "$T/val" > "$T/val2.log" 2>&1
st2=$?
grep -q "continuing the run" "$T/val2.log"
check $((st2 + $?)) "validate --resume continues it from its checkpoint (exit $st2)"
cmp -s "$T/val_ref/validation.csv" "$T/val/validation.csv" &&
  cmp -s "$T/val_ref/bumper-1/measurements.csv" "$T/val/bumper-1/measurements.csv"
check $? "its validation.csv and measurements.csv are identical to the straight run's"
grep -q '^| bumper-1 | [0-9]* | [0-9]* (2 segments) | ok |' "$T/val/validation.md"
check $? "validation.md gives its runtime summed over its 2 segments: $(grep '^| bumper-1 | [0-9]* |' "$T/val/validation.md")"

# a run with the options "$@" made straight to 12 us into $T/TAG_ref, and again stopped
# after 300 steps into $T/TAG and continued on 1 thread (sections 6-8)
straight_and_continued() {  # TAG LABEL OPTION...
  local tag=$1 label=$2
  shift 2
  "$BIN" run "$CASE" -o "$T/${tag}_ref" "${SETS[@]}" "$@" --threads 2 --quiet 2> /dev/null &&
    "$BIN" run "$CASE" -o "$T/$tag" "${SETS[@]}" "$@" --set time.max_steps=300 --threads 2 \
      --quiet 2> /dev/null &&
    "$BIN" restart "$T/$tag" --set time.max_steps=0 --threads 1 --quiet 2> /dev/null
  check $? "$label: straight run, stopped run and its continuation"
}
# a copy of the no-tension run ($T/nt_ref, made without OPTION...) continued with them
# must end with exit 2 and a message matching PATTERN, its files untouched
refuses_to_take_up() {  # TAG LABEL PATTERN OPTION...
  local tag=$1 label=$2 pattern=$3
  shift 3
  cp -r "$T/nt_ref" "$T/$tag"
  "$BIN" restart "$T/$tag" "$@" --set time.end=15us --quiet > "$T/$tag.log" 2>&1
  local st=$?
  [ $st -eq 2 ] && grep -q "$pattern" "$T/$tag.log" && same_files "$T/nt_ref" "$T/$tag"
  check $? "$label: continuing a run made without it ends with exit 2 ($st) and a message, files untouched"
}

# 6. split material without tension (fracture.split: no-tension): its state is (rho, e,
#    S) with S projected at each step's end and p from the EOS, so a continued run must
#    again equal a straight one
NT=(--set materials.steel-bumper.library=steel-bumper
    --set materials.steel-bumper.fracture.split=no-tension
    --set materials.steel-projectile.library=steel-projectile
    --set materials.steel-projectile.fracture.split=no-tension)
straight_and_continued nt "split: no-tension" "${NT[@]}"
nsplit=$(awk -F, 'NR > 2 && $17 == 1' "$T/nt_ref/particles_00004.csv" | wc -l)
[ "$nsplit" -gt 100 ]
check $? "split: no-tension: $nsplit particles split by 12 us"
same_files "$T/nt_ref" "$T/nt"
check $? "split: no-tension: continued run, every file identical to the straight run's"

# 7. the viscosity switch: alpha and the last divergence are carried in the checkpoint
SW=(--set sph.viscosity.switch=cullen-dehnen)
straight_and_continued sw "switch" "${SW[@]}"
head -3 "$T/sw_ref/particles_00004.csv" | grep -q ',alpha'
check $? "switch: the snapshots carry each particle's alpha"
same_files "$T/sw_ref" "$T/sw"
check $? "switch: continued run, every file identical to the straight run's"
# a run made without the switch cannot take it up when continued: exit 2, nothing changed
refuses_to_take_up nt_sw "switch" "without sph.viscosity.switch" "${SW[@]}"

# 8. split along a crack (fracture.split: crack) with the cracked state's strain to failure
#    (crack_eps_f): the crack normal and opening strain are state, carried in the
#    checkpoint; a run made without the crack cannot take it up when continued
CR=(--set materials.steel-bumper.library=steel-bumper
    --set materials.steel-bumper.fracture.split=crack
    --set materials.steel-bumper.fracture.crack_eps_f=0.3
    --set materials.steel-projectile.library=steel-projectile
    --set materials.steel-projectile.fracture.split=crack)
straight_and_continued cr "split: crack" "${CR[@]}"
dcol=$(grep -m1 '^id,' "$T/cr_ref/particles_00004.csv" | tr ',' '\n' | grep -n '^damage$' | cut -d: -f1)
ncr=$(awk -F, -v c="${dcol:-0}" '$1 !~ /^[#i]/ && $c == 1' "$T/cr_ref/particles_00004.csv" | wc -l)
nfl=$(awk -F, -v c="${dcol:-0}" '$1 !~ /^[#i]/ && $c == 2' "$T/cr_ref/particles_00004.csv" | wc -l)
[ "$ncr" -gt 50 ] && [ "$nfl" -gt 50 ]
check $? "split: crack: $ncr particles cracked (damage 1) and $nfl split again (damage 2) by 12 us"
same_files "$T/cr_ref" "$T/cr"
check $? "split: crack: continued run, every file identical to the straight run's"
refuses_to_take_up nt_cr "split: crack" "without fracture.split: crack" "${CR[@]}"

# 9. a checkpoint from before the fracture state was a field (no record p.fstate; made
#    here by dropping the record from the crack run's, its CRC recomputed): the state
#    follows from the damage, so the continued run is again identical to the straight one
"$BIN" run "$CASE" -o "$T/cr_old" "${SETS[@]}" "${CR[@]}" --set time.max_steps=300 \
  --threads 2 --quiet 2> /dev/null &&
  python3 - "$T/cr_old/checkpoint.hvc" <<'PY'
import struct, sys, zlib
path = sys.argv[1]
b = open(path, 'rb').read()
out, off, dropped = bytearray(b[:16]), 16, 0
while True:   # records: name[56], uint32 type, uint32 0, uint64 count, data (io/checkpoint.h)
    name = b[off:off + 56].rstrip(b'\0')
    typ, _, cnt = struct.unpack_from('=IIQ', b, off + 56)
    end = off + 72 + cnt * {1: 1, 2: 4, 3: 8, 4: 8}[typ]
    if name == b'p.fstate':
        dropped = 1
    else:
        out += b[off:end]
    off = end
    if name == b'end':
        break
out += struct.pack('=I', zlib.crc32(bytes(out)) & 0xffffffff)
open(path, 'wb').write(bytes(out))
sys.exit(0 if dropped else 1)
PY
check $? "split: crack: a run stopped at step 300, its checkpoint without the record p.fstate"
"$BIN" restart "$T/cr_old" --set time.max_steps=0 --threads 1 --quiet 2> /dev/null &&
  same_files "$T/cr_ref" "$T/cr_old"
check $? "split: crack: continued from a checkpoint without p.fstate, every file identical"

# 10. individual time steps: a checkpoint is written between blocks, where every particle
#     has ended its step; what the next block needs beyond the global step's state (each
#     particle's last step, its own limit, its last density rate and velocity gradient)
#     is in it
IND=(--set time.individual=true)
"$BIN" run "$CASE" -o "$T/ind_ref" "${SETS[@]}" "${IND[@]}" --threads 2 --quiet 2> /dev/null &&
  "$BIN" run "$CASE" -o "$T/ind" "${SETS[@]}" "${IND[@]}" --set time.max_steps=25 --threads 2 \
    --quiet 2> /dev/null &&
  "$BIN" restart "$T/ind" --set time.max_steps=0 --threads 1 --quiet 2> /dev/null
check $? "individual: straight run, run stopped after 25 blocks and its continuation"
nblk=$(awk -F, '$1 ~ /^[0-9]/ {s = $1} END {print s}' "$T/ind_ref/summary.csv")
[ "${nblk:-0}" -gt 25 ]
check $? "individual: the straight run took $nblk blocks (> 25: the stop fell within it)"
same_files "$T/ind_ref" "$T/ind"
check $? "individual: continued run on 1 thread, every file identical to the straight run's on 2"
refuses_to_take_up nt_ind "individual" "without time.individual" "${IND[@]}"
# and an individual run is not continued with the global step (its next step is a block)
cp -r "$T/ind_ref" "$T/ind_g"
"$BIN" restart "$T/ind_g" --set time.individual=false --set time.end=15us --quiet \
  > "$T/ind_g.log" 2>&1
st=$?
[ $st -eq 2 ] && grep -q "made with time.individual" "$T/ind_g.log" && same_files "$T/ind_ref" "$T/ind_g"
check $? "individual: continuing it with the global step ends with exit 2 ($st) and a message, files untouched"

echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
