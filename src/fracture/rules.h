/* rules.h — the fracture rules' own functions (one file each, see fracture.h), which
 * fracture_end_step (fracture.c) calls per particle, and the unit tests call directly.
 * Nothing here reads the config; the rules' readers are in fracture/read.h. */
#ifndef HV_FRACTURE_RULES_H
#define HV_FRACTURE_RULES_H

#include "fracture/fracture.h"

/* ---- tresca.c, cumulative.c: the tensile test ------------------------------------ */

/* Whether the largest principal stress of σ = −pI + S exceeds |σ_c| (σ_c < 0; never
 * when σ_c is 0, the cumulative model without a tensile criterion). */
int fracture_over_limit(const struct fracture_params *fp, double p, const double S[6]);
/* Damage after a step dt [s] in the stress state p [Pa], S [Pa] of a particle of damage
 * D < 1 (D itself when D >= 1 or without fracture): 1 beyond |σ_c| (tresca), or D +
 * Δt/τ (cumulative, capped at 1; 1 at once without τ). */
double fracture_tension(const struct fracture_params *fp, double damage, double p,
                        const double S[6], double dt);
/* cumulative.c: the time-to-failure part of fracture_tension: D + Δt/τ when over, capped
 * at 1. */
double fracture_cumulative_tension(const struct fracture_params *fp, double damage, int over,
                                   double dt);

/* ---- plane.c: an opening plane ---------------------------------------------------- */

/* σ_nn = nᵀσn of σ = −pI + S: the normal stress on the plane of normal n. */
double fracture_normal_stress(double p, const double S[6], const double n[3]);
/* The deviator's change when the plane of normal n opens by a strain dw (the pressure's,
 * about K dw, follows from the EOS): S −= 2G dw dev(nnᵀ). */
void fracture_open_by(double S[6], const double n[3], double G, double dw);
/* The moduli particle i's opening plane returns its normal stress with: M = ρ_m c² from
 * its longitudinal speed at its material's density ρ_m = ρ e^{ε_c}, *G the material's
 * shear modulus, *K = max(M − 4G/3, 0). */
void fracture_opening_moduli(const struct particles *p, size_t i, const struct material *m,
                             double *K, double *G);

/* ---- crack.c: split: crack -------------------------------------------------------- */

/* The strain to failure of the cracked state (fracture.crack_eps_f) in the stress state
 * −pI + S: d1 + d2 exp(d3 σ*), σ* = −p/√(3J₂) clamped to [−1.5, 1.5] (±1.5 without a
 * deviator, by the sign of −p); HUGE_VAL when crack_eps_f is not given. */
double fracture_crack_eps_f(const struct fracture_params *fp, double p, const double S[6]);
/* The end of a step of a cracked particle (split: crack). split_now: it split in this
 * step; p, S the end-of-step pressure and deviator, K and G the bulk and shear moduli,
 * eps_p the equivalent plastic strain, n the crack normal and *eps_c the crack strain. A
 * particle split in this step cracks across its largest principal tension (n, ε_c = 0).
 * The crack opens or closes by Δε_c = σ_nn/(K + 4G/3) (ε_c >= 0): S −= 2G Δε_c
 * dev(nnᵀ), and the pressure rises by about K Δε_c (*dp; the caller evaluates the EOS
 * again at ρ e^{ε_c}); while open, the shear traction on the plane is removed from S. If
 * then the largest principal stress of −(p + dp)I + S exceeds |σ_c| (σ_c < 0), or eps_p
 * reaches fracture_crack_eps_f of that state, the particle splits again: S = 0, n = 0,
 * ε_c = 0. Returns the new state: FRACTURE_SPLIT (cracked) or FRACTURE_SPLIT_AGAIN. */
int fracture_crack_return(const struct fracture_params *fp, int split_now, double p, double K,
                          double G, double eps_p, double S[6], double n[3], double *eps_c,
                          double *dp);
/* fracture_crack_return on particle i (its S holding the end-of-step deviator): returns 1
 * when its pressure must be evaluated again. */
int fracture_crack_end(struct particles *p, size_t i, const struct material *m, int split_now);

/* ---- cohesive.c: fracture.energy -------------------------------------------------- */

/* The opening's end w_u = 2 G_f/(|σ_c| l) [-] of a particle of spacing l [m]. */
double fracture_open_strain(const struct fracture_params *fp, double l);
/* The end of a step of an intact or opening particle with fracture.energy > 0: d0 its
 * opening D = w_max/w_u at the step's start (0: intact), d the tensile test's result
 * (fracture_tension): nothing unless it opens already (d0 > 0) or starts to (d >= 1:
 * then n = its largest principal tension's normal, w = 0). p, S the end-of-step pressure
 * and deviator (S updated), K and G the moduli, l the particle's spacing, n the normal,
 * *w the opening strain. With σ_nn = −p + nᵀSn and the traction limit T = |σ_c|(1 − D):
 * σ_nn > T opens it (Δw > 0, w_max with it) to σ_nn − M Δw = |σ_c|(1 − (w_max + Δw)/w_u)
 * on the softening line (M = K + 4G/3; all of w_u − w_max at once where the line is
 * steeper than M); σ_nn < 0 closes it without traction (Δw = max(σ_nn/M, −w)), and a part
 * so closed (w < w_max) reopens without traction before the opening goes on; S −= 2G Δw
 * dev(nnᵀ), *dp = K Δw (the caller evaluates the EOS at ρ e^{w}); the shear on the plane
 * is left to the yield stress. Returns the new D: w_max/w_u (at least 10⁻¹²), or 1 when
 * w_max reaches w_u (split: the caller drops S; n = 0, w = 0); d0 when nothing opens. */
double fracture_cohesive_return(const struct fracture_params *fp, double d0, double d, double p,
                                double K, double G, double l, double S[6], double n[3], double *w,
                                double *dp);
/* fracture_cohesive_return on particle i given its tensile test d (its S holding the
 * end-of-step deviator): moves its state and damage; returns 1 when its pressure must be
 * evaluated again. */
int fracture_cohesive_end(struct particles *p, size_t i, const struct material *m, double d);

/* ---- no_tension.c, split_fluid.c: the other split particles ----------------------- */

/* split: no-tension: S takes the deviator of σ with its principal tensions removed. */
void fracture_no_tension_end(struct particles *p, size_t i);
/* split: fluid: a particle split in this step (split_now), or any without friction,
 * drops its deviator; returns 1 when it is in tension (its pressure is then dropped). */
int fracture_fluid_end(struct particles *p, size_t i, const struct fracture_params *fp,
                       int split_now);
/* split: fluid: the yield stress of the split material, min(Y, μ max(p, 0)). */
double fracture_fluid_yield(const struct fracture_params *fp, double Y, double p);

#endif
