#!/usr/bin/env bash
# test_sweep.sh — `hvsph sweep` on a tiny case (a 2 mm plate of 4 layers, 0.5 mm apart,
# with a hole of radius r along the impact axis, and a sphere; about 820 particles, run
# to 0.05 us: a few steps, a fraction of a second a point). The plate is measured as
# the backwall, so `perforated` is known without any impact: the lattice's columns
# nearest the axis sit at 0.354 mm (0.25 mm in y and z), so a hole of r > 0.354 mm
# removes them and leaves a line of sight (the next ones are 0.79 mm out, beyond the
# plate measurement's tolerance of one spacing, 0.5 mm), and r < 0.354 mm removes none:
# the critical radius is 0.3536 mm exactly, whatever the sphere's speed.
#  1. bad input exits 2 before any run and leaves no folder: a key the case does not
#     have (--vary, --bisect), an empty range, a bare number where the case writes a unit;
#  2. --vary (2 speeds) with --bisect of the hole's radius, 0.1..1 mm to 0.1 mm, --jobs 2:
#     exit 0,
#     ballistic_limit.csv's critical_diameter (the radius doubled) within half its bracket
#     of 2 x 0.3536 mm and the bracket no wider than the tolerance; sweep.csv's rows; the
#     PNG;
#  3. resume: the same sweep again runs nothing and writes the same sweep.csv; with one
#     point's .done removed, that point alone runs again;
#  4. a range whose two ends agree says the limit lies outside it;
#  5. a failed point (exit 3) is marked failed, the other point runs, the sweep exits 3;
#     a --measure that no run writes is named (exit 3);
#  6. --emit slurm writes a job array of the grid points; its tasks run by hand (as Slurm
#     would) and `hvsph sweep --collect` gather the same limits as (2); a point that said
#     yes at an earlier output and no at its last stays a yes;
#  7. a case holding its own `sweep:` runs with no options, and `hvsph run` takes it.
#  8. command-line mistakes exit 1 (2 for a stored command line that cannot be read).
set -u
BIN=${HVSPH_BIN:-build/hvsph}
T=${HVSPH_TMP:-/tmp/hvsph_test_sweep}
rm -rf "$T" && mkdir -p "$T"
cd "$T" || exit 1
pass=0 fail=0
check() {  # check STATUS MESSAGE
  if [ "$1" -eq 0 ]; then pass=$((pass + 1)); echo "PASS: $2"; else fail=$((fail + 1)); echo "FAIL: $2"; fi
}
cat > tiny-shield.yaml <<'YAML'
name: sweep-tiny
domain:
  min: [-3 mm, -6 mm, 0]
  max: [6 mm, 6 mm, 6 mm]
  half_model: true
  boundary: {x: absorbing, y: absorbing, z_max: absorbing}
bodies:
  - name: plate
    material: al-6061-t6
    shape:
      type: box
      min: [0, -5 mm, -5 mm]
      max: [2 mm, 5 mm, 5 mm]
      minus: [{type: cylinder, center: [1 mm, 0, 0], axis: [1, 0, 0], radius: 0.1 mm, length: 2 mm}]
    spacing: 0.5 mm
  - name: projectile
    material: al-2024-t3
    shape: {type: sphere, center: [-1.5 mm, 0, 0], radius: 1 mm}
    spacing: 0.5 mm
    speed: 1 km/s
time: {end: 0.05 us}
output: {every: 0.05 us}
measure: {backwall: plate}
YAML
HOLE='bodies[0].shape.minus[0].radius'
SPEED='bodies[1].speed'

# 1. bad input
for args in "--vary bodies[1].sped=1km/s,2km/s" "--bisect bodies[0].shape.radius=1mm..2mm" \
            "--bisect $HOLE=1mm..0.5mm" "--bisect $HOLE=0.5mm..0.5mm" "--vary $SPEED=1000,2000" \
            "--bisect $HOLE=0.1..1"; do
  out=$("$BIN" sweep tiny-shield.yaml -o bad $args 2>&1); st=$?
  check $(( st == 2 ? 0 : 1 )) "bad input ($args): exit 2 (got $st: $out)"
  check $([ ! -e bad ] && echo 0 || echo 1) "bad input ($args): no folder, no run"
done

# 2. vary and bisect
"$BIN" sweep tiny-shield.yaml -o s --vary "$SPEED=1 km/s,2 km/s" --bisect "$HOLE=0.1 mm..1 mm" \
    --tol "0.1 mm" --jobs 2 --threads 2 > s.out 2>&1
check $? "vary + bisect, two grid points side by side (--jobs 2): exit 0"
check $([ "$(grep -c '^[0-9]' s/ballistic_limit.csv)" = 2 ] && echo 0 || echo 1) \
  "ballistic_limit.csv: one row per grid point"
check $(head -2 s/ballistic_limit.csv | tail -1 | grep -q '^speed,obliquity,critical_diameter,' && echo 0 || echo 1) \
  "ballistic_limit.csv: columns speed, obliquity, critical_diameter"
awk -F, '/^[0-9]/ { r = $3 / 2; h = $4 / 2; ok = (r - 0.35355e-3 <= h + 1e-9 && 0.35355e-3 - r <= h + 1e-9 && 2 * h <= 0.1e-3 + 1e-12);
  if (!ok) bad = 1; n++ } END { exit (bad || n != 2) }' s/ballistic_limit.csv
check $? "critical radius 0.3536 mm within half the bracket, bracket <= 0.1 mm: $(grep '^[0-9]' s/ballistic_limit.csv | tr '\n' ' ')"
check $(awk -F, '/^[0-9]/ && ($1 != 1000 && $1 != 2000 || $2 != 0) { bad = 1 } END { exit bad }' s/ballistic_limit.csv; echo $?) \
  "speeds 1000 and 2000 m/s, obliquity 0"
npts=$(ls s/points/*.done | wc -l)
check $([ "$(grep -c ',ok,0,' s/sweep.csv)" = "$npts" ] && [ "$npts" -ge 8 ] && echo 0 || echo 1) \
  "sweep.csv: $npts points, all ok (4 layers)"
check $(grep -q '^point,bodies\[1\].speed,bodies\[0\].shape.minus\[0\].radius,.*perforated,crater_depth_max \[m\],hole_diameters \[m\],through_velocity \[m/s\],through_mass \[kg\],wall_layers,status,exit,wall_time \[s\]$' s/sweep.csv && echo 0 || echo 1) \
  "sweep.csv header"
check $(head -c 8 s/ballistic_limit.png | od -An -tx1 | tr -d ' \n' | grep -q '^89504e470d0a1a0a$' && echo 0 || echo 1) \
  "ballistic_limit.png is a PNG"

# 3. resume
cp s/sweep.csv s1.csv
"$BIN" sweep tiny-shield.yaml -o s --vary "$SPEED=1 km/s,2 km/s" --bisect "$HOLE=0.1 mm..1 mm" \
    --tol "0.1 mm" --threads 1 > s2.out 2>&1
check $? "resumed sweep: exit 0"
check $(grep -q 'running\|continuing' s2.out && echo 1 || echo 0) "resumed sweep: no point runs again"
cmp -s s1.csv s/sweep.csv
check $? "resumed sweep: the same sweep.csv"
one=$(ls s/points/*.done | head -1)
rm "$one"
"$BIN" sweep tiny-shield.yaml -o s --vary "$SPEED=1 km/s,2 km/s" --bisect "$HOLE=0.1 mm..1 mm" \
    --tol "0.1 mm" --threads 1 > s3.out 2>&1
check $? "sweep with an unfinished point: exit 0"
check $([ "$(grep -c 'running\|continuing' s3.out)" = 1 ] && [ -e "$one" ] && echo 0 || echo 1) \
  "sweep with an unfinished point: that point alone runs ($(grep 'running\|continuing' s3.out))"
check $(diff <(cut -d, -f1-11 s1.csv) <(cut -d, -f1-11 s/sweep.csv) > /dev/null && echo 0 || echo 1) \
  "sweep with an unfinished point: the same results"

# 4. outside the range
"$BIN" sweep tiny-shield.yaml -o o --bisect "$HOLE=0.5 mm..1 mm" --threads 1 > o.out 2>&1
check $? "range without the limit: exit 0"
check $(grep -q 'outside' o.out && grep -q '^[0-9.e+]*,0,nan,nan,.*outside the range: yes at both ends' o/ballistic_limit.csv && echo 0 || echo 1) \
  "range without the limit: said so ($(tail -1 o/ballistic_limit.csv))"

# 5. a failed point
"$BIN" sweep tiny-shield.yaml -o f --vary "time.end=0.05 us,10 s" --set "time.dt_init=10 s" \
    --set output.every=0 --threads 1 > f.out 2>&1
st=$?
check $(( st == 3 ? 0 : 1 )) "a failed point: the sweep exits 3 (got $st)"
check $(grep -q ',failed,3,' f/sweep.csv && grep -q ',ok,0,' f/sweep.csv && echo 0 || echo 1) \
  "a failed point: marked failed (exit 3), the other ok"

# a measurement no run writes: the points run, the sweep says which is missing, exit 3
"$BIN" sweep tiny-shield.yaml -o m --bisect "$HOLE=0.1 mm..1 mm" --measure perforatd --threads 1 > m.out 2>&1
st=$?
check $(( st == 3 ? 0 : 1 )) "an unknown --measure: exit 3 (got $st)"
check $(grep -q 'no perforatd of plate' m.out && grep -q 'no such measurement' m/ballistic_limit.csv && echo 0 || echo 1) \
  "an unknown --measure: named in the output and ballistic_limit.csv"

# 6. Slurm job array and --collect
"$BIN" sweep tiny-shield.yaml -o a --vary "$SPEED=1 km/s,2 km/s" --bisect "$HOLE=0.1 mm..1 mm" \
    --tol "0.1 mm" --emit slurm > a.out 2>&1
check $? "--emit slurm: exit 0"
check $(grep -q '^#SBATCH --array=0-1$' a/sweep.slurm && [ ! -e a/sweep.csv ] && echo 0 || echo 1) \
  "--emit slurm: a job array of 2 tasks, nothing run"
for i in 0 1; do
  SLURM_ARRAY_TASK_ID=$i SLURM_CPUS_PER_TASK=1 HVSPH="$BIN" bash a/sweep.slurm > "a$i.out" 2>&1
  check $? "job array task $i: exit 0"
done
"$BIN" sweep --collect a > c.out 2>&1
check $? "--collect: exit 0"
check $(diff <(grep '^[0-9]' s/ballistic_limit.csv) <(grep '^[0-9]' a/ballistic_limit.csv) > /dev/null && echo 0 || echo 1) \
  "--collect: the limits of the sweep run in one go"
# a yes that the last output no longer shows (spall or debris through the wall gone by an
# absorbing face, a line of sight closed again) stays a yes: the answer is yes when any
# output said yes. One yes point gets a later output reading no; collected again, the
# limits are the same (read at the last output only, that point would turn no and move
# its bracket, or put the limit outside the range)
yes_pt=$(grep -l ',perforated,1,,plate$' a/points/*/measurements.csv | head -1)
check $([ -n "$yes_pt" ] && echo 0 || echo 1) "--collect: a point that reads perforated"
echo "1,perforated,0,,plate" >> "$yes_pt"
"$BIN" sweep --collect a > c2.out 2>&1
check $(diff <(grep '^[0-9]' s/ballistic_limit.csv) <(grep '^[0-9]' a/ballistic_limit.csv) > /dev/null && echo 0 || echo 1) \
  "--collect: a yes at an earlier output stays a yes ($yes_pt)"

# 7. the case's own sweep
cp tiny-shield.yaml own.yaml
cat >> own.yaml <<'YAML'
sweep:
  vary:
    - {key: "bodies[1].speed", values: [1 km/s]}
  bisect: {key: "bodies[0].shape.minus[0].radius", low: 0.1 mm, high: 1 mm, tolerance: 0.1 mm}
  measure: perforated
YAML
"$BIN" sweep own.yaml -o w --threads 1 > w.out 2>&1
check $? "the case's own sweep: exit 0"
check $(diff <(grep '^1000,' s/ballistic_limit.csv) <(grep '^[0-9]' w/ballistic_limit.csv) > /dev/null && echo 0 || echo 1) \
  "the case's own sweep: the same limit"
"$BIN" run own.yaml -o r --threads 1 --quiet > r.out 2>&1
check $? "hvsph run takes a case with a sweep: section"
sed 's/tolerance:/tolerence:/' own.yaml > typo.yaml
out=$("$BIN" sweep typo.yaml -o typo 2>&1); st=$?
check $(( st == 2 ? 0 : 1 )) "a misspelt key of sweep: exit 2 (got $st: $out)"
check $(echo "$out" | grep -q "typo.yaml:[0-9]*: unknown key 'sweep.bisect.tolerence'" && [ ! -e typo ] && echo 0 || echo 1) \
  "a misspelt key of sweep: named with its line, nothing run"

# 8. command-line mistakes: exit 1 before anything is read or written, the argument named
#    as the hand-written walk over argv named it before the options went through
#    cli_parse (a value missing at the end, a --set beyond the 256 kept, "--name=value",
#    a second case, a line of a stored command line that is no sweep option); a stored
#    command line that cannot be read exits 2
usage() {  # usage "MESSAGE" ARGS...
  local want=$1; shift
  out=$("$BIN" sweep "$@" 2>&1); st=$?
  check $(( st == 1 ? 0 : 1 )) "command line '$*': exit 1 (got $st: $out)"
  check $(echo "$out" | grep -qF -- "$want" && [ ! -e u ] && echo 0 || echo 1) \
    "command line '$*': says $want, no folder"
}
printf '%s\n' "$T/tiny-shield.yaml" -o u --help > help-args.txt
sets=$(for i in $(seq 257); do printf -- '--set a=%d ' "$i"; done)
usage "unexpected argument '--jobs'" tiny-shield.yaml -o u --jobs
usage "--jobs needs a positive integer, not '0'" tiny-shield.yaml -o u --jobs 0
usage "--only needs a grid point's index, not 'x'" tiny-shield.yaml -o u --only x
usage "--emit pbs: only 'slurm' is known" tiny-shield.yaml -o u --emit pbs
usage "unexpected argument '--output=u'" tiny-shield.yaml --output=u
usage "unexpected argument 'own.yaml'" tiny-shield.yaml -o u own.yaml
usage "unexpected argument '--collect'" tiny-shield.yaml -o u --collect
usage "unexpected argument '--help'" --args-from help-args.txt
# shellcheck disable=SC2086
usage "unexpected argument '--set'" tiny-shield.yaml -o u $sets
out=$("$BIN" sweep --collect nowhere 2>&1); st=$?
check $(( st == 2 ? 0 : 1 )) "--collect of a folder without sweep_args.txt: exit 2 (got $st: $out)"
check $(echo "$out" | grep -qF "nowhere/sweep_args.txt: No such file or directory (not a sweep folder?)" \
  && echo 0 || echo 1) "--collect of a folder without sweep_args.txt: named"

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
