#!/bin/sh
# Session 54: ws-frag.sh's two runs carried on from 10 us to 50 us (the cloud strikes the
# backwall at about 34 us), 1 thread each. From the repository root.
H=${HVSPH:-out/s54/hvsph}
for r in rule crack; do
  $H restart out/s54/frag-$r/whipple-steel --threads 1 --set time.end=50us --set output.every=5us \
    > out/s54/frag-$r-50.log 2>&1 &
done
wait
