#!/bin/sh
# Session 35: where rod-5841's energy goes (docs/validation.md, Still to do, the rods'
# mushroom). Session 32's cheap rod-5841 case to 20 us, hvsph eb711de (src as 02e8e9f), 2 threads
# (135 s), then energy.py on its snapshots (energy.txt).
set -e
hvsph run ../../s32/rod-erode/r41-case-c10.yaml -o e41 --threads 2 --set time.end=20us
/usr/bin/python3 energy.py e41 > energy.txt
