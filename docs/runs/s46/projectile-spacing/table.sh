#!/bin/sh
# Session 46: the 12 us readings of each run (hole, equivalent, intact; the cloud's
# mass-mean and leading-edge velocity, half angle of 90 % of its mass); OBJ as holes.sh.
for d in "$@"; do
  awk -F, -v d="$d" -v obj="${OBJ:-bumper}" '
    $1+0 > 1.19e-05 && $1+0 < 1.21e-05 {
      if ($5==obj && $2=="hole_diameter") h=$3*1000
      if ($5==obj && $2=="hole_diameter_equiv") he=$3*1000
      if ($5==obj && $2=="hole_diameter_intact") hi=$3*1000
      if ($5=="cloud:" obj && $2=="cloud_velocity_mean") vm=$3/1000
      if ($5=="cloud:" obj && $2=="cloud_velocity_lead") vl=$3/1000
      if ($5=="cloud:" obj && $2=="cloud_half_angle") ha=$3 }
    END { printf "%-40s hole %.2f equiv %.2f intact %.2f | cloud mean %.2f lead %.2f km/s angle %.1f\n", d, h, he, hi, vm, vl, ha }' $d/measurements.csv
done
