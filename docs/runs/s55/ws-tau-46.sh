#!/bin/sh
# Session 55: ws-tau.sh's two runs carried on from 40 to 46 us, outputs every 1 us (the
# backwall's craters form from 38 us on), 1 thread; tau-0.3 first, tau-1 when given "1".
# From the repository root.
H=${HVSPH:-out/s55/hvsph}
for tau in ${1:-0.3}; do
  $H restart out/s55/tau-$tau/whipple-steel --threads 1 --set time.end=46us \
    --set output.every=1us >> out/s55/tau-$tau.log 2>&1
done
