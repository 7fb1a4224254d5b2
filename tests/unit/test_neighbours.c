/* test_neighbours.c — the cell-grid neighbour search against an O(N²) brute force.
 *
 * A pair interacts when r < hᵢ + hⱼ. Cells are sized by the smallest h, each cell
 * searches as far as its own largest h and the largest h of the others need, and the
 * neighbour cells are found row by row (src/neighbours/grid.c). These sets are built
 * to stress exactly that:
 *   - three populations of h in the ratio 1 : 3 : 8 (a fine projectile, a plate, a
 *     coarse backwall), in separate clusters with empty space between them, and mixed
 *     at their boundaries;
 *   - a thin sheet of large-h particles one layer thick (whose cells reach several
 *     cells out through empty rows);
 *   - particles on cell faces (a lattice whose spacing is a multiple of the cell).
 * For every particle the neighbour count from the grid (sph_count_neighbours, the
 * same gather and selection the SPH loops use) must equal the brute-force count;
 * the selection has no false positives by construction (it keeps only r < hᵢ + hⱼ),
 * so equal counts mean equal sets.
 * A search state reused from cell to cell, as the SPH loops reuse it (a lone particle's
 * cell of 1 candidate, then a cluster's of 65): it keeps room for the selection's
 * 16-wide stores (cap >= n + 16) and selects the cluster's 64 neighbours.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "neighbours/grid.h"
#include "particles/particles.h"
#include "sph/nsearch.h"
#include "sph/sph.h"
#include "testlib.h"
#include "testparticles.h"

static uint64_t rng = 0x2545F4914F6CDD1Dull;
static double uniform(void) /* [0, 1) */
{
  rng ^= rng >> 12;
  rng ^= rng << 25;
  rng ^= rng >> 27;
  return (double)((rng * 0x2545F4914F6CDD1Dull) >> 11) * 0x1.0p-53;
}

static void add(struct particles *p, double x, double y, double z, double h)
{
  tp_add(p, x, y, z, 1.0, h, 1.0, 0);
}

static int brute_count(const struct particles *p, size_t i)
{
  int c = 0;
  for (size_t j = 0; j < p->n; j++) {
    if (j == i) continue;
    const double dx = p->x[0][i] - p->x[0][j], dy = p->x[1][i] - p->x[1][j],
                 dz = p->x[2][i] - p->x[2][j], r = p->h[i] + p->h[j];
    c += dx * dx + dy * dy + dz * dz < r * r;
  }
  return c;
}

/* Builds the grid as the solver does and compares every particle's count. */
static void compare(const char *what, struct particles *p)
{
  double hmin = HUGE_VAL, hmax = 0.0;
  for (size_t i = 0; i < p->n; i++) {
    if (p->h[i] < hmin) hmin = p->h[i];
    if (p->h[i] > hmax) hmax = p->h[i];
  }
  struct nbr_grid g;
  nbr_grid_init(&g);
  char msg[256];
  const double *xs[3] = {p->x[0], p->x[1], p->x[2]};
  int ok = nbr_grid_build(&g, xs, p->h, p->n, nbr_cell_size(hmin, hmax), msg, sizeof msg) == 0;
  CHECK(ok, "%s: grid built (%s)", what, ok ? "ok" : msg);
  if (!ok) return;
  size_t bad = 0, first_bad = 0;
  long pairs = 0;
  int want_bad = 0, got_bad = 0;
  for (size_t i = 0; i < p->n; i++) {
    const int want = brute_count(p, i), got = sph_count_neighbours(p, &g, i);
    pairs += want;
    if (want != got) {
      if (!bad) {
        first_bad = i;
        want_bad = want;
        got_bad = got;
      }
      bad++;
    }
  }
  CHECK(bad == 0,
        "%s: %zu particles, %ld neighbour pairs (h %g..%g, %zu cells): every count "
        "equals the brute force (%zu differ; first: particle %zu, %d expected, %d found)",
        what, p->n, pairs, hmin, hmax, g.ncells, bad, first_bad, want_bad, got_bad);
  CHECK(pairs > 5 * (long)p->n,
        "%s: the set is dense enough to mean something (%.1f "
        "neighbours per particle)",
        what, (double)pairs / (double)p->n);
  nbr_grid_free(&g);
}

int main(void)
{
  struct particles p;

  /* 1. three clusters, h 1 : 3 : 8, with gaps, overlapping at their edges */
  particles_init(&p);
  for (int k = 0; k < 1500; k++) /* fine: a ball of radius 1 at the origin */
    for (;;) {
      const double x = 2 * uniform() - 1, y = 2 * uniform() - 1, z = 2 * uniform() - 1;
      if (x * x + y * y + z * z < 1) {
        add(&p, x, y, z, 0.1);
        break;
      }
    }
  for (int k = 0; k < 1500; k++) /* medium: a slab 0.8 < x < 1.6, overlapping the ball */
    add(&p, 0.8 + 0.8 * uniform(), 6 * uniform() - 3, 6 * uniform() - 3, 0.3);
  for (int k = 0; k < 600; k++) /* coarse: a thin sheet far away, one layer of h 0.8 */
    add(&p, 12.0 + 0.2 * uniform(), 20 * uniform() - 10, 20 * uniform() - 10, 0.8);
  for (int k = 0; k < 300; k++) /* coarse particles drifting into the fine ball */
    add(&p, 1.6 * uniform() - 0.8, 1.6 * uniform() - 0.8, 1.6 * uniform() - 0.8, 0.8);
  compare("three populations", &p);
  particles_free(&p);

  /* 2. a lattice on cell faces: spacing 0.2 with h 0.1 gives cells of exactly 0.2 */
  particles_init(&p);
  for (int k = 0; k < 12; k++)
    for (int j = 0; j < 12; j++)
      for (int i = 0; i < 12; i++) add(&p, 0.2 * i, 0.2 * j, 0.2 * k, 0.1 + 0.1 * (i % 3 == 0));
  compare("lattice on cell faces", &p);
  particles_free(&p);

  /* 3. a single-layer sheet of large h beside a block of small h (W.P.1's backwall) */
  particles_init(&p);
  for (int j = 0; j < 40; j++)
    for (int k = 0; k < 40; k++) add(&p, 5.0, 0.5 * j - 10, 0.5 * k - 10, 0.6);
  for (int k = 0; k < 2000; k++)
    add(&p, 4.0 + 0.8 * uniform(), 2 * uniform() - 1, 2 * uniform() - 1, 0.075);
  compare("sheet beside a fine block", &p);
  particles_free(&p);

  /* 4. one search state for two cells, as a thread of the SPH loops keeps it: a lone
     particle's cell first (1 candidate: room made for 65), then a cluster of 65 within
     one cell (65 candidates, all within reach of each other). The AVX-512 selection
     stores 16 indices at sel + k, k up to 64: without 16 slots beyond the candidates
     it wrote past sel (heap corruption in RZ runs, src/sph/nsearch.c) */
  particles_init(&p);
  add(&p, 100.0, 100.0, 100.0, 0.5);
  for (int k = 0; k < 65; k++) add(&p, 0.01 * (k % 4), 0.01 * (k / 4 % 4), 0.01 * (k / 16), 0.5);
  {
    struct nbr_grid g;
    nbr_grid_init(&g);
    char msg[256];
    const double *xs[3] = {p.x[0], p.x[1], p.x[2]};
    CHECK(nbr_grid_build(&g, xs, p.h, p.n, nbr_cell_size(0.5, 0.5), msg, sizeof msg) == 0 &&
              g.ncells == 2,
          "a lone particle and a cluster: two cells (%zu)", g.ncells);
    size_t lone = 0, cluster = 1;
    if (g.cell_start[1] - g.cell_start[0] != 1) {
      lone = 1;
      cluster = 0;
    }
    struct nsearch cd = {0};
    nsearch_gather(&cd, &g, lone, &p);
    const size_t cap1 = cd.cap;
    nsearch_gather(&cd, &g, cluster, &p);
    const uint32_t i = g.order[g.cell_start[cluster]];
    const size_t k = nsearch_select(&cd, i, p.x[0][i], p.x[1][i], p.x[2][i], p.h[i]);
    CHECK(cd.n == 65 && cd.cap >= cd.n + 16 && k == 64,
          "a reused search state: %zu candidates after 1 (room for %zu, then %zu: at least "
          "n + 16 for the 16-wide stores), %zu neighbours selected (64)",
          cd.n, cap1, cd.cap, k);
    nsearch_free(&cd);
    nbr_grid_free(&g);
  }
  particles_free(&p);
  return test_finish();
}
