#!/usr/bin/env bash
# docs/rendering.md: `make demo`'s bumper face on at 30 us, an x-ray along the impact axis
# through a slab x = -2..4 mm around the 1.5 mm plate (the debris before and behind it
# would cover the hole). Reuses or makes out/demo-whipple (fig_demo).
. "$(dirname "$0")/lib/common.sh"
mkdir -p "$WORK"
fig_demo
"$HVSPH" render "$DEMO_LAST" -o "$FIG_TMP" --mode radiograph --axis x \
  --box -2mm,4mm,-25mm,25mm,-25mm,25mm --size 700x724 --no-labels
fig_done
