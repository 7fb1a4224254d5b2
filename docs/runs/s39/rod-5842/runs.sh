#!/bin/sh
# Session 39: rod-5842 at resolution 0.3 to its end, as the case (Table 2's steel,
# alpha = 1) and with session 31's set (Johnson-Cook 4340 target, alpha = 0.2,
# beta = 0.4); 1 thread each, the two at once on the 2-core machine, hvsph a232b4e.
# The same commands as docs/runs/s38/rod-jc/runs.sh.  Run from a scratch folder two
# levels below the repository root (out/s39); then copy the small outputs here and
# run /usr/bin/python3 rods.py here (it reads session 38's five rods too).
. ../../docs/runs/rod_pair.sh  # one NAME KIND
( one 5842 case ) &
( one 5842 jc ) &
wait
