/* cumulative.c — cumulative damage (fracture.model: cumulative): D grows with plastic
 * strain, ΔD = Δε_p/ε_f, and with time under tension beyond |σ_c|, ΔD = Δt/τ; the
 * particle splits when D reaches 1 (then as split: fluid, no-tension or crack says).
 * See fracture.h. */
#include "fracture/rules.h"

#include <math.h>

#include "fracture/read.h"

void fracture_plastic(const struct fracture_params *fp, double deps, double *damage, int32_t *state)
{
  /* D < 1 in the intact state only (cumulative has no opening: fracture_read) */
  if (fp->kind != FRACTURE_CUMULATIVE || fp->eps_f <= 0 || *damage >= 1.0) return;
  const double d = *damage + deps / fp->eps_f;
  *damage = d >= 1.0 ? 1.0 : d;
  if (*damage >= 1.0) *state = FRACTURE_SPLIT;
}

double fracture_cumulative_tension(const struct fracture_params *fp, double damage, int over,
                                   double dt)
{
  if (over) damage += fp->tau > 0 ? dt / fp->tau : 1.0;
  return damage >= 1.0 ? 1.0 : damage;
}

/* ---- reading (fracture_read.c) ---------------------------------------------------- */

int fracture_read_cumulative(struct cfg *c, const char *fp, struct material *m,
                             struct hv_error *err)
{
  struct fracture_params *f = &m->frac;
  const double zero = 0.0;
  char k[320];
  if (material_not_used_here(c, fp, "energy",
                             "energy (a cohesive opening before the split) "
                             "applies to model: tresca only",
                             err) ||
      fracture_read_sigma_c(c, fp, &zero, 1, &f->sigma_c, err) ||
      material_get_q(c, fp, "eps_f", UNIT_NONE, &zero, 0.0, HUGE_VAL, &f->eps_f, err) ||
      material_get_q(c, fp, "tau", UNIT_TIME, &zero, 0.0, HUGE_VAL, &f->tau, err))
    return -1;
  if (!(f->eps_f > 0.0) && !(f->sigma_c < 0.0))
    return material_key_error(c, material_key(k, sizeof k, fp, "model"), err,
                              "cumulative damage needs eps_f > 0 (plastic strain to failure) "
                              "or sigma_c < 0 (with tau, the time under tension to failure)");
  return 0;
}
