/* split_fluid.c — the paper's split (fracture.split: fluid, the default): a split
 * particle carries no deviatoric stress and no tension (p ← max(p, 0): fracture_pressure).
 * With fracture.friction = μ > 0 it keeps a deviatoric stress limited by Y_d = min(Y,
 * μ max(p, 0)), the strength of a cohesionless granular material (Coulomb friction; as
 * the damaged-rock strength of Collins, Melosh & Ivanov 2004, MAPS 39:217, without its
 * cohesion): the stress drops at the split and builds up again under pressure. */
#include "fracture/rules.h"

#include <math.h>

#include "fracture/read.h"
#include "particles/particles.h"

double fracture_fluid_yield(const struct fracture_params *fp, double Y, double p)
{
  const double Yd = fp->friction * (p > 0.0 ? p : 0.0);
  return Yd < Y ? Yd : Y;
}

int fracture_fluid_end(struct particles *p, size_t i, const struct fracture_params *fp,
                       int split_now)
{
  if (split_now || !(fp->friction > 0.0))
    for (int k = 0; k < 6; k++) p->S[k][i] = 0.0;
  return p->p[i] < 0.0; /* split (now or in the first pass) and in tension */
}

/* ---- reading (fracture_read.c) ---------------------------------------------------- */

int fracture_read_friction(struct cfg *c, const char *fp, struct material *m, struct hv_error *err)
{
  const double zero = 0.0;
  char k[320];
  if (material_get_q(c, fp, "friction", UNIT_NONE, &zero, 0.0, HUGE_VAL, &m->frac.friction, err))
    return -1;
  if (m->frac.friction > 0.0 && !m->str.enabled)
    return material_key_error(c, material_key(k, sizeof k, fp, "friction"), err,
                              "friction limits the deviatoric stress of split material, but "
                              "the material has no strength (give strength with shear "
                              "modulus and yield > 0)");
  return 0;
}
