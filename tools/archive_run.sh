#!/usr/bin/env bash
# Copies the small outputs of finished validation runs into the repository, so the
# numbers in docs/validation.md can be checked (and `hvsph validate --no-run` re-read)
# without the runs' snapshots and checkpoints, which stay out of git.
# Usage: tools/archive_run.sh RUNDIR DEST
#   e.g. tools/archive_run.sh out/validation-s11/wp1 docs/runs/s11/wp1
# Copies measurements.csv, summary.csv, run_segments.csv and used_parameters.yaml
# (each if present); refuses a RUNDIR without measurements.csv.
set -euo pipefail
if [ $# -ne 2 ]; then echo "usage: $0 RUNDIR DEST" >&2; exit 1; fi
src=$1 dest=$2
if [ ! -f "$src/measurements.csv" ]; then
  echo "archive_run: $src/measurements.csv: no such file (not a run folder?)" >&2; exit 2
fi
mkdir -p "$dest"
for f in measurements.csv summary.csv run_segments.csv used_parameters.yaml; do
  if [ -f "$src/$f" ]; then cp "$src/$f" "$dest/$f.tmp" && mv "$dest/$f.tmp" "$dest/$f"; fi
done
echo "archive_run: $src -> $dest ($(du -sh "$dest" | cut -f1))"
