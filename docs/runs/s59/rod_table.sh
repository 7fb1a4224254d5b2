#!/bin/sh
# A rod run's crater over time, in mm: depth L, largest diameter D and its mean over the
# depth (cavity_diameter_mean), D by filled volume (cavity_diameter_wall) and its mean,
# at each output time (docs/measurements.md).
# Usage: sh docs/runs/s59/rod_table.sh RUNDIR/measurements.csv
set -eu
awk -F, '
  /^#/ || $1 == "time" { next }
  $2 == "penetration_depth" || $2 == "cavity_diameter" || $2 == "cavity_diameter_mean" ||
  $2 == "cavity_diameter_wall" ||
  $2 == "cavity_diameter_wall_mean" {
    t = sprintf("%.1f", $1 * 1e6)
    if (!(t in seen)) { seen[t] = 1; order[n++] = t }
    v[t, $2] = $3 * 1e3
  }
  END {
    print "t_us  L_mm    D_mm  D_mean_mm  D_wall_mm  D_wall_mean_mm"
    for (i = 0; i < n; i++) {
      t = order[i]
      printf "%5s %7.2f %6.2f %9.2f %9.2f %9.2f\n", t, v[t, "penetration_depth"],
             v[t, "cavity_diameter"], v[t, "cavity_diameter_mean"],
             v[t, "cavity_diameter_wall"], v[t, "cavity_diameter_wall_mean"]
    }
  }' "$1"
