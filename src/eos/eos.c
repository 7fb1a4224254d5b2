/* eos.c — the single dispatch on the EOS kind (see eos.h; the equations are in each
 * EOS's own file and in docs/models.md). */
#include "eos/eos.h"

#include <math.h>
#include <stdio.h>

int eos_evaluate(const struct material *m, double rho, double e, struct eos_state *out)
{
  if (!(rho > 0.0) || !isfinite(rho) || !isfinite(e)) return EOS_ERR_INPUT;
  switch (m->eos) {
  case EOS_IDEAL_GAS:
    eos_ideal_gas_evaluate(&m->eosp.gas, rho, e, out);
    return EOS_OK;
  case EOS_MIE_GRUNEISEN:
    eos_mg_evaluate(&m->eosp.mg, rho, e, out);
    return EOS_OK;
  case EOS_TILLOTSON:
    eos_tillotson_evaluate(&m->eosp.til, rho, e, out);
    return EOS_OK;
  case EOS_TABLE:
    return eos_table_evaluate(&m->eosp.tab, rho, e, out);
  case EOS_KIND_COUNT:
    break;
  }
  return EOS_ERR_KIND;
}

int eos_energy_from_pressure(const struct material *m, double rho, double p, double *e)
{
  if (!(rho > 0.0) || !isfinite(rho) || !isfinite(p)) return EOS_ERR_INPUT;
  switch (m->eos) {
  case EOS_IDEAL_GAS:
    *e = p / ((m->eosp.gas.gamma - 1.0) * rho);
    return EOS_OK;
  case EOS_MIE_GRUNEISEN:
    return eos_mg_energy_from_pressure(&m->eosp.mg, rho, p, e);
  case EOS_TILLOTSON:
    return eos_tillotson_energy_from_pressure(&m->eosp.til, rho, p, e);
  case EOS_TABLE:
    return eos_table_energy_from_pressure(&m->eosp.tab, rho, p, e);
  case EOS_KIND_COUNT:
    break;
  }
  return EOS_ERR_KIND;
}

void eos_describe(const struct material *m, double rho, double e, int status, char *buf,
                  size_t len)
{
  const char *kind = (int)m->eos >= 0 && m->eos < EOS_KIND_COUNT ? eos_kind_names[m->eos] : "?";
  int k = snprintf(buf, len, "material '%s' (%s", m->name, kind);
  if (m->eos == EOS_TABLE && k >= 0 && (size_t)k < len)
    k += snprintf(buf + k, len - (size_t)k, " '%s'", m->eosp.tab.path);
  if (k < 0 || (size_t)k >= len) return;
  char *r = buf + k;
  size_t rl = len - (size_t)k;
  switch (status) {
  case EOS_OK:
    /* taken, but its result is not finite (the caller found it so) */
    snprintf(r, rl, "): rho = %.9g kg/m3, e = %.9g J/kg gives no finite pressure or sound "
             "speed", rho, e);
    break;
  case EOS_ERR_INPUT:
    snprintf(r, rl, "): cannot evaluate rho = %.9g kg/m3, e = %.9g J/kg (density must be a "
             "positive finite number and the energy finite)", rho, e);
    break;
  case EOS_ERR_OUTSIDE_TABLE: {
    const struct eos_table *t = &m->eosp.tab;
    if (m->eos == EOS_TABLE && t->nrho >= 2 && t->ne >= 2)
      snprintf(r, rl, "): rho = %.9g kg/m3, e = %.9g J/kg is outside the table (rho %.6g to "
               "%.6g kg/m3, e %.6g to %.6g J/kg)", rho, e, t->rho[0], t->rho[t->nrho - 1],
               t->e[0], t->e[t->ne - 1]);
    else
      snprintf(r, rl, "): rho = %.9g kg/m3, e = %.9g J/kg is outside the table", rho, e);
    break;
  }
  case EOS_ERR_NO_SOLUTION:
    snprintf(r, rl, "): no energy gives pressure %.9g Pa at rho = %.9g kg/m3", e, rho);
    break;
  default:
    snprintf(r, rl, "): internal error (EOS status %d) at rho = %.9g kg/m3, e = %.9g J/kg",
             status, rho, e);
    break;
  }
}
