/* fracture.h — tensile splitting (the paper's Tresca-type criterion) and cumulative
 * damage.
 *
 * Tresca-type (paper §2.1): a particle whose largest principal stress σ₁ (tension
 * positive) exceeds |σ_c| splits: damage D = 1, and from then on it carries no
 * deviatoric stress and no tension (p ← max(p, 0)).
 * Split material with friction (option, fracture.friction = μ > 0): a split particle
 * keeps a deviatoric stress limited by Y_d = min(Y, μ max(p, 0)), the strength of a
 * cohesionless granular material (Coulomb friction; as the damaged-rock strength of
 * Collins, Melosh & Ivanov 2004, MAPS 39:217, without its cohesion).
 * Split without tension (option, fracture.split: no-tension): a split particle keeps its
 * deviatoric stress and yield stress as if intact, but the principal tensions of
 * σ = −pI + S are removed (σ' = Q min(Λ, 0) Qᵀ) wherever the stress enters the forces
 * and the energy: cracks open under tension and close under compression (the
 * "directional" or orthotropic post-failure response of hydrocodes). A split wall in
 * radial compression and hoop tension keeps its radial compression and its shear.
 * The state (ρ, e, S) is not projected within a step — p stays the EOS's, S the
 * updated deviator — only the stress the forces and the heating use; at the end of
 * the step S takes the deviator of σ' (the elastic stress a crack releases).
 * Cumulative (option): D grows with plastic strain, ΔD = Δε_p/ε_f, and with time
 * under tension beyond |σ_c|, ΔD = Δt/τ; the particle splits when D reaches 1.
 */
#ifndef HV_FRACTURE_H
#define HV_FRACTURE_H

#include "material/material.h"

/* Damage after a plastic strain increment (cumulative model; unchanged otherwise). */
double fracture_plastic(const struct fracture_params *fp, double damage, double deps_p);
/* Damage after a step dt [s] in the stress state p [Pa], S [Pa]. */
double fracture_tension(const struct fracture_params *fp, double damage, double p,
                        const double S[6], double dt);
/* Whether a particle of damage D keeps a deviatoric stress: intact (D < 1), split with
 * friction > 0, or split without tension. (The material must have strength as well.) */
int fracture_keeps_stress(const struct fracture_params *fp, double damage);
/* Yield stress [Pa] of a particle of damage D whose intact yield stress is Y and
 * pressure p: Y while D < 1 or split without tension; once split (fluid),
 * min(Y, μ max(p, 0)) (0 without friction). */
double fracture_yield(const struct fracture_params *fp, double damage, double Y, double p);
/* Whether particle of damage D is split with fracture.split: no-tension. */
int fracture_no_tension(const struct fracture_params *fp, double damage);
/* σ = −pI + T with its positive principal stresses set to 0, returned as T (no longer
 * traceless: σ' = −pI + T'); 1 if anything was removed, 0 if σ had no tension. */
int fracture_project(double p, double T[6]);
/* The pressure and deviator of σ' (σ = −pI + S with its tensions removed): returns p',
 * Se gets S' (σ' = −p'I + S'); p and S themselves if σ has no tension. */
double fracture_effective(double p, const double S[6], double Se[6]);
/* Largest principal stress of σ = −p I + S [Pa], tension positive. */
double fracture_max_principal(double p, const double S[6]);

#endif
