#!/bin/sh
# Session 44: the free test at 1.29 km/s (free129.yaml, the cases' viscosity and contact
# rule) with study.patch's HV_DDIFF = delta: Molteni & Colagrossi's (2009) density
# diffusion, delta h c sum_j V_j psi_ij . grad_i W_ij with psi_ij = 2 (rho_j - rho_i)
# (x_j - x_i) / r_ij^2, over the pairs of one piece and one material, added to the
# continuity rate: whether the particle-scale pressure noise in the head (rms 4-6 GPa
# against 1-2 GPa of smoothed pressure at 20 us) is what the contact rule's clipping
# turns into a slower floor. build-exp3 built at bfc9be7 with study.patch. To 30 us,
# 1 thread beside the other runs; from the repository root.
Y=docs/runs/s41/floor-free/free129.yaml
HV_DDIFF=0.1 build-exp3/hvsph run $Y -o out/s44/free-a1-dd01 --threads 1 --quiet --set time.end=30us
