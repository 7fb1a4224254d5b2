/* tresca.c — the paper's splitting criterion (§2.1), and the tensile test the other
 * rules share: a particle whose largest principal stress σ₁ (tension positive) exceeds
 * |σ_c| splits (D = 1). See fracture.h. */
#include "fracture/rules.h"

#include <math.h>

#include "fracture/read.h"
#include "strength/sym3.h"

int fracture_over_limit(const struct fracture_params *fp, double p, const double S[6])
{
  const double limit = -fp->sigma_c; /* σ_c < 0: tension */
  const double sig[6] = {S[0] - p, S[1] - p, S[2] - p, S[3], S[4], S[5]};
  /* the bound first: most particles are far from the limit, the eigenvalues cost more */
  return limit > 0 && sym3_max_bound(sig) > limit && fracture_max_principal(p, S) > limit;
}

double fracture_tension(const struct fracture_params *fp, double damage, double p,
                        const double S[6], double dt)
{
  if (damage >= 1.0 || fp->kind == FRACTURE_NONE) return damage;
  const int over = fracture_over_limit(fp, p, S);
  if (fp->kind == FRACTURE_TRESCA) return over ? 1.0 : damage;
  return fracture_cumulative_tension(fp, damage, over, dt);
}

/* ---- reading (fracture_read.c) ---------------------------------------------------- */

int fracture_read_sigma_c(struct cfg *c, const char *fp, const double *def, int zero_off,
                          double *out, struct hv_error *err)
{
  char k[320];
  material_key(k, sizeof k, fp, "sigma_c");
  if (cfg_get_quantity(c, k, UNIT_PRESSURE, def, -HUGE_VAL, HUGE_VAL, out, err)) return -1;
  if (cfg_has(c, k) && !(*out < 0.0) && !(zero_off && *out == 0.0))
    return material_key_error(c, k, err,
                              "sigma_c = %.9g Pa must be negative (tension is "
                              "negative, as in the paper's tables)%s",
                              *out, zero_off ? "; 0 switches the tensile criterion off" : "");
  return 0;
}

int fracture_read_tresca(struct cfg *c, const char *fp, struct material *m, struct hv_error *err)
{
  if (material_not_used_here(c, fp, "eps_f", "eps_f applies to model: cumulative only", err) ||
      material_not_used_here(c, fp, "tau", "tau applies to model: cumulative only", err) ||
      fracture_read_sigma_c(c, fp, NULL, 0, &m->frac.sigma_c, err))
    return -1;
  return fracture_read_energy(c, fp, m, err);
}
