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
/* Whether a particle of damage D keeps a deviatoric stress: intact (D < 1), or split
 * with friction > 0. (The material must have strength as well.) */
int fracture_keeps_stress(const struct fracture_params *fp, double damage);
/* Yield stress [Pa] of a particle of damage D whose intact yield stress is Y and
 * pressure p: Y while D < 1; once split, min(Y, μ max(p, 0)) (0 without friction). */
double fracture_yield(const struct fracture_params *fp, double damage, double Y, double p);
/* Largest principal stress of σ = −p I + S [Pa], tension positive. */
double fracture_max_principal(double p, const double S[6]);

#endif
