/* eos.c — the single dispatch on the EOS kind, through the table of models
 * (material.h, eos_models[]; the equations are in each EOS's own file and in
 * docs/models.md). */
#include "eos/eos.h"

#include <math.h>
#include <stdio.h>

int eos_evaluate(const struct material *m, double rho, double e, struct eos_state *out)
{
  if (!(rho > 0.0) || !isfinite(rho) || !isfinite(e)) return EOS_ERR_INPUT;
  if ((unsigned)m->eos >= EOS_KIND_COUNT) return EOS_ERR_KIND;
  return eos_models[m->eos]->evaluate(m, rho, e, out);
}

int eos_energy_from_pressure(const struct material *m, double rho, double p, double *e)
{
  if (!(rho > 0.0) || !isfinite(rho) || !isfinite(p)) return EOS_ERR_INPUT;
  if ((unsigned)m->eos >= EOS_KIND_COUNT) return EOS_ERR_KIND;
  return eos_models[m->eos]->energy_from_pressure(m, rho, p, e);
}

void eos_describe(const struct material *m, double rho, double e, int status, char *buf, size_t len)
{
  const struct eos_model *model = (unsigned)m->eos < EOS_KIND_COUNT ? eos_models[m->eos] : NULL;
  char name[600] = "", outside[200] = "";
  if (model && model->describe_name) model->describe_name(m, name, sizeof name);
  if (model && model->describe_outside) model->describe_outside(m, outside, sizeof outside);
  int k = snprintf(buf, len, "material '%s' (%s%s", m->name, model ? model->name : "?", name);
  if (k < 0 || (size_t)k >= len) return;
  char *r = buf + k;
  size_t rl = len - (size_t)k;
  switch (status) {
  case EOS_OK:
    /* taken, but its result is not finite (the caller found it so) */
    snprintf(r, rl,
             "): rho = %.9g kg/m3, e = %.9g J/kg gives no finite pressure or sound "
             "speed",
             rho, e);
    break;
  case EOS_ERR_INPUT:
    snprintf(r, rl,
             "): cannot evaluate rho = %.9g kg/m3, e = %.9g J/kg (density must be a "
             "positive finite number and the energy finite)",
             rho, e);
    break;
  case EOS_ERR_OUTSIDE_TABLE:
    snprintf(r, rl, "): rho = %.9g kg/m3, e = %.9g J/kg is outside the table%s", rho, e, outside);
    break;
  case EOS_ERR_NO_SOLUTION:
    snprintf(r, rl, "): no energy gives pressure %.9g Pa at rho = %.9g kg/m3", e, rho);
    break;
  default:
    snprintf(r, rl, "): internal error (EOS status %d) at rho = %.9g kg/m3, e = %.9g J/kg", status,
             rho, e);
    break;
  }
}
