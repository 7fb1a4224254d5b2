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
 * Split along a crack (option, fracture.split: crack; a smeared crack): a particle
 * that splits cracks across the plane normal to its largest principal tension (the
 * unit normal n, stored per particle and turned with the material's spin, ṅ = Ωn).
 * The crack opens by a strain ε_c >= 0 of its own (a distension, as porosity: the
 * material's density is ρ_m = ρ e^{ε_c}, and the EOS takes ρ_m), so that the open
 * plane carries no traction: at the end of each step the normal stress σ_nn = nᵀσn is
 * returned to 0 by Δε_c = σ_nn/M (M = K + 4G/3, the uniaxial-strain modulus; the
 * material's stress changes by −Δε_c (K I + 2G dev(nnᵀ))), bounded by ε_c >= 0 (a
 * closed crack carries compression), and while it is open the shear traction on the
 * plane is released. Within its plane the material keeps its stress, tension included,
 * and its strength: a spalled plate keeps its membrane tension. When the largest
 * principal stress within the plane exceeds |σ_c| the particle splits a second time
 * and is split fluid (the default rule); with fracture.crack_eps_f it does so as well once
 * its equivalent plastic strain ε_p reaches ε_f = d1 + d2 exp(d3 σ*), σ* = σ_m/σ_eq the
 * stress triaxiality (the Johnson–Cook failure strain without its rate and temperature
 * factors): a cracked membrane, in plane stress below |σ_c|, tears by stretching.
 * D = 1 marks the cracked state, D = 2 the fluid.
 * Cumulative (option): D grows with plastic strain, ΔD = Δε_p/ε_f, and with time
 * under tension beyond |σ_c|, ΔD = Δt/τ; the particle splits when D reaches 1.
 * Cohesive opening before the split (option, fracture.energy = G_f > 0, model tresca,
 * split fluid; a crack band, Bažant & Oh 1983, Mater. Struct. 16:155): where the
 * paper's rule would split the particle, it starts to open across the plane normal to
 * its largest principal tension (n, as split: crack) by a strain w >= 0 of its own (the
 * EOS takes ρ e^{w}); the traction the opening plane carries falls linearly from |σ_c|
 * to 0 as the largest opening w_max reached grows to w_u = 2 G_f/(|σ_c| l), l = (m/ρ₀)^{1/3}
 * the particle's spacing, so that a particle opened through has taken G_f per unit area
 * of its cross-section, ½|σ_c| w_u l = G_f, whatever its size. D = max(w_max/w_u, 10⁻¹²)
 * while it opens (0 < D < 1; it keeps its deviatoric stress and yield stress); at w_u
 * it splits (D = 1, the paper's rule). G_f → 0 is the paper's rule. The opening runs
 * only while the tension is there: a short tensile pulse leaves D < 1.
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
 * friction > 0, split without tension, or cracked once (split: crack, 1 <= D < 2). (The
 * material must have strength as well.) */
int fracture_keeps_stress(const struct fracture_params *fp, double damage);
/* Yield stress [Pa] of a particle of damage D whose intact yield stress is Y and
 * pressure p: Y while D < 1, split without tension or cracked once; once split (fluid),
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

/* Whether a particle of damage D is cracked once with fracture.split: crack (1 <= D < 2). */
int fracture_cracked(const struct fracture_params *fp, double damage);
/* The unit normal of the largest principal stress of σ = −pI + S (the crack's plane). */
void fracture_crack_normal(double p, const double S[6], double n[3]);
/* Turns the crack normal n with the spin Ω = ½(L − Lᵀ) over dt (L[3a+b] = ∂v_a/∂x_b):
 * n ← (n + dt Ω n)/|n + dt Ω n|. */
void fracture_crack_rotate(double n[3], const double L[9], double dt);
/* The strain to failure of the cracked state (fracture.crack_eps_f) in the stress state
 * −pI + S: d1 + d2 exp(d3 σ*), σ* = −p/√(3J₂) clamped to [−1.5, 1.5] (±1.5 without a
 * deviator, by the sign of −p); HUGE_VAL when crack_eps_f is not given. */
double fracture_crack_eps_f(const struct fracture_params *fp, double p, const double S[6]);
/* The end of a step with fracture.split: crack. d0 the damage at the step's start, d the
 * damage after the tensile test (fracture_tension); p, S the end-of-step pressure and
 * deviator, K and G the bulk and shear moduli, eps_p the equivalent plastic strain, n the
 * crack normal and *eps_c the crack strain. A particle split in this step (d0 < 1 <= d)
 * cracks across its largest principal tension (n, ε_c = 0). A cracked one's crack opens or
 * closes by Δε_c = σ_nn/(K + 4G/3) (ε_c >= 0): S −= 2G Δε_c dev(nnᵀ), and the pressure
 * rises by about K Δε_c (*dp; the caller evaluates the EOS again at ρ e^{ε_c}); while open,
 * the shear traction on the plane is removed from S. If then the largest principal stress
 * of −(p + dp)I + S exceeds |σ_c| (σ_c < 0), or eps_p reaches fracture_crack_eps_f of that
 * state, the particle splits again: D = 2 (fluid), S = 0, n = 0, ε_c = 0. Returns the new
 * damage. */
double fracture_crack_return(const struct fracture_params *fp, double d0, double d, double p,
                             double K, double G, double eps_p, double S[6], double n[3],
                             double *eps_c, double *dp);

/* Whether a particle of damage D carries an opening strain (p->eps_c) and a normal
 * (p->crack): cracked once with fracture.split: crack (1 <= D < 2), or opening with
 * fracture.energy (0 < D < 1). */
int fracture_opening(const struct fracture_params *fp, double damage);
/* The opening's end w_u = 2 G_f/(|σ_c| l) [-] of a particle of spacing l [m]. */
double fracture_open_strain(const struct fracture_params *fp, double l);
/* The end of a step with fracture.energy > 0 for a particle of damage d0 < 1 whose
 * split test (fracture_tension) gave d: nothing unless it opens already (d0 > 0) or
 * starts to (d >= 1: then n = its largest principal tension's normal, w = 0). p, S the
 * end-of-step pressure and deviator (S updated), K and G the moduli, l the particle's
 * spacing, n the normal, *w the opening strain. With σ_nn = −p + nᵀSn and the
 * traction limit T = |σ_c|(1 − D) (D = w_max/w_u): σ_nn > T opens it (Δw > 0, w_max
 * with it) to σ_nn − M Δw = |σ_c|(1 − (w_max + Δw)/w_u) on the softening line (M = K +
 * 4G/3; all of w_u − w_max at once where the line is steeper than M); σ_nn < 0 closes it
 * without traction (Δw = max(σ_nn/M, −w)), and a part so closed (w < w_max) reopens
 * without traction before the opening goes on; S −= 2G Δw dev(nnᵀ), *dp = K Δw (the
 * caller evaluates the EOS at ρ e^{w}); the shear on the plane is left to the yield
 * stress. Returns the new damage: w_max/w_u (at least 10⁻¹²), or 1 when w_max reaches
 * w_u (split: the caller drops S; n = 0, w = 0). */
double fracture_cohesive_return(const struct fracture_params *fp, double d0, double d, double p,
                                double K, double G, double l, double S[6], double n[3],
                                double *w, double *dp);

#endif
