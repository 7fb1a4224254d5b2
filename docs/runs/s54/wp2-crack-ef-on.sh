#!/bin/sh
# Session 54: wp2-crack-ef.sh's run carried on from 50 us to the backwall's craters
# (to 130 us, outputs every 10 us), 2 threads. From the repository root.
H=${HVSPH:-out/s54/hvsph}
$H restart out/s54/wp2-crackef/wp2 --threads 2 --set time.end=130us --set output.every=10us \
  > out/s54/wp2-crackef-on.log 2>&1
