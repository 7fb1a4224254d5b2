/* nsearch.c — the neighbour search and the neighbour cache; see nsearch.h. */
#include "sph/nsearch.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"

#if defined(__AVX512F__)
#include <immintrin.h>
#endif

static void nsearch_free_arrays(struct nsearch *cd)
{
  free(cd->x);
  free(cd->y);
  free(cd->z);
  free(cd->h);
  free(cd->j);
  free(cd->sel);
  free(cd->d);
}

void nsearch_free(struct nsearch *cd)
{
  nsearch_free_arrays(cd);
  free(cd->off);
  free(cd->lo);
  free(cd->hc);
}

/* Room for the n candidates of a cell, and 16 slots more: the AVX-512 selection
 * (nsearch_select) stores 16 indices at sel + k whatever their count, k up to n − 1, so
 * sel needs n + 15. With room for n only, a search state sized by a sparse first cell
 * (cap 65 after a cell of 1 candidate) overran sel on a later cell of 50 to 65: heap
 * corruption in the RZ Whipple sweep of 2026-12-08 at d0c2718 ("corrupted size vs.
 * prev_size", 3 km/s, 3.53 mm sphere, after 50 us) and the "free(): invalid pointer"
 * in nsearch_free of 2026-12-07 at 5e03719 (3 km/s, 8 mm, 64.6 us). */
static void nsearch_reserve(struct nsearch *cd, size_t n)
{
  if (n + 16 > cd->cap) {
    nsearch_free_arrays(cd);
    cd->cap = n + n / 2 + 64;
    cd->x = hv_malloc(cd->cap * sizeof(double), "candidates");
    cd->y = hv_malloc(cd->cap * sizeof(double), "candidates");
    cd->z = hv_malloc(cd->cap * sizeof(double), "candidates");
    cd->h = hv_malloc(cd->cap * sizeof(double), "candidates");
    cd->j = hv_malloc(cd->cap * sizeof(uint32_t), "candidates");
    cd->sel = hv_malloc(cd->cap * sizeof(uint32_t), "candidates");
#if !defined(__AVX512F__)
    cd->d = hv_malloc(cd->cap * sizeof(double), "candidates");
#endif
  }
}

/* r² − (hᵢ + hⱼ)² of a pair (< 0: within reach): the portable selection's test and
 * nsearch_any's, the same operations as the AVX-512 lanes. */
static inline double nsearch_gap(double dx, double dy, double dz, double s)
{
  return dx * dx + dy * dy + dz * dz - s * s;
}

static size_t nsearch_count(const struct nbr_grid *g, size_t c)
{
  const int32_t *nb = g->nbr_list + g->nbr_start[c];
  const uint32_t nnb = g->nbr_start[c + 1] - g->nbr_start[c];
  size_t n = 0;
  for (uint32_t k = 0; k < nnb; k++) n += g->cell_start[nb[k] + 1] - g->cell_start[nb[k]];
  return n;
}

/* Only the slots (cd->j) of the candidates of cell c, in the order nsearch_gather uses. */
static void nsearch_gather_slots(struct nsearch *cd, const struct nbr_grid *g, size_t c)
{
  nsearch_reserve(cd, nsearch_count(g, c));
  const int32_t *nb = g->nbr_list + g->nbr_start[c];
  const uint32_t nnb = g->nbr_start[c + 1] - g->nbr_start[c];
  size_t q = 0;
  for (uint32_t k = 0; k < nnb; k++)
    for (uint32_t jj = g->cell_start[nb[k]]; jj < g->cell_start[nb[k] + 1]; jj++)
      cd->j[q++] = g->order[jj];
  cd->n = q;
}

void nsearch_gather(struct nsearch *cd, const struct nbr_grid *g, size_t c,
                    const struct particles *p)
{
  const int32_t *nb = g->nbr_list + g->nbr_start[c];
  const uint32_t nnb = g->nbr_start[c + 1] - g->nbr_start[c];
  nsearch_reserve(cd, nsearch_count(g, c));
  if (nnb + 1 > cd->ccap) {
    cd->ccap = nnb + 32;
    cd->off = hv_realloc(cd->off, cd->ccap * sizeof *cd->off, "candidate cells");
    cd->lo = hv_realloc(cd->lo, 3 * cd->ccap * sizeof *cd->lo, "candidate cells");
    cd->hc = hv_realloc(cd->hc, cd->ccap * sizeof *cd->hc, "candidate cells");
  }
  cd->ncell = nnb;
  cd->cellw = g->cell;
  size_t q = 0;
  for (uint32_t k = 0; k < nnb; k++) {
    double lo[3];
    nbr_cell_corner(g, (size_t)nb[k], lo);
    cd->lo[3 * k] = lo[0];
    cd->lo[3 * k + 1] = lo[1];
    cd->lo[3 * k + 2] = lo[2];
    cd->hc[k] = g->cell_h[nb[k]];
    cd->off[k] = (uint32_t)q;
    for (uint32_t jj = g->cell_start[nb[k]]; jj < g->cell_start[nb[k] + 1]; jj++) {
      const uint32_t j = g->order[jj];
      cd->x[q] = p->x[0][j];
      cd->y[q] = p->x[1][j];
      cd->z[q] = p->x[2][j];
      cd->h[q] = p->h[j];
      cd->j[q] = j;
      q++;
    }
  }
  cd->off[nnb] = (uint32_t)q;
  cd->n = q;
}

/* Selects the candidates within reach of particle i (r < h_i + h_j, j != i): whole
 * cells out of reach are skipped, then a vectorisable distance test and a
 * compaction. Order: cells, then particles, as gathered. */
size_t nsearch_select(struct nsearch *cd, uint32_t i, double xi, double yi, double zi, double hi)
{
  const double *restrict x = cd->x, *restrict y = cd->y, *restrict z = cd->z, *restrict h = cd->h;
  const uint32_t *restrict jj = cd->j;
  uint32_t *restrict sel = cd->sel;
  size_t k = 0;
#if defined(__AVX512F__)
  const __m512d vx = _mm512_set1_pd(xi), vy = _mm512_set1_pd(yi), vz = _mm512_set1_pd(zi);
  const __m512d vh = _mm512_set1_pd(hi), zero = _mm512_setzero_pd();
  const __m512i iota = _mm512_set_epi32(15, 14, 13, 12, 11, 10, 9, 8, 7, 6, 5, 4, 3, 2, 1, 0);
  const __m512i vi = _mm512_set1_epi32((int)i);
#else
  double *restrict d = cd->d;
#endif
  for (size_t c = 0; c < cd->ncell; c++) {
    const double *lo = cd->lo + 3 * c, cell = cd->cellw, reach = hi + cd->hc[c];
    double d2 = 0.0, t;
    t = lo[0] - xi;
    if (t > 0) d2 += t * t;
    t = xi - lo[0] - cell;
    if (t > 0) d2 += t * t;
    t = lo[1] - yi;
    if (t > 0) d2 += t * t;
    t = yi - lo[1] - cell;
    if (t > 0) d2 += t * t;
    t = lo[2] - zi;
    if (t > 0) d2 += t * t;
    t = zi - lo[2] - cell;
    if (t > 0) d2 += t * t;
    if (d2 >= reach * reach * (1.0 + 1e-12)) continue; /* margin for rounding of the corner */
    const size_t q0 = cd->off[c], q1 = cd->off[c + 1];
#if defined(__AVX512F__)
    /* 16 candidates at a time: the same distance test in two 8-lane halves (the same
       operations in the same order as the scalar code below, so the same selection),
       the selected indices packed by a compress and stored 16 wide (sel has room) */
    for (size_t q = q0; q < q1; q += 16) {
      const size_t left = q1 - q;
      const __mmask16 live = left >= 16 ? (__mmask16)0xFFFF : (__mmask16)((1u << left) - 1u);
      __mmask8 half[2];
      for (int u = 0; u < 2; u++) {
        const __mmask8 lm = (__mmask8)(live >> (8 * u));
        const size_t b = q + 8 * (size_t)u;
        const __m512d dx = _mm512_sub_pd(vx, _mm512_maskz_loadu_pd(lm, x + b));
        const __m512d dy = _mm512_sub_pd(vy, _mm512_maskz_loadu_pd(lm, y + b));
        const __m512d dz = _mm512_sub_pd(vz, _mm512_maskz_loadu_pd(lm, z + b));
        const __m512d sh = _mm512_add_pd(vh, _mm512_maskz_loadu_pd(lm, h + b));
        const __m512d r2 = _mm512_add_pd(
            _mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy)), _mm512_mul_pd(dz, dz));
        const __m512d dd = _mm512_sub_pd(r2, _mm512_mul_pd(sh, sh));
        half[u] = _mm512_mask_cmp_pd_mask(lm, dd, zero, _CMP_LT_OQ);
      }
      const __m512i js = _mm512_maskz_loadu_epi32(live, jj + q);
      const __mmask16 m = (__mmask16)(((unsigned)half[0] | ((unsigned)half[1] << 8)) &
                                      _mm512_cmpneq_epi32_mask(js, vi));
      const __m512i idx = _mm512_add_epi32(_mm512_set1_epi32((int)q), iota);
      _mm512_storeu_si512((void *)(sel + k), _mm512_maskz_compress_epi32(m, idx));
      k += (size_t)__builtin_popcount((unsigned)m);
    }
#else
    for (size_t q = q0; q < q1; q++) {
      const double dx = xi - x[q], dy = yi - y[q], dz = zi - z[q], s = hi + h[q];
      d[q] = nsearch_gap(dx, dy, dz, s);
    }
    for (size_t q = q0; q < q1; q++) {
      sel[k] = (uint32_t)q;
      k += (d[q] < 0.0) & (jj[q] != i);
    }
#endif
  }
  return k;
}

/* Whether particle i of cell c has any neighbour: the answer only, so the cells are
 * searched in any order, c itself first (in a lattice at rest, where the resting cells
 * ask this every step, it holds one within reach nearly always). */
int nsearch_any(const struct nbr_grid *g, size_t c, const struct particles *p, uint32_t i)
{
  const double xi = p->x[0][i], yi = p->x[1][i], zi = p->x[2][i], hi = p->h[i];
  for (uint32_t jj = g->cell_start[c]; jj < g->cell_start[c + 1]; jj++) {
    const uint32_t j = g->order[jj];
    const double dx = xi - p->x[0][j], dy = yi - p->x[1][j], dz = zi - p->x[2][j];
    if (nsearch_gap(dx, dy, dz, hi + p->h[j]) < 0.0 && j != i) return 1;
  }
  for (uint32_t k = g->nbr_start[c]; k < g->nbr_start[c + 1]; k++) {
    const int32_t nb = g->nbr_list[k];
    if ((size_t)nb == c) continue;
    for (uint32_t jj = g->cell_start[nb]; jj < g->cell_start[nb + 1]; jj++) {
      const uint32_t j = g->order[jj];
      const double dx = xi - p->x[0][j], dy = yi - p->x[1][j], dz = zi - p->x[2][j];
      if (nsearch_gap(dx, dy, dz, hi + p->h[j]) < 0.0 && j != i) return 1;
    }
  }
  return 0;
}

void sph_cache_free(struct sph_cache *c)
{
  free(c->mask);
  free(c->cell_off);
  free(c->cell_words);
  free(c->gradv);
  free(c->partner);
  free(c->partner_tag);
  free(c->quiet);
  free(c->rest);
  memset(c, 0, sizeof *c);
}

size_t sph_cache_bytes(const struct sph_cache *c)
{
  return c->cap * sizeof *c->mask + c->ccap * (sizeof *c->cell_off + sizeof *c->cell_words) +
         c->gcap * 9 * sizeof *c->gradv +
         c->partner_cap * (SPH_PARTNER_LEN * sizeof *c->partner + sizeof *c->partner_tag) +
         c->rcap * 2;
}

/* Sizes the rows: a cell's row has one bit per candidate of that cell. */
void cache_layout(struct sph_cache *cache, const struct nbr_grid *g)
{
  if (g->ncells + 1 > cache->ccap) {
    cache->ccap = g->ncells + g->ncells / 4 + 64;
    cache->cell_off = hv_realloc(cache->cell_off, cache->ccap * sizeof *cache->cell_off, "cache");
    cache->cell_words =
        hv_realloc(cache->cell_words, cache->ccap * sizeof *cache->cell_words, "cache");
  }
#pragma omp parallel for schedule(static)
  for (size_t c = 0; c < g->ncells; c++) {
    size_t n = 0;
    for (uint32_t k = g->nbr_start[c]; k < g->nbr_start[c + 1]; k++)
      n += g->cell_start[g->nbr_list[k] + 1] - g->cell_start[g->nbr_list[k]];
    cache->cell_words[c] = (uint32_t)((n + 63) / 64);
  }
  size_t off = 0;
  for (size_t c = 0; c < g->ncells; c++) {
    cache->cell_off[c] = off;
    off += (size_t)cache->cell_words[c] * (g->cell_start[c + 1] - g->cell_start[c]);
  }
  cache->cell_off[g->ncells] = off;
  if (off > cache->cap) {
    cache->cap = off + off / 4 + 1024;
    free(cache->mask);
    cache->mask = hv_malloc(cache->cap * sizeof *cache->mask, "neighbour cache");
  }
}

void cache_store(const struct sph_cache *cache, size_t c, uint32_t slot, const uint32_t *sel,
                 size_t nsel)
{
  const uint32_t w = cache->cell_words[c];
  uint64_t *row = cache->mask + cache->cell_off[c] + (size_t)slot * w;
  for (uint32_t k = 0; k < w; k++) row[k] = 0;
  for (size_t k = 0; k < nsel; k++) row[sel[k] >> 6] |= (uint64_t)1 << (sel[k] & 63);
}

/* Reads a stored row back into sel (same order as the search produced). */
size_t cache_load(const struct sph_cache *cache, size_t c, uint32_t slot, uint32_t *sel)
{
  const uint32_t w = cache->cell_words[c];
  const uint64_t *row = cache->mask + cache->cell_off[c] + (size_t)slot * w;
  size_t k = 0;
  for (uint32_t wi = 0; wi < w; wi++) {
    uint64_t bits = row[wi];
    while (bits) {
      sel[k++] = wi * 64 + (uint32_t)__builtin_ctzll(bits);
      bits &= bits - 1;
    }
  }
  return k;
}

size_t nsearch_neighbours(struct nsearch *cd, int *gathered, const struct nbr_grid *g, size_t c,
                          uint32_t ii, const struct particles *p, const struct sph_cache *load,
                          const struct sph_cache *store)
{
  const uint32_t slot = ii - g->cell_start[c], i = g->order[ii];
  if (load && load->valid) { /* the stored selection needs only the candidates' slots */
    if (!*gathered) {
      nsearch_gather_slots(cd, g, c);
      *gathered = 1;
    }
    return cache_load(load, c, slot, cd->sel);
  }
  if (!*gathered) {
    nsearch_gather(cd, g, c, p);
    *gathered = 1;
  }
  const size_t nsel = nsearch_select(cd, i, p->x[0][i], p->x[1][i], p->x[2][i], p->h[i]);
  if (store) cache_store(store, c, slot, cd->sel, nsel);
  return nsel;
}
