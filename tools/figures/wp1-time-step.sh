#!/usr/bin/env bash
# docs/rendering.md, `--color dt`: W.P.1 at resolution 0.3 at 20 us, a slice 1.5 mm thick at
# z = 0 coloured by the time step each particle allows (the bumper's refined disc holds
# the run's step). Runs the case (62 467 particles, about 2 345 steps, 2.5 minutes on 2
# idle cores) into out/figures/wp1-time-step, then renders its snapshot at 20 us.
. "$(dirname "$0")/lib/common.sh"
fig_need_hvsph
fig_fresh_work
echo "$FIG_NAME: running examples/paper/wp1.yaml at resolution 0.3 to 20 us ($THREADS threads)"
"$HVSPH" run examples/paper/wp1.yaml -o "$FIG_WORK/wp1" --threads "$THREADS" -q \
  --set resolution=0.3 --set time.end=20us --set output.every=10us \
  --set output.csv=true --set output.vtu=false > "$FIG_WORK/run.log" 2>&1 ||
  fig_fail "the run failed (see $FIG_WORK/run.log)"
"$HVSPH" render "$FIG_WORK/wp1/particles_00002.csv" -o "$FIG_TMP" --mode particles \
  --color dt --box -20mm,210mm,-70mm,70mm,0,1.5mm
fig_done
