#!/usr/bin/env bash
# README's second picture: a simulated flash radiograph of `make demo`'s debris cloud at
# 30 us (x-ray along z, mass attenuation 1 m2/kg so that the thin cloud shows). Reuses or
# makes out/demo-whipple (fig_demo).
. "$(dirname "$0")/lib/common.sh"
mkdir -p "$WORK"
fig_demo
"$HVSPH" render "$DEMO_LAST" -o "$FIG_TMP" --mode radiograph --axis z --mu 1
fig_done
