#!/bin/bash
# W.P.3 to 15 us at the paper's counts: the projectile's spacing against the code's version
cd /work/main
( /tmp/s51/hvsph-new run examples/paper/wp3.yaml -o out/s51/new-paper --set bodies[0].particles=2000 --set time.end="15 us" --threads 1 > out/s51/new-paper.log 2>&1 ) &
( cd /tmp/s51/old && /tmp/s51/hvsph-old run examples/paper/wp3.yaml -o /work/main/out/s51/old-match --set bodies[0].particles=4091 --set time.end="15 us" --threads 1 > /work/main/out/s51/old-match.log 2>&1 ) &
wait
