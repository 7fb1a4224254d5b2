/* axis.c — the domain of an axisymmetric run (domain.geometry: axisymmetric).
 *
 * The particles lie in the meridional half-plane (x, r), r ≥ 0 (particles.h). The axis
 * r = 0 is a mirror made by the code, never by the user: the dimension y's min face is
 * a symmetry plane at y = 0, so that boundary.c's mirror ghosts stand at (x, −r) with
 * v_r, and the tensor components with one r index (xy), reversed; ρ, p, e, S_xx, S_rr
 * and the hoop S_zz are copied. The ghost keeps its source's ring mass m: the pair
 * loops weigh a neighbour by its area mass m/(2π|r|) (sph_rz.c), the same for the
 * ghost at −r as for its source, as a mirror must (the "ghost mass" of Spheral's
 * SPHHydroBaseRZ, which divides by 2πr before making ghosts and multiplies back after).
 * A wall at r = R (face r_max) is a mirror too: its ghost stands at 2R − r with its
 * source's ring mass, and the loops weigh it with its source's radius, 2R − (2R − r)
 * (sph_params.rz_rmax, sph_rz_weight_radius), so that its area mass is its source's and
 * the η-form's ghost pairs stay reciprocal (a ring mass scaled to the ghost's own radius
 * kept the area mass but not the energy: +0.75 % in 0.8 µs of a 19 GPa shock along a
 * cylinder against the wall, test_hugoniot --rz).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "boundary/boundary.h"
#include "config/config.h"
#include "core/error.h"

/* A two-component (x, r) corner of the domain into lo[0..1]; 0 if absent. */
static int read_corner(struct cfg *c, const char *key, double out[2], int *given,
                       struct hv_error *err)
{
  *given = cfg_has(c, key);
  if (!*given) return 0;
  double *v = NULL;
  int n = 0;
  char where[256];
  if (cfg_get_list(c, key, UNIT_LENGTH, &v, &n, err)) return -1;
  if (n != 2) {
    free(v);
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: %s: an axisymmetric domain takes two components (x, r), "
                        "the axial and the radial coordinate, not %d",
                        cfg_where(c, key, where, sizeof where), key, n);
  }
  out[0] = v[0];
  out[1] = v[1];
  free(v);
  return 0;
}

int boundary_read_axisym(struct boundary *b, struct cfg *c, struct hv_error *err)
{
  char where[256], key[128];
  b->axisym = 1;
  /* the 3D-only keys, each refused with its reason */
  if (cfg_has(c, "domain.half_model"))
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: domain.half_model: a half model is a 3D option; an "
                        "axisymmetric domain is already one meridional half-plane (remove the key)",
                        cfg_where(c, "domain.half_model", where, sizeof where));
  static const char *const axis_faces[] = {"y", "y_min", "r_min", "z", "z_min", "z_max", "y_max"};
  for (size_t k = 0; k < sizeof axis_faces / sizeof axis_faces[0]; k++) {
    snprintf(key, sizeof key, "domain.boundary.%s", axis_faces[k]);
    if (!cfg_has(c, key)) continue;
    const int axis = k < 3;
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: %s: %s; an axisymmetric domain has the faces x_min, x_max and "
                        "r_max (x the axis)",
                        cfg_where(c, key, where, sizeof where), key,
                        axis ? "a face across the axis: the axis r = 0 is a reflecting "
                               "boundary the code makes itself"
                             : "a face of a 3D domain");
  }
  /* x: as in 3D (shorthand or per face); r: r_max only */
  static const char *const xf[2] = {"x_min", "x_max"};
  int both = BND_OPEN;
  const int has_both = cfg_has(c, "domain.boundary.x");
  if (has_both && cfg_get_choice(c, "domain.boundary.x", NULL, bnd_kind_names, &both, err))
    return -1;
  for (int s = 0; s < 2; s++) {
    snprintf(key, sizeof key, "domain.boundary.%s", xf[s]);
    if (has_both && cfg_has(c, key))
      return hv_error_set(err, HV_EXIT_INPUT, "%s: %s: give either 'x' or '%s', not both",
                          cfg_where(c, key, where, sizeof where), key, xf[s]);
    b->kind[0][s] = both;
    if (!has_both &&
        cfg_get_choice(c, key, bnd_kind_names[BND_OPEN], bnd_kind_names, &b->kind[0][s], err))
      return -1;
  }
  if ((b->kind[0][0] == BND_PERIODIC) != (b->kind[0][1] == BND_PERIODIC))
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: domain.boundary: periodic in x needs both x_min and x_max periodic",
                        cfg_where(c, "domain.boundary", where, sizeof where));
  const char *rkey =
      cfg_has(c, "domain.boundary.r") ? "domain.boundary.r" : "domain.boundary.r_max";
  if (cfg_has(c, "domain.boundary.r") && cfg_has(c, "domain.boundary.r_max"))
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: domain.boundary.r_max: give either 'r' or 'r_max', not both",
                        cfg_where(c, "domain.boundary.r_max", where, sizeof where));
  if (cfg_get_choice(c, rkey, bnd_kind_names[BND_OPEN], bnd_kind_names, &b->kind[1][1], err))
    return -1;
  if (b->kind[1][1] == BND_PERIODIC)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: %s: periodic has no meaning in r (the other side is the axis); "
                        "use wall, symmetry, absorbing or open",
                        cfg_where(c, rkey, where, sizeof where), rkey);
  b->kind[1][0] = BND_SYMMETRY; /* the axis */
  b->kind[2][0] = b->kind[2][1] = BND_OPEN;
  double lo[2] = {-HUGE_VAL, 0.0}, hi[2] = {HUGE_VAL, HUGE_VAL};
  int glo, ghi;
  if (read_corner(c, "domain.min", lo, &glo, err) || read_corner(c, "domain.max", hi, &ghi, err))
    return -1;
  b->has_box = glo || ghi;
  if (glo && lo[1] != 0.0)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: domain.min: the radial component of an axisymmetric domain starts "
                        "at the axis, r = 0, not %g m",
                        cfg_where(c, "domain.min", where, sizeof where), lo[1]);
  const int needs[2][2] = {{b->kind[0][0] != BND_OPEN, b->kind[0][1] != BND_OPEN},
                           {0, b->kind[1][1] != BND_OPEN}};
  for (int d = 0; d < 2; d++) {
    if ((needs[d][0] && !glo) || (needs[d][1] && !ghi))
      return hv_error_set(err, HV_EXIT_INPUT,
                          "%s: domain: a face that is not open needs domain.min and domain.max "
                          "(x, r) to place it",
                          cfg_where(c, "domain", where, sizeof where));
    if (glo && ghi && !(hi[d] > lo[d]))
      return hv_error_set(err, HV_EXIT_INPUT, "%s: domain.max must exceed domain.min in %s",
                          cfg_where(c, "domain.max", where, sizeof where), d ? "r" : "x");
    b->lo[d] = lo[d];
    b->hi[d] = hi[d];
  }
  b->lo[2] = -HUGE_VAL;
  b->hi[2] = HUGE_VAL;
  return 0;
}
