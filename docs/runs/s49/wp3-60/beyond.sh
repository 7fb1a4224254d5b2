#!/bin/sh
# Session 49: the paper's rule and the crack with crack_eps_f on past the case's 60 us,
# to 90 us, continued from runs.sh's rule and ef lanes (out/s49/wp3-60/rule,
# out/s49/crack-ef/wp3), 1 thread each, side by side. From the repository root:
# sh docs/runs/s49/wp3-60/beyond.sh; HVSPH names the binary.
H=${HVSPH:-./build/hvsph}
$H restart out/s49/wp3-60/rule --threads 1 --quiet --set time.end="90 us" > out/s49/wp3-60/rule-90.log 2>&1 &
$H restart out/s49/crack-ef/wp3 --threads 1 --quiet --set time.end="90 us" > out/s49/wp3-60/ef-90.log 2>&1 &
wait
