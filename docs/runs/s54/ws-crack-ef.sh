#!/bin/sh
# Session 54: §2.4 at resolution 0.3 with the crack model on Table 5's steels and a strain to
# failure for the cracked state (fracture.crack_eps_f) from Johnson & Cook's (1985) AISI 4340
# failure strain as usually quoted (d1 = 0.05, d2 = 3.44, d3 = -2.12), to 45 us, 1 thread.
# From the repository root.
H=${HVSPH:-out/s54/hvsph}
S=""
for m in steel-bumper steel-projectile; do
  S="$S --set materials.$m.library=$m --set materials.$m.fracture.split=crack"
  S="$S --set materials.$m.fracture.crack_eps_f.d1=0.05 --set materials.$m.fracture.crack_eps_f.d2=3.44"
  S="$S --set materials.$m.fracture.crack_eps_f.d3=-2.12"
done
$H validate --scale 0.3 --only whipple-steel --threads 1 -o out/s54/frag-crackef \
  --set time.end=45us --set output.every=5us $S > out/s54/frag-crackef.log 2>&1
