/* grid.h — cell lists sorted by Morton key, for neighbour search.
 *
 * Cells are cubes of edge `cell` (>= the largest interaction radius, h_i + h_j
 * <= 2 h_max). Only occupied cells exist: particles are sorted by the Morton key of
 * their cell (a stable radix sort, so the order is deterministic), occupied cells
 * are runs in that order, and a hash table maps a key to its cell. Memory therefore
 * grows with the number of particles, never with the volume of the bounding box.
 * Each cell keeps the indices of its (up to 27) neighbour cells.
 */
#ifndef HV_GRID_H
#define HV_GRID_H

#include <stddef.h>
#include <stdint.h>

struct nbr_grid {
  double cell;           /* [m] cell edge */
  double origin[3];      /* [m] corner of cell (0,0,0) */
  size_t n;              /* particles indexed */
  size_t ncells;         /* occupied cells */
  uint32_t *order;       /* [n] particle indices sorted by cell */
  uint32_t *cell_start;  /* [ncells+1] ranges into order */
  uint64_t *cell_key;    /* [ncells] Morton key of each cell */
  int32_t *cell_nbr;     /* [ncells*27] neighbour cells (-1: none), self included */
  /* hash table key -> cell */
  size_t hcap;
  uint64_t *hkey;
  int32_t *hval;
  /* work arrays, kept between builds */
  uint64_t *key, *key2;
  uint32_t *idx2;
  size_t wcap, ccap;
};

void nbr_grid_init(struct nbr_grid *g);
void nbr_grid_free(struct nbr_grid *g);
/* Indexes particles [0, n) at positions x. `cell` is the cell edge. Returns 0, or -1
 * (with a message in msg) if the particles span more than 2^21 cells in a direction. */
int nbr_grid_build(struct nbr_grid *g, const double *const x[3], size_t n, double cell,
                   char *msg, size_t msglen);
/* The order that sorts particles [0, n) by cell: fills order[n] (a permutation). */
int nbr_sort_order(const double *const x[3], size_t n, double cell, uint32_t *order);

/* Bytes held by the grid. */
size_t nbr_grid_bytes(const struct nbr_grid *g);

#endif
