#!/bin/sh
# Session 47: the second bumper's hole over time in each lane of runs.sh (and the first
# bumper's, and the first cloud, as a check that the lanes meet the same cloud), from
# out/s47/b2-LANE or the copy committed beside this script.
# Usage (from the repository root): sh docs/runs/s47/wp3-bumper2/table.sh [LANE...]
lanes=${*:-one two three cloud040 cloud016}
for l in $lanes; do
    f=out/s47/b2-$l/measurements.csv
    [ -f "$f" ] || f=docs/runs/s47/wp3-bumper2/$l/measurements.csv   # the committed copy
    [ -f "$f" ] || continue
    echo "== $l"
    awk -F, 'NR > 2 && ($5 == "bumper2" || $5 == "bumper1") &&
             ($2 == "hole_diameter" || $2 == "hole_diameter_intact" || $2 == "hole_diameter_equiv" || $2 == "hole_diameter_intact_equiv") &&
             ($1 + 0 == 0 || int($1 * 1e6 + 0.5) % 5 == 0) && ($1 * 1e6 - int($1 * 1e6 + 0.5))^2 < 1e-6 {
                 printf "%5.1f us  %-8s %-27s %7.2f mm\n", $1 * 1e6, $5, $2, $3 * 1e3 }' "$f"
    awk -F, 'NR > 2 && $5 == "cloud:bumper1" && ($2 == "cloud_velocity_lead" || $2 == "cloud_mass") &&
             ($1 * 1e6 - 7.5)^2 < 1e-6 { printf "  7.5 us  first cloud %s %g %s\n", $2, $3, $4 }' "$f"
done
