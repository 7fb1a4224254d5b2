#!/bin/sh
# Session 39: rod-5842 at resolution 0.3 to its end, as the case (Table 2's steel,
# alpha = 1) and with session 31's set (Johnson-Cook 4340 target, alpha = 0.2,
# beta = 0.4); 1 thread each, the two at once on the 2-core machine, hvsph a232b4e.
# The same commands as docs/runs/s38/rod-jc/runs.sh.  Run from a scratch folder two
# levels below the repository root (out/s39); then copy the small outputs here and
# run /usr/bin/python3 ../../s38/rod-jc/rods.py (which reads this folder too).
H=../../build/hvsph
one() {  # one NAME KIND
  C=../../examples/paper/rod-$1.yaml
  if [ "$2" = case ]; then
    $H run $C -o c$1 --set resolution=0.3 --threads 1 --quiet > c$1.log 2>&1
  else
    $H run $C -o jc$1 --set resolution=0.3 --threads 1 --quiet \
      --set "materials.st={library: steel-target-jc}" --set 'bodies[1].material=st' \
      --set sph.viscosity.alpha=0.2 --set sph.viscosity.beta=0.4 > jc$1.log 2>&1
  fi
  echo "$1 $2 rc=$? $(date -u +%H:%M:%S)" >> done.txt
}
( one 5842 case ) &
( one 5842 jc ) &
wait
