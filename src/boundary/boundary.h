/* boundary.h — faces of the domain: open, periodic, rigid wall, symmetry plane,
 * absorbing.
 *
 * Periodic faces wrap the reals and copy a layer of particles across; walls reflect
 * any real that crossed and mirror a layer of particles as ghosts (position mirrored,
 * normal velocity reversed: a frictionless rigid wall; the shear stresses with one
 * index normal to the wall reversed, so a wall is also a symmetry plane). Ghosts are appended after the
 * reals every step; they carry the fields their source carries, so the SPH loops
 * need no knowledge of boundaries. Dimensions are processed x, y, z in turn and a
 * later dimension also copies earlier ghosts, which fills edges and corners.
 * A symmetry plane is a wall (the mirror is exact for a symmetric flow); it is named
 * separately for clarity, e.g. the z = 0 plane of a half model, or the y = 0 and
 * z = 0 planes of a quarter model (whose corner ghosts, a y ghost mirrored again in z,
 * the order x, y, z makes).
 * Absorbing faces remove the particles that cross them and tally what they carried,
 * so the balances in summary.csv still close.
 */
#ifndef HV_BOUNDARY_H
#define HV_BOUNDARY_H

#include <stdint.h>

#include "core/error.h"
#include "particles/particles.h"

struct cfg; /* boundary_read's case file: boundary.c includes the config layer, this
               header does not (physics headers stay free of it, docs/design.md) */

enum bnd_kind { BND_OPEN = 0, BND_PERIODIC, BND_WALL, BND_SYMMETRY, BND_ABSORBING, BND_KIND_COUNT };
extern const char *const bnd_kind_names[];

/* What absorbing faces removed, summed over the run. */
struct absorbed {
  long n;              /* particles */
  double mass;         /* [kg] */
  double mom[3];       /* [kg m/s] */
  double e_kin, e_int; /* [J] */
};

struct boundary {
  int kind[3][2]; /* [dim][0 = min face, 1 = max face] */
  int half_model; /* bodies cut at z = 0, z_min a symmetry plane (a quarter model too) */
  int axisym;     /* domain.geometry: axisymmetric (particles.h): x the axis, y = r ≥ 0;
                     the axis is the mirror face y_min = 0 (a symmetry plane, made by
                     the code), y_max is the face r_max, z is open */
  int has_box;    /* domain.min/max given */
  /* bodies cut at y = 0 as well, y_min a symmetry plane: domain.symmetry: quarter */
  int quarter_model;
  struct absorbed absorbed;
  double lo[3], hi[3]; /* [m] domain box */
  size_t cap;
  uint32_t *src;    /* [ghost] source slot of each ghost */
  uint8_t *flip;    /* [ghost] shear components reversed by mirrors: bit k for
                            tensor component T_XY + k (xy, yz, xz) */
  uint8_t *side;    /* [ghost] the face (0 min, 1 max) it was made for */
  size_t gstart[4]; /* ghosts made before dimension d's; [3] all of them */
};

void boundary_init(struct boundary *b);
void boundary_free(struct boundary *b);
/* Reads domain.geometry, domain.min, domain.max, domain.boundary.{x,y,z,x_min,...} (in
 * an axisymmetric domain: min/max as (x, r), faces x, x_min, x_max, r, r_max) and the
 * symmetry (domain.symmetry: none, half, quarter; domain.half_model: true is symmetry:
 * half). */
int boundary_read(struct boundary *b, struct cfg *c, struct hv_error *err);
/* The axisymmetric domain (axis.c), after domain.geometry: axisymmetric. */
int boundary_read_axisym(struct boundary *b, struct cfg *c, struct hv_error *err);
/* 1 if any face is not open. */
int boundary_any(const struct boundary *b);
/* Wraps reals through periodic faces and reflects those that crossed a wall. */
void boundary_apply(const struct boundary *b, struct particles *p);
/* Removes the reals beyond absorbing faces, adding what they carried to b->absorbed.
 * Returns the number removed. */
size_t boundary_absorb(struct boundary *b, struct particles *p);
/* Rebuilds the ghosts within `width` of the faces. Returns -1 (msg) if a periodic
 * dimension is shorter than 2 × width (ghosts would overlap their sources). */
int boundary_make_ghosts(struct boundary *b, struct particles *p, double width, char *msg,
                         size_t msglen);
/* Copies the fields that change during a step (rho, p, cs, e; S and R with the
 * mirrors' sign changes) from sources to ghosts. */
void boundary_refresh_ghosts(const struct boundary *b, struct particles *p);
/* The same for a 3×3 velocity gradient per slot, G[9 slot + 3a + b] = ∂v_a/∂x_b
 * (sph.viscosity.reconstruct): ghosts take their source's, mirrored. */
void boundary_refresh_gradv(const struct boundary *b, size_t n, size_t n_ghost, double *G);

#endif
