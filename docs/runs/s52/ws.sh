#!/bin/sh
# Session 52: §2.4 (whipple-steel) at the paper's counts (398 938 particles, session 46's
# projectile), hvsph 65c151b, on 2 threads once the W.P.2 run had ended; to go on to
# the backwall (80 us) in later sessions: stopped by SIGINT, continued with
#   out/s52/hvsph validate --resume --scale 1 --only whipple-steel --threads 2 -o out/s52/val-ws
# From the repository root.
out/s52/hvsph validate --scale 1 --only whipple-steel --threads 2 -o out/s52/val-ws
