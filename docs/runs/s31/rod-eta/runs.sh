#!/bin/sh
# Session 31: session 26's r41-case-c10.yaml (copied here) at three kernel widths, 1 thread
# each; only the small outputs are kept. Then: /usr/bin/python3 eta.py
set -e
hvsph run r41-case-c10.yaml -o r41-eta10 --threads 1 --set sph.eta=1.0
hvsph run r41-case-c10.yaml -o ../rod-stress/r41-base --threads 1
hvsph run r41-case-c10.yaml -o r41-eta15 --threads 1 --set sph.eta=1.5
