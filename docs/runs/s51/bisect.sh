#!/bin/bash
# W.P.3 with the paper's projectile to 10.5 us at two commits around the contact density cap
cd /work/main
NEWPID=$1; OLDPID=$2
lane() { # commit
  c=$1; cd /tmp/s51/w-$c && ./build/hvsph run examples/paper/wp3.yaml -o /work/main/out/s51/b-$c --set time.end="10.5 us" --threads 1 > /work/main/out/s51/b-$c.log 2>&1
}
( while kill -0 $NEWPID 2>/dev/null; do sleep 5; done; lane 89fa149 ) &
( while ! awk -F, '$1+0 >= 1.05e-5 {f=1} END{exit !f}' out/s51/old-match/measurements.csv 2>/dev/null; do sleep 10; done
  kill -INT $OLDPID; while kill -0 $OLDPID 2>/dev/null; do sleep 5; done; lane c1eca58 ) &
wait
