#!/usr/bin/env bash
# `make demo`: a Whipple-shield impact (the paper's W.P.1: a 5 mm aluminium sphere at
# 6.5 km/s through a 1.5 mm aluminium bumper), coarse enough to finish in a few minutes
# on 2 cores; ends by writing a simulated flash radiograph, movie frames and the
# measurements.
set -euo pipefail
build=${1:-build}
case=examples/paper/wp1.yaml
out=out/demo-whipple
res=${HVSPH_DEMO_RESOLUTION:-0.2}
echo "hvsph demo: $case at resolution $res (particle counts x $res), to t = 30 us"
echo "hvsph demo: two setup warnings are expected at this coarse resolution: the backwall's"
echo "  disc is much heavier than the projectile's particles (the debris does not reach it by"
echo "  30 us), and the projectile's 400-particle lattice overfills its sphere by some per cent"
# bodies[4] is the backwall's four-layer disc (backwall-core): the debris does not reach
# the backwall by 30 us, so at the demo's resolution the disc is as coarse as the plate
# around it (at least three layers otherwise: 30 000 of the demo's 43 000 particles)
# --overwrite: the demo's own folder, replaced by each `make demo`
"$build/hvsph" run "$case" -o "$out" --overwrite --threads "${HVSPH_THREADS:-2}" \
  --set resolution="$res" --set time.end="30 us" --set output.every="2 us" --set output.csv=true \
  --set bodies[4].particles=1000
last=$(ls "$out"/particles_*.csv | sort | tail -n 1)
"$build/hvsph" render "$last" -o "$out/radiograph.png" --mode radiograph --axis z
# the bumper face on, along the impact axis: a slab x = -2..4 mm around the 1.5 mm plate,
# so that the debris in front of it and behind it does not cover the hole
"$build/hvsph" render "$last" -o "$out/bumper_hole.png" --mode radiograph --axis x \
  --box -2mm,4mm,-25mm,25mm,-25mm,25mm --size 700x724 --no-labels
"$build/hvsph" render "$last" -o "$out/side_velocity.png" --mode particles --axis z --color velocity
# every snapshot as a frame of a movie, framed and coloured alike
"$build/hvsph" render "$out" -o "$out/frames" --mode particles --axis z --color velocity \
  --size 960 --quiet
echo
echo "Results in $out/:"
echo "  radiograph.png        simulated flash x-ray of the debris cloud (side view, mirrored)"
echo "  side_velocity.png     particles coloured by speed"
echo "  bumper_hole.png       the bumper face on (x-ray along the impact axis): its hole, white"
echo "  frames/               every snapshot (2 us apart) coloured by speed, for a movie:"
echo "                        ffmpeg -framerate 5 -i $out/frames/frame_%05d.png -pix_fmt yuv420p demo.mp4"
echo "  measurements.csv      hole diameter, debris-cloud velocities and spray angle, fragments"
echo "  summary.csv           totals (mass, momentum, energies) at each output time"
echo "  run.pvd               open in ParaView (particles_*.vtu, one per output time)"
echo "  used_parameters.yaml  every parameter of the run, defaults included"
echo
echo "Final measurements (SI units):"
awk -F, -v t="$(tail -n 1 "$out/measurements.csv" | cut -d, -f1)" \
  '$1 == t && ($2 == "hole_diameter" || $2 ~ /^cloud_velocity_(mean|lead)$/ || $2 ~ /^cloud_half_angle(_front)?$/ || $2 == "fragments_count") {printf "  %-22s %-12s %.4g %s\n", $5, $2, $3, $4}' \
  "$out/measurements.csv"
