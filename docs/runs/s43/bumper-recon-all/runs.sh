#!/bin/sh
# Session 43: session 33's §2.4 bumper case (ws-base.yaml) and W.P.1 bumper case
# (wp1-base.yaml) to 12 us with the viscosity's reconstruction for pairs of different
# bodies too (HV_RECON_ALL of ../floor-joined/study.patch, built in build-exp), 1 thread
# each, from this folder; holes.txt: the hole every us, beside session 33's runs of the
# cases (the solver unchanged since: git log e31c8e7..f408187 -- src has no physics).
set -e
H=../../../../build-exp/hvsph
O=../../../../out/s43
HV_RECON_ALL=1 $H run ../../s33/ws-bumper-fracture/ws-base.yaml -o $O/ws-ra --threads 1 --quiet
HV_RECON_ALL=1 $H run ../../s33/al-bumper-fracture/wp1-base.yaml -o $O/wp1-ra --threads 1 --quiet
(cd $O && sh ../../docs/runs/s33/ws-bumper-fracture/holes.sh ws-ra wp1-ra) > holes.txt
