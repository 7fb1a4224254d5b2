/* rest.c — sph.skip_resting: the cells the solid passes (sph_solid.c) leave out. */
#include "sph/rest.h"

#include <stdlib.h>

#include "core/error.h"
#include "sph/nsearch.h"
#include "sph/partner.h"

/* sph.skip_resting. A particle whose neighbours (itself included) all have v = 0,
 * p = 0, S = 0 and R = 0, exactly, has exactly zero rates: no velocity difference for
 * the density rate, the velocity gradient and the viscosity, no stress for the forces;
 * its stress stays (S = 0, L = 0: nothing to update or return). A cell is skipped when
 * every cell of its candidate list (which covers every particle's search) holds only
 * such particles, "quiet". The first pass tests v and S at the step's start (the pass
 * changes S only from L); the second pass tests the mid-step v, p, S and R, and skips
 * only cells the first pass skipped. What a skipped particle's pass would have written
 * is written: 0 for ρ̇, the heating and a, S for S₁, and its signal speed, which
 * depends only on whether it has a neighbour (nsearch_any). The switch is excluded: its
 * αᵢ decays at rest. rest[c]: bit 0 the first pass skipped c, bit 1 the second. */
static void rest_alloc(struct sph_cache *cache, size_t ncells)
{
  if (ncells > cache->rcap) {
    cache->rcap = ncells + ncells / 4 + 64;
    free(cache->quiet);
    free(cache->rest);
    cache->quiet = hv_malloc(cache->rcap, "rest flags");
    cache->rest = hv_malloc(cache->rcap, "rest flags");
  }
}

/* Sets bit `bit` of rest[c] where every neighbour cell of c is quiet (and, for bit 1,
 * bit 0 is set). */
static void rest_mark(const struct nbr_grid *g, struct sph_cache *cache, int bit)
{
  const uint8_t *quiet = cache->quiet;
  uint8_t *rest = cache->rest;
#pragma omp parallel for schedule(static)
  for (size_t c = 0; c < g->ncells; c++) {
    int r = bit == 0 || (rest[c] & 1);
    for (uint32_t k = g->nbr_start[c]; r && k < g->nbr_start[c + 1]; k++) r = quiet[g->nbr_list[k]];
    rest[c] = (uint8_t)(bit == 0 ? r : (rest[c] & 1) | (r << 1));
  }
}

/* The first pass's quiet cells: v = 0 and S = 0 at the step's start. */
void rest_mark_first(const struct particles *p, const struct nbr_grid *g, struct sph_cache *cache)
{
  const double *vx = p->v[0], *vy = p->v[1], *vz = p->v[2];
  rest_alloc(cache, g->ncells);
#pragma omp parallel for schedule(static)
  for (size_t c = 0; c < g->ncells; c++) {
    int q = 1;
    for (uint32_t ii = g->cell_start[c]; q && ii < g->cell_start[c + 1]; ii++) {
      const uint32_t j = g->order[ii];
      q = vx[j] == 0.0 && vy[j] == 0.0 && vz[j] == 0.0;
      for (int k = 0; q && k < 6; k++) q = p->S[k][j] == 0.0;
    }
    cache->quiet[c] = (uint8_t)q;
  }
  rest_mark(g, cache, 0);
}

/* What the first pass would write for the reals of a resting cell c. */
void rest_write_first(struct particles *p, const struct nbr_grid *g, size_t c, double *gradv,
                      const int32_t *act)
{
  for (uint32_t ii = g->cell_start[c]; ii < g->cell_start[c + 1]; ii++) {
    const uint32_t i = g->order[ii];
    if (i >= p->n || (act && !act[i])) continue;
    p->drho[i] = 0.0;
    p->de[i] = 0.0;
    for (int k = 0; k < 6; k++) p->S1[k][i] = p->S[k][i];
    if (gradv)
      for (int t = 0; t < 9; t++) gradv[9 * (size_t)i + t] = 0.0;
  }
}

/* The second pass's quiet cells, from the mid-step state in the partner records
 * (v, p/ρ², S/ρ², and R through the tag) and p itself. */
void rest_mark_second(const struct particles *p, const struct nbr_grid *g, struct sph_cache *cache,
                      const double *rec, const int32_t *tag)
{
#pragma omp parallel for schedule(static)
  for (size_t c = 0; c < g->ncells; c++) {
    int q = 1;
    for (uint32_t ii = g->cell_start[c]; q && ii < g->cell_start[c + 1]; ii++) {
      const uint32_t j = g->order[ii];
      const double *w = rec + PR_LEN * (size_t)j;
      q = w[PR_V] == 0.0 && w[PR_V + 1] == 0.0 && w[PR_V + 2] == 0.0 && w[PR_P] == 0.0 &&
          p->p[j] == 0.0 && !(tag[j] & 1);
      for (int t = 0; q && t < 6; t++) q = w[PR_S + t] == 0.0;
    }
    cache->quiet[c] = (uint8_t)q;
  }
  rest_mark(g, cache, 1);
}

/* What the second pass would write for the reals of a resting cell c: a = 0, de
 * unchanged, the signal speed. Returns the number of reals. */
long rest_write_second(struct particles *p, const struct nbr_grid *g, size_t c,
                       const struct sph_params *sp, const int32_t *act)
{
  long rested = 0;
  for (uint32_t ii = g->cell_start[c]; ii < g->cell_start[c + 1]; ii++) {
    const uint32_t i = g->order[ii];
    if (i >= p->n || (act && !act[i])) continue;
    p->a[0][i] = p->a[1][i] = p->a[2][i] = 0.0;
    p->vsig[i] = sph_signal_speed(nsearch_any(g, c, p, i), p->cs[i], sp->alpha, sp->beta, 0.0, 0.0);
    rested++;
  }
  return rested;
}
