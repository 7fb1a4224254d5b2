# Sourced by the rods' pair scripts (docs/runs/s38/rod-jc/runs.sh, s39/rod-5842/runs.sh)
# from a scratch folder two levels below the repository root.  one NAME KIND runs
# examples/paper/rod-NAME.yaml at resolution 0.3 on 1 thread, KIND "case" as committed
# (Table 2's steel, alpha = 1) into cNAME, else with session 31's set (Johnson-Cook 4340
# target, alpha = 0.2, beta = 0.4) into jcNAME, and logs its exit status to done.txt.
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
