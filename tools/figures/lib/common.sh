# Sourced by the figure scripts tools/figures/*.sh (bash). The contract of a figure
# script (tools/README.md, "Figures"): it reads HVSPH (the hvsph binary, default
# build/hvsph), RUNS (a folder of `hvsph validate` run folders, default out/validation)
# and OUT (where the picture goes, default docs/img); it writes one picture,
# $OUT/<its own name>.png; where its input run folder is missing it prints one line
# "skip: ..." and exits 0; any other failure exits non-zero and leaves the picture that
# was there before as it was. Relative paths are taken from the directory the script was
# started in; the script itself works from the repository root.
#
# After sourcing: FIG_NAME (the script's name without .sh), FIG_PNG (the picture),
# FIG_TMP (write the picture here, then call fig_done, which renames it onto FIG_PNG so
# that a failure half-way never leaves a broken picture), FIG_WORK (a scratch folder of
# the script's own, $WORK/$FIG_NAME, WORK default out/figures), FIG_BUILD (the folder of
# the hvsph binary, where the test programs are), ROOT (the repository root), THREADS
# (threads for the runs a script makes, default 2) and PY (/usr/bin/python3, Debian's,
# which has python3-numpy and python3-matplotlib: tools/install-deps.sh --docs).
set -euo pipefail

fig_abs() { case $1 in /*) printf '%s\n' "$1" ;; *) printf '%s\n' "$PWD/$1" ;; esac; }

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)
HVSPH=$(fig_abs "${HVSPH:-$ROOT/build/hvsph}")
RUNS=$(fig_abs "${RUNS:-$ROOT/out/validation}")
OUT=$(fig_abs "${OUT:-$ROOT/docs/img}")
WORK=$(fig_abs "${WORK:-$ROOT/out/figures}")
THREADS=${THREADS:-2}
PY=${PY:-/usr/bin/python3}
# the pictures of docs/validation.md are named without their scripts' "val-" prefix
# (val-wp1-100us.sh draws wp1-100us.png); make-figures.sh looks for them by the same rule
FIG_NAME=$(basename "$0" .sh)
FIG_NAME=${FIG_NAME#val-}
FIG_PNG=$OUT/$FIG_NAME.png
FIG_TMP=$OUT/.$FIG_NAME.tmp.png
FIG_WORK=$WORK/$FIG_NAME
FIG_BUILD=$(dirname "$HVSPH")
cd "$ROOT"
mkdir -p "$OUT"
trap 'rm -f "$FIG_TMP"' EXIT

# fig_skip MESSAGE: the input is missing; nothing to draw (exit 0).
fig_skip() { echo "skip: $FIG_NAME: $*"; exit 0; }

# fig_fail MESSAGE: the figure cannot be made (exit 1).
fig_fail() { echo "$FIG_NAME: $*" >&2; exit 1; }

# fig_need_hvsph: the binary must exist (a figure of a run made here needs it).
fig_need_hvsph() {
  [ -x "$HVSPH" ] || fig_fail "$HVSPH: no hvsph binary (make build, or set HVSPH)"
}

# fig_need_python: Debian's python3 with numpy and matplotlib.
fig_need_python() {
  "$PY" -c 'import numpy, matplotlib' 2>/dev/null ||
    fig_fail "$PY cannot import numpy and matplotlib (bash tools/install-deps.sh --docs)"
}

# fig_need_run DIR: DIR must be a run folder (its measurements.csv); otherwise skip.
fig_need_run() {
  [ -f "$1/measurements.csv" ] ||
    fig_skip "no run in $1 (make it with: $HVSPH validate --scale 1 -o $RUNS)"
}

# fig_need_done CASE...: each $RUNS/CASE must be a run of `hvsph validate` that reached
# the case's end (the last row of its run_segments.csv says done in its 10th field);
# otherwise skip, naming the validate command that makes the run, or resumes it.
fig_need_done() {
  local case run
  for case in "$@"; do
    run=$RUNS/$case
    [ -f "$run/run_segments.csv" ] ||
      fig_skip "needs $run ($HVSPH validate --scale 1 --only $case -o $RUNS)"
    [ "$(tail -n 1 "$run/run_segments.csv" | cut -d, -f10)" = done ] ||
      fig_skip "needs $run run to its end ($HVSPH validate --resume --scale 1 --only $case -o $RUNS)"
  done
}

# fig_render_last CASE RENDER-OPTION...: the picture is `hvsph render` of the last
# particle snapshot of the finished run $RUNS/CASE (skipped without it, as
# fig_need_done), with the options given.
fig_render_last() {
  local case=$1
  shift
  fig_need_done "$case"
  local snaps=("$RUNS/$case"/particles_*.vtu) # in time order: the names are numbered
  local snap=${snaps[${#snaps[@]} - 1]}
  [ -f "$snap" ] || fig_fail "no snapshot in $RUNS/$case"
  fig_need_hvsph
  "$HVSPH" render "$snap" -o "$FIG_TMP" --quiet "$@"
  echo "$FIG_NAME: from $snap"
  fig_done
}

# fig_sweep_png CASE DEFAULT-DIR: the picture is the ballistic_limit.png of the `hvsph
# sweep` of CASE in SWEEP (default DEFAULT-DIR under the repository), collected again
# from its finished points (`hvsph sweep --collect` also rewrites its sweep.csv and
# ballistic_limit.csv); skipped without the sweep's sweep_args.txt.
fig_sweep_png() {
  local sweep
  sweep=$(fig_abs "${SWEEP:-$ROOT/$2}")
  [ -f "$sweep/sweep_args.txt" ] ||
    fig_skip "no sweep in $sweep (run: $HVSPH sweep $1 -o $sweep)"
  fig_need_hvsph
  "$HVSPH" sweep --collect "$sweep" > /dev/null
  cp "$sweep/ballistic_limit.png" "$FIG_TMP"
  echo "$FIG_NAME: from $sweep"
  fig_done
}

# fig_fresh_work: an empty scratch folder FIG_WORK (the script's own; nothing else).
fig_fresh_work() {
  rm -rf "$FIG_WORK"
  mkdir -p "$FIG_WORK"
}

# fig_test NAME [ARGS...]: runs the test program FIG_BUILD/test_NAME as ctest does, its
# scratch folder FIG_WORK/test_NAME (the layout plot_solids.py --tmp reads; FIG_TEST_DIR
# names another), with THREADS threads; ARGS go to the test (e.g. test_noh --spacings). A test that misses a threshold (exit 1) still leaves its profiles and
# snapshots, and the figure shows them: a warning, not a failure (make check is where
# thresholds fail). A crash or a missing program is a failure.
fig_test() {
  local name=$1 rc=0
  shift
  local dir=${FIG_TEST_DIR:-$FIG_WORK/test_$name}
  [ -x "$FIG_BUILD/test_$name" ] ||
    fig_fail "$FIG_BUILD/test_$name: no such test program (build the tests: make build)"
  fig_need_hvsph
  echo "$FIG_NAME: running test_$name${*:+ $*} ($THREADS threads) in $dir"
  HVSPH_BIN=$HVSPH HVSPH_SOURCE_DIR=$ROOT HVSPH_TMP=$dir \
    HVSPH_TEST_THREADS=$THREADS OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive} \
    "$FIG_BUILD/test_$name" "$@" > "$dir.log" 2>&1 || rc=$?
  case $rc in
    0) ;;
    1) echo "$FIG_NAME: warning: test_$name missed a threshold (see $dir.log)" ;;
    *) fig_fail "test_$name ended with status $rc (see $dir.log)" ;;
  esac
}

# fig_done: the picture drawn into FIG_TMP becomes FIG_PNG.
fig_done() {
  [ -s "$FIG_TMP" ] || fig_fail "nothing was drawn into $FIG_TMP"
  mv -f "$FIG_TMP" "$FIG_PNG"
  echo "made $FIG_PNG"
}

# fig_demo: the run of `make demo` (tools/demo.sh: W.P.1 at resolution 0.2 to 30 us, about
# a minute on 2 threads), out/demo-whipple, made by this HVSPH: reused when its last
# run_segments.csv row is a finished run of the same version as `HVSPH --version`,
# otherwise made again by tools/demo.sh. Sets DEMO (the folder) and DEMO_LAST (its last
# particle snapshot).
fig_demo() {
  fig_need_hvsph
  DEMO=$ROOT/out/demo-whipple
  local want have
  want=$("$HVSPH" --version | awk '{print $2}')
  # (under pipefail a missing file must not end the script: hence the || true)
  have=$( { tail -n 1 "$DEMO/run_segments.csv" 2>/dev/null || true; } |
          awk -F, '$NF == "done" {print $2}')
  if [ -z "$want" ] || [ "$have" != "$want" ]; then
    echo "$FIG_NAME: running the demo (tools/demo.sh $FIG_BUILD) into $DEMO"
    HVSPH_THREADS=$THREADS bash tools/demo.sh "$FIG_BUILD" > "$WORK/demo.log" 2>&1 ||
      fig_fail "tools/demo.sh failed (see $WORK/demo.log)"
  else
    echo "$FIG_NAME: the demo run in $DEMO is of this hvsph ($want): reused"
  fi
  DEMO_LAST=$( { ls "$DEMO"/particles_*.csv 2>/dev/null || true; } | sort | tail -n 1)
  [ -n "$DEMO_LAST" ] || fig_fail "$DEMO: no particles_*.csv after the demo"
}
