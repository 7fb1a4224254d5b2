/* johnson_cook.c — the yield model `johnson-cook` (Johnson & Cook 1983):
 *   Y = (A + B ε_pᴺ)(1 + C ln(ε̇_eq/ε̇₀))(1 − T*ᴹ), T* = (T − T_ref)/(T_melt − T_ref),
 *   T = T_ref + e/c_v.
 * The rate factor acts above ε̇₀ only (it never lowers Y); Y = 0 at and above the melt.
 * Keys under the material's strength mapping: A (default: yield), B, N, C (0), M (1),
 * rate0 (1/s), T_ref (293.15 K), T_melt, cv; hardening is refused (it hardens through
 * B and N). */
#include <float.h>
#include <math.h>

#include "material/material_read.h"
#include "strength/strength.h"

static double jc_yield(const struct strength_params *sp, double eps_p, double rate, double e)
{
  double Y = sp->jc_A + sp->jc_B * (eps_p > 0 ? pow(eps_p, sp->jc_N) : 0.0);
  if (sp->jc_C > 0 && sp->jc_rate0 > 0 && rate > sp->jc_rate0)
    Y *= 1.0 + sp->jc_C * log(rate / sp->jc_rate0);
  if (sp->cv > 0 && sp->T_melt > sp->T_ref) {
    double T = sp->T_ref + (e > 0 ? e : 0.0) / sp->cv;
    double Ts = (T - sp->T_ref) / (sp->T_melt - sp->T_ref);
    if (Ts >= 1.0) return 0.0;
    if (Ts > 0.0) Y *= 1.0 - pow(Ts, sp->jc_M);
  }
  return Y;
}

/* A + B, the yield stress at unit plastic strain, at rest and cold: 0 only when A = B =
 * 0, a fluid (which is all material.c asks of it) */
static double jc_yield_max(const struct strength_params *s) { return s->jc_A + s->jc_B; }

static int jc_read_keys(struct cfg *c, const char *sp, struct material *m, struct hv_error *err)
{
  struct strength_params *s = &m->str;
  const double inf = HUGE_VAL, zero = 0.0, one = 1.0, rate0 = 1.0, tref = 293.15;
  char ky[320], ka[320];
  if (material_not_used_here(c, sp, "hardening",
                             "hardening applies to model: linear only "
                             "(Johnson-Cook hardens through B and N)",
                             err))
    return -1;
  material_key(ky, sizeof ky, sp, "yield");
  material_key(ka, sizeof ka, sp, "A");
  /* A defaults to `yield` (the initial yield stress); if both are given, A is used */
  if (!cfg_has(c, ka) && cfg_has(c, ky)) {
    if (cfg_get_quantity(c, ky, UNIT_PRESSURE, NULL, 0.0, inf, &s->jc_A, err)) return -1;
  } else {
    if (cfg_get_quantity(c, ka, UNIT_PRESSURE, NULL, 0.0, inf, &s->jc_A, err)) return -1;
    if (cfg_has(c, ky)) cfg_mark_used(c, ky);
  }
  if (material_get_q(c, sp, "B", UNIT_PRESSURE, NULL, 0.0, inf, &s->jc_B, err) ||
      material_get_q(c, sp, "N", UNIT_NONE, NULL, 0.0, inf, &s->jc_N, err) ||
      material_get_q(c, sp, "C", UNIT_NONE, &zero, 0.0, inf, &s->jc_C, err) ||
      material_get_q(c, sp, "M", UNIT_NONE, &one, DBL_MIN, inf, &s->jc_M, err) ||
      material_get_q(c, sp, "rate0", UNIT_RATE, &rate0, DBL_MIN, inf, &s->jc_rate0, err) ||
      material_get_q(c, sp, "T_ref", UNIT_TEMPERATURE, &tref, 0.0, inf, &s->T_ref, err) ||
      material_get_q(c, sp, "T_melt", UNIT_TEMPERATURE, NULL, 0.0, inf, &s->T_melt, err) ||
      material_get_q(c, sp, "cv", UNIT_SPECIFIC_HEAT, NULL, DBL_MIN, inf, &s->cv, err))
    return -1;
  if (!(s->T_melt > s->T_ref)) {
    char k[320];
    return material_key_error(c, material_key(k, sizeof k, sp, "T_melt"), err,
                              "T_melt = %.9g K must be above T_ref = %.9g K", s->T_melt, s->T_ref);
  }
  s->Y0 = s->jc_A;
  return 0;
}

static void jc_print(FILE *f, const struct strength_params *s)
{
  material_print_quantity(f, "A", s->jc_A, "Pa");
  material_print_quantity(f, "B", s->jc_B, "Pa");
  material_print_quantity(f, "N", s->jc_N, "");
  material_print_quantity(f, "C", s->jc_C, "");
  material_print_quantity(f, "M", s->jc_M, "");
  material_print_quantity(f, "rate0", s->jc_rate0, "1/s");
  material_print_quantity(f, "T_ref", s->T_ref, "K");
  material_print_quantity(f, "T_melt", s->T_melt, "K");
  material_print_quantity(f, "cv", s->cv, "J/kg/K");
}

const struct yield_model yield_johnson_cook_model = {
    .name = "johnson-cook",
    .read = jc_read_keys,
    .print = jc_print,
    .yield = jc_yield,
    .yield_max = jc_yield_max,
};
