/* bodies.c — filling bodies with particles and setting their initial state.
 *
 * A body is a shape (shapes.c) filled with a lattice:
 *   cubic   points at anchor + (i + ½, j + ½, k + ½) Δ;
 *   hcp     hexagonal close packing with nearest-neighbour distance Δ (ABAB layers
 *           along z, volume Δ³/√2 per particle).
 * The anchor is the box corner, or the centre of a sphere or cylinder — but for a cubic
 * lattice in a cylinder along x, y or z the anchor along its axis is an end face, as a
 * box's corner is, so that a disc whose length is L spacings holds L layers (centred,
 * an odd L put the end layers on the faces); in a half model (domain.symmetry: half) the
 * z anchor is the plane z = 0 and only z > 0 is kept, so the lattice is mirror-symmetric
 * about the symmetry plane; in a quarter model the y anchor is y = 0 as well and only
 * y > 0 is kept too (points at ±Δ/2 about each plane). Δ is given (`spacing`) or
 * follows from a particle count (`particles`, in the simulated part), both scaled by
 * the case's `resolution` (particle counts × resolution). Particle mass ρV/N with V the
 * exact volume of the shape (so a projectile has its true mass), or ρ × lattice volume
 * when the exact volume is unknown; h = η (m/ρ)^(1/3).
 * Velocity: `velocity`, or `speed` with `impact_angle` α measured from the target
 * surface in the x–y plane, v = speed (sin α, −cos α, 0) (α = 90°: along +x), or with
 * `obliquity` θ = 90° − α measured from the target's normal (the ballistic-limit
 * equations' angle; θ = 0: along +x); plus
 * `radial_velocity` r̂ about the shape's centre.
 * `damage` (0 to 1) starts a body damaged; 1: split material (docs/models.md).
 * `energy_deposit` adds energy E within a radius R about a point, shared with the
 * weights m_i W(r_i, R/2) (the Sedov blast).
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "eos/eos.h"
#include "fracture/fracture.h"
#include "material/material_read.h"
#include "neighbours/grid.h"
#include "setup/setup.h"

#define HV_SPEED_OF_LIGHT 299792458.0 /* [m/s] */
#define BARE_LENGTH_WARN  1.0         /* [m] (read_body) */

enum lattice_kind { LATTICE_CUBIC = 0, LATTICE_HCP };
static const char *const lattice_names[] = {"cubic", "hcp", NULL};

struct body_spec {
  struct shape shape;
  int mat, lattice;
  double spacing, rho, e, vel[3], vrad;
  double damage;        /* [-] initial damage, 0 (intact) to 1 (split) */
  double vol;           /* [m3] exact volume of the simulated part, or -1 */
  unsigned char fit[3]; /* a box on a cubic lattice with a face on a wall or symmetry
                            face of the domain, along that axis: its step is fitted to
                            its length (lattice_points) */
};

static double cell_volume(int lattice, double d)
{
  return lattice == LATTICE_HCP ? d * d * d / sqrt(2.0) : d * d * d;
}

/* The coordinate axis (0, 1, 2) a cylinder lies along, or -1 (another shape, an oblique
 * axis). */
static int cylinder_axis(const struct shape *sh)
{
  if (sh->kind != SHAPE_CYLINDER) return -1;
  for (int d = 0; d < 3; d++)
    if (fabs(sh->axis[d]) > 1.0 - 1e-12) return d;
  return -1;
}

/* Physical memory of this machine [bytes] (1e18 when unknown). */
static double machine_bytes(void)
{
  long pages = sysconf(_SC_PHYS_PAGES), psize = sysconf(_SC_PAGESIZE);
  return pages > 0 && psize > 0 ? (double)pages * (double)psize : 1e18;
}

/* Bytes n particles need (ghosts and grid included) and whether that fits: 80 % of
 * the machine's memory. */
static double particles_need(double n, int solid) { return n * (solid ? 900.0 : 600.0); }
static int particles_fit(double n, int solid)
{
  return particles_need(n, solid) <= 0.8 * machine_bytes();
}

/* The most lattice points lattice_points scans (its shape's bounding box in lattice
 * steps): 64 times the gas particles this machine's memory holds, at least 1e9 (a scan
 * of 1e9 points takes seconds). A long body lying across the axes scans more
 * points than it holds (a rod 20 diameters long along a diagonal, about 120 times); a
 * scan beyond this is a shape far larger than meant (a length in metres where
 * millimetres were meant), and would take hours. */
static double lattice_scan_max(void)
{
  return fmax(1e9, 64.0 * 0.8 * machine_bytes() / particles_need(1.0, 0));
}

/* The number of symmetry planes through the axis: 0 (a full model), 1 (a half model,
 * z = 0) or 2 (a quarter model, z = 0 and y = 0). */
static int sym_planes(const struct sim *s) { return s->bnd.half_model + s->bnd.quarter_model; }

/* 1 when axis k is cut at 0 by a symmetry plane of a model with `planes` planes. */
static int cut_axis(int planes, int k)
{
  return (k == 2 && planes >= 1) || (k == 1 && planes >= 2);
}

/* Visits the lattice points of a body inside its shape (and z > 0 in a half model, y > 0
 * and z > 0 in a quarter model, `planes` 1 or 2):
 * counts them, and stores them at p->x[.][first + k] when p is not NULL. SIZE_MAX,
 * without scanning, when its bounding box holds more than lattice_scan_max() points
 * (*scan, when not NULL, gets their number): spacing_for_count's searches take it as
 * "enough" and stop, and setup_bodies reports it. */
static size_t lattice_points_scan(const struct body_spec *bs, int planes, struct particles *p,
                                  size_t first, double *scan)
{
  const struct shape *sh = &bs->shape;
  const double d = bs->spacing;
  double anchor[3], step[3] = {d, d, d};
  if (bs->lattice == LATTICE_HCP) {
    step[1] = d * sqrt(3.0) / 2.0;
    step[2] = d * sqrt(2.0 / 3.0);
  }
  for (int k = 0; k < 3; k++) {
    anchor[k] = sh->kind == SHAPE_BOX ? sh->min[k] : sh->center[k];
    if (bs->fit[k]) {
      /* a whole number of layers along k, the first and last half a step inside its faces
         (from a symmetry plane that cuts it); unchanged when it already fits */
      const double ext = sh->max[k] - (cut_axis(planes, k) ? 0.0 : sh->min[k]);
      const double nl = fmax(1.0, round(ext / d));
      if (fabs(ext / d - nl) > 1e-9 * nl) step[k] = ext / nl;
    }
  }
  const int ax = cylinder_axis(sh);
  if (ax >= 0 && bs->lattice == LATTICE_CUBIC) anchor[ax] = sh->center[ax] - 0.5 * sh->length;
  for (int k = 1; k < 3; k++)
    if (cut_axis(planes, k)) anchor[k] = 0.0;
  double dlo[3], dhi[3], npts = 1.0; /* as doubles first: a huge box overflows a long */
  for (int k = 0; k < 3; k++) {
    dlo[k] = floor((sh->min[k] - anchor[k]) / step[k]) - 2.0;
    dhi[k] = ceil((sh->max[k] - anchor[k]) / step[k]) + 1.0;
    if (cut_axis(planes, k) && dlo[k] < 0.0) dlo[k] = 0.0;
    npts *= dhi[k] - dlo[k] + 1.0;
  }
  if (scan) *scan = npts;
  if (!(npts <= lattice_scan_max())) return SIZE_MAX;
  long lo[3], hi[3];
  for (int k = 0; k < 3; k++) {
    lo[k] = (long)dlo[k];
    hi[k] = (long)dhi[k];
  }
  size_t count = 0;
  for (long k = lo[2]; k <= hi[2]; k++)
    for (long j = lo[1]; j <= hi[1]; j++)
      for (long i = lo[0]; i <= hi[0]; i++) {
        double x[3];
        if (bs->lattice == LATTICE_HCP) {
          long kk = labs(k) % 2, jj = labs(j) % 2;
          x[0] = anchor[0] + ((double)i + 0.5 * (double)jj + 0.5 * (double)kk + 0.25) * step[0];
          x[1] = anchor[1] + ((double)j + (double)kk / 3.0 + 0.5) * step[1];
        } else {
          x[0] = anchor[0] + ((double)i + 0.5) * step[0];
          x[1] = anchor[1] + ((double)j + 0.5) * step[1];
        }
        x[2] = anchor[2] + ((double)k + 0.5) * step[2];
        if (!shape_contains(sh, x) || (planes >= 1 && x[2] <= 0.0) || (planes >= 2 && x[1] <= 0.0))
          continue;
        if (p)
          for (int c = 0; c < 3; c++) p->x[c][first + count] = x[c];
        count++;
      }
  return count;
}

static size_t lattice_points(const struct body_spec *bs, int planes, struct particles *p,
                             size_t first)
{
  return lattice_points_scan(bs, planes, p, first, NULL);
}

static int read_velocity(struct cfg *c, const char *path, const char *name, struct body_spec *bs,
                         struct hv_error *err)
{
  char key[256], key2[256], where[256];
  double v0[3] = {0, 0, 0}, zero = 0.0, right = HV_KERNEL_PI / 2;
  snprintf(key, sizeof key, "%s.velocity", path);
  snprintf(key2, sizeof key2, "%s.speed", path);
  if (cfg_has(c, key) && cfg_has(c, key2))
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: body '%s': give velocity or speed (with "
                        "impact_angle), not both",
                        cfg_where(c, key2, where, sizeof where), name);
  /* obliquity θ, measured from the plate's normal as the ballistic-limit equations
     measure it: the same direction as impact_angle α = 90° − θ */
  char okey[256];
  snprintf(okey, sizeof okey, "%s.obliquity", path);
  snprintf(key, sizeof key, "%s.impact_angle", path);
  if (cfg_has(c, okey) && cfg_has(c, key))
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: body '%s': give impact_angle (from the plate's "
                        "surface) or obliquity (from its normal), not both",
                        cfg_where(c, okey, where, sizeof where), name);
  if (cfg_has(c, okey) && !cfg_has(c, key2))
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: body '%s': obliquity applies with speed "
                        "(v = speed (cos t, -sin t, 0)); with velocity, the vector's components "
                        "give the direction",
                        cfg_where(c, okey, where, sizeof where), name);
  if (cfg_has(c, key) && !cfg_has(c, key2))
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: body '%s': impact_angle applies with speed "
                        "(v = speed (sin a, -cos a, 0)); with velocity, the vector's components "
                        "give the direction",
                        cfg_where(c, key, where, sizeof where), name);
  snprintf(key, sizeof key, "%s.velocity", path);
  if (cfg_has(c, key2)) {
    double speed, angle;
    if (cfg_get_quantity(c, key2, UNIT_VELOCITY, NULL, 0.0, HUGE_VAL, &speed, err)) return -1;
    snprintf(key, sizeof key, "%s.impact_angle", path);
    if (cfg_has(c, okey)) {
      double obl;
      if (cfg_get_quantity(c, okey, UNIT_ANGLE, NULL, -HUGE_VAL, HUGE_VAL, &obl, err)) return -1;
      if (!(obl >= 0.0 && obl < HV_KERNEL_PI / 2))
        return hv_error_set(err, HV_EXIT_INPUT,
                            "%s: body '%s': obliquity %g deg is outside "
                            "[0, 90) deg (0 is a normal impact)",
                            cfg_where(c, okey, where, sizeof where), name,
                            obl * 180 / HV_KERNEL_PI);
      angle = HV_KERNEL_PI / 2 - obl;
    } else if (cfg_get_quantity(c, key, UNIT_ANGLE, &right, -HUGE_VAL, HUGE_VAL, &angle, err)) {
      return -1;
    }
    if (!(angle > 0.0 && angle <= HV_KERNEL_PI / 2 * (1 + 1e-12)))
      return hv_error_set(err, HV_EXIT_INPUT,
                          "%s: body '%s': impact_angle %g deg is outside "
                          "(0, 90] deg (90 deg is a normal impact)",
                          cfg_where(c, key, where, sizeof where), name, angle * 180 / HV_KERNEL_PI);
    /* a normal impact (α = 90°, θ = 0) lies exactly along +x: cos(π/2) is 6e-17 in
       floating point, a lateral 4e-13 m/s at 7 km/s that an axisymmetric domain, which
       admits only velocities along its axis, refused as breaking the symmetry */
    const int normal = fabs(angle - HV_KERNEL_PI / 2) <= 1e-12 * HV_KERNEL_PI / 2;
    bs->vel[0] = normal ? speed : speed * sin(angle);
    bs->vel[1] = normal ? 0.0 : -speed * cos(angle);
    bs->vel[2] = 0.0;
  } else if (cfg_get_vec3(c, key, UNIT_VELOCITY, v0, bs->vel, err)) {
    return -1;
  }
  snprintf(key, sizeof key, "%s.radial_velocity", path);
  if (cfg_get_quantity(c, key, UNIT_VELOCITY, &zero, -HUGE_VAL, HUGE_VAL, &bs->vrad, err))
    return -1;
  /* hvsph's mechanics are Newtonian: a body at or above the speed of light is a slip
     (1e300 m/s ran until its first step overflowed; 3e8 m/s ran to exit 0). The
     fastest natural impactors, meteoroids, reach 72 km/s, four thousand times below. */
  const double speed = hypot(hypot(bs->vel[0], bs->vel[1]), bs->vel[2]);
  const char *vkey = cfg_has(c, key2) ? "speed" : "velocity";
  if (!(speed < HV_SPEED_OF_LIGHT) || !(fabs(bs->vrad) < HV_SPEED_OF_LIGHT) ||
      !(speed + fabs(bs->vrad) < HV_SPEED_OF_LIGHT)) {
    const int radial = !(speed < HV_SPEED_OF_LIGHT) ? 0 : 1;
    snprintf(key, sizeof key, "%s.%s", path, radial ? "radial_velocity" : vkey);
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: %s: body '%s': a speed of %g m/s%s is not "
                        "below the speed of light (%.0f m/s); hvsph's mechanics are "
                        "Newtonian, for impacts up to some tens of km/s",
                        cfg_where(c, key, where, sizeof where), key, name,
                        radial ? speed + fabs(bs->vrad) : speed,
                        radial ? " (with its radial velocity)" : "", HV_SPEED_OF_LIGHT);
  }
  return 0;
}

static int read_state(struct cfg *c, const char *path, const char *name, const struct material *m,
                      struct body_spec *bs, struct hv_error *err)
{
  char key[256], key2[256], where[256];
  snprintf(key, sizeof key, "%s.density", path);
  const double *rdef = m->rho0 > 0 ? &m->rho0 : NULL;
  if (cfg_get_quantity(c, key, UNIT_DENSITY, rdef, DBL_MIN, HUGE_VAL, &bs->rho, err)) return -1;
  /* wrong units: a bare density far from any condensed material's (2.78, in g/cm3) */
  if (m->eos != EOS_IDEAL_GAS && cfg_check_typical(c, key, UNIT_DENSITY, HV_RHO_CONDENSED_LO,
                                                   HV_RHO_CONDENSED_HI, HV_RHO_CONDENSED_WHAT, err))
    return -1;
  snprintf(key, sizeof key, "%s.pressure", path);
  snprintf(key2, sizeof key2, "%s.energy", path);
  if (cfg_has(c, key) && cfg_has(c, key2))
    return hv_error_set(err, HV_EXIT_INPUT, "%s: body '%s': give pressure or energy, not both",
                        cfg_where(c, key, where, sizeof where), name);
  if (cfg_has(c, key)) {
    double pr;
    /* a gas has no tension; a solid may start stretched, down to −ρ₀c₀² */
    const double plo = m->eos == EOS_IDEAL_GAS ? 0.0 : -HUGE_VAL;
    if (cfg_get_quantity(c, key, UNIT_PRESSURE, NULL, plo, HUGE_VAL, &pr, err)) return -1;
    if (eos_energy_from_pressure(m, bs->rho, pr, &bs->e) || !isfinite(bs->e))
      return hv_error_set(err, HV_EXIT_INPUT,
                          "%s: body '%s': material '%s' cannot reach "
                          "p = %g Pa at rho = %g kg/m3",
                          cfg_where(c, key, where, sizeof where), name, m->name, pr, bs->rho);
    return 0;
  }
  double zero = 0.0;
  return cfg_get_quantity(c, key2, UNIT_SPECIFIC_ENERGY, &zero, -HUGE_VAL, HUGE_VAL, &bs->e, err);
}

/* Wrong units in a shape: a length of body `path` written as a bare number (SI, so
 * metres) where millimetres were almost certainly meant. The first bare one of the
 * shape's radius, length, max and min whose magnitude is at least `least` (> 0; not of
 * its `minus`: a hole does not make a body large); its key goes to key, its value (m)
 * to *v. 0 when none. */
static int bare_length(struct cfg *c, const char *path, const struct shape *sh, double least,
                       char *key, size_t klen, double *v)
{
  static const char *const names[] = {"radius", "length", "max", "min"};
  for (int k = 0; k < 4; k++) {
    const int vec = k >= 2;
    for (int d = 0; d < (vec ? 3 : 1); d++) {
      const double val = k == 0   ? sh->radius
                         : k == 1 ? sh->length
                         : k == 2 ? sh->max[d]
                                  : sh->min[d];
      if (vec)
        snprintf(key, klen, "%s.shape.%s[%d]", path, names[k], d);
      else
        snprintf(key, klen, "%s.shape.%s", path, names[k]);
      if (fabs(val) >= least && (sh->kind == SHAPE_BOX) == vec && cfg_is_bare(c, key)) {
        *v = val;
        return 1;
      }
    }
  }
  return 0;
}

/* The bare lengths of body b's shape that, read in millimetres, would make it fit in
 * memory at its spacing: its radius, its length, or a box's bare corners together (one
 * corner alone read in millimetres could turn the box inside out). The one of largest
 * magnitude: its key to key, its value (m) to *v; 0 when none fits. */
static int bare_length_culprit(struct cfg *c, int b, const struct body_spec *bs, char *key,
                               size_t klen, double *v)
{
  const struct shape *sh = &bs->shape;
  const double cell = cell_volume(bs->lattice, bs->spacing);
  char k[96];
  int found = 0;
  *v = 0.0;
  if (sh->kind != SHAPE_BOX) {
    for (int which = 0; which < 2; which++) { /* radius, length */
      double r = sh->radius, len = sh->length;
      const double val = which ? len : r;
      snprintf(k, sizeof k, "bodies[%d].shape.%s", b, which ? "length" : "radius");
      if ((which && sh->kind != SHAPE_CYLINDER) || val == 0.0 || !cfg_is_bare(c, k)) continue;
      if (which)
        len *= 1e-3;
      else
        r *= 1e-3;
      const double vol = sh->kind == SHAPE_SPHERE ? 4.0 / 3.0 * HV_KERNEL_PI * r * r * r
                                                  : HV_KERNEL_PI * r * r * len;
      double box = 1.0; /* its bounding box, which lattice_points scans */
      for (int d = 0; d < 3; d++)
        box *= sh->kind == SHAPE_SPHERE
                   ? 2.0 * r
                   : len * fabs(sh->axis[d]) +
                         2.0 * r * sqrt(fmax(0.0, 1.0 - sh->axis[d] * sh->axis[d]));
      if (particles_fit(vol / cell, 1) && box / cell <= lattice_scan_max() &&
          fabs(val) > fabs(*v)) {
        snprintf(key, klen, "%s", k);
        *v = val;
        found = 1;
      }
    }
    return found;
  }
  double lo[3], hi[3], vol = 1.0;
  for (int d = 0; d < 3; d++) {
    for (int m = 0; m < 2; m++) {
      double *x = m ? &hi[d] : &lo[d];
      *x = m ? sh->max[d] : sh->min[d];
      snprintf(k, sizeof k, "bodies[%d].shape.%s[%d]", b, m ? "max" : "min", d);
      if (*x == 0.0 || !cfg_is_bare(c, k)) continue;
      if (fabs(*x) > fabs(*v)) {
        snprintf(key, klen, "%s", k);
        *v = *x;
      }
      *x *= 1e-3;
    }
    vol *= hi[d] - lo[d];
  }
  return *v != 0.0 && vol > 0.0 && particles_fit(vol / cell, 1) && vol / cell <= lattice_scan_max();
}

/* A body too large for memory whose shape has a bare length that, in millimetres, makes
 * it fit: the error is said at that key, as the wrong-units check of densities is
 * (cfg_check_typical): "case.yaml:12: bodies[0].shape.radius: the bare number 1.5 is
 * read as 1.5 m ...; was it 1.5 mm?". `then` says what the body would need ("needs about
 * 9e+11 particles, more than this machine's memory holds"). -1 with err set, or 0 (no
 * such length: the caller says its own error). */
static int bare_length_error(struct cfg *c, int b, const struct body_spec *bs, const char *name,
                             const char *then, struct hv_error *err)
{
  char key[96], where[256];
  double v;
  if (!bare_length_culprit(c, b, bs, key, sizeof key, &v)) return 0;
  return hv_error_set(err, HV_EXIT_INPUT,
                      "%s: %s: the bare number %g is read as %g m (a "
                      "number without a unit is SI), and body '%s' then %s; was it %g mm? Write "
                      "the value with its unit",
                      cfg_where(c, key, where, sizeof where), key, v, v, name, then, v);
}

/* "needs about 9e+11 particles, more than this machine's memory holds" */
static const char *needs_text(char *buf, size_t len, double particles)
{
  snprintf(buf, len, "needs about %.2g particles, more than this machine's memory holds",
           particles);
  return buf;
}

/* The thinnest side of a box, or the length of a disc (a cylinder along x, y or z no
 * longer than its diameter), filled on a cubic lattice (0 for other shapes and
 * lattices; a shape's `minus` does not change it): a count-given plate's spacing is set
 * so that it holds a whole number of layers, else a thin plate could get no particle
 * or an uneven last layer. */
static double box_thickness(const struct sim *s, const struct body_spec *bs)
{
  const struct shape *sh = &bs->shape;
  if (bs->lattice != LATTICE_CUBIC) return 0.0;
  const int ax = cylinder_axis(sh);
  if (ax >= 0 && sh->length <= 2.0 * sh->radius && !cut_axis(sym_planes(s), ax)) return sh->length;
  if (sh->kind != SHAPE_BOX) return 0.0;
  double t = HUGE_VAL;
  for (int d = 0; d < 3; d++) {
    double ext = sh->max[d] - sh->min[d];
    if (cut_axis(sym_planes(s), d)) ext = sh->max[d] > 0 ? fmin(ext, sh->max[d]) : ext;
    t = fmin(t, ext);
  }
  return t;
}

/* The spacing for a body given by its particle count n: the lattice spacing of the
 * shape's volume per particle, then made finer until the body has at least n
 * particles (a lattice cut by a shape's surface holds a few per cent fewer points than
 * the volume suggests); a box's thinnest side gets a whole number of layers, rounded
 * up (rounding to the nearest could give a thin plate one layer and a fraction of the
 * particles asked for, as it did §2.4's bumper). */
static int spacing_for_count(const struct sim *s, struct cfg *c, const char *key,
                             struct body_spec *bs, const char *name, double n, struct hv_error *err)
{
  const double d0 = bs->spacing, t = box_thickness(s, bs);
  const int planes = sym_planes(s);
  double layers = 0.0;
  if (t > 0) { /* whole layers, rounded up, then a layer more while short */
    layers = fmax(1.0, ceil(t / d0 * (1.0 - 1e-9)));
    bs->spacing = t / layers;
    /* a plate or disc far wider than it is thick for its count (a radius in metres
       where millimetres were meant): even one layer fills it with more particles than
       memory holds, and counting them would take hours */
    const double est = bs->vol / cell_volume(bs->lattice, bs->spacing);
    if (!particles_fit(est, 0)) {
      char where[256];
      /* key is "bodies[b].particles" */
      char then[128];
      if (bare_length_error(c, (int)strtol(key + 7, NULL, 10), bs, name,
                            needs_text(then, sizeof then, est), err))
        return -1;
      return hv_error_set(err, HV_EXIT_INPUT,
                          "%s: body '%s': %.0f particles asked, but its "
                          "thinnest side, %g mm, in whole layers needs a spacing of at most "
                          "%g mm, which fills its %g m3 with about %.3g particles, more than "
                          "this machine's memory holds; check the shape's size and units",
                          cfg_where(c, key, where, sizeof where), name, n, 1e3 * t,
                          1e3 * bs->spacing, bs->vol, est);
    }
    for (int it = 0; it < 60 && (double)lattice_points(bs, planes, NULL, 0) < n; it++) {
      layers += 1.0;
      bs->spacing = t / layers;
    }
  } else { /* the coarsest spacing that gives n: bracket, then bisect */
    double hi = bs->spacing, lo = hi;
    double cnt = (double)lattice_points(bs, planes, NULL, 0);
    for (int it = 0; it < 60 && cnt < n; it++) {
      hi = lo;
      lo *= fmin(0.99, cbrt(fmax(cnt, 1.0) / n));
      bs->spacing = lo;
      cnt = (double)lattice_points(bs, planes, NULL, 0);
    }
    for (int it = 0; it < 40 && hi > lo * (1.0 + 1e-6); it++) {
      bs->spacing = 0.5 * (lo + hi);
      if ((double)lattice_points(bs, planes, NULL, 0) >= n)
        lo = bs->spacing;
      else
        hi = bs->spacing;
    }
    bs->spacing = lo;
  }
  if (t > 0 && bs->spacing < 0.8 * d0)
    hv_info("body '%s': spacing %.4g mm -> %.4g mm so that its %.4g mm thickness holds %.0f "
            "whole layer(s) and at least %.0f particles",
            name, 1e3 * d0, 1e3 * bs->spacing, 1e3 * t, layers, n);
  return 0;
}

/* The shape (with everything it subtracts) is mirror-symmetric about the plane x_d = 0
 * (d = 1: y, 2: z): a box spanning it evenly, a sphere centred on it, a cylinder centred
 * on it whose axis lies in it or is its normal. */
static int symmetric_about(const struct shape *sh, int d)
{
  const int o1 = (d + 1) % 3, o2 = (d + 2) % 3;
  const int axis_ok = sh->axis[d] == 0.0 || (sh->axis[o1] == 0.0 && sh->axis[o2] == 0.0);
  int sym = sh->kind == SHAPE_BOX ? sh->min[d] == -sh->max[d]
                                  : sh->center[d] == 0.0 && (sh->kind == SHAPE_SPHERE || axis_ok);
  for (int k = 0; k < sh->nminus; k++) sym = sym && symmetric_about(&sh->minus[k], d);
  return sym;
}

/* Spacing from `spacing` or `particles`, scaled by the resolution factor. */
static int read_spacing(struct sim *s, struct cfg *c, const char *path, const char *name,
                        struct body_spec *bs, double resolution, struct hv_error *err)
{
  char key[256], key2[256], where[256];
  snprintf(key, sizeof key, "%s.spacing", path);
  snprintf(key2, sizeof key2, "%s.particles", path);
  if (cfg_has(c, key) == cfg_has(c, key2))
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: body '%s': give exactly one of 'spacing' and "
                        "'particles'",
                        cfg_where(c, path, where, sizeof where), name);
  if (cfg_has(c, key)) {
    if (cfg_get_quantity(c, key, UNIT_LENGTH, NULL, DBL_MIN, HUGE_VAL, &bs->spacing, err))
      return -1;
    /* a factor on the particle count: rings in an axisymmetric domain */
    bs->spacing /= s->p.axisym ? sqrt(resolution) : cbrt(resolution);
    return 0;
  }
  long np;
  if (cfg_get_int(c, key2, NULL, 1, 2000000000L, &np, err)) return -1;
  if (bs->vol <= 0)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: body '%s': 'particles' needs a shape of known "
                        "volume; give 'spacing' instead",
                        cfg_where(c, key2, where, sizeof where), name);
  double n = (double)np * resolution, v1 = bs->vol / n; /* volume per particle */
  if (s->p.axisym) {                                    /* rings */
    bs->spacing = rz_spacing_for_count(&bs->shape, n);
    return 0;
  }
  bs->spacing = bs->lattice == LATTICE_HCP ? cbrt(sqrt(2.0) * v1) : cbrt(v1);
  /* counted only where it could fit (as gas, the least): check_memory refuses the rest
     before anything is allocated, without minutes of counting first */
  if (particles_fit(n, 0)) return spacing_for_count(s, c, key2, bs, name, n, err);
  return 0;
}

/* Body b's name (bodies[b].name, else "body<b>") into s->body[b].name and *name, refused
 * when an earlier body has it. */
static int read_body_name(struct sim *s, struct cfg *c, int b, const char *path, const char **name,
                          struct hv_error *err)
{
  char key[256], defname[32];
  snprintf(defname, sizeof defname, "body%d", b);
  snprintf(key, sizeof key, "%s.name", path);
  if (cfg_get_string(c, key, defname, name, err)) return -1;
  snprintf(s->body[b].name, sizeof s->body[b].name, "%s", *name);
  /* names pick bodies out (part_of, measure:, the render's labels, messages): two
     bodies of one name would leave it to the order which is meant */
  for (int a = 0; a < b; a++)
    if (!strcmp(s->body[a].name, s->body[b].name)) {
      char where[256], first[256], akey[64];
      snprintf(akey, sizeof akey, "bodies[%d].name", a);
      if (!cfg_has(c, akey)) snprintf(akey, sizeof akey, "bodies[%d]", a);
      return hv_error_set(err, HV_EXIT_INPUT,
                          "%s: %s: a second body named '%s' (the first, "
                          "bodies[%d], at %s); give each body a name of its own",
                          cfg_where(c, cfg_has(c, key) ? key : path, where, sizeof where), key,
                          s->body[b].name, a, cfg_where(c, akey, first, sizeof first));
    }
  return 0;
}

/* bs->fit: the axes along which the lattice's step is fitted to the box's length. */
static void fit_to_faces(const struct sim *s, struct body_spec *bs)
{
  /* A box's lattice starts Δ/2 inside its min face and ends wherever its length
     leaves it — anywhere from 0 to Δ from its max face. Next to a wall or symmetry face
     the gap matters: the mirror ghosts stand twice the gap from the last layer, not Δ,
     and a gas at rest under pressure is pushed across the gap (the §3 vessel's nitrogen
     was: docs/design.md, "Where hvsph departs from its design brief, and why"). Along
     an axis on which a box of gas touches such a face its step is fitted to its length,
     within Δ/(2n) of Δ for n layers (the mass follows from the exact volume, h from the
     mass). Condensed bodies start at zero pressure, where the gap exerts no force, and
     keep their lattice. */
  for (int k = 0; k < 3; k++) {
    const double tol = 1e-9 * fmax(1.0, fabs(s->bnd.hi[k] - s->bnd.lo[k]));
    const int kh = s->bnd.kind[k][1], kl = s->bnd.kind[k][0];
    const int on_hi =
        (kh == BND_WALL || kh == BND_SYMMETRY) && fabs(bs->shape.max[k] - s->bnd.hi[k]) <= tol;
    const int on_lo =
        (kl == BND_WALL || kl == BND_SYMMETRY) && fabs(bs->shape.min[k] - s->bnd.lo[k]) <= tol;
    bs->fit[k] = s->bnd.has_box && bs->shape.kind == SHAPE_BOX &&
                 s->mat[bs->mat].eos == EOS_IDEAL_GAS && bs->lattice == LATTICE_CUBIC &&
                 (on_hi || on_lo) && !(cut_axis(sym_planes(s), k) && bs->shape.min[k] > 0.0);
  }
}

/* Warns of a bare length that reads as a metre or more in a solid body. */
static void warn_bare_length(const struct sim *s, struct cfg *c, const char *path, const char *name,
                             const struct body_spec *bs)
{
  /* wrong units that still fit in memory: a body of a condensed material at a real
     density (the range of the density check, so not a case in scaled units like the
     rubber rings') with a bare length of a metre or more. The bodies of examples/ measure
     0.3 to 300 mm; a bare "radius: 1.5" there is far more often 1.5 mm without its unit
     than a sphere of 3 m, but one can be meant and it runs: a warning */
  if (s->mat[bs->mat].eos != EOS_IDEAL_GAS && bs->rho >= HV_RHO_CONDENSED_LO &&
      bs->rho <= HV_RHO_CONDENSED_HI) {
    char lkey[96], where[256];
    double v;
    if (bare_length(c, path, &bs->shape, BARE_LENGTH_WARN, lkey, sizeof lkey, &v))
      hv_warn("%s: %s: body '%s': the bare number %g is read as %g m (a number without a unit "
              "is SI), large for a solid body of this code's cases; was it %g mm? (write the "
              "value with its unit: '%g m' keeps this one)",
              cfg_where(c, lkey, where, sizeof where), lkey, name, v, v, v, v);
  }
}

/* bs->damage, the body's initial damage, refused without a fracture model. */
static int read_damage(const struct sim *s, struct cfg *c, const char *path, const char *name,
                       struct body_spec *bs, struct hv_error *err)
{
  char key[256];
  /* initial damage: 1 makes a body of broken (split) material, e.g. to test the
     fracture.friction of split material or to start from a rubble target */
  const double zero = 0.0;
  snprintf(key, sizeof key, "%s.damage", path);
  if (cfg_get_quantity(c, key, UNIT_NONE, &zero, 0.0, 1.0, &bs->damage, err)) return -1;
  if (bs->damage > 0.0 && s->mat[bs->mat].frac.kind == FRACTURE_NONE) {
    char where[256];
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: %s: body '%s': damage = %g needs a material "
                        "with fracture (material '%s' has fracture: none)",
                        cfg_where(c, key, where, sizeof where), key, name, bs->damage,
                        s->mat[bs->mat].name);
  }
  return 0;
}

/* A quarter model holds the y > 0, z > 0 quarter of a flow symmetric about both planes
 * y = 0 and z = 0: every body must be so (mirror-symmetric about both; an off-axis body
 * or one turned across them would be mirrored into three bodies that are not in the
 * case), refused otherwise. */
static int quarter_shape(const struct sim *s, struct cfg *c, const char *path, const char *name,
                         const struct body_spec *bs, struct hv_error *err)
{
  if (!s->bnd.quarter_model) return 0;
  for (int d = 1; d < 3; d++) {
    if (symmetric_about(&bs->shape, d)) continue;
    char key[256], where[256];
    snprintf(key, sizeof key, "%s.shape", path);
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: %s: body '%s' is not mirror-symmetric about the plane %c = 0, one "
                        "of the quarter model's two symmetry planes (domain.symmetry: quarter "
                        "is for normal impacts along x on the axis y = 0, z = 0: every body "
                        "centred on it; a box spanning -a to a in y and z, a sphere or a "
                        "cylinder centred on the axis); use symmetry: half or none",
                        cfg_where(c, key, where, sizeof where), key, name, "xyz"[d]);
  }
  return 0;
}

/* A quarter model's bodies move along x only (the flow stays symmetric about both
 * planes): a velocity with a y or z component, an oblique impact, is refused. A
 * component below 1e-12 of the speed (speed with impact_angle 90 deg: cos(pi/2) is
 * 6e-17, not 0) is taken as zero and set to it, so the lattice stays symmetric. */
static int quarter_velocity(const struct sim *s, struct cfg *c, const char *path, const char *name,
                            struct body_spec *bs, struct hv_error *err)
{
  if (!s->bnd.quarter_model) return 0;
  const double speed = fabs(bs->vel[0]) + fabs(bs->vel[1]) + fabs(bs->vel[2]);
  if (fabs(bs->vel[1]) <= 1e-12 * speed && fabs(bs->vel[2]) <= 1e-12 * speed) {
    bs->vel[1] = bs->vel[2] = 0.0;
    return 0;
  }
  static const char *const keys[] = {"obliquity", "impact_angle", "speed", "velocity"};
  char key[256], where[256];
  for (int k = 0; k < 4; k++) {
    snprintf(key, sizeof key, "%s.%s", path, keys[k]);
    if (cfg_has(c, key)) break;
  }
  return hv_error_set(err, HV_EXIT_INPUT,
                      "%s: %s: body '%s': velocity (%g, %g, %g) m/s is not along x; a "
                      "quarter model (domain.symmetry: quarter) is for normal impacts along x, "
                      "symmetric about y = 0 and z = 0: use symmetry: half (velocity in the "
                      "x-y plane) or none",
                      cfg_where(c, key, where, sizeof where), key, name, bs->vel[0], bs->vel[1],
                      bs->vel[2]);
}

/* Body b of the case: name, material, shape, lattice, spacing, state, velocity, damage. */
static int read_body(struct sim *s, struct cfg *c, int b, struct body_spec *bs, double resolution,
                     struct hv_error *err)
{
  char key[256], path[64];
  const char *name, *mname;
  snprintf(path, sizeof path, "bodies[%d]", b);
  if (read_body_name(s, c, b, path, &name, err)) return -1;
  snprintf(key, sizeof key, "%s.material", path);
  if (cfg_get_string(c, key, NULL, &mname, err)) return -1;
  bs->mat = material_find_or_load(c, key, mname, s->mat, &s->nmat, HV_MAX_MATERIALS, err);
  if (bs->mat < 0) return -1;
  snprintf(key, sizeof key, "%s.shape", path);
  if (shape_read(&bs->shape, c, key, err)) return -1;
  snprintf(key, sizeof key, "%s.lattice", path);
  if (cfg_get_choice(c, key, "cubic", lattice_names, &bs->lattice, err)) return -1;
  /* The hcp lattice has no mirror plane between two of its layers: in a half model the
     layer next to z = 0 would meet its own mirror ghosts stacked straight below it,
     √(2/3) Δ = 0.82 Δ away, where a full model has the next layer's three neighbours at
     Δ. A body the symmetry plane cuts must take the cubic lattice. */
  if (bs->lattice == LATTICE_HCP && s->bnd.half_model && bs->shape.min[2] <= 0.0) {
    char where[256];
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: %s: body '%s': lattice hcp cannot be cut by the "
                        "symmetry plane of a %s model (its layer next to z = 0 would meet its "
                        "mirror images 0.82 spacings away, not 1): use lattice: cubic, or a full "
                        "model",
                        cfg_where(c, key, where, sizeof where), key, name,
                        s->bnd.quarter_model ? "quarter" : "half");
  }
  if (quarter_shape(s, c, path, name, bs, err)) return -1;
  fit_to_faces(s, bs);
  bs->vol = shape_volume(&bs->shape);
  if (s->bnd.quarter_model && bs->vol > 0) {
    bs->vol *= 0.25; /* symmetric about both planes (quarter_shape) */
  } else if (s->bnd.half_model && bs->vol > 0) {
    /* a half model keeps z > 0: exact when the shape is symmetric about z = 0 */
    bs->vol = symmetric_about(&bs->shape, 2) ? 0.5 * bs->vol : -1.0;
  }
  s->body[b].mat = bs->mat;
  if (read_spacing(s, c, path, name, bs, resolution, err) ||
      read_state(c, path, name, &s->mat[bs->mat], bs, err) ||
      read_velocity(c, path, name, bs, err) || quarter_velocity(s, c, path, name, bs, err))
    return -1;
  if (s->p.axisym &&
      rz_check_body(c, path, name, &bs->shape, bs->lattice == LATTICE_HCP, bs->vel, err))
    return -1;
  warn_bare_length(s, c, path, name, bs);
  if (read_damage(s, c, path, name, bs, err)) return -1;
  return 0;
}

static void init_body(struct sim *s, const struct body_spec *bs, int b, size_t first, size_t cnt)
{
  struct particles *p = &s->p;
  const double m = bs->vol > 0 ? bs->rho * bs->vol / (double)cnt
                               : bs->rho * cell_volume(bs->lattice, bs->spacing);
  const double h = s->sph.eta * cbrt(m / bs->rho);
  for (size_t q = first; q < first + cnt; q++) {
    p->id[q] = (int64_t)q;
    p->mat[q] = bs->mat;
    p->body[q] = b;
    p->m[q] = m;
    p->rho[q] = bs->rho;
    p->h[q] = h;
    p->e[q] = bs->e;
    if (p->solid) fracture_start(&s->mat[bs->mat].frac, bs->damage, &p->damage[q], &p->fstate[q]);
    double r[3], rn = 0.0;
    for (int c = 0; c < 3; c++) {
      r[c] = p->x[c][q] - bs->shape.center[c];
      rn += r[c] * r[c];
    }
    rn = sqrt(rn);
    for (int c = 0; c < 3; c++) p->v[c][q] = bs->vel[c] + (rn > 0 ? bs->vrad * r[c] / rn : 0.0);
  }
  if (p->axisym) rz_ring_masses(p, first, cnt, bs->rho, bs->vol, bs->spacing, s->sph.eta);
}

static int energy_deposit(struct sim *s, struct cfg *c, struct hv_error *err)
{
  if (!cfg_has(c, "energy_deposit")) return 0;
  double E, ctr[3], R, zero3[3] = {0, 0, 0};
  char where[256];
  if (cfg_get_quantity(c, "energy_deposit.energy", UNIT_ENERGY, NULL, 0.0, HUGE_VAL, &E, err) ||
      cfg_get_vec3(c, "energy_deposit.center", UNIT_LENGTH, zero3, ctr, err) ||
      cfg_get_quantity(c, "energy_deposit.radius", UNIT_LENGTH, NULL, DBL_MIN, HUGE_VAL, &R, err))
    return -1;
  if (s->p.axisym && (ctr[1] != 0.0 || ctr[2] != 0.0))
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: energy_deposit.center: a deposit off the axis (r = %g m) breaks "
                        "the symmetry of an axisymmetric domain; centre it on the axis",
                        cfg_where(c, "energy_deposit.center", where, sizeof where),
                        hypot(ctr[1], ctr[2]));
  struct particles *p = &s->p;
  double wsum = 0.0;
  for (size_t i = 0; i < p->n; i++) {
    double r2 = 0.0;
    for (int k = 0; k < 3; k++) r2 += (p->x[k][i] - ctr[k]) * (p->x[k][i] - ctr[k]);
    wsum += p->m[i] * kernel_w(KERNEL_CUBIC_SPLINE, sqrt(r2), 0.5 * R);
  }
  if (!(wsum > 0))
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: energy_deposit: no particle within radius "
                        "%g m of the centre",
                        cfg_where(c, "energy_deposit", where, sizeof where), R);
  for (size_t i = 0; i < p->n; i++) {
    double r2 = 0.0;
    for (int k = 0; k < 3; k++) r2 += (p->x[k][i] - ctr[k]) * (p->x[k][i] - ctr[k]);
    double w = kernel_w(KERNEL_CUBIC_SPLINE, sqrt(r2), 0.5 * R);
    p->e[i] += E * w / wsum; /* m_i e_i gains E m_i w_i / Σ m w */
  }
  return 0;
}

/* Bodies must not overlap, and must lie inside the domain box when there is one. */
static int check_placement(struct sim *s, struct cfg *c, const struct body_spec *bs, int b,
                           size_t first, size_t cnt, struct hv_error *err)
{
  char key[64], where[256];
  snprintf(key, sizeof key, "bodies[%d]", b);
  const struct particles *p = &s->p;
  for (size_t q = first; q < first + cnt; q++) {
    const double x[3] = {p->x[0][q], p->x[1][q], p->x[2][q]};
    for (int a = 0; a < b; a++)
      if (shape_contains(&bs[a].shape, x))
        return hv_error_set(err, HV_EXIT_INPUT,
                            "%s: bodies '%s' and '%s' overlap (e.g. at "
                            "x = (%g, %g, %g) m)",
                            cfg_where(c, key, where, sizeof where), s->body[a].name,
                            s->body[b].name, x[0], x[1], x[2]);
    if (s->bnd.has_box)
      for (int d = 0; d < 3; d++)
        if (x[d] < s->bnd.lo[d] || x[d] > s->bnd.hi[d]) {
          /* a bare length of the shape (metres) beyond half the domain's largest side is
             the likely cause (a radius of 0.5 in a domain of millimetres) */
          char lkey[96], hint[256] = "";
          double v, side = 0.0;
          for (int e = 0; e < 3; e++) side = fmax(side, s->bnd.hi[e] - s->bnd.lo[e]);
          if (bare_length(c, key, &bs[b].shape, fmax(0.5 * side, DBL_MIN), lkey, sizeof lkey, &v))
            snprintf(hint, sizeof hint, "; %s is the bare number %g, read as %g m: was it %g mm?",
                     lkey, v, v, v);
          return hv_error_set(err, HV_EXIT_INPUT,
                              "%s: body '%s' reaches outside the domain "
                              "(%c = %g m, domain %g to %g m)%s",
                              cfg_where(c, key, where, sizeof where), s->body[b].name, "xyz"[d],
                              x[d], s -> bnd.lo[d], s->bnd.hi[d], hint);
        }
  }
  return 0;
}

/* Refuses, before allocating, a body that would not fit in memory (at a bare length of
 * its shape, bare_length_error, when it has one). */
static int check_memory(struct sim *s, struct cfg *c, int b, const struct body_spec *bs,
                        size_t total, struct hv_error *err)
{
  char key[64], where[256];
  snprintf(key, sizeof key, "bodies[%d]", b);
  const double avail = machine_bytes(), need = particles_need((double)total, s->p.solid);
  if (total >= ((size_t)1 << 31) || !particles_fit((double)total, s->p.solid)) {
    char then[128];
    if (bare_length_error(c, b, bs, s->body[b].name,
                          needs_text(then, sizeof then, (double)(total - s->p.n)), err))
      return -1;
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: body '%s': %zu particles in all would need about "
                        "%.1f GiB, more than this machine's %.1f GiB allows; use a coarser "
                        "spacing or fewer particles",
                        cfg_where(c, key, where, sizeof where), s->body[b].name, total,
                        need / 1073741824.0, avail / 1073741824.0);
  }
  return 0;
}

/* Bodies whose particle masses differ more than this many times get a warning: light
 * particles striking heavy ones at a few km/s stay near their shocked density up to
 * about this ratio and are over-compressed well beyond it (measured on a planar slab;
 * docs/case-files.md, "bodies", gives the figures). */
#define MASS_RATIO_WARN 30.0

#define MEET_MAX_COLUMNS 4000000.0

/* Cell index of coordinate u on a grid of cells `cell` wide from u0. */
static long meet_cell(double u, double u0, double cell) { return (long)floor((u - u0) / cell); }

/* 1 when bodies a and b can meet (their particles first_of[·] .. + count): a particle of
 * one lies within `reach` (twice the larger spacing) of a particle of the other at the
 * start (bodies that touch: a seam, a plate on a plate; found on the neighbour search's
 * cell grid), or the footprint of a, swept along the relative velocity of the two (their
 * mean velocities), comes within reach of a particle of b ahead of it (a projectile aimed
 * at a body; columns of reach/2, so b's particles up to 1.5 reach from the footprint
 * across the flight may count too). A region too wide for either grid answers 1 (the
 * warning is kept rather than missed). */
/* Whether bodies a and b touch at the start: a pair of their particles closer than
 * reach, found on the solver's cell grid (1 also when the region is too wide for it). */
static int bodies_touch(const struct sim *s, const size_t *first_of, int a, int b, double reach)
{
  const struct particles *p = &s->p;
  const struct body_info *A = &s->body[a], *B = &s->body[b];
  const size_t fa = first_of[a], na = A->count, fb = first_of[b], nb = B->count;
  /* 1: touching at the start: the particles of both within the overlap of their boxes
     grown by reach, on the solver's cell grid with h = reach/2 (a pair links when
     r < h_i + h_j = reach) */
  double lo[3], hi[3];
  int overlap = 1;
  for (int d = 0; d < 3; d++) {
    lo[d] = fmax(A->lo[d], B->lo[d]) - reach;
    hi[d] = fmin(A->hi[d], B->hi[d]) + reach;
    overlap &= hi[d] >= lo[d];
  }
  if (!overlap) return 0;
  size_t n = 0;
  uint32_t *id = hv_malloc((na + nb + 1) * sizeof *id, "body contact selection");
  for (size_t q = 0; q < na + nb; q++) {
    const size_t r = q < na ? fa + q : fb + (q - na);
    int in = 1;
    for (int d = 0; d < 3; d++) in &= p->x[d][r] >= lo[d] && p->x[d][r] <= hi[d];
    if (in) id[n++] = (uint32_t)r;
  }
  double *xs[3], *hs = hv_malloc((n + 1) * sizeof *hs, "body contact h");
  for (int d = 0; d < 3; d++) xs[d] = hv_malloc((n + 1) * sizeof *xs[d], "body contact x");
  for (size_t k = 0; k < n; k++) {
    for (int d = 0; d < 3; d++) xs[d][k] = p->x[d][id[k]];
    hs[k] = 0.5 * reach;
  }
  struct nbr_grid g;
  nbr_grid_init(&g);
  char msg[256];
  int meet = 0;
  if (n > 1 && nbr_grid_build(&g, (const double *const *)xs, hs, n,
                              nbr_cell_size(0.5 * reach, 0.5 * reach), msg, sizeof msg))
    meet = 1; /* too wide a region for the grid: keep the warning */
  for (size_t cc = 0; n > 1 && cc < g.ncells && !meet; cc++)
    for (uint32_t ii = g.cell_start[cc]; ii < g.cell_start[cc + 1] && !meet; ii++) {
      const uint32_t i = g.order[ii];
      const int ia = p->body[id[i]] == a;
      for (uint32_t kk = g.nbr_start[cc]; kk < g.nbr_start[cc + 1] && !meet; kk++) {
        const int32_t nc = g.nbr_list[kk];
        for (uint32_t jj = g.cell_start[nc]; jj < g.cell_start[nc + 1] && !meet; jj++) {
          const uint32_t j = g.order[jj];
          if ((p->body[id[j]] == a) == ia) continue; /* a pair of one body */
          const double dx = xs[0][i] - xs[0][j], dy = xs[1][i] - xs[1][j], dz = xs[2][i] - xs[2][j];
          meet = dx * dx + dy * dy + dz * dz < reach * reach;
        }
      }
    }
  nbr_grid_free(&g);
  for (int d = 0; d < 3; d++) free(xs[d]);
  free(hs);
  free(id);
  return meet;
}

/* Whether a's footprint, swept along the bodies' relative mean velocity, passes within
 * reach of a particle of b (1 also when the footprint is too wide for the columns). */
static int bodies_in_path(const struct sim *s, const size_t *first_of, int a, int b, double reach)
{
  const struct particles *p = &s->p;
  const struct body_info *A = &s->body[a], *B = &s->body[b];
  const size_t fa = first_of[a], na = A->count, fb = first_of[b], nb = B->count;
  /* 2: a's footprint swept along u = v̄_a − v̄_b */
  double u[3] = {0, 0, 0};
  for (size_t q = fa; q < fa + na; q++)
    for (int d = 0; d < 3; d++) u[d] += p->v[d][q] / (double)na;
  for (size_t q = fb; q < fb + nb; q++)
    for (int d = 0; d < 3; d++) u[d] -= p->v[d][q] / (double)nb;
  const double un = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  if (!(un > 0)) return 0;
  for (int d = 0; d < 3; d++) u[d] /= un;
  /* e1, e2: an orthonormal basis of the plane across u */
  const int m = fabs(u[0]) < 0.6 ? 0 : 1;
  double e1[3] = {0, 0, 0}, e2[3];
  e1[m] = 1.0;
  const double ud = u[m];
  for (int d = 0; d < 3; d++) e1[d] -= ud * u[d];
  const double n1n = sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
  for (int d = 0; d < 3; d++) e1[d] /= n1n;
  e2[0] = u[1] * e1[2] - u[2] * e1[1];
  e2[1] = u[2] * e1[0] - u[0] * e1[2];
  e2[2] = u[0] * e1[1] - u[1] * e1[0];
  double plo[2] = {HUGE_VAL, HUGE_VAL}, phi[2] = {-HUGE_VAL, -HUGE_VAL};
  for (size_t q = fa; q < fa + na; q++) {
    const double x[3] = {p->x[0][q], p->x[1][q], p->x[2][q]};
    const double c1 = x[0] * e1[0] + x[1] * e1[1] + x[2] * e1[2];
    const double c2 = x[0] * e2[0] + x[1] * e2[1] + x[2] * e2[2];
    plo[0] = fmin(plo[0], c1);
    phi[0] = fmax(phi[0], c1);
    plo[1] = fmin(plo[1], c2);
    phi[1] = fmax(phi[1], c2);
  }
  /* columns half the reach wide; a particle of b within reach of a's footprint is at
     most two columns from one of a's (caught), one farther than 1.5 reach is not */
  const double col = 0.5 * reach;
  const long m1 = (long)floor((phi[0] - plo[0]) / col) + 1;
  const long m2 = (long)floor((phi[1] - plo[1]) / col) + 1;
  if ((double)m1 * (double)m2 > MEET_MAX_COLUMNS) return 1;
  double *rear = hv_malloc((size_t)(m1 * m2) * sizeof *rear, "body sweep grid");
  for (long t = 0; t < m1 * m2; t++) rear[t] = HUGE_VAL; /* a's rearmost point per column */
  for (size_t q = fa; q < fa + na; q++) {
    const double x[3] = {p->x[0][q], p->x[1][q], p->x[2][q]};
    const long i = meet_cell(x[0] * e1[0] + x[1] * e1[1] + x[2] * e1[2], plo[0], col);
    const long j = meet_cell(x[0] * e2[0] + x[1] * e2[1] + x[2] * e2[2], plo[1], col);
    const double s0 = x[0] * u[0] + x[1] * u[1] + x[2] * u[2];
    if (s0 < rear[i * m2 + j]) rear[i * m2 + j] = s0;
  }
  int meet = 0;
  for (size_t q = fb; q < fb + nb && !meet; q++) {
    const double x[3] = {p->x[0][q], p->x[1][q], p->x[2][q]};
    const long i = meet_cell(x[0] * e1[0] + x[1] * e1[1] + x[2] * e1[2], plo[0], col);
    const long j = meet_cell(x[0] * e2[0] + x[1] * e2[1] + x[2] * e2[2], plo[1], col);
    const double s0 = x[0] * u[0] + x[1] * u[1] + x[2] * u[2];
    for (long di = -2; di <= 2 && !meet; di++)
      for (long dj = -2; dj <= 2 && !meet; dj++) {
        const long ii = i + di, jj = j + dj;
        meet = ii >= 0 && ii < m1 && jj >= 0 && jj < m2 && s0 >= rear[ii * m2 + jj] - reach;
      }
  }
  free(rear);
  return meet;
}

static int bodies_can_meet(const struct sim *s, const size_t *first_of, int a, int b)
{
  const double reach = 2.0 * fmax(s->body[a].spacing, s->body[b].spacing);
  return bodies_touch(s, first_of, a, b, reach) || bodies_in_path(s, first_of, a, b, reach);
}

/* Where bodies of very different particle masses meet, the light particles' continuity
 * density is dominated by their few heavy neighbours: they are over-compressed and set
 * a tiny time step (the §3 vessel at the paper's counts, a fine projectile against a
 * coarse wall: docs/case-files.md, "bodies"). Said once per heavy body, naming every
 * body that much lighter that it can meet (bodies_can_meet: a rod aimed at a block's finer
 * core does not meet the coarse block around it), with the remedy. */
static void warn_mass_ratios(const struct sim *s, const size_t *first_of, int nb)
{
  for (int b = 0; b < nb; b++) {
    const double mb = s->p.m[first_of[b]];
    char list[512] = "";
    size_t len = 0;
    int nlight = 0;
    double worst = 0.0;
    for (int a = 0; a < nb; a++) {
      const double ma = s->p.m[first_of[a]];
      if (a == b || mb < MASS_RATIO_WARN * ma || !bodies_can_meet(s, first_of, a, b)) continue;
      int w = snprintf(list + len, sizeof list - len, "%s'%s' (%.*f-fold, %.3g kg)",
                       nlight ? ", " : "", s->body[a].name, mb / ma < 100.0 ? 1 : 0, mb / ma, ma);
      if (w > 0) len = len + (size_t)w < sizeof list ? len + (size_t)w : sizeof list - 1;
      nlight++;
      worst = fmax(worst, mb / ma);
    }
    if (!nlight) continue;
    /* the spacing factor that brings the worst ratio below the threshold (masses scale
       as the spacing cubed), rounded down to two significant digits so that it does:
       just above the threshold the exact factor is 0.999, which "%.2g" would print as 1 */
    const double f = cbrt(MASS_RATIO_WARN / worst);
    const double unit = pow(10.0, floor(log10(f)) - 1.0);
    const double fdown = floor(f / unit) * unit;
    hv_warn(
        "body '%s' (particles of %.3g kg) is much heavier than %s; where they meet, the "
        "light particles are over-compressed by their heavy neighbours and hold the time "
        "step down (in impacts of a few km/s). A spacing for '%s' at most %.2g times its present one "
        "brings the ratio below %.0f",
        s->body[b].name, mb, list, s->body[b].name, fdown, MASS_RATIO_WARN);
  }
}

/* A body whose lattice cells fill more than this share of its exact volume gets a
 * warning. Its masses ρV/N are then lighter than ρΔ³ and its SPH sums read low by
 * that ratio: an overfilled rod's crater floor trails the exact speed several times
 * further than that of a rod whose lattice fills at most its volume (docs/case-files.md,
 * "bodies", gives the figures; docs/validation.md, "Two short checks", the case). The
 * warning offers the spacing nearest the body's (within ±10 %, in steps of 0.25 %)
 * whose lattice fills COVER_LO to 1. */
#define COVER_WARN 1.02
#define COVER_LO   0.95
#define COVER_SEARCH_MAX                                                                           \
  500000 /* points; larger bodies get no suggestion (up to 80
                                     counts of the lattice) */

static double lattice_cover(const struct body_spec *bs, size_t n)
{
  return (double)n * cell_volume(bs->lattice, bs->spacing) / bs->vol;
}

static void warn_lattice_cover(const struct sim *s, const struct body_spec *bs, int nb)
{
  const int planes = sym_planes(s);
  for (int b = 0; b < nb; b++) {
    /* a fitted gas box's step is not Δ along its fitted axes */
    if (!(bs[b].vol > 0) || bs[b].fit[0] || bs[b].fit[1] || bs[b].fit[2]) continue;
    const double cover = lattice_cover(&bs[b], s->body[b].count);
    if (cover <= COVER_WARN) continue;
    char fix[160] = "a spacing whose lattice fills the shape more closely";
    if (s->body[b].count <= COVER_SEARCH_MAX) {
      struct body_spec t = bs[b];
      for (int k = 1; k <= 40; k++) {
        int found = 0;
        for (int sgn = -1; sgn <= 1 && !found; sgn += 2) {
          t.spacing = bs[b].spacing * (1.0 + sgn * 0.0025 * k);
          const double c = lattice_cover(&t, lattice_points(&t, planes, NULL, 0));
          if (c >= COVER_LO && c <= 1.0) {
            snprintf(fix, sizeof fix, "spacing %.5g mm (its lattice fills %.3f)", 1e3 * t.spacing,
                     c);
            found = 1;
          }
        }
        if (found) break;
      }
    }
    hv_warn("body '%s': its %zu lattice cells of %.5g mm fill %.3f times the shape's volume, "
            "so each particle (mass from the exact volume) is %.1f %% lighter than density "
            "x lattice cell and the SPH sums inside it read low; in a free penetration test, "
            "rods whose lattices filled 1.02-1.12 of their volume had crater floors 3-5 %% "
            "slow (docs/case-files.md, \"bodies\"). "
            "Nearest fit: %s",
            s->body[b].name, s->body[b].count, 1e3 * bs[b].spacing, cover,
            100.0 * (1.0 - 1.0 / cover), fix);
  }
}

/* bodies[i].part_of: NAME joins body i to body NAME: one solid, whose particles interact
 * across the seam as within a body (a plate refined by a disc of finer lattice around
 * the impact point; a target block with a finer core). Chains are followed to their
 * root; s->piece[b] is the root, and sph.piece points at the table once any body is
 * joined (NULL otherwise: every body its own piece, the code path of old). */
static int read_pieces(struct sim *s, struct cfg *c, int nb, struct hv_error *err)
{
  char key[64], where[256];
  int part_of[64], any = 0;
  for (int b = 0; b < nb; b++) {
    s->piece[b] = b;
    part_of[b] = b;
    snprintf(key, sizeof key, "bodies[%d].part_of", b);
    const char *name;
    if (!cfg_has(c, key)) continue;
    if (cfg_get_string(c, key, NULL, &name, err)) return -1;
    int t = -1;
    for (int k = 0; k < nb; k++)
      if (!strcmp(s->body[k].name, name)) t = k;
    if (t < 0 || t == b) {
      char names[1024] = "";
      for (int k = 0; k < nb; k++)
        if (k != b)
          snprintf(names + strlen(names), sizeof names - strlen(names), "%s'%s'",
                   names[0] ? ", " : "", s->body[k].name);
      return hv_error_set(err, HV_EXIT_INPUT,
                          "%s: %s: body '%s': part_of '%s' %s (the other "
                          "bodies: %s)",
                          cfg_where(c, key, where, sizeof where), key, s->body[b].name, name,
                          t == b ? "is the body itself" : "names no body",
                          names[0] ? names : "none");
    }
    if (s->mat[s->body[b].mat].eos == EOS_IDEAL_GAS || s->mat[s->body[t].mat].eos == EOS_IDEAL_GAS)
      return hv_error_set(err, HV_EXIT_INPUT,
                          "%s: %s: body '%s': part_of joins solid bodies; "
                          "'%s' or '%s' is a gas",
                          cfg_where(c, key, where, sizeof where), key, s->body[b].name,
                          s->body[b].name, s->body[t].name);
    part_of[b] = t;
    any = 1;
  }
  for (int b = 0; b < nb; b++) {
    int r = b, hops = 0;
    while (part_of[r] != r && hops <= nb) {
      r = part_of[r];
      hops++;
    }
    if (hops > nb) {
      snprintf(key, sizeof key, "bodies[%d].part_of", b);
      return hv_error_set(err, HV_EXIT_INPUT,
                          "%s: %s: body '%s': part_of goes round in a "
                          "circle",
                          cfg_where(c, key, where, sizeof where), key, s->body[b].name);
    }
    s->piece[b] = r;
  }
  s->sph.piece = any ? s->piece : NULL;
  return 0;
}

/* The particle fields the materials and options need (solid, viscosity switch, crack
 * normals), and the sph options refused that the materials contradict. Returns 0 or -1
 * with err set. */
static int enable_fields(struct sim *s, struct cfg *c, struct hv_error *err)
{
  char where[256];
  /* solid fields are needed once any material has strength or fracture */
  for (int m = 0; m < s->nmat; m++)
    if (s->mat[m].str.enabled || s->mat[m].frac.kind != FRACTURE_NONE)
      particles_enable_solid(&s->p);
  /* each particle's viscosity coefficient and last velocity divergence (the switch) */
  if (s->sph.av_switch) particles_enable_av(&s->p);
  /* each particle's crack normal (fracture.split: crack) */
  for (int m = 0; m < s->nmat; m++)
    if (s->mat[m].frac.kind != FRACTURE_NONE &&
        (s->mat[m].frac.split == SPLIT_CRACK || s->mat[m].frac.energy > 0.0))
      particles_enable_crack(&s->p);
  /* each ring's initial radius (the stretch its h follows, sph.rz_stretch_max) */
  if (s->p.axisym) particles_enable_rings(&s->p);
  if (s->p.axisym && rz_check_materials(s, c, err)) return -1;
  if (s->sph.summation && s->p.solid)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: sph.density: summation is for cases without "
                        "strength or fracture (a free surface of a solid would lose density); "
                        "use continuity",
                        cfg_where(c, "sph.density", where, sizeof where));
  if (s->sph.reconstruct && !s->p.solid)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: sph.viscosity.reconstruct: it acts on pairs of "
                        "particles with strength, and no material here has strength or fracture; "
                        "set it to false",
                        cfg_where(c, "sph.viscosity.reconstruct", where, sizeof where));
  if (s->sph.continuity_mass && s->p.solid)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: sph.continuity: mass is for cases without "
                        "strength or fracture (the solid loops use the volume form, which holds "
                        "at interfaces where density jumps a hundredfold); use volume",
                        cfg_where(c, "sph.continuity", where, sizeof where));
  return 0;
}

/* Body b's particle count (*cnt), refused before any is made when its bounding box is
 * too large to scan or to hold, or when its spacing leaves the shape empty. Returns 0 or
 * -1 with err set. */
static int count_body(struct sim *s, struct cfg *c, const struct body_spec *bs, int b,
                      size_t *cnt_out, struct hv_error *err)
{
  char where[256], key[64];
  snprintf(key, sizeof key, "bodies[%d]", b);
  /* an upper bound first (the bounding box), so that an absurd spacing is refused
     before the lattice is even counted */
  const struct shape *sh = &bs[b].shape;
  double bound = 1.0;
  for (int d = 0; d < 3; d++) bound *= (sh->max[d] - sh->min[d]) / bs[b].spacing + 2.0;
  double est = bs[b].vol > 0 ? bs[b].vol / cell_volume(bs[b].lattice, bs[b].spacing) : bound;
  if (s->p.axisym) est = rz_points_bound(sh, bs[b].spacing); /* rings */
  if (est > 1e8 && check_memory(s, c, b, &bs[b], s->p.n + (size_t)fmin(est, 1e18), err)) return -1;
  double scan = est;
  const size_t cnt =
      s->p.axisym ? (est <= lattice_scan_max() ? rz_lattice(sh, bs[b].spacing, NULL, 0) : SIZE_MAX)
                  : lattice_points_scan(&bs[b], sym_planes(s), NULL, 0, &scan);
  if (cnt == SIZE_MAX) {
    char then[160];
    snprintf(then, sizeof then,
             "spans %.3g lattice points in its bounding box, more than "
             "%.3g to scan",
             scan, lattice_scan_max());
    if (bare_length_error(c, b, &bs[b], s->body[b].name, then, err)) return -1;
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: body '%s': its bounding box, %g x %g x %g m, "
                        "spans %.3g lattice points of %g mm to scan, more than %.3g (64 times the "
                        "particles this machine's memory holds); check the shape's size and units",
                        cfg_where(c, key, where, sizeof where), s->body[b].name,
                        sh->max[0] - sh->min[0], sh->max[1] - sh->min[1], sh->max[2] - sh->min[2],
                        scan, 1e3 * bs[b].spacing, lattice_scan_max());
  }
  if (cnt == 0) {
    /* a bare spacing (metres) wider than the body: `spacing: 0.25` for 0.25 mm */
    char skey[96], hint[256] = "";
    double ext = 0.0;
    for (int d = 0; d < 3; d++) ext = fmax(ext, sh->max[d] - sh->min[d]);
    snprintf(skey, sizeof skey, "%s.spacing", key);
    if (cfg_is_bare(c, skey) && bs[b].spacing > ext)
      snprintf(hint, sizeof hint,
               "; %s is the bare number %g, read as %g m (a number "
               "without a unit is SI): was it %g mm?",
               skey, bs[b].spacing, bs[b].spacing, bs[b].spacing);
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: body '%s': spacing %g m gives no particle inside "
                        "the shape%s",
                        cfg_where(c, key, where, sizeof where), s->body[b].name, bs[b].spacing,
                        hint);
  }
  *cnt_out = cnt;
  return 0;
}

/* Body b's cnt particles made on its lattice, initialised, and its body_info (count,
 * spacing, density, extent) filled; returns the first particle's index. */
static size_t place_body(struct sim *s, const struct body_spec *bs, int b, size_t cnt)
{
  const size_t first = particles_add(&s->p, cnt);
  if (s->p.axisym)
    rz_lattice(&bs[b].shape, bs[b].spacing, &s->p, first);
  else
    lattice_points(&bs[b], sym_planes(s), &s->p, first);
  init_body(s, &bs[b], b, first, cnt);
  struct body_info *bi = &s->body[b];
  bi->count = cnt;
  bi->spacing = bs[b].spacing;
  bi->rho = bs[b].rho;
  for (int d = 0; d < 3; d++) {
    bi->lo[d] = HUGE_VAL;
    bi->hi[d] = -HUGE_VAL;
    for (size_t q = first; q < first + cnt; q++) {
      bi->lo[d] = fmin(bi->lo[d], s->p.x[d][q]);
      bi->hi[d] = fmax(bi->hi[d], s->p.x[d][q]);
    }
    bi->lo[d] -= 0.5 * bs[b].spacing;
    bi->hi[d] += 0.5 * bs[b].spacing;
  }
  return first;
}

int setup_bodies(struct sim *s, struct cfg *c, struct hv_error *err)
{
  char where[256];
  double one = 1.0, resolution;
  if (cfg_get_quantity(c, "resolution", UNIT_NONE, &one, 1e-6, 1e6, &resolution, err)) return -1;
  int nb = cfg_len(c, "bodies");
  if (nb <= 0)
    return hv_error_set(err, HV_EXIT_INPUT, "%s: 'bodies' must be a list of at least one body",
                        cfg_where(c, "bodies", where, sizeof where));
  if (nb > (int)(sizeof s->body / sizeof s->body[0]))
    return hv_error_set(err, HV_EXIT_INPUT, "%s: too many bodies (%d)",
                        cfg_where(c, "bodies", where, sizeof where), nb);
  struct body_spec *bs = hv_calloc((size_t)nb, sizeof *bs, "bodies");
  int rc = 0;
  for (int b = 0; b < nb && !rc; b++) rc = read_body(s, c, b, &bs[b], resolution, err);
  if (!rc) rc = read_pieces(s, c, nb, err);
  if (!rc) rc = enable_fields(s, c, err);
  size_t first_of[64];
  for (int b = 0; b < nb && !rc; b++) {
    size_t cnt;
    if (count_body(s, c, bs, b, &cnt, err) < 0) {
      rc = -1;
      break;
    }
    if (check_memory(s, c, b, &bs[b], s->p.n + cnt, err)) {
      rc = -1;
      break;
    }
    const size_t first = place_body(s, bs, b, cnt);
    first_of[b] = first;
    rc = check_placement(s, c, bs, b, first, cnt, err);
  }
  s->nbody = nb;
  /* (not in an axisymmetric domain: ring masses grow with r, and the lattice covers the
     half-plane, not the volume) */
  if (!rc && !s->p.axisym) warn_mass_ratios(s, first_of, nb);
  if (!rc && !s->p.axisym) warn_lattice_cover(s, bs, nb);
  for (int b = 0; b < nb; b++) shape_free(&bs[b].shape);
  free(bs);
  return rc ? -1 : energy_deposit(s, c, err);
}
