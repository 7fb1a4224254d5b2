/* fof.h — fragments by friends-of-friends (FoF).
 *
 * Definition (docs/measurements.md, "Fragments"): two selected particles are
 * friends when they lie closer than the linking length b, r_ij < b (with
 * per-particle lengths: r_ij < (b_i + b_j)/2); a fragment is a maximal set of
 * particles joined by chains of friends. In the paper's sense a fragment is a
 * cloud of material, so the link is purely geometric: damage does not cut links
 * (a fractured but still touching piece is one fragment until its parts separate
 * by more than b). To count only some material, pass a mask.
 *
 * Linking length: the documented default is b = FOF_B_FACTOR × the initial
 * lattice spacing of the body (1.5 Δ: on a cubic lattice this joins face and edge
 * neighbours, √2 Δ, but not the body diagonal, √3 Δ; on hcp it joins the 12
 * nearest neighbours at Δ). The caller passes b.
 *
 * Half models (only z >= 0 simulated, symmetry plane z = 0): a fragment with a
 * particle at z_i < b_i/2 is a friend of its own mirror image, so in the full
 * picture it is one fragment of twice the mass, centred on the plane (z = 0,
 * v_z = 0): multiplicity 1. Any other fragment has a separate mirror twin:
 * multiplicity 2, and its values are those of one of the pair. Masses are full
 * masses (of one fragment of the full picture).
 *
 * Determinism: union-find where the root of every set is its smallest particle
 * index; the result does not depend on the thread count or the grid's cell order.
 * Fragments are sorted by (full) mass, largest first, ties by smallest index.
 * Cost O(N): candidates come from the Morton cell grid (neighbours/grid.h) built
 * with h_i = b_i/2, so that the grid's pair test r < h_i + h_j is r < b.
 */
#ifndef HV_FOF_H
#define HV_FOF_H

#include <stddef.h>
#include <stdint.h>

#include "core/error.h"
#include "particles/particles.h"

#define FOF_B_FACTOR 1.5 /* documented default: b = 1.5 × initial lattice spacing */

struct fof_params {
  double b;                  /* [m] linking length (> 0); used when b_particle is NULL */
  const double *b_particle;  /* optional [p->n] per-particle linking length [m]: i, j link
                                 when r < (b_i + b_j)/2; NULL: b for every particle */
  const unsigned char *mask; /* optional [p->n]: only particles with mask[i] != 0 take part;
                                 NULL: every real particle */
  int nmat;                  /* materials 0 .. nmat-1 get a mass column (others are in m only) */
  int half_model;            /* 1: only z >= 0 is simulated; report the mirrored full picture */
  int quarter_model;         /* 1: only y >= 0, z >= 0 (half_model set too); the same */
};

struct fof_fragment {
  double m;         /* [kg] mass of the fragment (full picture; see multiplicity) */
  double x[3];      /* [m] centre of mass */
  double v[3];      /* [m/s] mass-weighted mean velocity (momentum / mass) */
  size_t count;     /* simulated particles in it (the half model's particles: a quarter
                       model's fragment on y = 0 counts its image's there too) */
  size_t root;      /* smallest particle slot in it */
  int64_t root_id;  /* id of that particle */
  int multiplicity; /* fragments of the full picture it stands for: 1, 2 (mirror twin) or 4
                       (a quarter model's fragment clear of both planes) */
};

struct fof_result {
  size_t nfrag;              /* fragments among the simulated particles */
  struct fof_fragment *frag; /* [nfrag] largest mass first */
  int nmat;                  /* material columns */
  double *mat_mass;          /* [nfrag * nmat] [kg] mass of material k in fragment f at
                                 mat_mass[f * nmat + k] (full picture, like m) */
  int32_t *group;            /* [n] fragment of each particle (index into frag), -1: not taken */
  size_t n;                  /* length of group (p->n at the call) */
  size_t n_skipped;          /* selected particles with a non-finite position (left out) */
  size_t n_full;             /* fragments of the full picture: sum of multiplicities */
  double m_total;            /* [kg] mass of all fragments of the full picture */
  double b;                  /* [m] linking length used (params.b, or the largest b_i) */
};

void fof_result_init(struct fof_result *r);
void fof_result_free(struct fof_result *r);

/* Finds the fragments of the selected real particles [0, p->n). Returns 0, or -1 with
 * err set (HV_EXIT_RUN) when the particles span more than 2^21 linking lengths in a
 * direction, or (HV_EXIT_INPUT) for a bad linking length. `out` is overwritten
 * (fof_result_free it before reuse, or pass one fresh from fof_result_init). */
int fof_find(const struct particles *p, const struct fof_params *par, struct fof_result *out,
             struct hv_error *err);

/* Number of fragments of the full picture made of at least nmin simulated particles
 * (mirror twins count twice). */
size_t fof_count_min(const struct fof_result *r, size_t nmin);

/* Writes fragments_NNNNN.csv (the caller names the file) through io_write_table_csv:
 * one row per fragment of the simulated half, largest first, columns
 *   rank,mass,multiplicity,count,x,y,z,vx,vy,vz,root_id,m_<material>...
 * rank 0-based; mass [kg] (full picture, one fragment); multiplicity 1 or 2; count
 * simulated particles; x,y,z [m] centre of mass; vx,vy,vz [m/s]; root_id the id of
 * its smallest-slot particle; one m_<name> [kg] column per material 0..nmat-1
 * (material_names[k], or "mat<k>" where names are NULL). `comment` (may be NULL) is
 * written as "# " lines first, followed by a line giving time [s] and b [m]. */
int fof_write_csv(const char *path, const struct fof_result *r, double time,
                  const char *const *material_names, const char *comment, struct hv_error *err);

#endif
