/* tillotson.c — the EOS `tillotson`: Tillotson (1962) for metals and rock. Keys: rho0, a,
 * b, A, B, E0, alpha, beta, E_iv, E_cv (> E_iv), rho_iv (default 0, < rho0), cs_floor;
 * its bulk modulus at rest, K0 = A, gives G from Poisson's ratio.
 *
 * Notation of Melosh (1989), Impact Cratering, appendix II, and Benz & Asphaug (1999),
 * Icarus 142:5, eqs. (A1)–(A3); η = ρ/ρ₀, μ = η − 1, z = ρ₀/ρ − 1, ω = E/(E₀η²) + 1:
 *
 *   compressed (ρ ≥ ρ₀, or any ρ with E ≤ E_iv: cold expanded states):
 *     p_c = (a + b/ω) ρE + Aμ + Bμ²
 *   expanded (ρ < ρ₀ and E ≥ E_cv):
 *     p_e = aρE + [bρE/ω + Aμ e^(−βz)] e^(−αz²)
 *   hybrid (ρ < ρ₀ and E_iv < E < E_cv), linear in E between the two:
 *     p = [(E − E_iv) p_e + (E_cv − E) p_c] / (E_cv − E_iv)
 *
 * p is continuous everywhere: at E_iv and E_cv by construction, and at ρ₀ because
 * p_e(ρ₀) = p_c(ρ₀) = (a + b/ω)ρ₀E. p(ρ₀, 0) = 0.
 *
 * Sound speed: the thermodynamic c² = ∂p/∂ρ|_E + (p/ρ²) ∂p/∂E|_ρ, with the analytic
 * derivatives of each branch (and of the interpolation, which adds (p_e − p_c)/(E_cv − E_iv)
 * to ∂p/∂E), floored at cs_floor (default 1% of √(A/ρ₀), the bulk sound speed: a lower
 * floor than Mie–Grüneisen's because Tillotson's expanded branch describes vapour, whose
 * sound speed is legitimately far below the solid's).
 *
 *   ∂p_c/∂E = ρ(a + b/ω²)            ∂p_c/∂ρ = (a + b/ω)E + 2bE(ω − 1)/ω² + (A + 2Bμ)/ρ₀
 *   ∂p_e/∂E = ρ(a + b e^(−αz²)/ω²)
 *   ∂p_e/∂ρ = aE + e^(−αz²)[bE/ω + 2bE(ω − 1)/ω² + A e^(−βz)/ρ₀ + Aμ e^(−βz) βρ₀/ρ²]
 *             + [bρE/ω + Aμ e^(−βz)] e^(−αz²) 2αzρ₀/ρ²
 *
 * Choices (documented in docs/models.md):
 * - Cold expanded states use p_c including Bμ², as Benz & Asphaug (1999); the tension
 *   they carry (down to −(A − B) as ρ → 0) is removed by the fracture model.
 * - `rho_iv` (default 0: off): below this density the compressed-branch pressure p_c
 *   (in the cold and hybrid regions) carries no tension, p_c ← max(p_c, 0) — the cut of
 *   cold expanded states Melosh (1989) suggests for strongly expanded (fragmented)
 *   material, typically ρ_iv ≈ 0.8ρ₀. This makes p discontinuous in ρ at ρ_iv.
 * - Tillotson's energy is measured from the reference state and its domain is E ≥ 0
 *   (ω → 0 at E = −E₀η²); a negative E (round-off) is evaluated as E = 0.
 */
#include <float.h>
#include <math.h>

#include "eos/eos.h"
#include "material/material_read.h"

/* ω = E/(E₀η²) + 1. At E = 0 it is 1, also where η² underflows to 0 (ρ below ~1e-160
 * kg/m3), which would give 0/0. */
static inline double till_omega(const struct eos_tillotson *t, double eta, double e)
{
  return e > 0.0 ? e / (t->E0 * eta * eta) + 1.0 : 1.0;
}

/* 2bE(ω − 1)/ω², the part of ∂(bρE/ω)/∂ρ from ω's dependence on ρ; it tends to 0 as
 * ω → ∞ (where ω itself overflows, ∞/∞ would give NaN). */
static inline double till_domega(double b, double e, double w)
{
  return w < HUGE_VAL ? 2.0 * b * e * (w - 1.0) / (w * w) : 0.0;
}

struct till_branch {
  double p;    /* [Pa] */
  double dpdr; /* [Pa m3/kg] ∂p/∂ρ at constant E */
  double dpde; /* [kg/m3] ∂p/∂E at constant ρ */
};

static void till_compressed(const struct eos_tillotson *t, double rho, double e,
                            struct till_branch *o)
{
  const double eta = rho / t->rho0, mu = eta - 1.0;
  const double w = till_omega(t, eta, e);
  o->p = (t->a + t->b / w) * rho * e + t->A * mu + t->B * mu * mu;
  o->dpde = rho * (t->a + t->b / (w * w));
  o->dpdr = (t->a + t->b / w) * e + till_domega(t->b, e, w) + (t->A + 2.0 * t->B * mu) / t->rho0;
  if (rho < t->rho_iv && o->p < 0.0) o->p = o->dpde = o->dpdr = 0.0;
}

static void till_expanded(const struct eos_tillotson *t, double rho, double e,
                          struct till_branch *o)
{
  const double eta = rho / t->rho0, mu = eta - 1.0, z = t->rho0 / rho - 1.0;
  const double w = till_omega(t, eta, e);
  const double X = exp(-t->alpha * z * z), Y = exp(-t->beta * z);
  const double q = t->b * rho * e / w + t->A * mu * Y;
  const double r2 = t->rho0 / (rho * rho);
  /* the e^(−βz) and e^(−αz²) terms: 0 once the exponential is, also where z or ρ₀/ρ²
     overflows (ρ below ~1e-150 kg/m3; 0·∞ would make c NaN) */
  const double dq = t->b * e / w + till_domega(t->b, e, w) + t->A * Y / t->rho0 +
                    (Y > 0.0 ? t->A * mu * Y * t->beta * r2 : 0.0);
  o->p = t->a * rho * e + q * X;
  o->dpde = rho * (t->a + t->b * X / (w * w));
  o->dpdr = t->a * e + X * dq + (X > 0.0 ? q * X * 2.0 * t->alpha * z * r2 : 0.0);
}

/* p and its partial derivatives in the region (ρ, E) falls in. */
static void till_state(const struct eos_tillotson *t, double rho, double e, struct till_branch *o)
{
  if (e < 0.0) e = 0.0;
  if (rho >= t->rho0 || e <= t->E_iv) {
    till_compressed(t, rho, e, o);
  } else if (e >= t->E_cv) {
    till_expanded(t, rho, e, o);
  } else {
    struct till_branch c, x;
    till_compressed(t, rho, e, &c);
    till_expanded(t, rho, e, &x);
    const double dE = t->E_cv - t->E_iv, y = (e - t->E_iv) / dE;
    o->p = y * x.p + (1.0 - y) * c.p;
    o->dpdr = y * x.dpdr + (1.0 - y) * c.dpdr;
    o->dpde = y * x.dpde + (1.0 - y) * c.dpde + (x.p - c.p) / dE;
  }
}

void eos_tillotson_evaluate(const struct eos_tillotson *t, double rho, double e,
                            struct eos_state *out)
{
  struct till_branch b;
  till_state(t, rho, e, &b);
  const double r2 = rho * rho;
  /* (p/ρ)(∂p/∂E/ρ) where ρ² underflows (ρ below ~1e-154 kg/m3): p/0 = ±∞ */
  double c2 = b.dpdr + (r2 >= DBL_MIN ? b.p / r2 * b.dpde : b.p / rho * (b.dpde / rho));
  const double f2 = t->cs_floor * t->cs_floor;
  if (!(c2 > f2)) c2 = f2;
  out->p = b.p;
  out->cs = sqrt(c2);
}

/* Bisection on E >= 0 for p(ρ, E) = p: p rises with E in every branch (∂p/∂E > 0 there;
 * the hybrid adds (p_e − p_c)/(E_cv − E_iv)), so the bracket [0, E_hi] holds one root. */
int eos_tillotson_energy_from_pressure(const struct eos_tillotson *t, double rho, double p,
                                       double *e)
{
  struct till_branch b;
  till_state(t, rho, 0.0, &b);
  if (b.p == p) {
    *e = 0.0;
    return EOS_OK;
  }
  if (b.p > p) return EOS_ERR_NO_SOLUTION; /* would need E < 0 */
  double lo = 0.0, hi = t->E_cv > t->E0 ? t->E_cv : t->E0;
  for (int k = 0;; k++) {
    till_state(t, rho, hi, &b);
    if (b.p >= p) break;
    if (k == 200 || !isfinite(b.p)) return EOS_ERR_NO_SOLUTION;
    lo = hi;
    hi *= 2.0;
  }
  for (int k = 0; k < 400 && hi - lo > 4e-16 * hi; k++) {
    const double mid = 0.5 * (lo + hi);
    till_state(t, rho, mid, &b);
    if (b.p < p)
      lo = mid;
    else
      hi = mid;
  }
  /* the end whose pressure is nearer */
  struct till_branch bl;
  till_state(t, rho, lo, &bl);
  till_state(t, rho, hi, &b);
  *e = fabs(bl.p - p) < fabs(b.p - p) ? lo : hi;
  return EOS_OK;
}

/* ---------------------------------------------------------------- the model's row */

static int til_evaluate(const struct material *m, double rho, double e, struct eos_state *out)
{
  eos_tillotson_evaluate(&m->eosp.til, rho, e, out);
  return EOS_OK;
}

static int til_energy(const struct material *m, double rho, double p, double *e)
{
  return eos_tillotson_energy_from_pressure(&m->eosp.til, rho, p, e);
}

static int til_read_keys(struct cfg *c, const char *path, struct material *m, struct hv_error *err)
{
  struct eos_tillotson *t = &m->eosp.til;
  const double inf = HUGE_VAL, zero = 0.0;
  char k[320];
  if (material_get_q(c, path, "rho0", UNIT_DENSITY, NULL, DBL_MIN, inf, &t->rho0, err) ||
      material_get_q(c, path, "a", UNIT_NONE, NULL, 0.0, inf, &t->a, err) ||
      material_get_q(c, path, "b", UNIT_NONE, NULL, 0.0, inf, &t->b, err) ||
      material_get_q(c, path, "A", UNIT_PRESSURE, NULL, DBL_MIN, inf, &t->A, err) ||
      material_get_q(c, path, "B", UNIT_PRESSURE, NULL, -inf, inf, &t->B, err) ||
      material_get_q(c, path, "E0", UNIT_SPECIFIC_ENERGY, NULL, DBL_MIN, inf, &t->E0, err) ||
      material_get_q(c, path, "alpha", UNIT_NONE, NULL, 0.0, inf, &t->alpha, err) ||
      material_get_q(c, path, "beta", UNIT_NONE, NULL, 0.0, inf, &t->beta, err) ||
      material_get_q(c, path, "E_iv", UNIT_SPECIFIC_ENERGY, NULL, 0.0, inf, &t->E_iv, err) ||
      material_get_q(c, path, "E_cv", UNIT_SPECIFIC_ENERGY, NULL, 0.0, inf, &t->E_cv, err))
    return -1;
  if (!(t->E_cv > t->E_iv))
    return material_key_error(c, material_key(k, sizeof k, path, "E_cv"), err,
                              "E_cv = %.9g J/kg must be greater than E_iv = %.9g J/kg "
                              "(complete vaporisation after incipient)",
                              t->E_cv, t->E_iv);
  if (material_get_q(c, path, "rho_iv", UNIT_DENSITY, &zero, 0.0, inf, &t->rho_iv, err)) return -1;
  if (!(t->rho_iv < t->rho0))
    return material_key_error(c, material_key(k, sizeof k, path, "rho_iv"), err,
                              "rho_iv = %.9g kg/m3 must be below rho0 = %.9g kg/m3", t->rho_iv,
                              t->rho0);
  const double floor_def = sqrt(t->A / t->rho0) / 100.0;
  if (material_get_q(c, path, "cs_floor", UNIT_VELOCITY, &floor_def, 0.0, inf, &t->cs_floor, err))
    return -1;
  m->rho0 = t->rho0;
  m->K0 = t->A;
  return 0;
}

static void til_print(FILE *f, const struct material *m)
{
  const struct eos_tillotson *t = &m->eosp.til;
  material_print_quantity(f, "rho0", t->rho0, "kg/m3");
  material_print_quantity(f, "a", t->a, "");
  material_print_quantity(f, "b", t->b, "");
  material_print_quantity(f, "A", t->A, "Pa");
  material_print_quantity(f, "B", t->B, "Pa");
  material_print_quantity(f, "E0", t->E0, "J/kg");
  material_print_quantity(f, "alpha", t->alpha, "");
  material_print_quantity(f, "beta", t->beta, "");
  material_print_quantity(f, "E_iv", t->E_iv, "J/kg");
  material_print_quantity(f, "E_cv", t->E_cv, "J/kg");
  material_print_quantity(f, "rho_iv", t->rho_iv, "kg/m3");
  material_print_quantity(f, "cs_floor", t->cs_floor, "m/s");
}

static const struct material_typical til_typical[] = {
    {"rho0", UNIT_DENSITY, HV_RHO_CONDENSED_LO, HV_RHO_CONDENSED_HI, HV_RHO_CONDENSED_WHAT},
    {"A", UNIT_PRESSURE, 1e6, 1e13, "bulk moduli of condensed materials (Tillotson A)"},
    {"E0", UNIT_SPECIFIC_ENERGY, 1e4, 1e10, "Tillotson E0 of real materials"},
    {"E_iv", UNIT_SPECIFIC_ENERGY, 1e4, 1e10, "vaporisation energies of real materials"},
    {"E_cv", UNIT_SPECIFIC_ENERGY, 1e4, 1e10, "vaporisation energies of real materials"},
    {NULL, 0, 0.0, 0.0, NULL},
};

const struct eos_model eos_tillotson_model = {
    .name = "tillotson",
    .read = til_read_keys,
    .print = til_print,
    .evaluate = til_evaluate,
    .energy_from_pressure = til_energy,
    .typical = til_typical,
};
