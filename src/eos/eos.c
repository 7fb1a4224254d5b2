/* eos.c — the single dispatch on the EOS kind. */
#include "eos/eos.h"

#include <math.h>

int eos_evaluate(const struct material *m, double rho, double e, struct eos_state *out)
{
  if (!(rho > 0.0) || !isfinite(rho) || !isfinite(e)) return -1;
  switch (m->eos) {
  case EOS_IDEAL_GAS:
    eos_ideal_gas_evaluate(&m->eosp.gas, rho, e, out);
    return 0;
  case EOS_MIE_GRUNEISEN:
  case EOS_TILLOTSON:
  case EOS_TABLE:
  case EOS_KIND_COUNT:
    break;
  }
  return -1;
}

int eos_energy_from_pressure(const struct material *m, double rho, double p, double *e)
{
  switch (m->eos) {
  case EOS_IDEAL_GAS:
    *e = p / ((m->eosp.gas.gamma - 1.0) * rho);
    return 0;
  case EOS_MIE_GRUNEISEN:
  case EOS_TILLOTSON:
  case EOS_TABLE:
  case EOS_KIND_COUNT:
    break;
  }
  return -1;
}
