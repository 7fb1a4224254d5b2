/* shapes.c — geometric bodies: reading, inside test, exact volume. */
#include <math.h>
#include <stdio.h>

#include "kernel/kernel.h"
#include "setup/setup.h"

static const char *const shape_names[] = {"box", "sphere", NULL};

int shape_read(struct shape *sh, struct cfg *c, const char *path, struct hv_error *err)
{
  char key[256], where[256];
  int kind;
  snprintf(key, sizeof key, "%s.type", path);
  if (cfg_get_choice(c, key, NULL, shape_names, &kind, err)) return -1;
  sh->kind = (enum shape_kind)kind;
  switch (sh->kind) {
  case SHAPE_BOX:
    snprintf(key, sizeof key, "%s.min", path);
    if (cfg_get_vec3(c, key, UNIT_LENGTH, NULL, sh->min, err)) return -1;
    snprintf(key, sizeof key, "%s.max", path);
    if (cfg_get_vec3(c, key, UNIT_LENGTH, NULL, sh->max, err)) return -1;
    for (int d = 0; d < 3; d++)
      if (!(sh->max[d] > sh->min[d]))
        return hv_error_set(err, HV_EXIT_INPUT, "%s: %s: max must exceed min in %c",
                            cfg_where(c, key, where, sizeof where), key, "xyz"[d]);
    break;
  case SHAPE_SPHERE:
    snprintf(key, sizeof key, "%s.center", path);
    if (cfg_get_vec3(c, key, UNIT_LENGTH, NULL, sh->center, err)) return -1;
    snprintf(key, sizeof key, "%s.radius", path);
    if (cfg_get_quantity(c, key, UNIT_LENGTH, NULL, 1e-300, HUGE_VAL, &sh->radius, err))
      return -1;
    for (int d = 0; d < 3; d++) {
      sh->min[d] = sh->center[d] - sh->radius;
      sh->max[d] = sh->center[d] + sh->radius;
    }
    break;
  case SHAPE_KIND_COUNT: break;
  }
  if (sh->kind == SHAPE_BOX)
    for (int d = 0; d < 3; d++) sh->center[d] = 0.5 * (sh->min[d] + sh->max[d]);
  return 0;
}

int shape_contains(const struct shape *sh, const double x[3])
{
  switch (sh->kind) {
  case SHAPE_BOX:
    return x[0] >= sh->min[0] && x[0] < sh->max[0] && x[1] >= sh->min[1] &&
           x[1] < sh->max[1] && x[2] >= sh->min[2] && x[2] < sh->max[2];
  case SHAPE_SPHERE: {
    double dx = x[0] - sh->center[0], dy = x[1] - sh->center[1], dz = x[2] - sh->center[2];
    return dx * dx + dy * dy + dz * dz < sh->radius * sh->radius;
  }
  case SHAPE_KIND_COUNT: break;
  }
  return 0;
}

double shape_volume(const struct shape *sh)
{
  switch (sh->kind) {
  case SHAPE_BOX:
    return (sh->max[0] - sh->min[0]) * (sh->max[1] - sh->min[1]) * (sh->max[2] - sh->min[2]);
  case SHAPE_SPHERE: return 4.0 / 3.0 * HV_KERNEL_PI * sh->radius * sh->radius * sh->radius;
  case SHAPE_KIND_COUNT: break;
  }
  return 0.0;
}
