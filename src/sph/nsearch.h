/* nsearch.h — internal to src/sph: the neighbour search (a cell's candidate
 * neighbours gathered, each particle's neighbours selected among them), and the
 * neighbour bit-cache kept between the two passes of a step.
 *
 * For each cell, the positions and smoothing lengths of all particles in its
 * neighbour cells are copied into contiguous per-thread arrays (the candidates);
 * each particle of the cell then skips candidate cells out of its reach and selects
 * its neighbours among the rest with a vectorised distance test and a branch-free
 * compaction. The order (cells in grid order, then particles in cell order) is
 * fixed, so sums do not depend on the number of threads.
 */
#ifndef HV_SPH_NSEARCH_H
#define HV_SPH_NSEARCH_H

#include "sph/sph.h"

/* One thread's search state: the candidates of the current cell and the selection. */
struct nsearch {
  size_t cap, n;
  double *x, *y, *z, *h;
  uint32_t *j;   /* particle slot of each candidate */
  uint32_t *sel; /* candidates selected for the current particle */
  double *d;     /* r² − (h_i + h_j)² of the current particle (< 0: within reach);
                         the portable selection loop only (NULL with AVX-512) */
  /* the neighbour cells: candidate ranges, box corners [m] and largest h [m] */
  size_t ncell, ccap;
  double cellw;  /* [m] cell edge */
  uint32_t *off; /* [ncell+1] */
  double *lo;    /* [3*ncell] */
  double *hc;    /* [ncell] */
};

void nsearch_free(struct nsearch *cd);
/* Copies the candidates of cell c. */
void nsearch_gather(struct nsearch *cd, const struct nbr_grid *g, size_t c,
                    const struct particles *p);
/* Selects into cd->sel the candidates within reach of particle i; returns the count. */
size_t nsearch_select(struct nsearch *cd, uint32_t i, double xi, double yi, double zi, double hi);
/* Whether nsearch_select would select anything for the real at slot i of cell c: the same
 * distance test on the same candidates, read from the grid, stopping at the first. */
int nsearch_any(const struct nbr_grid *g, size_t c, const struct particles *p, uint32_t i);
/* The neighbours of the real particle at position ii of cell c, into cd->sel: the
 * cell's candidates are gathered on first use (*gathered), then read from `load`
 * when it holds this grid's neighbours, else selected (and kept in `store` if given).
 * Returns the count. */
size_t nsearch_neighbours(struct nsearch *cd, int *gathered, const struct nbr_grid *g, size_t c,
                          uint32_t ii, const struct particles *p, const struct sph_cache *load,
                          const struct sph_cache *store);

/* Sizes the cache rows for grid g. */
void cache_layout(struct sph_cache *cache, const struct nbr_grid *g);
/* Stores / loads the selection of the particle at position `slot` within cell c. */
void cache_store(const struct sph_cache *cache, size_t c, uint32_t slot, const uint32_t *sel,
                 size_t nsel);
size_t cache_load(const struct sph_cache *cache, size_t c, uint32_t slot, uint32_t *sel);

#endif
