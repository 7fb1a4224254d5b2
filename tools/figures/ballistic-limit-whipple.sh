#!/usr/bin/env bash
# docs/ballistic-limit.md, "Oblique impacts (45°)": the 3D half model's points at 5 km/s
# and 45° beside Christiansen's equation at 45°, as `hvsph sweep` draws them (its
# ballistic_limit.png). Made from the sweep of examples/sweeps/whipple-ble-45.yaml in
# SWEEP (default out/whipple-ble-45:
#   build/hvsph sweep examples/sweeps/whipple-ble-45.yaml -o out/whipple-ble-45 --threads 2
# 29 to 44 minutes a point on 2 threads, 2026-12-08, which `make figures` does not
# make), collected again from its finished points (`hvsph sweep
# --collect`, which also rewrites its sweep.csv and ballistic_limit.csv). Environment:
# HVSPH, SWEEP, OUT (default docs/img). Writes $OUT/ballistic-limit-whipple.png; without
# the sweep's sweep_args.txt it says "skip: ..." and exits 0.
. "$(dirname "$0")/lib/common.sh"
fig_sweep_png examples/sweeps/whipple-ble-45.yaml out/whipple-ble-45
