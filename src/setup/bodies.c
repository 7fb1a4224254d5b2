/* bodies.c — filling bodies with particles and setting their initial state.
 *
 * A body is a shape filled with a cubic lattice of spacing Δ (points at the centres
 * of the lattice cells, aligned with the shape's box corner, or centred on a
 * sphere's centre), particle mass ρΔ³, smoothing length h = η Δ, and initial
 * velocity `velocity` plus `radial_velocity` r̂ about the shape's centre.
 * `energy_deposit` adds energy E within a radius R about a point, shared with the
 * weights m_i W(r_i, R/2) (the Sedov blast).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "eos/eos.h"
#include "setup/setup.h"

struct body_spec {
  struct shape shape;
  int mat;
  double spacing, rho, e, vel[3], vrad;
};

static int read_body(struct sim *s, struct cfg *c, int b, struct body_spec *bs,
                     struct hv_error *err)
{
  char key[256], path[64], where[256];
  const char *name, *mname;
  snprintf(path, sizeof path, "bodies[%d]", b);
  char defname[32];
  snprintf(defname, sizeof defname, "body%d", b);
  snprintf(key, sizeof key, "%s.name", path);
  if (cfg_get_string(c, key, defname, &name, err)) return -1;
  snprintf(s->body[b].name, sizeof s->body[b].name, "%s", name);
  snprintf(key, sizeof key, "%s.material", path);
  if (cfg_get_string(c, key, NULL, &mname, err)) return -1;
  bs->mat = sim_material_index(s, mname);
  if (bs->mat < 0)
    return hv_error_set(err, HV_EXIT_INPUT, "%s: body '%s': unknown material '%s' (not "
                        "under 'materials')", cfg_where(c, key, where, sizeof where), name, mname);
  const struct material *m = &s->mat[bs->mat];
  snprintf(key, sizeof key, "%s.shape", path);
  if (shape_read(&bs->shape, c, key, err)) return hv_error_prefix(err, "body '%s': ", name);
  snprintf(key, sizeof key, "%s.spacing", path);
  if (cfg_get_quantity(c, key, UNIT_LENGTH, NULL, 1e-300, HUGE_VAL, &bs->spacing, err))
    return -1;
  snprintf(key, sizeof key, "%s.density", path);
  const double *rdef = m->rho0 > 0 ? &m->rho0 : NULL;
  if (cfg_get_quantity(c, key, UNIT_DENSITY, rdef, 1e-300, HUGE_VAL, &bs->rho, err)) return -1;
  snprintf(key, sizeof key, "%s.pressure", path);
  char key2[256];
  snprintf(key2, sizeof key2, "%s.energy", path);
  if (cfg_has(c, key) && cfg_has(c, key2))
    return hv_error_set(err, HV_EXIT_INPUT, "%s: body '%s': give pressure or energy, not both",
                        cfg_where(c, key, where, sizeof where), name);
  if (cfg_has(c, key)) {
    double pr;
    if (cfg_get_quantity(c, key, UNIT_PRESSURE, NULL, 0.0, HUGE_VAL, &pr, err)) return -1;
    if (eos_energy_from_pressure(m, bs->rho, pr, &bs->e))
      return hv_error_set(err, HV_EXIT_INPUT, "%s: body '%s': cannot set a pressure for "
                          "material '%s'", cfg_where(c, key, where, sizeof where), name, m->name);
  } else {
    double zero = 0.0;
    if (cfg_get_quantity(c, key2, UNIT_SPECIFIC_ENERGY, &zero, 0.0, HUGE_VAL, &bs->e, err))
      return -1;
  }
  double v0[3] = {0, 0, 0}, zero = 0.0;
  snprintf(key, sizeof key, "%s.velocity", path);
  if (cfg_get_vec3(c, key, UNIT_VELOCITY, v0, bs->vel, err)) return -1;
  snprintf(key, sizeof key, "%s.radial_velocity", path);
  if (cfg_get_quantity(c, key, UNIT_VELOCITY, &zero, -HUGE_VAL, HUGE_VAL, &bs->vrad, err))
    return -1;
  s->body[b].mat = bs->mat;
  return 0;
}

/* Lattice points of a body: counts them (x == NULL) or fills them. */
static size_t lattice_points(const struct body_spec *bs, struct particles *p, size_t first)
{
  const struct shape *sh = &bs->shape;
  const double d = bs->spacing;
  double start[3];
  long n[3];
  for (int k = 0; k < 3; k++) {
    if (sh->kind == SHAPE_BOX) {
      start[k] = sh->min[k] + 0.5 * d;
    } else { /* symmetric about the centre */
      long half = (long)ceil(sh->radius / d) + 1;
      start[k] = sh->center[k] - (double)half * d + 0.5 * d;
    }
    n[k] = (long)ceil((sh->max[k] - start[k]) / d) + 1;
  }
  size_t count = 0;
  for (long k = 0; k < n[2]; k++)
    for (long j = 0; j < n[1]; j++)
      for (long i = 0; i < n[0]; i++) {
        double x[3] = {start[0] + (double)i * d, start[1] + (double)j * d,
                       start[2] + (double)k * d};
        if (!shape_contains(sh, x)) continue;
        if (p) {
          size_t q = first + count;
          for (int c = 0; c < 3; c++) p->x[c][q] = x[c];
        }
        count++;
      }
  return count;
}

static void init_body(struct sim *s, const struct body_spec *bs, int b, size_t first, size_t cnt)
{
  struct particles *p = &s->p;
  const double d = bs->spacing;
  for (size_t q = first; q < first + cnt; q++) {
    p->id[q] = (int64_t)q;
    p->mat[q] = bs->mat;
    p->body[q] = b;
    p->m[q] = bs->rho * d * d * d;
    p->rho[q] = bs->rho;
    p->h[q] = s->sph.eta * d;
    p->e[q] = bs->e;
    double r[3], rn = 0.0;
    for (int c = 0; c < 3; c++) {
      r[c] = p->x[c][q] - bs->shape.center[c];
      rn += r[c] * r[c];
    }
    rn = sqrt(rn);
    for (int c = 0; c < 3; c++)
      p->v[c][q] = bs->vel[c] + (rn > 0 ? bs->vrad * r[c] / rn : 0.0);
  }
}

static int energy_deposit(struct sim *s, struct cfg *c, struct hv_error *err)
{
  if (!cfg_has(c, "energy_deposit")) return 0;
  double E, ctr[3], R, zero3[3] = {0, 0, 0};
  char where[256];
  if (cfg_get_quantity(c, "energy_deposit.energy", UNIT_ENERGY, NULL, 0.0, HUGE_VAL, &E, err) ||
      cfg_get_vec3(c, "energy_deposit.center", UNIT_LENGTH, zero3, ctr, err) ||
      cfg_get_quantity(c, "energy_deposit.radius", UNIT_LENGTH, NULL, 1e-300, HUGE_VAL, &R, err))
    return -1;
  struct particles *p = &s->p;
  double wsum = 0.0;
  for (size_t i = 0; i < p->n; i++) {
    double r2 = 0.0;
    for (int k = 0; k < 3; k++) r2 += (p->x[k][i] - ctr[k]) * (p->x[k][i] - ctr[k]);
    wsum += p->m[i] * kernel_w(KERNEL_CUBIC_SPLINE, sqrt(r2), 0.5 * R);
  }
  if (!(wsum > 0))
    return hv_error_set(err, HV_EXIT_INPUT, "%s: energy_deposit: no particle within radius "
                        "%g m of the centre", cfg_where(c, "energy_deposit", where, sizeof where), R);
  for (size_t i = 0; i < p->n; i++) {
    double r2 = 0.0;
    for (int k = 0; k < 3; k++) r2 += (p->x[k][i] - ctr[k]) * (p->x[k][i] - ctr[k]);
    double w = kernel_w(KERNEL_CUBIC_SPLINE, sqrt(r2), 0.5 * R);
    p->e[i] += E * w / wsum;   /* m_i e_i gains E m_i w_i / Σ m w */
  }
  return 0;
}

int setup_bodies(struct sim *s, struct cfg *c, struct hv_error *err)
{
  char where[256];
  int nb = cfg_len(c, "bodies");
  if (nb <= 0)
    return hv_error_set(err, HV_EXIT_INPUT, "%s: 'bodies' must be a list of at least one body",
                        cfg_where(c, "bodies", where, sizeof where));
  if (nb > (int)(sizeof s->body / sizeof s->body[0]))
    return hv_error_set(err, HV_EXIT_INPUT, "%s: too many bodies (%d)",
                        cfg_where(c, "bodies", where, sizeof where), nb);
  for (int b = 0; b < nb; b++) {
    struct body_spec bs;
    memset(&bs, 0, sizeof bs);
    if (read_body(s, c, b, &bs, err)) return -1;
    size_t cnt = lattice_points(&bs, NULL, 0);
    char key[64];
    snprintf(key, sizeof key, "bodies[%d]", b);
    if (cnt == 0)
      return hv_error_set(err, HV_EXIT_INPUT, "%s: body '%s': spacing %g m gives no particle "
                          "inside the shape", cfg_where(c, key, where, sizeof where),
                          s->body[b].name, bs.spacing);
    if (cnt > ((size_t)1 << 31) - s->p.n)
      return hv_error_set(err, HV_EXIT_INPUT, "%s: body '%s': %zu particles is more than "
                          "hvsph can index", cfg_where(c, key, where, sizeof where),
                          s->body[b].name, cnt);
    size_t first = particles_add(&s->p, cnt);
    lattice_points(&bs, &s->p, first);
    init_body(s, &bs, b, first, cnt);
    s->body[b].count = cnt;
  }
  s->nbody = nb;
  return energy_deposit(s, c, err);
}
