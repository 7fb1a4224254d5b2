#!/usr/bin/env bash
# docs/ballistic-limit.md, "The aluminium Whipple shield": the axisymmetric sweep's
# brackets of the critical sphere diameter at 3, 5 and 7 km/s beside Christiansen's
# equation, as `hvsph sweep` draws them (its ballistic_limit.png). Made from the sweep
# of examples/sweeps/whipple-ble-rz.yaml in SWEEP (default out/whipple-ble-rz: an hour
# or more of runs, which `make figures` does not make):
#
#   build/hvsph sweep examples/sweeps/whipple-ble-rz.yaml -o out/whipple-ble-rz --jobs 1 --threads 1
#
# collected again from its finished points (`hvsph sweep --collect`, which also
# rewrites its sweep.csv and ballistic_limit.csv). Environment: HVSPH, SWEEP, OUT
# (default docs/img). Writes $OUT/ballistic-limit-whipple-rz.png; without the sweep's
# sweep_args.txt it says "skip: ..." and exits 0.
. "$(dirname "$0")/lib/common.sh"
fig_sweep_png examples/sweeps/whipple-ble-rz.yaml out/whipple-ble-rz
