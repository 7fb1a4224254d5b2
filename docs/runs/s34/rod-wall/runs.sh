#!/bin/sh
# Session 34: the rods' turning flow on a rigid wall (docs/validation.md, "The rods'
# turning flow on a rigid wall"). hvsph 7fd365b; hvsph-study is the same with
# recon-split.patch applied (git apply recon-split.patch): HVSPH_RECON_SPLIT=1 gives
# split particles of a material with strength the viscosity's reconstruction too.
# 1 thread each, two at a time; then wall.py on each run (wall.txt) and, for the two
# rod runs, ../../s32/rod-erode/erode.py rs41 rs29 (rods.txt).
set -e
hvsph run rw.yaml -o rw032 --threads 1
hvsph run rw.yaml -o rw064 --threads 1 --set 'bodies[0].spacing=0.64 mm'
hvsph run rw.yaml -o rw016 --threads 1 --set 'bodies[0].spacing=0.16 mm' --set time.end=14us
hvsph run rw.yaml -o rw032-fluid --threads 1 --set 'materials.w={library: tungsten-alloy, strength: {yield: 1 kPa}, fracture: {model: none}}'
hvsph run rw.yaml -o rw032-nofrac --threads 1 --set 'materials.w={library: tungsten-alloy, fracture: {model: none}}'
hvsph run rw.yaml -o rw032-a02 --threads 1 --set 'sph.viscosity={alpha: 0.2, beta: 0.4, reconstruct: true}'
HVSPH_RECON_SPLIT=1 hvsph-study run rw.yaml -o rw032-rs --threads 1
HVSPH_RECON_SPLIT=1 hvsph-study run rw.yaml -o rw064-rs --threads 1 --set 'bodies[0].spacing=0.64 mm'
HVSPH_RECON_SPLIT=1 hvsph-study run rw.yaml -o rw016-rs --threads 1 --set 'bodies[0].spacing=0.16 mm' --set time.end=14us
HVSPH_RECON_SPLIT=1 hvsph-study run ../../s32/rod-erode/r41-case-c10.yaml -o rs41 --threads 1
HVSPH_RECON_SPLIT=1 hvsph-study run ../../s32/rod-erode/r29-case-c10.yaml -o rs29 --threads 1
HVSPH_RECON_SPLIT=1 hvsph-study run ../../s32/rod-erode/r44-core.yaml -o rs44 --threads 1 --set time.end=30us --set output.every=5us
for d in rw064 rw032 rw016 rw064-rs rw032-rs rw016-rs rw032-nofrac rw032-a02 rw032-fluid; do
  /usr/bin/python3 wall.py $d; done > wall.txt
