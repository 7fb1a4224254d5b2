/* rz.c — the set-up of an axisymmetric run (domain.geometry: axisymmetric): what an RZ
 * case may hold, and its ring lattices.
 *
 * A body is a shape of revolution about the x axis: a cylinder along x with its centre
 * on the axis (a rectangle in the (x, r) half-plane; a tube with a coaxial cylinder in
 * its `minus`), or a sphere centred on the axis (a half disc). Its rings stand on a
 * square lattice of the half-plane at the cells' centroids: x as a 3D cubic lattice's
 * (from a cylinder's end face, from a sphere's centre), r = (j + ½)Δ, the first row at
 * Δ/2, never on the axis. A ring's mass is 2π rᵢ ρ Δ², the annulus of its cell (exact:
 * the centroid of a cell [r − Δ/2, r + Δ/2] is r), scaled like the 3D lattice's so that
 * the body has the shape's exact mass; h = η (m/(2π r ρ))^(1/2) (rz.h).
 * `resolution` keeps its meaning, a factor on the particle (ring) count: Δ scales as
 * resolution^(-1/2).
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "config/config.h"
#include "fracture/fracture.h"
#include "kernel/kernel.h"
#include "setup/setup.h"

/* Whether the shape (and every subtracted shape) is one of revolution about x; if not,
 * a message into why. */
static int shape_axisymmetric(const struct shape *sh, char *why, size_t len)
{
  const double size = fmax(sh->radius, 1e-300), tol = 1e-12 * size;
  const int on_axis = fabs(sh->center[1]) <= tol && fabs(sh->center[2]) <= tol;
  switch (sh->kind) {
  case SHAPE_BOX:
    snprintf(why, len,
             "a box has no axis of symmetry; in an axisymmetric domain use a cylinder "
             "along x centred on the axis (type: cylinder, center: [x, 0, 0], axis: [1, 0, 0])");
    return 0;
  case SHAPE_SPHERE:
    if (!on_axis) {
      snprintf(why, len,
               "a sphere off the axis (centre at r = %g m) reaches r < 0 and is no body of "
               "revolution about it; centre it on the axis (center: [x, 0, 0])",
               hypot(sh->center[1], sh->center[2]));
      return 0;
    }
    break;
  case SHAPE_CYLINDER:
    if (!(fabs(sh->axis[0]) > 1.0 - 1e-12)) {
      snprintf(why, len,
               "a cylinder whose axis (%g, %g, %g) is not the x axis; in an axisymmetric "
               "domain a cylinder lies along x (axis: [1, 0, 0])",
               sh->axis[0], sh->axis[1], sh->axis[2]);
      return 0;
    }
    if (!on_axis) {
      snprintf(why, len,
               "a cylinder off the axis (centre at r = %g m) reaches r < 0 and is no body of "
               "revolution about it; centre it on the axis (center: [x, 0, 0])",
               hypot(sh->center[1], sh->center[2]));
      return 0;
    }
    break;
  case SHAPE_KIND_COUNT: break;
  }
  for (int k = 0; k < sh->nminus; k++)
    if (!shape_axisymmetric(&sh->minus[k], why, len)) return 0;
  return 1;
}

int rz_check_body(struct cfg *c, const char *path, const char *name, const struct shape *sh,
                  int hcp, const double vel[3], struct hv_error *err)
{
  char key[256], where[256], why[320];
  snprintf(key, sizeof key, "%s.shape", path);
  if (!shape_axisymmetric(sh, why, sizeof why))
    return hv_error_set(err, HV_EXIT_INPUT, "%s: %s: body '%s': %s",
                        cfg_where(c, key, where, sizeof where), key, name, why);
  snprintf(key, sizeof key, "%s.lattice", path);
  if (hcp)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: %s: body '%s': lattice hcp is a 3D lattice; an axisymmetric "
                        "domain places rings on a square lattice of the (x, r) half-plane "
                        "(remove the key)",
                        cfg_where(c, key, where, sizeof where), key, name);
  if (vel[1] != 0.0 || vel[2] != 0.0) {
    /* the key that set the direction: an angle, or the vector */
    static const char *const vkeys[] = {"impact_angle", "obliquity", "velocity", "speed"};
    for (size_t k = 0; k < sizeof vkeys / sizeof vkeys[0]; k++) {
      snprintf(key, sizeof key, "%s.%s", path, vkeys[k]);
      if (cfg_has(c, key)) break;
    }
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: %s: body '%s': a velocity (%g, %g, %g) m/s not along the axis "
                        "breaks the symmetry of an axisymmetric domain: only normal impacts "
                        "along x (velocity: [v, 0, 0], impact_angle 90 deg, obliquity 0)",
                        cfg_where(c, key, where, sizeof where), key, name, vel[0], vel[1], vel[2]);
  }
  return 0;
}

size_t rz_lattice(const struct shape *sh, double d, struct particles *p, size_t first)
{
  const double x0 = sh->kind == SHAPE_CYLINDER ? sh->center[0] - 0.5 * sh->length : sh->center[0];
  const double rmax = fmax(sh->max[1], sh->max[2]);
  const long ilo = (long)floor((sh->min[0] - x0) / d) - 2,
             ihi = (long)ceil((sh->max[0] - x0) / d) + 1;
  const long jhi = (long)ceil(rmax / d) + 1;
  size_t count = 0;
  for (long j = 0; j <= jhi; j++)
    for (long i = ilo; i <= ihi; i++) {
      const double x[3] = {x0 + ((double)i + 0.5) * d, ((double)j + 0.5) * d, 0.0};
      if (!shape_contains(sh, x)) continue;
      if (p)
        for (int k = 0; k < 3; k++) p->x[k][first + count] = x[k];
      count++;
    }
  return count;
}

double rz_points_bound(const struct shape *sh, double d)
{
  const double rmax = fmax(sh->max[1], sh->max[2]);
  return ((sh->max[0] - sh->min[0]) / d + 4.0) * (rmax / d + 2.0);
}

double rz_spacing_for_count(const struct shape *sh, double n)
{
  /* the meridional area from a fine count, then the coarsest spacing giving n rings */
  const double rmax = fmax(sh->max[1], sh->max[2]);
  const double fine = fmax(sh->max[0] - sh->min[0], rmax) / 400.0;
  const double area = (double)rz_lattice(sh, fine, NULL, 0) * fine * fine;
  double hi = sqrt(area / fmax(n, 1.0)) * 1.5, lo = hi;
  for (int k = 0; k < 60 && (double)rz_lattice(sh, lo, NULL, 0) < n; k++) lo *= 0.9;
  for (int k = 0; k < 50; k++) {
    const double mid = 0.5 * (lo + hi);
    if ((double)rz_lattice(sh, mid, NULL, 0) >= n)
      lo = mid;
    else
      hi = mid;
  }
  return lo;
}

void rz_ring_masses(struct particles *p, size_t first, size_t cnt, double rho, double vol, double d,
                    double eta)
{
  double vsum = 0.0;
  for (size_t q = first; q < first + cnt; q++) vsum += 2.0 * HV_KERNEL_PI * p->x[1][q] * d * d;
  const double scale = vol > 0 && vsum > 0 ? vol / vsum : 1.0;
  for (size_t q = first; q < first + cnt; q++) {
    p->m[q] = 2.0 * HV_KERNEL_PI * p->x[1][q] * rho * d * d * scale;
    p->h[q] = eta * d * sqrt(scale);
    p->r0[q] = p->x[1][q];
    p->x[2][q] = p->v[2][q] = 0.0;
  }
}

int sim_axisym_params(struct sim *s, struct cfg *c, struct hv_error *err)
{
  if (!s->bnd.axisym) return 0;
  s->p.axisym = 1;
  const int rk = s->bnd.kind[1][1];
  s->sph.rz_rmax = rk == BND_WALL || rk == BND_SYMMETRY ? s->bnd.hi[1] : HUGE_VAL;
  s->sph.kernel = (enum kernel_kind)((int)s->sph.kernel | KERNEL_2D);
  char where[256];
  /* the options whose 3D matrices or vectors have no RZ form here */
  static const char *const keys[] = {"sph.gradient_correction", "sph.viscosity.reconstruct",
                                     "sph.viscosity.reconstruct_contact", "sph.viscosity.switch"};
  const int on[] = {s->sph.grad_correction, s->sph.reconstruct, s->sph.reconstruct_contact,
                    s->sph.av_switch};
  /* the artificial stress: with it the rings near the axis of a Taylor bar went
     unstable (density 6 560 to 17 245 kg/m3 at 80 us, the bar 24 % too narrow; without
     it 8 731 to 8 956); its default in an axisymmetric case is 0 (params.c) */
  if (s->sph.as_eps > 0.0)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: sph.artificial_stress.epsilon: the artificial stress is a 3D-only "
                        "option in hvsph (near the axis of an axisymmetric run it drove the rings "
                        "unstable); an axisymmetric case runs without it (remove the key or set 0)",
                        cfg_where(c, "sph.artificial_stress.epsilon", where, sizeof where));
  for (int k = 0; k < 4; k++)
    if (on[k])
      return hv_error_set(err, HV_EXIT_INPUT,
                          "%s: %s: a 3D-only option (its 3x3 correction matrix or velocity "
                          "gradient has no axisymmetric form in hvsph); an axisymmetric case "
                          "runs without it",
                          cfg_where(c, keys[k], where, sizeof where), keys[k]);
  return 0;
}

int rz_check_materials(struct sim *s, struct cfg *c, struct hv_error *err)
{
  char where[256];
  for (int m = 0; m < s->nmat; m++)
    if (s->mat[m].frac.kind != FRACTURE_NONE &&
        (s->mat[m].frac.split == SPLIT_CRACK || s->mat[m].frac.energy > 0.0)) {
      char key[160];
      snprintf(key, sizeof key, "materials.%s.fracture", s->mat[m].name);
      return hv_error_set(err, HV_EXIT_INPUT,
                          "%s: %s: crack planes (split: crack, or an energy) are 3D-only: a "
                          "crack of a ring has no plane in an axisymmetric domain; use split: "
                          "fluid or no-tension",
                          cfg_where(c, cfg_has(c, key) ? key : "materials", where, sizeof where),
                          key);
    }
  return 0;
}
