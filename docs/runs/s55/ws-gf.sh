#!/bin/sh
# Session 55: §2.4 at resolution 0.3 with a cohesive opening before the paper's split
# (fracture.energy = G_f, hvsph with the option), to 40 us, 1 thread each:
#   gf-proj: on the projectile's steel only, G_f = 13 kJ/m2 (K_IC = 55 MPa m^0.5, a typical
#            handbook value for AISI 4340 at a yield of ~1.5 GPa; G_f = K_IC^2 (1 - nu^2)/E,
#            E = 209 GPa from Table 5's rho0, c0 and nu);
#   gf-all:  on every Table 5 material: projectile 13 kJ/m2, bumper 45 kJ/m2 (100 MPa m^0.5,
#            a mild steel's, E = 206 GPa), backwall al-alloy 14 kJ/m2 (34 MPa m^0.5, 2024-T351,
#            E = 72.5 GPa).
# From the repository root.
H=${HVSPH:-out/s55/hvsph-gf}
P="--set materials.steel-projectile.library=steel-projectile --set materials.steel-projectile.fracture.energy=13kJ/m2"
B="--set materials.steel-bumper.library=steel-bumper --set materials.steel-bumper.fracture.energy=45kJ/m2"
A="--set materials.al-alloy.library=al-alloy --set materials.al-alloy.fracture.energy=14kJ/m2"
$H validate --scale 0.3 --only whipple-steel --threads 1 -o out/s55/gf-proj \
  --set time.end=40us --set output.every=5us $P > out/s55/gf-proj.log 2>&1 &
$H validate --scale 0.3 --only whipple-steel --threads 1 -o out/s55/gf-all \
  --set time.end=40us --set output.every=5us $P $B $A > out/s55/gf-all.log 2>&1 &
wait
