/* ideal_gas.c — ideal (polytropic) gas: p = (γ − 1) ρ e, c² = γ p / ρ.
 * A negative energy (possible only through round-off in cold flows) gives p = 0. */
#include <math.h>

#include "eos/eos.h"

void eos_ideal_gas_evaluate(const struct eos_ideal_gas *g, double rho, double e,
                            struct eos_state *out)
{
  double p = (g->gamma - 1.0) * rho * e;
  if (p < 0.0) p = 0.0;
  out->p = p;
  out->cs = sqrt(g->gamma * p / rho);
}
