#!/bin/bash
# cmp.sh CSV... : second cloud and holes at 10, 12.5, 15 us
for f in "$@"; do echo "== $f"
awk -F, '($5=="cloud:bumper2" && ($2=="cloud_mass"||$2=="cloud_velocity_mean"||$2=="cloud_velocity_lead")) || ($5=="bumper2" && $2=="hole_diameter") || ($5=="cloud:bumper1" && ($2=="cloud_mass"||$2=="cloud_velocity_mean")) {t=$1*1e6; if (t>9.9 && t<15.1 && ((t*10)%25<0.01 || (t*10)%25>24.99)) printf "%.1f %s:%s %.4g\n", t,$5,$2,$3}' $f | awk '{a[$1]=a[$1]" "$2"="$3} END{for (t in a) print t, a[t]}' | sort -n
done
