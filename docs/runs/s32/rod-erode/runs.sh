#!/bin/sh
# Session 32: session 26's r41-case-c10.yaml (copied here) and its variants, 1 thread
# each, two at a time; only the small outputs are kept. hvsph is the committed binary
# (base); hvsph-study the build with study.patch applied (git apply study.patch).
# HVSPH_ERODE=vcut,d[,ecap]: ecap absent takes the selected rod particles out, 0 cools
# them to the cold curve, > 0 caps e, -2 zeroes their outward radial velocity.
# Then: /usr/bin/python3 erode.py
set -e
hvsph run r41-case-c10.yaml -o base --threads 1
HVSPH_ERODE=1820,10e-3 hvsph-study run r41-case-c10.yaml -o e10 --threads 1
HVSPH_ERODE=1820,5.3e-3 hvsph-study run r41-case-c10.yaml -o e53 --threads 1
HVSPH_ERODE=1600,2.5e-3 hvsph-study run r41-case-c10.yaml -o e25 --threads 1
HVSPH_ERODE=1600,1.0e-3 hvsph-study run r41-case-c10.yaml -o e01 --threads 1
HVSPH_ERODE=1600,1.0e-3,0 hvsph-study run r41-case-c10.yaml -o c01 --threads 1
HVSPH_ERODE=1600,1.0e-3,3e5 hvsph-study run r41-case-c10.yaml -o k01 --threads 1
HVSPH_RODVISC=0.2 hvsph-study run r41-case-c10.yaml -o rv02 --threads 1
HVSPH_NCONTACT=1 hvsph-study run r41-case-c10.yaml -o nc41 --threads 1
HVSPH_NCONTACT=1 hvsph-study run r29-case-c10.yaml -o nc29 --threads 1
hvsph run r44-core.yaml -o b44 --threads 1 --set time.end=30us --set output.every=5us
HVSPH_ERODE=3100,1.0e-3 hvsph-study run r44-core.yaml -o e44 --threads 1 --set time.end=30us --set output.every=5us
HVSPH_ERODE=840,2.5e-3 hvsph-study run r29-case-c10.yaml -o e29b --threads 1
HVSPH_ERODE=840,1.0e-3 hvsph-study run r29-case-c10.yaml -o e29 --threads 1
HVSPH_ERODE=1600,2.5e-3,-2 hvsph-study run r41-case-c10.yaml -o r25 --threads 1
HVSPH_ERODE=1600,1.0e-3,-2 hvsph-study run r41-case-c10.yaml -o r01 --threads 1
HVSPH_ERODE=1600,0,0 hvsph-study run r41-case-c10.yaml -o c00 --threads 1
HVSPH_ERODE=1600,0,6e5 hvsph-study run r41-case-c10.yaml -o k00 --threads 1
HVSPH_ERODE=840,1.0e-3,-2 hvsph-study run r29-case-c10.yaml -o r29 --threads 1
HVSPH_ERODE=3100,1.0e-3,-2 hvsph-study run r44-core.yaml -o r44 --threads 1 --set time.end=30us --set output.every=5us
