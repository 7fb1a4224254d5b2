/* ideal_gas.c — the EOS `ideal-gas`: an ideal (polytropic) gas, p = (γ − 1) ρ e,
 * c² = γ p / ρ, e(ρ, p) = p / ((γ − 1) ρ).
 * A negative energy (possible only through round-off in cold flows) gives p = 0.
 * Keys: gamma (required, > 1), rho0 (optional, 0: none). The one EOS the code treats as
 * a gas, not condensed material (its row has no typical ranges; docs/adding-a-model.md). */
#include <math.h>

#include "eos/eos.h"
#include "material/material_read.h"

void eos_ideal_gas_evaluate(const struct eos_ideal_gas *g, double rho, double e,
                            struct eos_state *out)
{
  double p = (g->gamma - 1.0) * rho * e;
  if (p < 0.0) p = 0.0;
  out->p = p;
  out->cs = sqrt(g->gamma * p / rho);
}

static int gas_evaluate(const struct material *m, double rho, double e, struct eos_state *out)
{
  eos_ideal_gas_evaluate(&m->eosp.gas, rho, e, out);
  return EOS_OK;
}

static int gas_energy(const struct material *m, double rho, double p, double *e)
{
  *e = p / ((m->eosp.gas.gamma - 1.0) * rho);
  return EOS_OK;
}

static int gas_read_keys(struct cfg *c, const char *path, struct material *m, struct hv_error *err)
{
  const double zero = 0.0;
  if (material_get_q(c, path, "gamma", UNIT_NONE, NULL, 1.0 + 1e-12, 10.0, &m->eosp.gas.gamma,
                     err) ||
      material_get_q(c, path, "rho0", UNIT_DENSITY, &zero, 0.0, HUGE_VAL, &m->rho0, err))
    return -1;
  return 0;
}

static void gas_print(FILE *f, const struct material *m)
{
  material_print_quantity(f, "gamma", m->eosp.gas.gamma, "");
  material_print_quantity(f, "rho0", m->rho0, "kg/m3");
}

const struct eos_model eos_ideal_gas_model = {
    .name = "ideal-gas",
    .read = gas_read_keys,
    .print = gas_print,
    .evaluate = gas_evaluate,
    .energy_from_pressure = gas_energy,
    .typical = NULL, /* a gas: no condensed ranges (material.c, check_units) */
};
