#!/bin/sh
# Session 33: the §2.4 bumper (five-layer disc, sphere, no backwall) to 12 us, session
# 26's ws-a1.yaml with output every 12 us (ws-base.yaml), 1 thread each, two at a time,
# hvsph 779c69e (ef05, ef10, ef20 with tau: 1 s in place of e31c8e7's sigma_c: 0, which
# 779c69e refused; the same criterion: 1 s of tension to failure is never reached in 12 us).
# Only the small outputs are kept; then ./holes.sh ... > holes.txt and
# /usr/bin/python3 rim.py base nofrac ef05 ef10 ef20 > rim.txt in the runs' folder.
set -e
hvsph run ws-base.yaml -o base --threads 1
hvsph run ws-base.yaml -o gc --threads 1 --set sph.gradient_correction=true
hvsph run ws-nofrac.yaml -o nofrac --threads 1
hvsph run ws-nofrac.yaml -o gcnofrac --threads 1 --set sph.gradient_correction=true
hvsph run ws-pnofrac.yaml -o pnofrac --threads 1
hvsph run ws-ef05.yaml -o ef05 --threads 1
hvsph run ws-ef10.yaml -o ef10 --threads 1
hvsph run ws-ef20.yaml -o ef20 --threads 1
# ef10 again with the committed form, sigma_c: 0 (hvsph e31c8e7, 2 threads): the same holes
# to 0.01 mm at every µs (to 1e-9 relative; the tau: 1 s run accumulates a damage of
# order 1e-5 that this one does not)
hvsph run ws-ef10s.yaml -o ef10s --threads 2
