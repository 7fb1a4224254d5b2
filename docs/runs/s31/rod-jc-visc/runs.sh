#!/bin/sh
# Session 31, "The Johnson-Cook steel with less viscosity" (docs/validation.md): session
# 28's case files (docs/runs/s28/rod-jc) with a weaker viscosity or the switch, 1 thread
# each, two at a time; only the small outputs are kept here. Then: /usr/bin/python3 jcvisc.py
set -e
S28=../../s28/rod-jc
for r in r29 r41 r44; do
  hvsph run $S28/$r-jc.yaml -o $r-jc-a02 --threads 1 \
    --set sph.viscosity.alpha=0.2 --set sph.viscosity.beta=0.4
  hvsph run $S28/$r-jc.yaml -o $r-jc-sw --threads 1 --set sph.viscosity.switch=cullen-dehnen
done
