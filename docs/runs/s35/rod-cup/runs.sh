#!/bin/sh
# Session 35: the rod's 180-degree turn in a rigid cup (docs/validation.md, "The rods'
# turn in a rigid cup"). hvsph 02e8e9f; 1 thread each unless said. Then summary.sh
# (cup.txt, cup-summary.txt: turn.py cup), path.py (path.txt) and turn.py slot on the
# four slot runs (slot.txt).
set -e
F='materials.w={library: tungsten-alloy, strength: {yield: 1 kPa}, fracture: {model: none}}'
S='bodies[0].spacing=0.64mm'
hvsph run cup.yaml -o c064 --threads 2 --set "$S"
hvsph run cup.yaml -o c032 --threads 1
hvsph run cup.yaml -o c032-fluid --threads 1 --set "$F"
hvsph run cup.yaml -o c016-fluid --threads 2 --set 'bodies[0].spacing=0.16 mm' --set "$F"
hvsph run cup.yaml -o c064-fluid --threads 1 --set "$S" --set "$F"
hvsph run cup.yaml -o c064-nofrac --threads 1 --set "$S" --set 'materials.w={library: tungsten-alloy, fracture: {model: none}}'
hvsph run cup.yaml -o c064-a02 --threads 1 --set "$S" --set 'sph.viscosity={alpha: 0.2, beta: 0.4, reconstruct: true}'
hvsph run cup.yaml -o c064-fluid-a02 --threads 1 --set "$S" --set 'sph.viscosity={alpha: 0.2, beta: 0.4, reconstruct: true}' --set "$F"
hvsph run cup.yaml -o c064-fluid-std --threads 1 --set "$S" --set 'sph.viscosity.reconstruct=false' --set "$F"
for W in 9 13; do hvsph run cup.yaml -o c064-W$W --threads 1 --set "$S" --set "domain.max=[70 mm, $W mm, $W mm]"; done
# the planar slot (slot.yaml)
hvsph run slot.yaml -o s032-fluid --threads 1 --set "$F"
hvsph run slot.yaml -o s032-fluid-W13 --threads 1 --set "$F" --set 'domain.max=[70 mm, 13 mm, 3.84 mm]'
G='domain.max=[70 mm, 13 mm, 5.12 mm]'; B='bodies[0].shape.max=[40 mm, 2.638 mm, 5.12 mm]'
hvsph run slot.yaml -o s064-fluid-W13 --threads 1 --set "$S" --set "$F" --set "$G" --set "$B"
hvsph run slot.yaml -o s064-W13 --threads 1 --set "$S" --set "$G" --set "$B"
