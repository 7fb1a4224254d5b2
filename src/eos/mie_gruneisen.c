/* mie_gruneisen.c — the EOS `mie-gruneisen`: Mie–Grüneisen with the Murnaghan cold curve
 * (the paper's §2.1). Keys: rho0, c0, n (>= 1), gamma (Γ), cs_floor (default 0.1 c0);
 * its bulk modulus at rest, K0 = ρ₀c₀², gives G from Poisson's ratio.
 *
 *   p    = p_c(ρ) + Γ ρ (E − E_c(ρ))
 *   p_c  = ρ₀c₀²/n · [(ρ/ρ₀)ⁿ − 1]                                   (Murnaghan 1944)
 *   E_c  = c₀²/n · [((ρ/ρ₀)ⁿ⁻¹ − 1)/(n − 1) − 1 + ρ₀/ρ]
 *   c²   = c₀² (ρ/ρ₀)ⁿ⁻¹ + Γ(Γ + 1)(E − E_c),  floored: c ≥ cs_floor
 *
 * ρ₀ reference density, c₀ bulk sound speed, n the Murnaghan exponent (K′ = dK/dp),
 * Γ the Grüneisen coefficient (constant). References: the seed paper §2.1 (its refs.
 * [17, 18]); F. D. Murnaghan, Proc. Natl. Acad. Sci. 30 (1944) 244; M. A. Meyers,
 * Dynamic Behavior of Materials (Wiley 1994), ch. 4 on the Grüneisen form.
 *
 * Properties (checked in tests/unit/test_eos.c):
 * - p(ρ₀, 0) = 0 and E_c(ρ₀) = 0.
 * - dE_c/dρ = p_c/ρ² holds exactly for these formulas: both equal
 *   c₀²/(nρ₀) · [(ρ/ρ₀)ⁿ⁻² − (ρ/ρ₀)⁻²], so E_c is the energy along the cold isentrope
 *   (de = p/ρ² dρ) and E_c ≥ 0 with its minimum at ρ₀.
 * - The sound speed is the exact thermodynamic one, c² = ∂p/∂ρ|_E + (p/ρ²) ∂p/∂E|_ρ:
 *   ∂p/∂ρ|_E = c₀²(ρ/ρ₀)ⁿ⁻¹ + Γ(E − E_c) − Γp_c/ρ and (p/ρ²)Γρ = Γp_c/ρ + Γ²(E − E_c).
 *
 * n = 1 is the limit ((ρ/ρ₀)ⁿ⁻¹ − 1)/(n − 1) → ln(ρ/ρ₀); with Γ = 0 it gives the linear
 * "weakly compressible" solid p = c₀²(ρ − ρ₀) of Gray, Monaghan & Swift (2001).
 * ((ρ/ρ₀)ⁿ⁻¹ − 1)/(n − 1) is computed as expm1((n − 1) ln(ρ/ρ₀))/(n − 1), accurate near ρ₀;
 * one log and one expm1 per evaluation give p_c, E_c and c.
 *
 * The floor: c² falls below zero only for E < E_c in strong expansion — e.g. steel-target
 * at E = 0 falls to c = 0.1 c₀ only below ρ ≈ 0.7ρ₀, where the tension is ≈ 0.24ρ₀c₀²
 * (≈ 45 GPa), far beyond any σ_c of the library, so the Tresca splitting (p ← max(p, 0))
 * has acted long before. The floor (default 0.1 c₀, key `cs_floor`) therefore never
 * touches a physically reachable state; it only keeps the time step and the artificial
 * viscosity finite for particles driven there numerically.
 */
#include <float.h>
#include <math.h>

#include "eos/eos.h"
#include "material/material_read.h"

/* The cold curve at x = ρ/ρ₀ from one log and one expm1: t = (ρ/ρ₀)ⁿ⁻¹ − 1, then
 * (ρ/ρ₀)ⁿ − 1 = x t + (x − 1) (both terms of one sign: no cancellation) and
 * ((ρ/ρ₀)ⁿ⁻¹ − 1)/(n − 1) = t/(n − 1), or ln x in the limit n = 1. */
struct mg_cold {
  double pc;  /* [Pa] p_c */
  double Ec;  /* [J/kg] E_c */
  double xn1; /* [-] (ρ/ρ₀)ⁿ⁻¹ */
};

static struct mg_cold mg_cold_curve(const struct eos_mie_gruneisen *g, double rho)
{
  const double x = rho / g->rho0, lx = log(x), k = g->n - 1.0, c02 = g->c0 * g->c0;
  const double t = k == 0.0 ? 0.0 : expm1(k * lx);
  const double power = k == 0.0 ? lx : t / k;
  struct mg_cold cc;
  cc.pc = g->rho0 * c02 / g->n * (x * t + (x - 1.0));
  cc.Ec = c02 / g->n * (power + (1.0 - x) / x); /* −1 + ρ₀/ρ = (1 − x)/x */
  cc.xn1 = 1.0 + t;
  return cc;
}

double eos_mg_cold_pressure(const struct eos_mie_gruneisen *g, double rho)
{
  return mg_cold_curve(g, rho).pc;
}

double eos_mg_cold_energy(const struct eos_mie_gruneisen *g, double rho)
{
  return mg_cold_curve(g, rho).Ec;
}

void eos_mg_evaluate(const struct eos_mie_gruneisen *g, double rho, double e, struct eos_state *out)
{
  const struct mg_cold cc = mg_cold_curve(g, rho);
  double Et = e - cc.Ec; /* thermal energy E_τ */
  out->p = cc.pc + g->Gamma * rho * Et;
  if (!isfinite(cc.Ec) && rho < g->rho0) {
    /* ρ → 0 (below ~1e-297 kg/m3): E_c ≈ c₀²ρ₀/(nρ) overflows, but ρE_c =
     * c₀²/n·(ρP + ρ₀ − ρ), P = ((ρ/ρ₀)ⁿ⁻¹ − 1)/(n − 1), stays finite: p tends to
     * −(1 + Γ)ρ₀c₀²/n, not −∞ (or NaN with Γ = 0). c² → −∞ (floored) for Γ > 0; with
     * Γ = 0 it is c₀²(ρ/ρ₀)ⁿ⁻¹. */
    const double k = g->n - 1.0;
    const double P = k == 0.0 ? log(rho) - log(g->rho0) : (cc.xn1 - 1.0) / k;
    const double rEc = g->c0 * g->c0 / g->n * (rho * P + (g->rho0 - rho));
    out->p = cc.pc + g->Gamma * (rho * e - rEc);
    if (g->Gamma == 0.0) Et = 0.0;
  }
  double c2 = g->c0 * g->c0 * cc.xn1 + g->Gamma * (g->Gamma + 1.0) * Et;
  const double f2 = g->cs_floor * g->cs_floor;
  if (!(c2 > f2)) c2 = f2;
  out->cs = sqrt(c2);
}

/* p is linear in E: E = E_c + (p − p_c)/(Γρ). With Γ = 0 the pressure does not depend on
 * E: only p = p_c(ρ) is reachable (to round-off), and E = E_c is returned. */
int eos_mg_energy_from_pressure(const struct eos_mie_gruneisen *g, double rho, double p, double *e)
{
  const struct mg_cold cc = mg_cold_curve(g, rho);
  const double pc = cc.pc, Ec = cc.Ec;
  if (g->Gamma > 0.0) {
    *e = Ec + (p - pc) / (g->Gamma * rho);
    return isfinite(*e) ? EOS_OK : EOS_ERR_NO_SOLUTION;
  }
  const double scale = fabs(pc) + fabs(p) + 1e-12 * g->rho0 * g->c0 * g->c0;
  if (fabs(p - pc) > 1e-12 * scale) return EOS_ERR_NO_SOLUTION;
  *e = Ec;
  return EOS_OK;
}

/* ---------------------------------------------------------------- the model's row */

static int mg_evaluate(const struct material *m, double rho, double e, struct eos_state *out)
{
  eos_mg_evaluate(&m->eosp.mg, rho, e, out);
  return EOS_OK;
}

static int mg_energy(const struct material *m, double rho, double p, double *e)
{
  return eos_mg_energy_from_pressure(&m->eosp.mg, rho, p, e);
}

static int mg_read_keys(struct cfg *c, const char *path, struct material *m, struct hv_error *err)
{
  struct eos_mie_gruneisen *g = &m->eosp.mg;
  if (material_get_q(c, path, "rho0", UNIT_DENSITY, NULL, DBL_MIN, HUGE_VAL, &g->rho0, err) ||
      material_get_q(c, path, "c0", UNIT_VELOCITY, NULL, DBL_MIN, HUGE_VAL, &g->c0, err) ||
      material_get_q(c, path, "n", UNIT_NONE, NULL, 1.0, 100.0, &g->n, err) ||
      material_get_q(c, path, "gamma", UNIT_NONE, NULL, 0.0, 100.0, &g->Gamma, err))
    return -1;
  const double floor_def = g->c0 / 10.0;
  if (material_get_q(c, path, "cs_floor", UNIT_VELOCITY, &floor_def, 0.0, HUGE_VAL, &g->cs_floor,
                     err))
    return -1;
  m->rho0 = g->rho0;
  m->K0 = g->rho0 * g->c0 * g->c0;
  return 0;
}

static void mg_print(FILE *f, const struct material *m)
{
  const struct eos_mie_gruneisen *g = &m->eosp.mg;
  material_print_quantity(f, "rho0", g->rho0, "kg/m3");
  material_print_quantity(f, "c0", g->c0, "m/s");
  material_print_quantity(f, "n", g->n, "");
  material_print_quantity(f, "gamma", g->Gamma, "");
  material_print_quantity(f, "cs_floor", g->cs_floor, "m/s");
  material_print_quantity(f, "K0 (rho0 c0^2)", m->K0, "Pa");
}

static const struct material_typical mg_typical[] = {
    {"rho0", UNIT_DENSITY, HV_RHO_CONDENSED_LO, HV_RHO_CONDENSED_HI, HV_RHO_CONDENSED_WHAT},
    {"c0", UNIT_VELOCITY, 100.0, 5e4, "bulk sound speeds of condensed materials"},
    {NULL, 0, 0.0, 0.0, NULL},
};

const struct eos_model eos_mie_gruneisen_model = {
    .name = "mie-gruneisen",
    .read = mg_read_keys,
    .print = mg_print,
    .evaluate = mg_evaluate,
    .energy_from_pressure = mg_energy,
    .typical = mg_typical,
};
