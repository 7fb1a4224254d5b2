#!/bin/sh
# Session 56: wp1-xmin.sh's two runs carried on to the case's end, 100 us.
H=${HVSPH:-out/s56/hvsph}
$H restart out/s56/wp1-wall --set time.end=100us --threads 1 --quiet >> out/s56/wp1-wall.log 2>&1 &
$H restart out/s56/wp1-abs --set time.end=100us --threads 1 --quiet >> out/s56/wp1-abs.log 2>&1 &
wait
