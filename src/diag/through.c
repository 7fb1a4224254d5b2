/* through.c — what went through a wall (definitions in through.h). */
#include "diag/through.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void meas_through_defaults(struct meas_through_params *par, const struct meas_geom *g)
{
  memset(par, 0, sizeof *par);
  par->margin = g->spacing;
  par->r_max = INFINITY;
}

int measure_through(const struct particles *p, const struct meas_geom *g,
                    const struct meas_through_params *par, struct meas_through *out,
                    struct hv_error *err)
{
  memset(out, 0, sizeof *out);
  if (!(g->spacing > 0) || !(g->thickness > 0) || !(par->margin >= 0) || !(par->r_max > 0))
    return hv_error_set(err, HV_EXIT_INPUT,
                        "measure_through: spacing, thickness and r_max "
                        "must be positive, the margin not negative");
  const size_t n = p->n;
  /* the wall's attached piece */
  unsigned char *wall = malloc(n + 1);
  if (!wall) return hv_error_set(err, HV_EXIT_RUN, "measure_through: out of memory");
  for (size_t i = 0; i < n; i++)
    wall[i] = (par->wall ? par->wall[i] != 0 : p->body[i] == g->body) && isfinite(p->x[0][i]);
  unsigned char *attached = malloc(n + 1);
  if (!attached) {
    free(wall);
    return hv_error_set(err, HV_EXIT_RUN, "measure_through: out of memory");
  }
  memcpy(attached, wall, n);
  if (meas_keep_largest_piece(p, g, par->scale, attached, err)) {
    free(wall);
    free(attached);
    return -1;
  }
  const double x_far = g->x0 + g->thickness + par->margin;
  const double mirror = meas_images(g->half_model, g->quarter_model);
  double m = 0.0, mv = 0.0, mw = 0.0;
  for (size_t i = 0; i < n; i++) {
    if (par->solid && !par->solid[i]) continue;
    if (attached[i]) continue;
    const double x = p->x[0][i];
    if (!isfinite(x) || !(x > x_far) || !(p->v[0][i] > 0)) continue;
    const double dy = p->x[1][i] - g->yc, dz = p->x[2][i];
    if (!(dy * dy + dz * dz <= par->r_max * par->r_max)) continue;
    out->n++;
    m += mirror * p->m[i];
    mv += mirror * p->m[i] * p->v[0][i];
    if (wall[i]) mw += mirror * p->m[i];
  }
  free(wall);
  free(attached);
  out->through = out->n > 0;
  out->mass = m;
  out->velocity = m > 0 ? mv / m : 0.0;
  out->wall_mass = mw;
  return 0;
}
