#!/usr/bin/env bash
# docs/validation.md, "Convergence in RZ": rod-5841's and rod-5844's depth and cavity
# diameter and W.P.1's bumper hole against particles per projectile radius (4 to 32),
# with Table 2's and the sourced material set, the Richardson-extrapolated values, the
# experiments and KERNEL, and each run's wall time. Made from the study of
# tools/rz-convergence.sh (its folder STUDY, default out/rz-convergence: hours of runs,
# which `make figures` does not make): its convergence.csv is collected again from the
# study's finished points and plot_rz_convergence.py draws it.
#
# Environment: HVSPH (the hvsph binary, default build/hvsph), STUDY (the study's folder,
# default out/rz-convergence), OUT (default docs/img), PY (the Python with matplotlib,
# default /usr/bin/python3: tools/install-deps.sh --docs); relative paths are taken from
# the directory the script is started in. Writes $OUT/rz-convergence.png; without a
# finished point of the study it says "skip: ..." and exits 0.
. "$(dirname "$0")/lib/common.sh"
STUDY=$(fig_abs "${STUDY:-$ROOT/out/rz-convergence}")
ls "$STUDY"/*.done > /dev/null 2>&1 ||
  fig_skip "no finished point in $STUDY (run: WORK=$STUDY tools/rz-convergence.sh)"
fig_need_hvsph
fig_need_python
HVSPH=$HVSPH WORK=$STUDY bash "$ROOT/tools/rz-convergence.sh" --collect > /dev/null
"$PY" "$ROOT/tools/figures/plot_rz_convergence.py" "$STUDY/convergence.csv" -o "$FIG_TMP"
echo "$FIG_NAME: from $STUDY/convergence.csv"
fig_done
