/* fracture.h — the fracture state of a solid particle and its rules (docs/models.md,
 * "Fracture").
 *
 * Each particle of a material with fracture carries an explicit state (the particle
 * field fstate) beside its damage D (the field damage, which the snapshots show):
 *
 *   FRACTURE_INTACT       D in [0, 1): 0, or the cumulative damage so far
 *   FRACTURE_OPENING      fracture.energy: opening across a plane, D = w_max/w_u in (0, 1)
 *   FRACTURE_SPLIT        D = 1: split (what it carries depends on fracture.split: fluid,
 *                         with or without friction; no-tension; crack: cracked once)
 *   FRACTURE_SPLIT_AGAIN  D = 2: split: crack only, split a second time: fluid
 *
 * The state only moves forward (INTACT → OPENING → SPLIT → SPLIT_AGAIN, each step
 * optional), and D takes exactly 1 and 2 in the split states, so that the snapshots'
 * damage column says the state as well. Where it moves:
 *   - fracture_plastic, in the mid-step stress update (sph_solid.c): cumulative damage
 *     from plastic strain reaches 1 (split);
 *   - fracture_end_step, once at the end of each step (step.c), on the end-of-step
 *     stress: the tensile test and each rule's return (the files of this folder).
 *
 * The rules, one file each:
 *   tresca.c      the paper's criterion (§2.1): the largest principal stress σ₁ (tension
 *                 positive) beyond |σ_c| splits the particle at once
 *   cumulative.c  D grows with plastic strain, ΔD = Δε_p/ε_f, and with time under tension
 *                 beyond |σ_c|, ΔD = Δt/τ; split at D = 1
 *   split_fluid.c split: fluid (the paper's rule): no deviatoric stress and no tension;
 *                 with fracture.friction = μ > 0 a deviator limited by Y_d = min(Y, μ
 *                 max(p, 0)), a cohesionless granular material (Collins, Melosh & Ivanov
 *                 2004, MAPS 39:217, without its cohesion)
 *   no_tension.c  split: no-tension: the stress of an intact particle with its principal
 *                 tensions removed wherever it enters the forces and the heating; at the
 *                 end of the step S takes the deviator of that stress
 *   crack.c       split: crack, a smeared crack across the plane of the largest principal
 *                 tension, opening by a strain ε_c of its own so that the plane carries no
 *                 traction, the material keeping its stress within the plane; split again
 *                 (fluid) beyond |σ_c| within the plane or at the strain to failure
 *                 fracture.crack_eps_f
 *   cohesive.c    fracture.energy = G_f: a crack band (Bažant & Oh 1983, Mater. Struct.
 *                 16:155) opening before the paper's split, its traction falling linearly
 *                 to 0 at w_u = 2 G_f/(|σ_c| l), then split
 *   plane.c       what crack.c and cohesive.c share: the plane's normal, its normal stress
 *                 and the stress change of an opening
 *   fracture_read.c  the case file's fracture mapping (each rule reads its own keys)
 * The rules' own functions are declared in fracture/rules.h.
 */
#ifndef HV_FRACTURE_H
#define HV_FRACTURE_H

#include <stddef.h>
#include <stdint.h>

#include "material/material.h"

struct particles;

/* A particle's fracture state (the particle field fstate; see the file's header). */
enum fracture_state {
  FRACTURE_INTACT = 0,
  FRACTURE_OPENING,
  FRACTURE_SPLIT,
  FRACTURE_SPLIT_AGAIN,
  FRACTURE_STATE_COUNT
};

/* ---- the end of a step ------------------------------------------------------------
 * Called once per step after the end-of-step EOS, with S the end-of-step deviator: the
 * tensile test of each intact or opening particle on σ = −pI + S, and the return of each
 * rule (a split drops S; no-tension removes the tensions from S; a crack or an opening
 * plane opens or closes to carry no normal traction). Moves fstate, damage, S and, with
 * crack or energy, the plane's normal (crack) and opening strain (eps_c). Returns how
 * many particles need their pressure evaluated again (a split one in tension loses it,
 * an opening plane changes the density the EOS takes): the caller does so when > 0. */
long fracture_end_step(struct particles *p, const struct material *mat, double dt);
/* The same for the real i alone, at the end of its own step dt (individual steps):
 * nonzero when its pressure must be evaluated again. */
int fracture_end_particle(struct particles *p, size_t i, const struct material *mat, double dt);

/* ---- what the state means to the rest of the step --------------------------------- */

/* Whether a particle in this state keeps a deviatoric stress: intact or opening, split
 * with friction > 0, split without tension, or cracked once (split: crack). (The
 * material must have strength as well.) */
int fracture_keeps_stress(const struct fracture_params *fp, int state);
/* Yield stress [Pa] of a particle in this state whose intact yield stress is Y and
 * pressure p: Y while intact or opening, split without tension or cracked once; once
 * split (fluid), min(Y, μ max(p, 0)) (0 without friction). */
double fracture_yield(const struct fracture_params *fp, int state, double Y, double p);
/* Whether the particle is split with fracture.split: no-tension. */
int fracture_no_tension(const struct fracture_params *fp, int state);
/* Whether the particle is cracked once with fracture.split: crack. */
int fracture_cracked(const struct fracture_params *fp, int state);
/* Whether the particle carries an opening strain (eps_c) and a plane's normal (crack):
 * cracked once (split: crack) or opening (fracture.energy). */
int fracture_opening(const struct fracture_params *fp, int state);
/* The density [kg/m3] particle i's EOS takes: its material's, ρ e^{ε_c}, while a plane
 * of it opens (fracture_opening), else ρ. */
double fracture_eos_density(const struct particles *p, size_t i, const struct fracture_params *fp);
/* The pressure [Pa] a particle carries whose EOS gives pe: no tension once split
 * (max(pe, 0)), except split: no-tension (which removes it from σ instead) and a cracked
 * particle (which keeps the material's tension within its plane); pe otherwise. */
double fracture_pressure(const struct fracture_params *fp, int state, double pe);
/* A particle's damage and state at the start from a body's damage D0 in [0, 1]: D0 < 1
 * intact (opening with fracture.energy and D0 > 0, a plane not yet known: normal 0);
 * 1 split, or split again (fluid, D = 2) with split: crack, whose crack is not known. */
void fracture_start(const struct fracture_params *fp, double d0, double *damage, int32_t *state);
/* The state of each real particle from its damage and material, as the damage alone
 * said it before the state was a field: D >= 2 split again, D >= 1 split, 0 < D < 1 with
 * fracture.energy opening, else intact (for a checkpoint without the record p.fstate). */
void fracture_states_from_damage(struct particles *p, const struct material *mat);
/* Cumulative damage from a plastic strain increment deps (model cumulative with eps_f):
 * D += deps/ε_f, and the particle splits when D reaches 1; nothing otherwise. */
void fracture_plastic(const struct fracture_params *fp, double deps, double *damage,
                      int32_t *state);
/* The first real particle whose state is not one its damage and material allow (a
 * state out of range, D not 1 or 2 in a split state, an opening without fracture.energy,
 * a second split without split: crack): its slot, or (size_t)-1 if none. For a
 * checkpoint's state, which a damaged file could carry. */
size_t fracture_check_states(const struct particles *p, const struct material *mat);

/* ---- the stress of split: no-tension (no_tension.c), also used by the forces ------ */

/* σ = −pI + T with its positive principal stresses set to 0, returned as T (no longer
 * traceless: σ' = −pI + T'); 1 if anything was removed, 0 if σ had no tension. */
int fracture_project(double p, double T[6]);
/* The pressure and deviator of σ' (σ = −pI + S with its tensions removed): returns p',
 * Se gets S' (σ' = −p'I + S'); p and S themselves if σ has no tension. */
double fracture_effective(double p, const double S[6], double Se[6]);

/* ---- the plane of a crack or an opening (plane.c), turned by the stress update ---- */

/* Largest principal stress of σ = −p I + S [Pa], tension positive. */
double fracture_max_principal(double p, const double S[6]);
/* The unit normal of the largest principal stress of σ = −pI + S (the crack's plane). */
void fracture_crack_normal(double p, const double S[6], double n[3]);
/* Turns the crack normal n with the spin Ω = ½(L − Lᵀ) over dt (L[3a+b] = ∂v_a/∂x_b):
 * n ← (n + dt Ω n)/|n + dt Ω n|. */
void fracture_crack_rotate(double n[3], const double L[9], double dt);

#endif
