/* partner.c — the solid force pass's partner records; see partner.h. */
#include "sph/partner.h"

#include <stdlib.h>

#include "core/error.h"
#include "fracture/fracture.h"

static void partner_pack_density_slot(const struct particles *p, const struct sph_params *sp,
                                      const struct material *mat, size_t j, double *restrict rec);

/* The partner records and tags for nt slots: the cache's, grown when short, or (a
 * call without a cache) allocated for this call only. */
void partner_reserve(struct sph_cache *cache, size_t nt, double **rec, int32_t **tag)
{
  if (cache && cache->partner_cap >= nt + 1) {
    *rec = cache->partner;
    *tag = cache->partner_tag;
    return;
  }
  const size_t cap = cache ? nt + nt / 4 + 64 : nt + 1;
  if (cache) {
    free(cache->partner);
    free(cache->partner_tag);
    cache->partner = NULL;
    cache->partner_tag = NULL;
    cache->partner_cap = 0;
  }
  *rec = aligned_alloc(64, cap * PR_LEN * sizeof **rec);
  *tag = malloc(cap * sizeof **tag);
  if (!*rec || !*tag)
    HV_FATAL("out of memory: %zu bytes for the pair terms", cap * (PR_LEN * sizeof **rec + 4));
  if (cache) {
    cache->partner = *rec;
    cache->partner_tag = *tag;
    cache->partner_cap = cap;
  }
}

/* Packs every slot's partner record and its tag, piece × 2 + 1 when R ≠ 0. */
void partner_pack(const struct particles *p, const struct sph_params *sp,
                  const struct material *mat, double *restrict rec, int32_t *restrict tag)
{
  const size_t nt = p->n + p->n_ghost;
#pragma omp parallel for schedule(static)
  for (size_t j = 0; j < nt; j++) {
    const double rj2 = 1.0 / (p->rho[j] * p->rho[j]);
    double *w = rec + PR_LEN * j;
    w[PR_X] = p->x[0][j];
    w[PR_X + 1] = p->x[1][j];
    w[PR_X + 2] = p->x[2][j];
    w[PR_H] = p->h[j];
    w[PR_V] = p->v[0][j];
    w[PR_V + 1] = p->v[1][j];
    w[PR_V + 2] = p->v[2][j];
    w[PR_M] = p->m[j];
    double Sj[6], pj = p->p[j];
    for (int t = 0; t < 6; t++) Sj[t] = p->S[t][j];
    if (fracture_no_tension(&mat[p->mat[j]].frac, p->fstate[j]))
      pj = fracture_effective(p->p[j], Sj, Sj); /* split without tension: σ' (fracture.h) */
    w[PR_P] = pj * rj2;
    for (int t = 0; t < 6; t++) w[PR_S + t] = Sj[t] * rj2;
    w[PR_RHO] = p->rho[j];
    int rany = 0;
    for (int t = 0; t < 6; t++) {
      w[PR_AS + t] = p->R[t][j];
      rany |= p->R[t][j] != 0.0;
    }
    tag[j] = 2 * (sph_piece_of(sp->piece, p->body[j])) + rany;
    w[PR_C] = p->cs[j];
    w[PR_KIND] = 2.0 * tag[j] + (mat[p->mat[j]].eos == EOS_IDEAL_GAS);
  }
}

/* Packs the density records of the slots of grid g that the first pass reads: with rest
 * (sph.skip_resting's marks, else NULL) only those of cells next to a cell it does not
 * skip (the neighbour-cell lists are symmetric: a slot is read only from its cell's
 * neighbour cells); an impact's target at rest costs nothing here. */
void partner_pack_density(const struct particles *p, const struct sph_params *sp,
                          const struct material *mat, const struct nbr_grid *g, const uint8_t *rest,
                          double *restrict rec)
{
#pragma omp parallel for schedule(static)
  for (size_t c = 0; c < g->ncells; c++) {
    int need = !rest;
    for (uint32_t q = g->nbr_start[c]; !need && q < g->nbr_start[c + 1]; q++)
      need = !rest[g->nbr_list[q]];
    if (!need) continue;
    for (uint32_t ii = g->cell_start[c]; ii < g->cell_start[c + 1]; ii++)
      partner_pack_density_slot(p, sp, mat, g->order[ii], rec);
  }
}

/* The density record of slot j. */
static void partner_pack_density_slot(const struct particles *p, const struct sph_params *sp,
                                      const struct material *mat, size_t j, double *restrict rec)
{
  double *w = rec + PR_LEN * j;
  const struct material *mj = &mat[p->mat[j]];
  for (int a = 0; a < 3; a++) w[DR_V + a] = p->v[a][j];
  w[DR_VOL] = p->m[j] / p->rho[j];
  w[DR_RHO] = p->rho[j];
  w[DR_WREF] = 2.0 * p->m[j] / mj->rho0;
  w[DR_KIND] = 4.0 * sph_piece_of(sp->piece, p->body[j]) + 2.0 * (p->rho[j] < 0.5 * mj->rho0) +
               (mj->eos == EOS_IDEAL_GAS);
  w[DR_MAT] = p->mat[j];
}
