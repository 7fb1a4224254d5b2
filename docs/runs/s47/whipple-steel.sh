#!/bin/sh
# Session 47: 2.4 (whipple-steel) at the paper's counts with session 46's projectile
# (PROJECTILE_MATCH: 5 518 particles, 398 938 in all), hvsph d04f054, 1 thread beside
# the W.P.3 study's lanes and then the W.P.3 run (started by after-t4.sh once bumper-3
# had freed its core); stopped by SIGINT at the session's end, continued later with
#   ./build/hvsph validate --resume --scale 1 --only whipple-steel --threads 2 -o out/s47/val-ws
# From the repository root.
./build/hvsph validate --scale 1 --only whipple-steel --threads 1 -o out/s47/val-ws
