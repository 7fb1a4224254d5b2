/* setup.h — bodies: shapes filled with particles on a lattice, and initial fields. */
#ifndef HV_SETUP_H
#define HV_SETUP_H

#include "run/sim.h"

/* Reads `bodies` (and `energy_deposit`) and creates the particles. */
int setup_bodies(struct sim *s, struct cfg *c, struct hv_error *err);

/* Shapes. */
enum shape_kind { SHAPE_BOX = 0, SHAPE_SPHERE, SHAPE_KIND_COUNT };
struct shape {
  enum shape_kind kind;
  double min[3], max[3];   /* [m] box; bounding box for every shape */
  double center[3];        /* [m] sphere */
  double radius;           /* [m] sphere */
};
int shape_read(struct shape *sh, struct cfg *c, const char *path, struct hv_error *err);
int shape_contains(const struct shape *sh, const double x[3]);
double shape_volume(const struct shape *sh);   /* [m3] exact */

#endif
