/* step.h — one time step, in the paper's predictor–corrector order.
 *
 *   1. coordinates (predictor)  x* = xⁿ + ½Δt vⁿ,  v* = vⁿ + ½Δt aⁿ⁻¹
 *      (boundaries applied, ghosts made, neighbour cells built at x*)
 *   2. density                  ρⁿ⁺¹ = ρⁿ + Δt Dρ(x*, v*);  ρ* = ρⁿ + ½Δt Dρ
 *      e* = eⁿ + ½Δt Deⁿ⁻¹, p* = EOS(ρ*, e*)
 *   3. velocity                 vⁿ⁺¹ = vⁿ + Δt a(x*, v*, ρ*, p*)
 *   4. coordinates (corrector)  xⁿ⁺¹ = x* + ½Δt vⁿ⁺¹  (= xⁿ + ½Δt (vⁿ + vⁿ⁺¹))
 *   5. energy                   eⁿ⁺¹ = eⁿ + Δt De(x*, v*, ρ*, p*)
 *   6. pressure                 pⁿ⁺¹ = EOS(ρⁿ⁺¹, eⁿ⁺¹);  h from ρⁿ⁺¹
 * The rates are evaluated at the mid-step state, so the scheme is second order
 * for smooth flow. The next Δt comes from the CFL and acceleration limits.
 *
 * Individual time steps (time.individual, p->indiv): step_advance advances one block of
 * s->dt, in which each particle takes this scheme on its own power-of-two fraction of
 * the block, its rates evaluated at its own mid-step with its neighbours drifted there,
 * neighbours' steps within a factor 4 (the limiter wakes a particle on a long step when
 * a neighbour starts a short one), and every particle at the block's ends (docs/models.md,
 * "Individual time steps"). s->dt is then the block, proposed from the particles' own
 * limits; s->evals counts the particles' rate evaluations.
 */
#ifndef HV_STEP_H
#define HV_STEP_H

#include "sim/sim.h"

/* Evaluates p, cs from the EOS and the initial accelerations; sets s->dt. */
int step_init(struct sim *s, struct hv_error *err);
/* Advances the state by s->dt (which the caller may have shortened to hit an output
 * time) and proposes the next s->dt. On a failure (NaN, ρ ≤ 0, EOS), err names the
 * particle, time and field; code HV_EXIT_RUN. */
int step_advance(struct sim *s, struct hv_error *err);
/* Largest smoothing length of the reals [m]. */
double step_hmax(const struct particles *p);
/* What set the last proposed step (s->dt_limit), in words. */
const char *step_limit_name(enum dt_limit k);

#endif
