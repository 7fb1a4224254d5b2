#!/bin/bash
# Session 41, on the lent 16-core machine (the device tool; not needed by the project):
# the wide free symmetric test at 1.29 km/s without artificial viscosity and with the rod
# and core at 0.5 mm (alpha = 1), both at once, then `hvsph bench` at 1-16 threads.
# Runs a portable build (cmake -DHVSPH_NATIVE=OFF) with Debian 12's libraries carried in
# build-dev/carry. Small outputs are tarred into $OUT/s41dev.tar.
C=build-dev/carry
export OMP_WAIT_POLICY=passive HVSPH_DATA=$PWD/data
H="$C/lib/ld-linux-x86-64.so.2 --library-path $C/lib $C/hvsph"
Y=docs/runs/s41/floor-free/free129.yaml
W=/tmp/s41; mkdir -p $W
{ nproc; grep -m1 'model name' /proc/cpuinfo; free -g | head -2; } > $W/machine.txt
$H --version > $W/version.txt 2>&1 || { cat $W/version.txt; exit 1; }
timeout -s INT 400 $H run $Y -o $W/free-a0 --threads 5 \
  --set sph.viscosity.alpha=0 --set sph.viscosity.beta=0 > $W/free-a0.log 2>&1 &
timeout -s INT 400 $H run $Y -o $W/free-h05 --threads 11 \
  --set 'bodies[0].spacing=0.5 mm' --set 'bodies[1].spacing=0.5 mm' > $W/free-h05.log 2>&1 &
wait
for t in 1 2 4 8 16; do
  $H bench --particles 200000 --steps 5 --threads $t --solid > $W/bench-solid-$t.txt 2>&1
done
cd $W && tar cf $OUT/s41dev.tar machine.txt version.txt *.log bench-*.txt \
  free-*/measurements.csv free-*/run_segments.csv free-*/summary.csv
tail -n 3 $W/free-a0.log $W/free-h05.log; grep -h -i "particle-steps" $W/bench-*.txt
