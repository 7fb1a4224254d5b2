/* fracture.h — tensile splitting (the paper's Tresca-type criterion) and cumulative
 * damage.
 *
 * Tresca-type (paper §2.1): a particle whose largest principal stress σ₁ (tension
 * positive) exceeds |σ_c| splits: damage D = 1, and from then on it carries no
 * deviatoric stress and no tension (p ← max(p, 0)).
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
/* Largest principal stress of σ = −p I + S [Pa], tension positive. */
double fracture_max_principal(double p, const double S[6]);

#endif
