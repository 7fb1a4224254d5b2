#!/bin/sh
# Session 49: Table 4's bumper-17 at the paper's counts with session 46's projectile
# (194 544 particles) to its t_x, 1 thread beside the W.P.3 lanes. From the repository
# root; HVSPH names the binary (a build of this session's source).
H=${HVSPH:-./build/hvsph}
$H validate --scale 1 --only bumper-17 --threads 1 -o out/s49/val-t4 > out/s49/val-t4.log 2>&1
