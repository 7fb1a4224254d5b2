#!/bin/sh
# Session 38: rods 5835 and 5839 at resolution 0.3 to their ends, each as the case
# (Table 2's steel, alpha = 1) and with session 31's set (Johnson-Cook 4340 target,
# alpha = 0.2, beta = 0.4); 1 thread each, two at once on the 2-core machine.  The cases
# ran with hvsph 00a20f4, the Johnson-Cook runs with 00a20f4 and the uncommitted
# change committed as 67c3be2 ('00a20f4-dirty' in run_segments.csv: it adds only the
# measure.cavity_min_count key, default unchanged).  rod-5842 was queued too but left
# for a later session: its pair would not have finished in this one.  Run from a scratch folder two levels below the repository root
# (out/s38); then copy the small outputs here and run /usr/bin/python3 rods.py > rods.txt
. ../../docs/runs/rod_pair.sh  # one NAME KIND
# as run: the two cases first, then the two Johnson-Cook runs (jc5839 started while
# c5835 had 10 us to go)
( one 5835 case ) &
( one 5839 case; one 5835 jc ) &
sleep 4800; one 5839 jc &
wait
# later: one 5842 case & one 5842 jc & wait
