#!/bin/sh
# Session 35: rod-5841's head at three refinements of the rod and the target's core
# (docs/validation.md, "The rods' turn in a rigid cup"). hvsph 02e8e9f. z064 and z032
# ran side by side (3 threads on the 2 cores), z096 alone.
set -e
hvsph run r41-zones.yaml -o z064 --threads 1
hvsph run r41-zones.yaml -o z032 --threads 2 --set 'bodies[0].spacing=0.32mm' --set 'bodies[3].spacing=0.32mm' --set time.end=16us
hvsph run r41-zones.yaml -o z096 --threads 2 --set 'bodies[0].spacing=0.956mm' --set 'bodies[3].spacing=0.669mm' --set time.end=16us
/usr/bin/python3 compare.py z096 z064 z032 > compare.txt
# profile-z*.txt: ../../s34/rod-forces/profile.py on each run's particles_00004.vtu (16 us)
