#!/bin/sh
# Session 44, after runs.sh: rod-1929 at the paper's counts with the same set, 2 threads,
# from out/s44 (started once runs.sh's rod-5835 had ended).
H=../../build/hvsph
while pgrep -f 'rod-5835.yaml -o pc5835jc' > /dev/null; do sleep 30; done
$H run ../../examples/paper/rod-1929.yaml -o pc1929jc --threads 2 --quiet \
  --material steel-target=steel-target-jc \
  --set sph.viscosity.alpha=0.2 --set sph.viscosity.beta=0.4 > pc1929jc.log 2>&1
# continue: $H restart pc1929jc --threads 2 --quiet
# Then: sh ../../docs/runs/s38/rod-jc/remeasure.sh pc1929jc (cavity_min_count: 2)
# Started 02:50:58 after rod-5835 and interrupted (SIGINT) at 28.2 us, step 713, for the
# session's studies; out/s44/pc1929jc holds its checkpoint: continue with
#   ../../build/hvsph restart pc1929jc --threads 2 --quiet   (from out/s44)
