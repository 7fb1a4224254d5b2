#!/bin/sh
# Session 39: rod-5844 at the paper's counts (329 018 particles) with session 31's set
# (Johnson-Cook 4340 target, alpha = 0.2, beta = 0.4), hvsph a232b4e; from a scratch
# folder two levels below the repository root (out/s39).  As run: 1 thread to 39.7 us
# (beside the rod-5842 pair), stopped by SIGTERM and continued on 2 threads to 71.4 us,
# stopped for make check, continued to 82.6 us (the binary rebuilt by make check at
# 8b571c0, the solver a232b4e's) and stopped for the session's end; to be continued
# with the last line.
H=../../build/hvsph
$H run ../../examples/paper/rod-5844.yaml -o pc5844jc --threads 1 --quiet \
  --set "materials.st={library: steel-target-jc}" --set 'bodies[1].material=st' \
  --set sph.viscosity.alpha=0.2 --set sph.viscosity.beta=0.4
# hvsph restart pc5844jc --threads 2 --quiet
