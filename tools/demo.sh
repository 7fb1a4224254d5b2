#!/usr/bin/env bash
# `make demo`: runs the default example and says where its results are.
set -euo pipefail
build=${1:-build}
case=examples/verification/sod.yaml
out=out/demo-sod
echo "hvsph demo: Sod shock tube ($case), 2 threads"
"$build/hvsph" run "$case" -o "$out" --threads "${HVSPH_THREADS:-2}"
echo
echo "Results in $out/:"
echo "  summary.csv           totals (mass, momentum, energies) at each output time"
echo "  run.pvd               open in ParaView (particles_*.vtu, one per output time)"
echo "  particles_*.csv       the same snapshots as CSV (id,x,y,z,vx,vy,vz,m,rho,p,e,h,mat,...)"
echo "  used_parameters.yaml  every parameter of the run, defaults included"
echo
echo "Last row of summary.csv:"
tail -n 1 "$out/summary.csv"
