#!/usr/bin/env bash
# README's picture: the debris cloud of `make demo` (W.P.1 at resolution 0.2, 30 us),
# particles seen along z, coloured by speed. Reuses or makes out/demo-whipple (fig_demo).
. "$(dirname "$0")/lib/common.sh"
mkdir -p "$WORK"
fig_demo
"$HVSPH" render "$DEMO_LAST" -o "$FIG_TMP" --mode particles --axis z --color velocity
fig_done
