/* setup.h — bodies: shapes filled with particles on a lattice, and initial fields. */
#ifndef HV_SETUP_H
#define HV_SETUP_H

#include "sim/sim.h"

/* Reads `bodies` (and `energy_deposit`) and creates the particles. */
int setup_bodies(struct sim *s, struct cfg *c, struct hv_error *err);

/* Shapes (shapes.c). */
enum shape_kind { SHAPE_BOX = 0, SHAPE_SPHERE, SHAPE_CYLINDER, SHAPE_KIND_COUNT };
struct shape {
  enum shape_kind kind;
  double min[3], max[3]; /* [m] box; bounding box for every shape */
  double center[3];      /* [m] sphere, cylinder (mid-point of the axis), box centre */
  double radius;         /* [m] sphere, cylinder */
  double axis[3];        /* [-] cylinder: unit vector */
  double length;         /* [m] cylinder */
  struct shape *minus;   /* shapes subtracted from this one */
  int nminus;
};
int shape_read(struct shape *sh, struct cfg *c, const char *path, struct hv_error *err);
void shape_free(struct shape *sh);
int shape_contains(const struct shape *sh, const double x[3]);
/* [m3] exact volume, or -1 when subtractions make it unknown. */
double shape_volume(const struct shape *sh);

#endif
