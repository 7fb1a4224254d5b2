#!/bin/sh
# hole diameters (mm) at each measured time for each run folder given
for d in "$@"; do
  printf '%-8s' "$d"
  awk -F, '$2=="hole_diameter" && $5=="bumper" {printf " %.2f", $3*1000}' $d/measurements.csv
  echo
done
