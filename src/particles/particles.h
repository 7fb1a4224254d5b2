/* particles.h — the particle store: structure of arrays, declared once.
 *
 * Every field is listed once below (X-macros). The lists drive the struct, the
 * allocation and growth, reordering, ghost copies, output and restart; adding a
 * field is one line. Real particles occupy [0, n); boundary ghosts follow in
 * [n, n + n_ghost) and are rebuilt every step.
 *
 * Columns: C type, name, SI unit, flags, description.
 *   PF_OUT     written to particle snapshots (VTU/CSV)
 *   PF_GHOST   copied from the parent when a ghost is made
 *   PF_STATE   part of the physical state (checkpoint/restart, MPI migration)
 *   PF_SOLID   allocated only when some material has strength or fracture
 *   PF_AV      allocated only with the viscosity switch (sph.viscosity.switch)
 *   PF_CRACK   allocated only when a material splits along cracks (fracture.split: crack)
 *   PF_RING    allocated only in an axisymmetric run (domain.geometry: axisymmetric)
 * Tensors are symmetric, 6 components in VTK's order: xx, yy, zz, xy, yz, xz.
 */
#ifndef HV_PARTICLES_H
#define HV_PARTICLES_H

#include <stddef.h>
#include <stdint.h>

enum {
  PF_OUT = 1u << 0,
  PF_GHOST = 1u << 1,
  PF_STATE = 1u << 2,
  PF_SOLID = 1u << 3,
  PF_AV = 1u << 4,
  PF_CRACK = 1u << 5,
  PF_RING = 1u << 6,
};

/* Components of a symmetric tensor (VTK order). */
enum { T_XX = 0, T_YY, T_ZZ, T_XY, T_YZ, T_XZ };

/* Scalars */
#define HV_PARTICLE_SCALARS(X)                                                                                            \
  X(int64_t, id, "", PF_OUT | PF_GHOST | PF_STATE, "particle identifier")                                                 \
  X(int32_t, mat, "", PF_OUT | PF_GHOST | PF_STATE, "material index")                                                     \
  X(int32_t, body, "", PF_OUT | PF_GHOST | PF_STATE, "body index")                                                        \
  X(double, m, "kg", PF_OUT | PF_GHOST | PF_STATE, "mass")                                                                \
  X(double, h, "m", PF_OUT | PF_GHOST | PF_STATE, "smoothing length")                                                     \
  X(double, rho, "kg/m3", PF_OUT | PF_GHOST | PF_STATE, "density")                                                        \
  X(double, e, "J/kg", PF_OUT | PF_GHOST | PF_STATE, "specific internal energy")                                          \
  X(double, p, "Pa", PF_OUT | PF_GHOST | PF_STATE, "pressure")                                                            \
  X(double, cs, "m/s", PF_OUT | PF_GHOST | PF_STATE, "sound speed")                                                       \
  X(double, drho, "kg/m3/s", 0, "density rate")                                                                           \
  X(double, de, "J/kg/s", PF_STATE, "energy rate (the predictor's)")                                                      \
  X(double, rho0, "kg/m3", 0, "density at step start")                                                                    \
  X(double, e0, "J/kg", 0, "energy at step start")                                                                        \
  X(double, vsig, "m/s", 0, "largest signal speed")                                                                       \
  X(double, vol, "m3", 0, "m/rho (per pass, all slots)")                                                                  \
  X(double, pr2, "m5/kg/s2", 0, "p/rho^2 (per pass, all slots)")                                                          \
  X(double, eps_p, "", PF_OUT | PF_STATE | PF_SOLID, "equivalent plastic strain")                                         \
  X(double, damage, "", PF_OUT | PF_STATE | PF_SOLID,                                                                     \
    "damage: 0-1 while intact (cumulative) or opening (fracture.energy); 1 split; 2 split again (fracture.split: crack)") \
  X(int32_t, fstate, "", PF_STATE | PF_SOLID,                                                                             \
    "fracture state (enum fracture_state, fracture.h); kept out of the snapshots, which show it in damage")               \
  X(double, alpha, "", PF_OUT | PF_GHOST | PF_STATE | PF_AV, "viscosity coefficient (switch)")                            \
  X(double, divv, "1/s", PF_STATE | PF_AV, "velocity divergence at the last mid-step")                                    \
  X(double, eps_c, "", PF_OUT | PF_STATE | PF_CRACK,                                                                      \
    "crack opening strain (fracture.split: crack, fracture.energy)")                                                      \
  X(double, r0, "m", PF_STATE | PF_RING, "radius the ring was made at (sph.rz_stretch_max)")                              \
  X(double, dt, "s", PF_OUT, "time step the particle allows (CFL, acceleration, wall approach)")

/* Vectors (3 components: name[0..2]) */
#define HV_PARTICLE_VECTORS(X)                                                                     \
  X(double, x, "m", PF_OUT | PF_GHOST | PF_STATE, "position")                                      \
  X(double, v, "m/s", PF_OUT | PF_GHOST | PF_STATE, "velocity")                                    \
  X(double, a, "m/s2", PF_STATE, "acceleration (last step)")                                       \
  X(double, v0, "m/s", 0, "velocity at step start")                                                \
  X(double, crack, "", PF_OUT | PF_STATE | PF_CRACK,                                               \
    "crack normal (fracture.split: crack, fracture.energy; 0: none)")

/* Symmetric tensors (6 components: name[0..5], order T_XX ... T_XZ) */
#define HV_PARTICLE_TENSORS(X)                                                                     \
  X(double, S, "Pa", PF_OUT | PF_GHOST | PF_STATE | PF_SOLID, "deviatoric stress")                 \
  X(double, S1, "Pa", PF_SOLID, "deviatoric stress at step end")                                   \
  X(double, R, "Pa", PF_GHOST | PF_SOLID, "artificial stress (Monaghan 2000)")

enum pf_type { PF_INT32, PF_INT64, PF_DOUBLE };

struct particles {
  int solid;      /* the PF_SOLID fields are allocated */
  int av;         /* the PF_AV fields are allocated */
  int cracks;     /* the PF_CRACK fields are allocated */
  int rings;      /* the PF_RING fields are allocated */
  int axisym;     /* axisymmetric (domain.geometry: axisymmetric): x is the axis, y the
                     radius r >= 0, z = 0 and v_z = 0 for every particle; m is the ring's
                     (the true 3D) mass, rho the true density; tensor component zz is
                     the hoop (theta-theta) one, xy the axial-radial shear, yz = xz = 0;
                     2 while the SPH loops run on area masses (src/sph/sph_rz.c) */
  size_t n;       /* real particles */
  size_t n_ghost; /* ghosts after the reals */
  size_t cap;     /* allocated length of every array */
  size_t touched; /* slots [0, touched) are initialised in every allocated array; the
                      rest of the capacity is never written, so it costs address space
                      but no memory */
#define HV_X(type, name, unit, flags, desc) type *name;
  HV_PARTICLE_SCALARS(HV_X)
#undef HV_X
#define HV_X(type, name, unit, flags, desc) type *name[3];
  HV_PARTICLE_VECTORS(HV_X)
#undef HV_X
#define HV_X(type, name, unit, flags, desc) type *name[6];
  HV_PARTICLE_TENSORS(HV_X)
#undef HV_X
};

/* A uniform view of one field, for generic loops (output, reorder, copy). */
struct pfield {
  const char *name, *unit, *desc;
  enum pf_type type;
  int ncomp; /* 1, 3 or 6 */
  unsigned flags;
  void *comp[6]; /* component arrays */
};

#define HV_MAX_FIELDS 64
/* Fills `out` (at least HV_MAX_FIELDS entries) with every allocated field (every field
 * if p is NULL); returns the count. */
int particles_fields(struct particles *p, struct pfield *out);
/* Every field, allocated or not (unallocated PF_SOLID fields have NULL components);
 * the indices are the same for every store. */
int particles_fields_all(struct particles *p, struct pfield *out);
size_t pf_type_size(enum pf_type t);
/* Bytes of particle storage per slot (sum over the fields allocated in p; the base
 * fields when p is NULL). */
size_t particles_bytes_per_particle(const struct particles *p);

void particles_init(struct particles *p);
/* Allocates the PF_SOLID fields (zeroed) from now on. */
void particles_enable_solid(struct particles *p);
/* Allocates the PF_AV fields (zeroed) from now on. */
void particles_enable_av(struct particles *p);
/* Allocates the PF_CRACK fields (zeroed) from now on. */
void particles_enable_crack(struct particles *p);
/* Allocates the PF_RING fields (zeroed) from now on. */
void particles_enable_rings(struct particles *p);
void particles_free(struct particles *p);
/* Ensures capacity for `cap` slots (reals + ghosts); contents kept. */
void particles_reserve(struct particles *p, size_t cap);
/* Zeroes slot `slot` in every allocated array if it has not been used before (ghost
 * slots: their non-ghost fields are then defined, though never read). */
void particles_touch(struct particles *p, size_t slot);
/* Appends `count` zeroed real particles (drops ghosts); returns the first index. */
size_t particles_add(struct particles *p, size_t count);
/* Copies every field of slot src into slot dst (either may be a ghost slot). */
void particles_copy(struct particles *p, size_t dst, size_t src, unsigned flags_mask);
/* Copies the fields with a flag in flags_mask of slots src[0..count) into dst, dst + 1,
 * …, in parallel: no src[k] may lie in [dst, dst + count), and those slots must be
 * reserved and touched. */
void particles_copy_many(struct particles *p, size_t dst, const uint32_t *src, size_t count,
                         unsigned flags_mask);
/* Reorders the reals: new slot k takes old slot order[k]. `order` is a permutation of [0, n). */
void particles_permute(struct particles *p, const uint32_t *order);
/* Removes the reals with remove[i] != 0, keeping the others' order; returns the count removed. */
size_t particles_remove(struct particles *p, const unsigned char *remove);

#endif
