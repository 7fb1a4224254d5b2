#!/usr/bin/env bash
# test_figures.sh — the contract of `make figures` (tools/figures/make-figures.sh and
# lib/common.sh; tools/README.md, "Figures"), on stand-in figure scripts in a copy of the
# two files, so that it runs in a second and needs neither Python nor simulations:
#  1. a script that draws counts as made, one whose run folder is missing as skipped
#     (its "skip: ..." line, exit 0), one that fails or exits 0 without a picture as
#     failed; the summary line counts 1 / 1 / 2 and the driver exits 1;
#  2. a failing script leaves the picture that was there before as it was, and no
#     temporary file;
#  3. only the scripts named run (the others' pictures untouched), and with no failure
#     the driver exits 0; an unknown name exits 2 and runs nothing;
#  4. HVSPH, RUNS and OUT reach the scripts, relative paths taken from where the
#     driver was started;
#  5. val-NAME.sh draws NAME.png and counts as made; fig_need_done skips a run whose
#     run_segments.csv does not end in a finished row, naming `validate --resume`.
set -u
src=${HVSPH_SOURCE_DIR:-.}
tmp=${HVSPH_TMP:-/tmp/hvsph-test}/test_figures
rm -rf "$tmp"
mkdir -p "$tmp/tree/tools/figures/lib" "$tmp/runs/present" "$tmp/out" || exit 1
cp "$src/tools/figures/make-figures.sh" "$tmp/tree/tools/figures/" || exit 1
cp "$src/tools/figures/lib/common.sh" "$tmp/tree/tools/figures/lib/" || exit 1
touch "$tmp/runs/present/measurements.csv"
mkdir -p "$tmp/runs/finished" "$tmp/runs/stopped" || exit 1
echo '1,v,a,b,c,d,e,f,g,done' > "$tmp/runs/finished/run_segments.csv"
echo '1,v,a,b,c,d,e,f,g,stopped' > "$tmp/runs/stopped/run_segments.csv"
fail=0
check() { # check CONDITION-STATUS MESSAGE
  if [ "$1" -eq 0 ]; then echo "  ok    $2"; else echo "  FAIL  $2"; fail=1; fi
}
fig() { # fig NAME BODY: a stand-in figure script
  printf '#!/usr/bin/env bash\n. "$(dirname "$0")/lib/common.sh"\n%s\n' "$2" \
    > "$tmp/tree/tools/figures/$1.sh"
}
fig drawn 'fig_need_run "$RUNS/present"; echo "$HVSPH" > "$FIG_TMP"; fig_done'
fig skipped 'fig_need_run "$RUNS/absent"; echo drawn > "$FIG_TMP"; fig_done'
fig broken 'echo half > "$FIG_TMP"; exit 3'
fig silent 'echo "drew nothing"'
fig val-finished 'fig_need_done finished; echo drawn > "$FIG_TMP"; fig_done'
fig unfinished 'fig_need_done finished stopped; echo drawn > "$FIG_TMP"; fig_done'
echo old > "$tmp/out/broken.png"

# 1. and 4.: from $tmp, with relative paths
out=$(cd "$tmp" && HVSPH=bin/hvsph RUNS=runs OUT=out bash tree/tools/figures/make-figures.sh 2>&1)
rc=$?
echo "$out" | sed 's/^/    /'
check $((rc != 1)) "one failed: exit status 1 (got $rc)"
echo "$out" | grep -q '^make-figures: 2 made, 2 skipped, 2 failed'
check $? "the summary counts 2 made, 2 skipped, 2 failed"
echo "$out" | grep -q '^  skip: skipped: no run in'
check $? "the skipped script says why"
echo "$out" | grep -q 'FAILED  silent (exit status 0, but it wrote no'
check $? "a script that exits 0 without its picture counts as failed"
[ "$(cat "$tmp/out/drawn.png" 2>/dev/null)" = "$tmp/bin/hvsph" ]
check $? "the picture is written, and HVSPH reached the script as an absolute path"
[ ! -e "$tmp/out/skipped.png" ]
check $? "a skipped script writes nothing"
[ "$(cat "$tmp/out/finished.png" 2>/dev/null)" = drawn ]
check $? "val-finished.sh draws finished.png (5.)"
echo "$out" | grep -q 'skip: unfinished: needs .*/runs/stopped run to its end (.* validate --resume --scale 1 --only stopped'
check $? "an unfinished run is skipped, naming validate --resume (5.)"

# 2.
[ "$(cat "$tmp/out/broken.png")" = old ]
check $? "a failing script leaves the earlier picture as it was"
[ -z "$(ls -A "$tmp/out" | grep tmp)" ]
check $? "no temporary picture is left behind"

# 3.
echo older > "$tmp/out/drawn.png"
out=$(cd "$tmp" && RUNS=runs OUT=out bash tree/tools/figures/make-figures.sh skipped 2>&1)
rc=$?
check $rc "only a skipped script named: exit status 0 (got $rc)"
[ "$(cat "$tmp/out/drawn.png")" = older ]
check $? "the scripts not named do not run"
out=$(cd "$tmp" && OUT=out bash tree/tools/figures/make-figures.sh drawn nosuch 2>&1)
rc=$?
check $((rc != 2)) "an unknown name: exit status 2 (got $rc)"
[ "$(cat "$tmp/out/drawn.png")" = older ]
check $? "an unknown name runs nothing"
echo "$out" | grep -q 'nosuch.sh: no such figure script'
check $? "and is named in the message"

exit $fail
