#!/bin/sh
# Session 52: W.P.1 at the paper's counts with today's code (hvsph 65c151b; session 12's
# run, the Status table's, was made with session 12's code), on 2 threads, with the §2.4
# run (ws.sh) paused by SIGINT at 5.0 us. From the repository root.
out/s52/hvsph validate --scale 1 --only wp1 --threads 2 -o out/s52/val-wp1
