#!/usr/bin/env bash
# Bitwise check for changes that must not change results (refactors, renames,
# reformatting): runs every case of examples/paper/ at resolution 0.2 and every case of
# examples/verification/ for 100 steps with two builds and compares every file each run
# writes, byte for byte, after masking what differs by design between builds (the
# version string "hvsph X.Y.Z (commit ...)", used_parameters.yaml's time of writing
# and run_segments.csv's wall times).
# Usage: tools/bitwise-check.sh REF_HVSPH NEW_HVSPH [SCRATCH] [CASE...]
#   e.g. tools/bitwise-check.sh /tmp/ref/hvsph build/hvsph
# Configure both builds with the same -DHVSPH_COMMIT=... (e.g. bitwise): the checkpoint
# records the version under its CRC, so the mask below cannot make two commits' equal.
# With CSV_ONLY=1 only the CSV files are compared, their '#' lines dropped: for a
# reference build from before a change of file layout (VTU block order, headers).
# Exit status 0 when every run is identical, 1 otherwise (the differing files listed).
# About 5 minutes on 2 cores (two runs of 29 cases).
set -u
ref=${1:?usage: tools/bitwise-check.sh REF_HVSPH NEW_HVSPH [SCRATCH] [CASE...]}
new=${2:?usage: tools/bitwise-check.sh REF_HVSPH NEW_HVSPH [SCRATCH] [CASE...]}
scratch=${3:-${TMPDIR:-/tmp}/hvsph-bitwise}
shift $(( $# < 3 ? $# : 3 ))
top=$(cd "$(dirname "$0")/.." && pwd)
cases=("$@")
if [ ${#cases[@]} -eq 0 ]; then
  cases=("$top"/examples/paper/*.yaml "$top"/examples/verification/*.yaml)
fi
rm -rf "$scratch" && mkdir -p "$scratch"
# mask the build's version string and the wall-clock columns before comparing
mask() {
  LC_ALL=C sed -E -e 's/hvsph [0-9]+\.[0-9]+\.[0-9]+[^ ]* \(commit [^)]*\)/hvsph VERSION/g' \
    -e 's/^# written: .*/# written: TIME/' "$1"
}
bad=0 n=0
for c in "${cases[@]}"; do
  c=$(realpath "$c"); name=$(basename "$c" .yaml)
  sets=(--set time.max_steps=100 --set output.csv=true)
  case "$c" in */paper/*) sets+=(--set resolution=0.2) ;; esac
  for side in ref new; do
    bin=$ref; [ $side = new ] && bin=$new
    # builds before 2026-12-07 take neither --overwrite nor --force (nor need them)
    extra=()
    "$bin" --help 2>&1 | grep -q -- '--overwrite' && extra=(--overwrite --force)
    (cd "$(dirname "$c")" && "$bin" run "$c" -o "$scratch/$side/$name" "${sets[@]}" \
      --threads 2 --quiet "${extra[@]}") > "$scratch/$side-$name.log" 2>&1
    echo $? > "$scratch/$side-$name.rc"
  done
  n=$((n + 1))
  if ! cmp -s "$scratch/ref-$name.rc" "$scratch/new-$name.rc"; then
    echo "DIFF $name: exit status $(cat "$scratch/ref-$name.rc") vs $(cat "$scratch/new-$name.rc")"
    bad=$((bad + 1)); continue
  fi
  same=1
  for f in "$scratch/ref/$name"/*; do
    b=$(basename "$f")
    [ "$b" = run_segments.csv ] && continue
    if [ "${CSV_ONLY:-0}" = 1 ]; then
      case "$b" in *.csv) ;; *) continue ;; esac
      if ! cmp -s <(grep -v '^#' "$f") <(grep -v '^#' "$scratch/new/$name/$b" 2>/dev/null); then
        echo "DIFF $name: $b"; same=0
      fi
      continue
    fi
    if [ ! -e "$scratch/new/$name/$b" ] || ! cmp -s <(mask "$f") <(mask "$scratch/new/$name/$b"); then
      echo "DIFF $name: $b"; same=0
    fi
  done
  for f in "$scratch/new/$name"/*; do
    [ -e "$scratch/ref/$name/$(basename "$f")" ] || { echo "DIFF $name: only new has $(basename "$f")"; same=0; }
  done
  if [ $same = 1 ]; then echo "same $name ($(ls "$scratch/ref/$name" | wc -l) files)"; else bad=$((bad + 1)); fi
done
echo "$((n - bad)) identical, $bad different (of $n cases; runs in $scratch)"
[ $bad -eq 0 ]
