#!/bin/sh
# Session 50: the paper-count bumper runs with session 46's projectiles (PROJECTILE_MATCH),
# hvsph c353f3f, two 1-thread lanes side by side on the 2-core machine. From the
# repository root; the binary is copied to out/s50/hvsph first (cp build/hvsph out/s50/).
# A stopped lane is continued with the same line and --resume after "validate".
nohup out/s50/hvsph validate --scale 1 --only wp3 --threads 1 -o out/s50/val-wp3 \
  > out/s50/val-wp3.log 2>&1 &
nohup out/s50/hvsph validate --scale 1 --only bumper-20 --threads 1 -o out/s50/val-b20 \
  > out/s50/val-b20.log 2>&1 &
# bumper-20 ended at 08:13 (6 722 s); W.P.3 was then stopped by SIGINT at 42.08 us (step
# 17 252, 7 282 s on 1 thread) and continued on both cores:
#   out/s50/hvsph validate --resume --scale 1 --only wp3 --threads 2 -o out/s50/val-wp3
