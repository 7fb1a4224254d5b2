#!/bin/sh
# Session 34: session 33's §2.4 bumper case (ws-base.yaml) and W.P.1 bumper case
# (wp1-base.yaml) to 12 us with split particles given the viscosity's reconstruction
# too (hvsph-study: hvsph 7fd365b with ../rod-wall/recon-split.patch), 1 thread each;
# holes.txt: the hole every us, against session 33's runs of the cases.
set -e
HVSPH_RECON_SPLIT=1 hvsph-study run ../../s33/ws-bumper-fracture/ws-base.yaml -o ws-rs --threads 1
HVSPH_RECON_SPLIT=1 hvsph-study run ../../s33/al-bumper-fracture/wp1-base.yaml -o wp1-rs --threads 1
sh ../../s33/ws-bumper-fracture/holes.sh ws-rs wp1-rs > holes.txt
