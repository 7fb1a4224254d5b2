#!/bin/sh
# Session 55: session 54's continuation of §2.4 at the paper's counts (out/s54/ws-200,
# a hard-linked copy of sessions 52-53's run) carried on toward 200 us on 1 thread, the
# other core left for the session's other runs. Stop it with SIGINT; run it (or
# docs/runs/s54/ws-200.sh, 2 threads) again to continue from the last checkpoint.
H=${HVSPH:-out/s54/hvsph}
$H restart out/s54/ws-200 --threads 1 --set time.end=200us >> out/s54/ws-200.log 2>&1
