/* grid.h — cell lists sorted by Morton key, for neighbour search.
 *
 * A pair (i, j) interacts when r < h_i + h_j (support 2 h_ij, h_ij = (h_i + h_j)/2).
 * Cells are cubes of edge `cell`; only occupied cells exist: particles are sorted
 * by the Morton key of their cell (a stable radix sort, so the order is
 * deterministic), occupied cells are runs in that order, and a hash table maps a
 * key to its cell. Memory therefore grows with the number of particles, never with
 * the volume of the bounding box.
 * Each cell c keeps the largest h of its particles, H_c, and a list of the cells c'
 * whose box lies closer than H_c + H_c' — every cell that can hold a partner of a
 * particle of c. With particles of very different h (a gas beside a metal, a fine
 * projectile on a coarse plate) the cell edge follows the small particles and the
 * large ones search further, instead of every particle searching the largest radius.
 */
#ifndef HV_GRID_H
#define HV_GRID_H

#include <stddef.h>
#include <stdint.h>

struct nbr_grid {
  double cell;          /* [m] cell edge */
  double origin[3];     /* [m] corner of cell (0,0,0) */
  size_t n;             /* particles indexed */
  size_t ncells;        /* occupied cells */
  uint32_t *order;      /* [n] particle indices sorted by cell */
  uint32_t *cell_start; /* [ncells+1] ranges into order */
  uint64_t *cell_key;   /* [ncells] Morton key of each cell */
  double *cell_h;       /* [ncells] largest h in the cell [m] */
  double *cell_lo;      /* [3*ncells] lower corner of each cell [m] */
  uint32_t *nbr_start;  /* [ncells+1] ranges into nbr_list */
  int32_t *nbr_list;    /* neighbour cells of each cell, self included, fixed order */
  size_t nbr_cap;
  /* rows: the cells sorted by (z, y, x) cell coordinates, so that the occupied cells of
     one row (fixed y and z) are contiguous and sorted by x; a hash table maps a row's
     (z, y) to its index */
  uint32_t *row_cell;  /* [ncells] cells in row order */
  uint32_t *row_x;     /* [ncells] x cell coordinate of each, in row order */
  uint32_t *row_start; /* [nrows+1] ranges into row_cell */
  size_t nrows;
  size_t hcap;
  uint64_t *hkey; /* row key (z << 21 | y) */
  int32_t *hval;  /* row index */
  /* work arrays, kept between builds */
  uint64_t *key, *key2;
  uint32_t *idx2;
  size_t wcap, ccap;
};

void nbr_grid_init(struct nbr_grid *g);
void nbr_grid_free(struct nbr_grid *g);
/* Indexes particles [0, n) at positions x with smoothing lengths h. `cell` is the
 * cell edge (nbr_cell_size). Returns 0, or -1 (with a message in msg) if the
 * particles span more than 2^21 cells in a direction. */
int nbr_grid_build(struct nbr_grid *g, const double *const x[3], const double *h, size_t n,
                   double cell, char *msg, size_t msglen);
/* The cell edge: 2 hmin, but at least hmax/2 so that no cell searches more than 4
 * cells away. `hmin` is the h the cells are sized for: the solver passes 1.1 × the
 * median of h (step.c), the friends-of-friends grid its smallest length. */
double nbr_cell_size(double hmin, double hmax);
/* The order that sorts particles [0, n) by cell: fills order[n] (a permutation). */
int nbr_sort_order(const double *const x[3], size_t n, double cell, uint32_t *order);

/* Lower corner of cell c [m]. */
static inline void nbr_cell_corner(const struct nbr_grid *g, size_t c, double lo[3])
{
  lo[0] = g->cell_lo[3 * c];
  lo[1] = g->cell_lo[3 * c + 1];
  lo[2] = g->cell_lo[3 * c + 2];
}

/* Bytes held by the grid. */
size_t nbr_grid_bytes(const struct nbr_grid *g);

#endif
