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

/* Axisymmetric set-up (rz.c; domain.geometry: axisymmetric). */
/* Refuses a body that is not a shape of revolution about x, an hcp lattice, or a
 * velocity off the axis, naming the key. */
int rz_check_body(struct cfg *c, const char *path, const char *name, const struct shape *sh,
                  int hcp, const double vel[3], struct hv_error *err);
/* The rings of a shape on the half-plane's square lattice of spacing d: counts them, and
 * stores (x, r, 0) at p->x[.][first + k] when p is not NULL. */
size_t rz_lattice(const struct shape *sh, double d, struct particles *p, size_t first);
/* An upper bound on the points rz_lattice scans. */
double rz_points_bound(const struct shape *sh, double d);
/* The coarsest spacing that gives at least n rings. */
double rz_spacing_for_count(const struct shape *sh, double n);
/* Ring masses 2π r ρ d² (scaled to the exact volume vol when vol > 0) and h. */
void rz_ring_masses(struct particles *p, size_t first, size_t cnt, double rho, double vol, double d,
                    double eta);
/* Refuses the materials' 3D-only options (crack planes). */
int rz_check_materials(struct sim *s, struct cfg *c, struct hv_error *err);

#endif
