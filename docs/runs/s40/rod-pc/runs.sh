#!/bin/sh
# Session 40: rods 5841 and 5842 at the paper's counts (329 018 particles each) with
# session 31's set (the Johnson-Cook 4340 target, alpha = 0.2, beta = 0.4), hvsph eaad7d8,
# 1 thread each, both at once on the 2-core machine, from a scratch folder two levels
# below the repository root (out/s40).  Stopped by SIGTERM for the session's end (each
# writes its checkpoint and its measurements at that time); to be continued with the
# last lines.  Then copy measurements.csv, summary.csv, run_segments.csv and
# used_parameters.yaml of each here and run /usr/bin/python3 pc.py > pc.txt
H=../../build/hvsph
for r in 5842 5841; do
  $H run ../../examples/paper/rod-$r.yaml -o pc${r}jc --threads 1 --quiet \
    --set "materials.st={library: steel-target-jc}" --set 'bodies[1].material=st' \
    --set sph.viscosity.alpha=0.2 --set sph.viscosity.beta=0.4 > pc${r}jc.log 2>&1 &
done
wait
# (the same, since 7b26924: --material steel-target=steel-target-jc in place of the first two --set)
# $H restart pc5842jc --threads 1 --quiet & $H restart pc5841jc --threads 1 --quiet & wait
