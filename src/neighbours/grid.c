/* grid.c — see grid.h. Morton (Z-order) keys make neighbouring cells close in
 * memory, and sorting particles by key groups every cell into one run. */
#include "neighbours/grid.h"

#include <float.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"

#define GRID_BITS 21
#define GRID_MAXC ((int64_t)1 << GRID_BITS)

static uint64_t spread3(uint64_t v)
{
  v &= 0x1fffff;
  v = (v | v << 32) & 0x1f00000000ffffULL;
  v = (v | v << 16) & 0x1f0000ff0000ffULL;
  v = (v | v << 8) & 0x100f00f00f00f00fULL;
  v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
  v = (v | v << 2) & 0x1249249249249249ULL;
  return v;
}

static uint64_t morton(uint64_t i, uint64_t j, uint64_t k)
{
  return spread3(i) | spread3(j) << 1 | spread3(k) << 2;
}

static uint64_t hash64(uint64_t k)
{
  k ^= k >> 33;
  k *= 0xff51afd7ed558ccdULL;
  k ^= k >> 33;
  return k;
}

void nbr_grid_init(struct nbr_grid *g) { memset(g, 0, sizeof *g); }

void nbr_grid_free(struct nbr_grid *g)
{
  free(g->order);
  free(g->cell_start);
  free(g->cell_key);
  free(g->cell_h);
  free(g->cell_lo);
  free(g->nbr_start);
  free(g->nbr_list);
  free(g->hkey);
  free(g->hval);
  free(g->row_cell);
  free(g->row_x);
  free(g->row_start);
  free(g->key);
  free(g->key2);
  free(g->idx2);
  memset(g, 0, sizeof *g);
}

/* Stable LSD radix sort of (key, idx) by key, 11-bit digits, `bits` significant bits. */
static void radix_sort(uint64_t *key, uint32_t *idx, uint64_t *key2, uint32_t *idx2, size_t n,
                       int bits)
{
  enum { D = 11, R = 1 << D };
  size_t count[R];
  for (int shift = 0; shift < bits; shift += D) {
    memset(count, 0, sizeof count);
    for (size_t i = 0; i < n; i++) count[(key[i] >> shift) & (R - 1)]++;
    size_t sum = 0;
    for (int d = 0; d < R; d++) {
      size_t c = count[d];
      count[d] = sum;
      sum += c;
    }
    for (size_t i = 0; i < n; i++) {
      size_t dst = count[(key[i] >> shift) & (R - 1)]++;
      key2[dst] = key[i];
      idx2[dst] = idx[i];
    }
    memcpy(key, key2, n * sizeof *key);
    memcpy(idx, idx2, n * sizeof *idx);
  }
}

/* Keys of particles' cells; returns the significant bits, or -1 if too many cells. */
static int compute_keys(const double *const x[3], size_t n, double cell, double origin[3],
                        uint64_t *key, char *msg, size_t msglen)
{
  double lo[3] = {DBL_MAX, DBL_MAX, DBL_MAX}, hi[3] = {-DBL_MAX, -DBL_MAX, -DBL_MAX};
  for (int d = 0; d < 3; d++)
    for (size_t i = 0; i < n; i++) {
      if (x[d][i] < lo[d]) lo[d] = x[d][i];
      if (x[d][i] > hi[d]) hi[d] = x[d][i];
    }
  int64_t maxc = 1;
  for (int d = 0; d < 3; d++) {
    origin[d] = n ? lo[d] - cell : 0.0; /* one empty layer keeps i-1 >= 0 */
    const double span = n ? (hi[d] - origin[d]) / cell + 2.0 : 1.0; /* cells, before any cast */
    if (!(span < (double)(GRID_MAXC - 1))) {
      snprintf(msg, msglen, "particles span %.6g m in direction %c, more than 2^21 cells of %.6g m",
               hi[d] - lo[d], "xyz"[d], cell);
      return -1;
    }
    const int64_t c = (int64_t)span;
    if (c > maxc) maxc = c;
  }
  int bits1 = 1;
  while (((int64_t)1 << bits1) < maxc) bits1++;
  double inv = 1.0 / cell;
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < n; i++) {
    uint64_t c0 = (uint64_t)((x[0][i] - origin[0]) * inv);
    uint64_t c1 = (uint64_t)((x[1][i] - origin[1]) * inv);
    uint64_t c2 = (uint64_t)((x[2][i] - origin[2]) * inv);
    key[i] = morton(c0, c1, c2);
  }
  return 3 * bits1;
}

static void grow(struct nbr_grid *g, size_t n)
{
  if (n <= g->wcap) return;
  size_t c = n + n / 4 + 64;
  g->order = hv_realloc(g->order, c * sizeof *g->order, "grid order");
  g->key = hv_realloc(g->key, c * sizeof *g->key, "grid keys");
  g->key2 = hv_realloc(g->key2, c * sizeof *g->key2, "grid keys");
  g->idx2 = hv_realloc(g->idx2, c * sizeof *g->idx2, "grid index");
  g->wcap = c;
}

static int32_t hash_find(const struct nbr_grid *g, uint64_t key)
{
  size_t mask = g->hcap - 1, s = hash64(key) & mask;
  while (g->hval[s] >= 0) {
    if (g->hkey[s] == key) return g->hval[s];
    s = (s + 1) & mask;
  }
  return -1;
}

/* Cell coordinates back from a Morton key. */
static uint64_t compact3(uint64_t v)
{
  v &= 0x1249249249249249ULL;
  v = (v ^ (v >> 2)) & 0x10c30c30c30c30c3ULL;
  v = (v ^ (v >> 4)) & 0x100f00f00f00f00fULL;
  v = (v ^ (v >> 8)) & 0x1f0000ff0000ffULL;
  v = (v ^ (v >> 16)) & 0x1f00000000ffffULL;
  v = (v ^ (v >> 32)) & 0x1fffff;
  return v;
}

/* The rows of the grid (see grid.h). The particles' key arrays are free by now and
 * serve as scratch. */
static void build_rows(struct nbr_grid *g)
{
  const size_t nc = g->ncells;
  uint64_t *rk = g->key;
  for (size_t c = 0; c < nc; c++) {
    const uint64_t k = g->cell_key[c];
    rk[c] = compact3(k >> 2) << (2 * GRID_BITS) | compact3(k >> 1) << GRID_BITS | compact3(k);
    g->row_cell[c] = (uint32_t)c;
  }
  radix_sort(rk, g->row_cell, g->key2, g->idx2, nc, 3 * GRID_BITS);
  size_t nr = 0;
  for (size_t s = 0; s < nc; s++) {
    g->row_x[s] = (uint32_t)(rk[s] & (GRID_MAXC - 1));
    if (s == 0 || rk[s] >> GRID_BITS != rk[s - 1] >> GRID_BITS) g->row_start[nr++] = (uint32_t)s;
  }
  g->row_start[nr] = (uint32_t)nc;
  g->nrows = nr;
  size_t hcap = 16;
  while (hcap < 2 * nr) hcap *= 2;
  if (hcap != g->hcap) {
    g->hkey = hv_realloc(g->hkey, hcap * sizeof *g->hkey, "row hash");
    g->hval = hv_realloc(g->hval, hcap * sizeof *g->hval, "row hash");
    g->hcap = hcap;
  }
  for (size_t s = 0; s < hcap; s++) g->hval[s] = -1;
  for (size_t r = 0; r < nr; r++) {
    const uint64_t key = rk[g->row_start[r]] >> GRID_BITS;
    size_t s = hash64(key) & (hcap - 1);
    while (g->hval[s] >= 0) s = (s + 1) & (hcap - 1);
    g->hkey[s] = key;
    g->hval[s] = (int32_t)r;
  }
}

static void build_cells(struct nbr_grid *g)
{
  size_t n = g->n, nc = 0;
  for (size_t i = 0; i < n; i++)
    if (i == 0 || g->key[i] != g->key[i - 1]) nc++;
  if (nc + 1 > g->ccap) {
    size_t c = nc + nc / 4 + 64;
    g->cell_start = hv_realloc(g->cell_start, (c + 1) * sizeof *g->cell_start, "cells");
    g->cell_key = hv_realloc(g->cell_key, c * sizeof *g->cell_key, "cells");
    g->cell_h = hv_realloc(g->cell_h, c * sizeof *g->cell_h, "cells");
    g->cell_lo = hv_realloc(g->cell_lo, 3 * c * sizeof *g->cell_lo, "cells");
    g->nbr_start = hv_realloc(g->nbr_start, (c + 1) * sizeof *g->nbr_start, "cells");
    g->row_cell = hv_realloc(g->row_cell, c * sizeof *g->row_cell, "cell rows");
    g->row_x = hv_realloc(g->row_x, c * sizeof *g->row_x, "cell rows");
    g->row_start = hv_realloc(g->row_start, (c + 1) * sizeof *g->row_start, "cell rows");
    g->ccap = c;
  }
  nc = 0;
  for (size_t i = 0; i < n; i++)
    if (i == 0 || g->key[i] != g->key[i - 1]) {
      g->cell_start[nc] = (uint32_t)i;
      g->cell_key[nc++] = g->key[i];
    }
  g->cell_start[nc] = (uint32_t)n;
  g->ncells = nc;
  build_rows(g);
}

/* Visits the candidate neighbour cells of cell c in a fixed order; stores them in
 * out (if not NULL) and returns their count. */
static uint32_t cell_neighbours(const struct nbr_grid *g, size_t c, double hglob, int32_t *out)
{
  uint64_t k = g->cell_key[c];
  int64_t ci = (int64_t)compact3(k), cj = (int64_t)compact3(k >> 1), ck = (int64_t)compact3(k >> 2);
  const double hc = g->cell_h[c], cell = g->cell;
  int R = (int)ceil((hc + hglob) / cell);
  if (R < 1) R = 1;
  uint32_t m = 0;
  /* row by row: only occupied cells are visited, in the order of a scan over
     dk, dj, di (so the neighbour order, and with it every sum, is as before) */
  for (int dk = -R; dk <= R; dk++)
    for (int dj = -R; dj <= R; dj++) {
      const int64_t b = cj + dj, d = ck + dk;
      if (b < 0 || d < 0) continue;
      const int32_t r = hash_find(g, (uint64_t)d << GRID_BITS | (uint64_t)b);
      if (r < 0) continue;
      uint32_t lo = g->row_start[r], hi = g->row_start[r + 1];
      const int64_t xmin = ci - R, xmax = ci + R;
      while (lo < hi) { /* first cell with x >= xmin */
        const uint32_t mid = lo + (hi - lo) / 2;
        if ((int64_t)g->row_x[mid] < xmin)
          lo = mid + 1;
        else
          hi = mid;
      }
      const double gj = abs(dj) > 1 ? (abs(dj) - 1) * cell : 0.0;
      const double gk = abs(dk) > 1 ? (abs(dk) - 1) * cell : 0.0;
      for (uint32_t s = lo; s < g->row_start[r + 1] && (int64_t)g->row_x[s] <= xmax; s++) {
        const int32_t nc = (int32_t)g->row_cell[s];
        const int64_t di = (int64_t)g->row_x[s] - ci;
        const double gi = llabs(di) > 1 ? (double)(llabs(di) - 1) * cell : 0.0;
        const double reach = hc + g->cell_h[nc];
        if (gi * gi + gj * gj + gk * gk >= reach * reach) continue;
        if (out) out[m] = nc;
        m++;
      }
    }
  return m;
}

static void link_cells(struct nbr_grid *g, const double *h)
{
  double hglob = 0.0;
  for (size_t c = 0; c < g->ncells; c++) {
    double hm = 0.0;
    for (uint32_t ii = g->cell_start[c]; ii < g->cell_start[c + 1]; ii++)
      if (h[g->order[ii]] > hm) hm = h[g->order[ii]];
    g->cell_h[c] = hm;
    if (hm > hglob) hglob = hm;
  }
#pragma omp parallel for schedule(static)
  for (size_t c = 0; c < g->ncells; c++) {
    const uint64_t k = g->cell_key[c];
    g->cell_lo[3 * c] = g->origin[0] + (double)compact3(k) * g->cell;
    g->cell_lo[3 * c + 1] = g->origin[1] + (double)compact3(k >> 1) * g->cell;
    g->cell_lo[3 * c + 2] = g->origin[2] + (double)compact3(k >> 2) * g->cell;
  }
  /* one search per cell: each thread appends its cells' lists to its own buffer, then
     the lists are copied in cell order (the result does not depend on the threads) */
  const size_t nc = g->ncells;
  const int nt = omp_get_max_threads();
  struct tbuf {
    int32_t *a;
    size_t n, cap;
  } *tb = hv_calloc((size_t)nt, sizeof *tb, "cell lists");
  size_t *where = hv_malloc((nc + 1) * sizeof *where, "cell lists"); /* thread << 40 | offset */
#pragma omp parallel
  {
    struct tbuf *b = &tb[omp_get_thread_num()];
#pragma omp for schedule(dynamic, 64)
    for (size_t c = 0; c < nc; c++) {
      int R = (int)ceil((g->cell_h[c] + hglob) / g->cell);
      if (R < 1) R = 1;
      const size_t worst = (size_t)(2 * R + 1) * (size_t)(2 * R + 1) * (size_t)(2 * R + 1);
      if (b->n + worst > b->cap) {
        b->cap = 2 * (b->n + worst) + 4096;
        b->a = hv_realloc(b->a, b->cap * sizeof *b->a, "cell lists");
      }
      const uint32_t m = cell_neighbours(g, c, hglob, b->a + b->n);
      where[c] = (size_t)omp_get_thread_num() << 40 | b->n;
      g->nbr_start[c + 1] = m;
      b->n += m;
    }
  }
  g->nbr_start[0] = 0;
  for (size_t c = 0; c < nc; c++) g->nbr_start[c + 1] += g->nbr_start[c];
  size_t total = g->nbr_start[nc];
  if (total > g->nbr_cap) {
    g->nbr_cap = total + total / 4 + 64;
    g->nbr_list = hv_realloc(g->nbr_list, g->nbr_cap * sizeof *g->nbr_list, "neighbour cells");
  }
#pragma omp parallel for schedule(static)
  for (size_t c = 0; c < nc; c++)
    memcpy(g->nbr_list + g->nbr_start[c],
           tb[where[c] >> 40].a + (where[c] & (((size_t)1 << 40) - 1)),
           (g->nbr_start[c + 1] - g->nbr_start[c]) * sizeof *g->nbr_list);
  for (int t = 0; t < nt; t++) free(tb[t].a);
  free(tb);
  free(where);
}

double nbr_cell_size(double hmin, double hmax)
{
  double c = 2.0 * hmin;
  return c < 0.5 * hmax ? 0.5 * hmax : c;
}

int nbr_grid_build(struct nbr_grid *g, const double *const x[3], const double *h, size_t n,
                   double cell, char *msg, size_t msglen)
{
  HV_CHECK(n < UINT32_MAX, "too many particles for 32-bit indices: %zu", n);
  HV_CHECK(cell > 0 && isfinite(cell), "bad cell size %g", cell);
  grow(g, n);
  g->n = n;
  g->cell = cell;
  int bits = compute_keys(x, n, cell, g->origin, g->key, msg, msglen);
  if (bits < 0) return -1;
  for (size_t i = 0; i < n; i++) g->order[i] = (uint32_t)i;
  radix_sort(g->key, g->order, g->key2, g->idx2, n, bits);
  build_cells(g);
  link_cells(g, h);
  return 0;
}

int nbr_sort_order(const double *const x[3], size_t n, double cell, uint32_t *order)
{
  char msg[256];
  double origin[3];
  uint64_t *key = hv_malloc((n + 1) * sizeof *key, "sort keys");
  uint64_t *key2 = hv_malloc((n + 1) * sizeof *key2, "sort keys");
  uint32_t *idx2 = hv_malloc((n + 1) * sizeof *idx2, "sort index");
  int bits = compute_keys(x, n, cell, origin, key, msg, sizeof msg);
  if (bits >= 0) {
    for (size_t i = 0; i < n; i++) order[i] = (uint32_t)i;
    radix_sort(key, order, key2, idx2, n, bits);
  }
  free(key);
  free(key2);
  free(idx2);
  return bits < 0 ? -1 : 0;
}

size_t nbr_grid_bytes(const struct nbr_grid *g)
{
  return g->wcap * (sizeof *g->order + 2 * sizeof *g->key + sizeof *g->idx2) +
         g->ccap * (sizeof *g->cell_start + sizeof *g->cell_key + 4 * sizeof *g->cell_h +
                    sizeof *g->nbr_start) +
         g->nbr_cap * sizeof *g->nbr_list + g->hcap * (sizeof *g->hkey + sizeof *g->hval) +
         g->ccap * (2 * sizeof *g->row_cell + sizeof *g->row_start);
}
