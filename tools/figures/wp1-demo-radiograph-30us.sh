#!/usr/bin/env bash
# docs/rendering.md: a simulated flash radiograph of `make demo`'s W.P.1 (resolution 0.2)
# at 30 us, x-ray along z at the automatic exposure, axes and body labels. Reuses or makes
# out/demo-whipple (fig_demo).
. "$(dirname "$0")/lib/common.sh"
mkdir -p "$WORK"
fig_demo
"$HVSPH" render "$DEMO_LAST" -o "$FIG_TMP" --mode radiograph --axis z
fig_done
