#!/bin/sh
# Session 55: session 54's §2.4 run at resolution 0.3 with the paper's rule
# (out/s54/frag-rule, stopped at 41 us) carried on to 46 us, outputs every 1 us, 1 thread,
# beside ws-tau-46.sh's. From the repository root.
H=${HVSPH:-out/s54/hvsph}
$H restart out/s54/frag-rule/whipple-steel --threads 1 --set time.end=46us \
  --set output.every=1us >> out/s54/frag-rule-50.log 2>&1
