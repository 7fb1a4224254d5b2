/* partner.h — internal to src/sph: the solid force pass's partner records, and the
 * piece of a body.
 */
#ifndef HV_SPH_PARTNER_H
#define HV_SPH_PARTNER_H

#include "material/material.h"
#include "sph/sph.h"

/* A partner's record in the force pass: each particle's data as a partner (ghosts
 * included) in two cache lines, read together for every pair instead of from 17 arrays:
 * x, y, z, h, v, m, then p/ρ², S/ρ² (computed once instead of once per pair: the same
 * operations, so the same bits) and ρ; a third line with the artificial stress R, read
 * only when a pair has one (the tag's bit 0). Kept in the cache between steps. */
enum {
  PR_X = 0,
  PR_H = 3,
  PR_V = 4,
  PR_M = 7,
  PR_P = 8,
  PR_S = 9,
  PR_RHO = 15,
  PR_AS = 16, /* the artificial stress R, 6 doubles and 2 of padding */
  PR_LEN = SPH_PARTNER_LEN
};

/* The piece of body b (bodies[i].part_of; every body its own without a table). */
static inline int32_t sph_piece_of(const int32_t *piece, int32_t b) { return piece ? piece[b] : b; }

/* The partner records and tags for nt slots: the cache's, grown when short, or (a
 * call without a cache) allocated for the caller to free. */
void partner_reserve(struct sph_cache *cache, size_t nt, double **rec, int32_t **tag);
/* Packs every slot's partner record and its tag, piece × 2 + 1 when R ≠ 0. */
void partner_pack(const struct particles *p, const struct sph_params *sp,
                  const struct material *mat, double *restrict rec, int32_t *restrict tag);

#endif
