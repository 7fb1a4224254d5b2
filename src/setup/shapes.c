/* shapes.c — geometric bodies: reading, inside test, exact volume.
 *
 * box {min, max}; sphere {center, radius}; cylinder {center (mid-point of the
 * axis), axis (any direction), radius, length}; any shape may subtract others:
 * `minus: [shape, ...]` (a hollow vessel is a cylinder minus a smaller one). The
 * exact volume of a shape with subtractions is known when each subtracted shape lies
 * inside it (any shape inside a box, a box inside a box, a coaxial cylinder inside a
 * cylinder) and they do not overlap each other (checked on bounding boxes); otherwise
 * shape_volume() returns -1 and the caller falls back to the lattice volume.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "config/config.h"
#include "kernel/kernel.h"
#include "setup/setup.h"

static const char *const shape_names[] = {"box", "sphere", "cylinder", NULL};

static int read_box(struct shape *sh, struct cfg *c, const char *path, struct hv_error *err)
{
  char key[256], where[256];
  snprintf(key, sizeof key, "%s.min", path);
  if (cfg_get_vec3(c, key, UNIT_LENGTH, NULL, sh->min, err)) return -1;
  snprintf(key, sizeof key, "%s.max", path);
  if (cfg_get_vec3(c, key, UNIT_LENGTH, NULL, sh->max, err)) return -1;
  for (int d = 0; d < 3; d++) {
    if (!(sh->max[d] > sh->min[d]))
      return hv_error_set(err, HV_EXIT_INPUT, "%s: %s: max must exceed min in %c",
                          cfg_where(c, key, where, sizeof where), key, "xyz"[d]);
    sh->center[d] = 0.5 * (sh->min[d] + sh->max[d]);
  }
  return 0;
}

static int read_sphere(struct shape *sh, struct cfg *c, const char *path, struct hv_error *err)
{
  char key[256];
  snprintf(key, sizeof key, "%s.center", path);
  if (cfg_get_vec3(c, key, UNIT_LENGTH, NULL, sh->center, err)) return -1;
  snprintf(key, sizeof key, "%s.radius", path);
  if (cfg_get_quantity(c, key, UNIT_LENGTH, NULL, DBL_MIN, HUGE_VAL, &sh->radius, err)) return -1;
  for (int d = 0; d < 3; d++) {
    sh->min[d] = sh->center[d] - sh->radius;
    sh->max[d] = sh->center[d] + sh->radius;
  }
  return 0;
}

static int read_cylinder(struct shape *sh, struct cfg *c, const char *path, struct hv_error *err)
{
  char key[256], where[256];
  const double xaxis[3] = {1, 0, 0};
  snprintf(key, sizeof key, "%s.center", path);
  if (cfg_get_vec3(c, key, UNIT_LENGTH, NULL, sh->center, err)) return -1;
  snprintf(key, sizeof key, "%s.axis", path);
  if (cfg_get_vec3(c, key, UNIT_NONE, xaxis, sh->axis, err)) return -1;
  double na =
      sqrt(sh->axis[0] * sh->axis[0] + sh->axis[1] * sh->axis[1] + sh->axis[2] * sh->axis[2]);
  if (!(na > 0))
    return hv_error_set(err, HV_EXIT_INPUT, "%s: %s: the axis must not be zero",
                        cfg_where(c, key, where, sizeof where), key);
  for (int d = 0; d < 3; d++) sh->axis[d] /= na;
  snprintf(key, sizeof key, "%s.radius", path);
  if (cfg_get_quantity(c, key, UNIT_LENGTH, NULL, DBL_MIN, HUGE_VAL, &sh->radius, err)) return -1;
  snprintf(key, sizeof key, "%s.length", path);
  if (cfg_get_quantity(c, key, UNIT_LENGTH, NULL, DBL_MIN, HUGE_VAL, &sh->length, err)) return -1;
  for (int d = 0; d < 3; d++) { /* bounding box of the two end discs */
    double a = sh->axis[d], half = 0.5 * sh->length * fabs(a);
    double rad = sh->radius * sqrt(fmax(0.0, 1.0 - a * a));
    sh->min[d] = sh->center[d] - half - rad;
    sh->max[d] = sh->center[d] + half + rad;
  }
  return 0;
}

int shape_read(struct shape *sh, struct cfg *c, const char *path, struct hv_error *err)
{
  char key[256];
  int kind;
  memset(sh, 0, sizeof *sh);
  snprintf(key, sizeof key, "%s.type", path);
  if (cfg_get_choice(c, key, NULL, shape_names, &kind, err)) return -1;
  sh->kind = (enum shape_kind)kind;
  int rc = sh->kind == SHAPE_BOX      ? read_box(sh, c, path, err)
           : sh->kind == SHAPE_SPHERE ? read_sphere(sh, c, path, err)
                                      : read_cylinder(sh, c, path, err);
  if (rc) return -1;
  snprintf(key, sizeof key, "%s.minus", path);
  int nm = cfg_len(c, key);
  if (cfg_has(c, key) && nm <= 0) {
    char where[256];
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: %s: expected a list of one or more shapes "
                        "(minus: [{type: ...}, ...])",
                        cfg_where(c, key, where, sizeof where), key);
  }
  if (nm > 0) {
    sh->minus = hv_calloc((size_t)nm, sizeof *sh->minus, "shape");
    sh->nminus = nm;
    for (int k = 0; k < nm; k++) {
      snprintf(key, sizeof key, "%s.minus[%d]", path, k);
      if (shape_read(&sh->minus[k], c, key, err)) return -1;
    }
  }
  return 0;
}

void shape_free(struct shape *sh)
{
  for (int k = 0; k < sh->nminus; k++) shape_free(&sh->minus[k]);
  free(sh->minus);
  sh->minus = NULL;
  sh->nminus = 0;
}

/* Position of x along a cylinder's axis from its centre (*t) and the squared distance
 * from the axis line (returned; |r|² − t², as the inside test has always computed it). */
static double axis_coords(const struct shape *cyl, const double x[3], double *t)
{
  const double r[3] = {x[0] - cyl->center[0], x[1] - cyl->center[1], x[2] - cyl->center[2]};
  *t = r[0] * cyl->axis[0] + r[1] * cyl->axis[1] + r[2] * cyl->axis[2];
  return r[0] * r[0] + r[1] * r[1] + r[2] * r[2] - *t * *t;
}

static int contains_primitive(const struct shape *sh, const double x[3])
{
  double r[3] = {x[0] - sh->center[0], x[1] - sh->center[1], x[2] - sh->center[2]};
  switch (sh->kind) {
  case SHAPE_BOX:
    return x[0] >= sh->min[0] && x[0] < sh->max[0] && x[1] >= sh->min[1] && x[1] < sh->max[1] &&
           x[2] >= sh->min[2] && x[2] < sh->max[2];
  case SHAPE_SPHERE: return r[0] * r[0] + r[1] * r[1] + r[2] * r[2] < sh->radius * sh->radius;
  case SHAPE_CYLINDER: {
    double t;
    const double q2 = axis_coords(sh, x, &t);
    if (fabs(t) >= 0.5 * sh->length) return 0;
    return q2 < sh->radius * sh->radius;
  }
  case SHAPE_KIND_COUNT: break;
  }
  return 0;
}

int shape_contains(const struct shape *sh, const double x[3])
{
  if (!contains_primitive(sh, x)) return 0;
  for (int k = 0; k < sh->nminus; k++)
    if (shape_contains(&sh->minus[k], x)) return 0;
  return 1;
}

/* in's bounding box inside out's, to rounding (1e-9 of out's size: a disc through a
 * plate's whole thickness, given by its centre and length, ends on the plate's faces
 * only to the last bits) */
static int box_inside(const struct shape *in, const struct shape *out)
{
  double size = 0.0;
  for (int d = 0; d < 3; d++) size = fmax(size, out->max[d] - out->min[d]);
  const double tol = 1e-9 * size;
  for (int d = 0; d < 3; d++)
    if (in->min[d] < out->min[d] - tol || in->max[d] > out->max[d] + tol) return 0;
  return 1;
}

static int boxes_overlap(const struct shape *a, const struct shape *b)
{
  for (int d = 0; d < 3; d++)
    if (a->max[d] <= b->min[d] || b->max[d] <= a->min[d]) return 0;
  return 1;
}

double shape_volume(const struct shape *sh)
{
  double v = 0.0;
  switch (sh->kind) {
  case SHAPE_BOX:
    v = (sh->max[0] - sh->min[0]) * (sh->max[1] - sh->min[1]) * (sh->max[2] - sh->min[2]);
    break;
  case SHAPE_SPHERE: v = 4.0 / 3.0 * HV_KERNEL_PI * sh->radius * sh->radius * sh->radius; break;
  case SHAPE_CYLINDER: v = HV_KERNEL_PI * sh->radius * sh->radius * sh->length; break;
  case SHAPE_KIND_COUNT: break;
  }
  for (int k = 0; k < sh->nminus; k++) {
    /* exact only for a subtraction inside the primitive (any shape whose bounding box
       is inside a box is inside it; a parallel cylinder that fits inside a cylinder;
       otherwise bounding boxes are only a necessary condition, so be conservative) */
    const struct shape *m = &sh->minus[k];
    const int in_box = box_inside(m, sh);
    int inside = in_box && sh->kind == SHAPE_BOX;
    if (in_box && sh->kind == SHAPE_CYLINDER && m->kind == SHAPE_CYLINDER &&
        fabs(sh->axis[0] * m->axis[0] + sh->axis[1] * m->axis[1] + sh->axis[2] * m->axis[2]) >
            1 - 1e-12) { /* parallel: inside when its centre's offset and extent fit */
      double tm;
      const double off = sqrt(fmax(axis_coords(sh, m->center, &tm), 0.0));
      const double tol = 1e-12 * (sh->radius + sh->length);
      inside = off + m->radius <= sh->radius + tol &&
               fabs(tm) + 0.5 * m->length <= 0.5 * sh->length + tol;
    }
    for (int j = 0; j < k; j++) inside = inside && !boxes_overlap(m, &sh->minus[j]);
    double vm = shape_volume(m);
    if (!inside || vm < 0) return -1.0;
    v -= vm;
  }
  return v;
}
