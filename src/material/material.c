/* material.c — reading a material's parameters from a case file. */
#include "material/material.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

const char *const eos_kind_names[] = {"ideal-gas", "mie-gruneisen", "tillotson", "table", NULL};

int material_read(struct cfg *c, const char *path, const char *name, struct material *m,
                  struct hv_error *err)
{
  char key[256];
  memset(m, 0, sizeof *m);
  snprintf(m->name, sizeof m->name, "%s", name);
  int kind;
  snprintf(key, sizeof key, "%s.eos", path);
  if (cfg_get_choice(c, key, NULL, eos_kind_names, &kind, err)) return -1;
  m->eos = (enum eos_kind)kind;
  switch (m->eos) {
  case EOS_IDEAL_GAS: {
    snprintf(key, sizeof key, "%s.gamma", path);
    if (cfg_get_quantity(c, key, UNIT_NONE, NULL, 1.0 + 1e-12, 10.0, &m->eosp.gas.gamma, err))
      return -1;
    double zero = 0.0;
    snprintf(key, sizeof key, "%s.rho0", path);
    if (cfg_get_quantity(c, key, UNIT_DENSITY, &zero, 0.0, HUGE_VAL, &m->rho0, err)) return -1;
    break;
  }
  default: {
    char where[300];
    return hv_error_set(err, HV_EXIT_INPUT, "%s: material '%s': EOS '%s' is not available yet",
                        cfg_where(c, key, where, sizeof where), name, eos_kind_names[m->eos]);
  }
  }
  return 0;
}

void material_free(struct material *m)
{
  (void)m;
}
