#!/usr/bin/env bash
# Benchmark table for docs/performance.md: hvsph bench at 1e5 and 1e6 particles, 1 and
# 2 threads, gas and solid; each configuration run REPEAT times, the median reported.
# Usage: tools/bench.sh [BUILD_DIR] [REPEAT]   (run on an otherwise idle machine)
set -euo pipefail
build=${1:-build}
repeat=${2:-3}
median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
printf "| material | particles | threads | steps | particle-steps/s (median of %s) | µs per particle-step × threads | bytes/particle (arrays) | bytes/particle (peak RSS) |\n" "$repeat"
printf "|---|---|---|---|---|---|---|---|\n"
for mat in gas solid; do
  flag=""; [ "$mat" = solid ] && flag="--solid"
  for n in 100000 1000000; do
    steps=10; [ "$n" = 1000000 ] && steps=4
    for t in 1 2; do
      rates=(); arr=""; rss=""; core=()
      for r in $(seq "$repeat"); do
        out=$("$build/hvsph" bench --particles "$n" --steps "$steps" --threads "$t" $flag)
        rates+=("$(echo "$out" | awk '/particle-steps\/s/ {print $2}')")
        core+=("$(echo "$out" | awk '/us per particle-step/ {print $(NF-1)}')")
        arr=$(echo "$out" | awk '/bytes per particle/ {print $4}')
        rss=$(echo "$out" | awk '/bytes per particle/ {print $(NF-2)}')
        np=$(echo "$out" | awk '/^particles/ {print $2}')
      done
      printf "| %s | %s | %s | %s | %.3g | %s | %s | %s |\n" "$mat" "$np" "$t" "$steps" \
        "$(printf '%s\n' "${rates[@]}" | median)" "$(printf '%s\n' "${core[@]}" | median)" "$arr" "$rss"
    done
  done
done
