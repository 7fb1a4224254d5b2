#!/bin/sh
# Session 35: turn.py cup on every run, and the mean over 20-30 us of the reversed sheet's
# <vx>/v and flux/inflow at X = 2 and 3 r0 (cup.txt, cup-summary.txt).
for d in c064 c064-nofrac c064-a02 c064-fluid c064-fluid-a02 c064-fluid-std c064-W9 c064-W13 c032 c032-fluid c016-fluid; do
  /usr/bin/python3 turn.py cup $d; done > cup.txt
awk '/^# c/{run=$2} !/^#/ && $1>=20 && $1<=30 {
  n[run]++; f2[run]+=($7<0?-$7:$7); v2[run]+=$8; f3[run]+=($10<0?-$10:$10); v3[run]+=$11; h[run]=$5 }
  END { printf "# run  <vx>/v at 2 r0, 3 r0 | flux/inflow at 2 r0, 3 r0 | held g at the last time (20-30 us means)\n";
        for (r in n) printf "%-16s %5.2f %5.2f | %5.2f %5.2f | %6.2f\n", r, v2[r]/n[r], v3[r]/n[r], f2[r]/n[r], f3[r]/n[r], h[r] }' cup.txt | sort > cup-summary.txt
