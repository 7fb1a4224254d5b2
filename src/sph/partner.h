/* partner.h — internal to src/sph: the solid force pass's partner records, and the
 * piece of a body.
 */
#ifndef HV_SPH_PARTNER_H
#define HV_SPH_PARTNER_H

#include "material/material.h"
#include "neighbours/grid.h"
#include "sph/sph.h"

/* A partner's record in the force pass: each particle's data as a partner (ghosts
 * included) in three cache lines, read together for every pair instead of from 20
 * arrays: x, y, z, h, v, m, then p/ρ², S/ρ² (computed once instead of once per pair:
 * the same operations, so the same bits) and ρ; a third line with the artificial stress
 * R, the sound speed c and the kind, 2 × tag + 1 for a gas (an integer held exactly in
 * a double). Kept in the cache between steps. */
enum {
  PR_X = 0,
  PR_H = 3,
  PR_V = 4,
  PR_M = 7,
  PR_P = 8,
  PR_S = 9,
  PR_RHO = 15,
  PR_AS = 16, /* the artificial stress R, 6 doubles */
  PR_C = 22,
  PR_KIND = 23,
  PR_LEN = SPH_PARTNER_LEN
};

/* The first pass's density record of a slot, in the first line of its partner record
 * (the force pass packs the partner records afresh): v, its volume m/ρ (one division
 * per slot instead of one per pair: the same operation, so the same bits), ρ, 2m/ρ₀
 * (ρ₀ its material's reference density), its kind (4 × piece, + 2 below ρ₀/2, + 1 for
 * a gas) and its material's index (integers held exactly in doubles): the neighbour's
 * side of the continuity sum and of L read from one line instead of from eight
 * arrays. */
enum { DR_V = 0, DR_VOL = 3, DR_RHO = 4, DR_WREF = 5, DR_KIND = 6, DR_MAT = 7 };

/* The piece of body b (bodies[i].part_of; every body its own without a table). */
static inline int32_t sph_piece_of(const int32_t *piece, int32_t b) { return piece ? piece[b] : b; }

/* The partner records and tags for nt slots: the cache's, grown when short, or (a
 * call without a cache) allocated for the caller to free. */
void partner_reserve(struct sph_cache *cache, size_t nt, double **rec, int32_t **tag);
/* Packs every slot's partner record and its tag, piece × 2 + 1 when R ≠ 0. */
void partner_pack(const struct particles *p, const struct sph_params *sp,
                  const struct material *mat, double *restrict rec, int32_t *restrict tag);
/* Packs the density records of the slots of grid g that the first pass reads (all, or
 * with sph.skip_resting's marks rest those next to a cell it does not skip) into rec. */
void partner_pack_density(const struct particles *p, const struct sph_params *sp,
                          const struct material *mat, const struct nbr_grid *g, const uint8_t *rest,
                          double *restrict rec);

#endif
