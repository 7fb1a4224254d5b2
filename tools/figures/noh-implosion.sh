#!/usr/bin/env bash
# docs/verification.md, Noh: the spherical implosion at t = 0.6 at three spacings, 0.025,
# 0.02 and 0.0167 (33 512, 65 498 and 113 120 particles), density and radial velocity
# against the exact solution: the plateau's convergence. Runs the test
# verification.test_noh twice, as in make check (0.025 and 0.02) and with --spacings
# 0.02 0.016666666666666666 for the finest, and draws the three profiles. The longest of
# the verification pictures: several minutes on 2 idle cores.
. "$(dirname "$0")/lib/common.sh"
fig_need_python
fig_fresh_work
fig_test noh
FIG_TEST_DIR=$FIG_WORK/test_noh_finer fig_test noh --spacings 0.02 0.016666666666666666
"$PY" tools/figures/plot_verification.py -o "$FIG_TMP" \
  "$FIG_WORK/test_noh/noh_profile.csv" "$FIG_WORK/test_noh/noh_fine_profile.csv" \
  "$FIG_WORK/test_noh_finer/noh_fine_profile.csv"
fig_done
