/* von_mises.c — the yield models `constant` and `linear` of the von Mises strength:
 * Y = Y₀, and linear hardening Y = Y₀ + H ε_p (strength.h has the stress update).
 * Keys under the material's strength mapping: yield (Y₀, required) and, for linear,
 * hardening (H, default 0); constant refuses a hardening the case writes (a library
 * material's is ignored, so that a case may switch it to constant). */
#include <math.h>

#include "material/material_read.h"
#include "strength/strength.h"

static double constant_yield(const struct strength_params *s, double eps_p, double rate, double e)
{
  (void)eps_p;
  (void)rate;
  (void)e;
  return s->Y0;
}

static double linear_yield(const struct strength_params *s, double eps_p, double rate, double e)
{
  (void)rate;
  (void)e;
  return s->Y0 + s->H * eps_p;
}

/* Y₀: 0 means a fluid for both (linear hardening starts from it) */
static double y0_max(const struct strength_params *s) { return s->Y0; }

static int constant_read_keys(struct cfg *c, const char *sp, struct material *m,
                              struct hv_error *err)
{
  if (material_not_used_here(c, sp, "hardening", "hardening applies to model: linear only", err) ||
      material_get_q(c, sp, "yield", UNIT_PRESSURE, NULL, 0.0, HUGE_VAL, &m->str.Y0, err))
    return -1;
  return 0;
}

static int linear_read_keys(struct cfg *c, const char *sp, struct material *m, struct hv_error *err)
{
  const double zero = 0.0;
  if (material_get_q(c, sp, "yield", UNIT_PRESSURE, NULL, 0.0, HUGE_VAL, &m->str.Y0, err) ||
      material_get_q(c, sp, "hardening", UNIT_PRESSURE, &zero, 0.0, HUGE_VAL, &m->str.H, err))
    return -1;
  return 0;
}

static void constant_print(FILE *f, const struct strength_params *s)
{
  material_print_quantity(f, "yield", s->Y0, "Pa");
}

static void linear_print(FILE *f, const struct strength_params *s)
{
  material_print_quantity(f, "yield", s->Y0, "Pa");
  material_print_quantity(f, "hardening", s->H, "Pa");
}

const struct yield_model yield_constant_model = {
    .name = "constant",
    .read = constant_read_keys,
    .print = constant_print,
    .yield = constant_yield,
    .yield_max = y0_max,
};

const struct yield_model yield_linear_model = {
    .name = "linear",
    .read = linear_read_keys,
    .print = linear_print,
    .yield = linear_yield,
    .yield_max = y0_max,
};
