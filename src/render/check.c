/* check.c — a snapshot's values checked before they are drawn.
 *
 * A snapshot is a file: it may be cut, edited or written by a run that went wrong. A NaN
 * position is silently left out of a picture, a position of 1e300 m stretches the
 * automatic extent until every other particle shares one pixel, a negative density or
 * mass darkens the film backwards, a material index beyond the snapshot's materials
 * gets a colour and no name. Rather than a picture that misleads without a word, the
 * command refuses such a snapshot (exit status 2) with one line naming the file, the
 * first bad particle (its index in the file and its id), the field with its value, and
 * how many particles more are bad.
 *
 * The bounds: positions finite and within RENDER_MAX_COORD = 1000 km of the origin
 * (hvsph's cases are a few metres across at most; a fragment at 10 km/s covers 1000 km
 * only after 100 s, ten thousand times the longest case's end time); velocities finite;
 * mass and smoothing length positive and finite (every particle hvsph writes has them);
 * density finite and not negative; material index among the snapshot's materials (its
 * "materials" comment), or below RENDER_MATERIAL_CAP where the snapshot names none;
 * body index not negative.
 */
#include <inttypes.h>
#include <math.h>
#include <stdio.h>

#include "render/render_internal.h"

/* The first bad field of particle i, as its CSV column name, with its value and the
 * rule it breaks; NULL when the particle is fine. */
static const char *bad_field(const struct particles *p, size_t i, int nmat, double *value,
                             const char **rule)
{
  static const char *const xname[3] = {"x", "y", "z"}, *const vname[3] = {"vx", "vy", "vz"};
  for (int k = 0; k < 3; k++)
    if (!(fabs(p->x[k][i]) <= RENDER_MAX_COORD)) {
      *value = p->x[k][i];
      *rule = "a position must be a finite number within 1e6 m of the origin";
      return xname[k];
    }
  for (int k = 0; k < 3; k++)
    if (!isfinite(p->v[k][i])) {
      *value = p->v[k][i];
      *rule = "a velocity must be a finite number";
      return vname[k];
    }
  if (!(p->m[i] > 0.0 && isfinite(p->m[i]))) {
    *value = p->m[i];
    *rule = "a mass must be a positive finite number";
    return "m";
  }
  if (!(p->h[i] > 0.0 && isfinite(p->h[i]))) {
    *value = p->h[i];
    *rule = "a smoothing length must be a positive finite number";
    return "h";
  }
  if (!(p->rho[i] >= 0.0 && isfinite(p->rho[i]))) {
    *value = p->rho[i];
    *rule = "a density must be a finite number, not negative";
    return "rho";
  }
  const int cap = nmat > 0 ? nmat : RENDER_MATERIAL_CAP;
  if (p->mat[i] < 0 || p->mat[i] >= cap) {
    *value = p->mat[i];
    *rule = nmat > 0 ? "not one of the snapshot's materials" : "not a material index";
    return "mat";
  }
  if (p->body[i] < 0) {
    *value = p->body[i];
    *rule = "a body index is not negative";
    return "body";
  }
  return NULL;
}

int render_check_particles(const struct particles *p, int nmat, const char *path,
                           struct hv_error *err)
{
  size_t first = 0, nbad = 0;
  const char *field = NULL, *rule = NULL;
  double value = 0.0;
  for (size_t i = 0; i < p->n; i++) {
    double v;
    const char *r, *f = bad_field(p, i, nmat, &v, &r);
    if (!f) continue;
    if (nbad++ == 0) {
      first = i;
      field = f;
      value = v;
      rule = r;
    }
  }
  if (!nbad) return 0;
  char more[96] = "", range[64] = "";
  if (nbad > 1) snprintf(more, sizeof more, "; %zu particles more are bad", nbad - 1);
  if (field[0] == 'm' && field[1] == 'a' && nmat > 0)
    snprintf(range, sizeof range, " (0 to %d)", nmat - 1);
  return hv_error_set(err, HV_EXIT_INPUT,
                      "%s: particle %zu (id %" PRId64 "), field '%s' = "
                      "%.9g: %s%s%s; not drawn",
                      path, first, p->id[first], field, value, rule, range, more);
}
