#!/bin/sh
# Session 54: §2.4 at the paper's counts carried on past the backwall bulge's peak, from
# sessions 52-53's run at 80 us (a hard-linked copy of out/s52/val-ws/whipple-steel in
# out/s54/ws-200, so the 80 us results stay as they were), to 200 us, 2 threads. Stop it
# with SIGINT; run this script again to continue from the last checkpoint.
H=${HVSPH:-out/s54/hvsph}
$H restart out/s54/ws-200 --threads 2 --set time.end=200us >> out/s54/ws-200.log 2>&1
