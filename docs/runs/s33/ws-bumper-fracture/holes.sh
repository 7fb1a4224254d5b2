#!/bin/sh
# hole diameters (mm) at each measured time for each run folder given;
# OBJ names the plate (default bumper; W.P.3's first plate is bumper1)
for d in "$@"; do
  printf '%-8s' "$d"
  awk -F, -v obj="${OBJ:-bumper}" '$2=="hole_diameter" && $5==obj {printf " %.2f", $3*1000}' $d/measurements.csv
  echo
done
