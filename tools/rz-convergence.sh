#!/usr/bin/env bash
# The convergence study of issue 74 (docs/validation.md, "Convergence in RZ"): rod-5841,
# rod-5844 and W.P.1 of examples/paper/rz/ at 4, 8, 16 and 32 particles per projectile
# radius (resolution 0.16, 0.64, 2.56, 10.24: the cases' resolution 1 is ten per radius
# and the ring count scales with it, so per radius = 10 x sqrt(resolution)), with Table 2's
# materials ("table2") and with the sourced set ("sourced": --material
# steel-target=steel-4340 --material tungsten-alloy=tungsten-wha-rod, the rods' headers).
# W.P.1 is aluminium on aluminium, which the sourced set leaves as it is: it runs with
# "table2" only.
#
# Usage: tools/rz-convergence.sh [--check] [--collect] [--cases "rod-5841 rod-5844 wp1"]
#          [--resolutions "0.16 0.64 2.56 10.24"] [--sets "table2 sourced"]
# Environment: HVSPH (the binary, default build/hvsph), WORK (the study's folder, default
# out/rz-convergence), THREADS (threads of each run, default 2), NICE (the runs' niceness,
# default 0).
#
# Points run one after another, coarsest first (all cases at one resolution before the
# next), each as `hvsph run CASE -o WORK/CASE-SET-rRES --set resolution=RES [--material
# ...]`, its messages in WORK/CASE-SET-rRES.log. A finished point leaves
# WORK/CASE-SET-rRES.done ("EXIT-STATUS WALL-SECONDS") and is not run again; a point
# stopped half-way (a checkpoint, no .done) continues with `hvsph restart`, so a stopped
# study continues when started again. A point that fails (exit status 3) is marked so
# and the others go on.
# --check runs nothing but `hvsph check` of each point (particles, steps and wall time
#   estimated), into WORK/check-CASE-SET-rRES.txt, and prints the summary lines.
# --collect runs nothing: it writes WORK/convergence.csv from the finished points.
# convergence.csv, one row per point: case, set, resolution, per_radius (10 sqrt(res)),
# particles (rings), steps, wall_s (over all its run segments), status (ok, failed, or
# running for a point without .done: its values are those of its last measurement, its
# steps and wall_s those of its last checkpoint),
# time (the last measured time [s]), depth and diameter (the thick target's
# penetration_depth and cavity_diameter [m], at the last time), hole (the bumper's
# hole_diameter [m], at the last time); nan where the case has no such measurement.
# tools/figures/val-rz-convergence.sh draws it.
set -euo pipefail
abs() { case $1 in /*) printf '%s\n' "$1" ;; *) printf '%s\n' "$PWD/$1" ;; esac; }
root=$(cd "$(dirname "$0")/.." && pwd)
hvsph=$(abs "${HVSPH:-$root/build/hvsph}")
work=$(abs "${WORK:-$root/out/rz-convergence}")
threads=${THREADS:-2}
niceness=${NICE:-0}
cases="rod-5841 rod-5844 wp1"
resolutions="0.16 0.64 2.56 10.24"
sets="table2 sourced"
mode=run
while [ $# -gt 0 ]; do
  case $1 in
  --check) mode=check ;;
  --collect) mode=collect ;;
  --cases) cases=$2; shift ;;
  --resolutions) resolutions=$2; shift ;;
  --sets) sets=$2; shift ;;
  -h | --help) sed -n '2,34p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
  *) echo "rz-convergence: unknown argument '$1' (--help)" >&2; exit 1 ;;
  esac
  shift
done
cd "$root"
[ -x "$hvsph" ] || { echo "rz-convergence: $hvsph: no hvsph binary (make build, or set HVSPH)" >&2; exit 1; }
mkdir -p "$work"

# material options of a set; "skip" where the set does not apply to the case
set_options() { # CASE SET
  case $2 in
  table2) echo "" ;;
  sourced)
    if grep -q 'steel-target\|tungsten-alloy' "examples/paper/rz/$1.yaml"; then
      echo "--material steel-target=steel-4340 --material tungsten-alloy=tungsten-wha-rod"
    else
      echo skip
    fi ;;
  *) echo "rz-convergence: unknown set '$2' (table2, sourced)" >&2; exit 1 ;;
  esac
}

# the last value of QUANTITY of OBJECT in a measurements.csv (nan without one)
last_value() { # FILE QUANTITY OBJECT
  awk -F, -v q="$2" -v o="$3" '$2 == q && $5 == o { v = $3 } END { print (v == "" ? "nan" : v) }' "$1"
}

collect() {
  local csv=$work/convergence.csv tmp=$work/.convergence.csv.tmp
  echo "case,set,resolution,per_radius,particles,steps,wall_s,status,time,depth,diameter,hole" > "$tmp"
  for res in $resolutions; do
    for c in $cases; do
      for s in $sets; do
        [ "$(set_options "$c" "$s")" = skip ] && continue
        local p=$work/$c-$s-r$res status wall steps n t
        [ -f "$p/measurements.csv" ] || continue
        if [ -f "$p.done" ]; then
          [ "$(cut -d' ' -f1 "$p.done")" = 0 ] && status=ok || status=failed
        else
          status=running
        fi
        # wall time and last step over the run segments (a restart adds a row)
        wall=$(awk -F, '!/^#/ && $1 != "segment" { w += $9 } END { printf "%.1f", w }' "$p/run_segments.csv" 2> /dev/null || echo nan)
        steps=$(awk -F, '!/^#/ && $1 != "segment" { s = $7 } END { print (s == "" ? "nan" : s) }' "$p/run_segments.csv" 2> /dev/null || echo nan)
        n=$(awk -F, '!/^#/ && $1 != "step" { n = $4 } END { print (n == "" ? "nan" : n) }' "$p/summary.csv")
        t=$(awk -F, '!/^#/ && $1 != "time" { t = $1 } END { print (t == "" ? "nan" : t) }' "$p/measurements.csv")
        printf '%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s\n' "$c" "$s" "$res" \
          "$(awk -v r="$res" 'BEGIN { printf "%.3g", 10 * sqrt(r) }')" "$n" "$steps" "$wall" \
          "$status" "$t" "$(last_value "$p/measurements.csv" penetration_depth target)" \
          "$(last_value "$p/measurements.csv" cavity_diameter target)" \
          "$(last_value "$p/measurements.csv" hole_diameter bumper)" >> "$tmp"
      done
    done
  done
  mv "$tmp" "$csv"
  echo "rz-convergence: $csv"
}

"$hvsph" --version
for res in $resolutions; do
  [ $mode = collect ] && break
  for c in $cases; do
    for s in $sets; do
      opts=$(set_options "$c" "$s")
      [ "$opts" = skip ] && continue
      p=$work/$c-$s-r$res
      read -ra optv <<< "$opts"
      if [ $mode = check ]; then
        nice -n "$niceness" "$hvsph" check "examples/paper/rz/$c.yaml" --threads "$threads" \
          --set resolution="$res" "${optv[@]}" > "$work/check-$c-$s-r$res.txt" 2>&1 || true
        echo "$c $s r$res: $(grep -E '^case ' "$work/check-$c-$s-r$res.txt" | sed 's/.*: //')"
        grep -E '^(steps|wall time) ' "$work/check-$c-$s-r$res.txt" | sed 's/^/    /'
        continue
      fi
      [ -f "$p.done" ] && { echo "rz-convergence: $p done ($(cat "$p.done"))"; continue; }
      echo "rz-convergence: $c, set $s, resolution $res -> $p ($(date -u +%H:%M:%S) UTC)"
      start=$(date +%s)
      rc=0
      if [ -f "$p/checkpoint.hvc" ]; then
        nice -n "$niceness" "$hvsph" restart "$p" --threads "$threads" --quiet >> "$p.log" 2>&1 || rc=$?
      else
        nice -n "$niceness" "$hvsph" run "examples/paper/rz/$c.yaml" -o "$p" --overwrite \
          --threads "$threads" --quiet --set resolution="$res" "${optv[@]}" > "$p.log" 2>&1 || rc=$?
      fi
      [ $rc = 130 ] && { echo "rz-convergence: stopped; run again to continue" >&2; exit 130; }
      echo "$rc $(($(date +%s) - start))" > "$p.done"
      [ $rc = 0 ] || echo "rz-convergence: $p failed (exit status $rc): $(tail -n 1 "$p.log")" >&2
    done
  done
done
[ $mode = check ] || collect
