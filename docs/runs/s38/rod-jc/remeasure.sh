#!/bin/sh
# The cavity read again with measure.cavity_min_count: 2 (one loose particle per slice
# passed over), on copies of each run folder whose snapshots are links; from the same
# scratch folder as runs.sh: sh ../../docs/runs/s38/rod-jc/remeasure.sh
H=../../build/hvsph
for r in "$@"; do
  d=$r-mc2; rm -rf $d; mkdir $d
  for f in $r/particles_*.vtu; do ln -s ../$f $d/; done
  cp $r/summary.csv $d/
  if grep -q '^  cavity_min_count:' $r/used_parameters.yaml; then  # written by 67c3be2 on
    sed 's/^  cavity_min_count: .*/  cavity_min_count: 2/' $r/used_parameters.yaml > $d/case.yaml
  else
    sed 's/^measure:/measure:\n  cavity_min_count: 2/' $r/used_parameters.yaml > $d/case.yaml
  fi
  $H measure $d --case $d/case.yaml --quiet && echo "$d measured"
done
