/* measure_plate.c — perforation and hole diameter of a plate; definitions in measure.h
 * and docs/measurements.md.
 *
 * Steps:
 * 1. Plate particles in the slab (with attached_only, those of the largest
 *    friends-of-friends group among them) are projected along x onto
 *    (u, w) = (y − yc, z) and, in a half model, mirrored to (u, −z).
 * 2. A grid of cells of edge c covers the window; cells whose centre lies within tol of
 *    a projected particle are material.
 * 3. The hole is the 4-connected set of empty cells grown from the empty cell nearest
 *    the impact point (u, w) = (0, 0), if one lies within seed_radius.
 * 4. Equivalent-area diameter from the hole's cell count.
 * 5. Largest circle: a squared Euclidean distance transform (Felzenszwalb and
 *    Huttenlocher 2012, "Distance transforms of sampled functions", Theory of
 *    Computing 8, 415) of the non-hole cells ranks the hole cells by their distance
 *    to the hole's edge; the best few start a compass search that maximises the exact
 *    distance to the rim particles (those within tol + 3c of the hole, found with a
 *    second transform whose sites are the hole cells) minus the footprint.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "diag/measure.h"
#include "diag/measure_rz.h"

#define PLATE_MAX_CELLS  4096 /* per side of the projection grid */
#define PLATE_CANDIDATES 8    /* starts of the circle search */

void meas_plate_defaults(struct meas_plate_params *par, const struct meas_geom *g)
{
  const double s = g->spacing;
  memset(par, 0, sizeof *par);
  par->tol = s;
  par->footprint = 0.5 * s;
  par->cell = 0.25 * s;
  par->slab_front = fmax(g->thickness, 2.0 * s);
  par->slab_rear = fmax(g->thickness, 2.0 * s);
  par->seed_radius = s;
  par->r_max = 0.0;
  par->mask = NULL;
  par->scale = NULL;
  par->attached_only = 1;
}

/* 1D squared distance transform of f along n samples (f[q] = INFINITY: no site);
 * v, z scratch of n and n + 1 entries. */
static void dt1d(const double *f, double *d, int n, int *v, double *z)
{
  int k = -1;
  for (int q = 0; q < n; q++) {
    if (!isfinite(f[q])) continue;
    const double fq = f[q] + (double)q * (double)q;
    double s = -INFINITY;
    while (k >= 0) {
      s = (fq - (f[v[k]] + (double)v[k] * (double)v[k])) / (2.0 * (double)(q - v[k]));
      if (s <= z[k])
        k--;
      else
        break;
    }
    if (k < 0) s = -INFINITY;
    k++;
    v[k] = q;
    z[k] = s;
  }
  if (k < 0) {
    for (int q = 0; q < n; q++) d[q] = INFINITY;
    return;
  }
  z[k + 1] = INFINITY;
  int j = 0;
  for (int q = 0; q < n; q++) {
    while (z[j + 1] < (double)q) j++;
    const double dq = (double)(q - v[j]);
    d[q] = dq * dq + f[v[j]];
  }
}

/* In place 2D squared distance transform of f[ny][nx] (0 at sites, INFINITY elsewhere),
 * in cell units squared. */
static void dt2d(double *f, int nx, int ny)
{
  const int m = nx > ny ? nx : ny;
  double *in = hv_malloc((size_t)m * sizeof *in, "distance transform");
  double *out = hv_malloc((size_t)m * sizeof *out, "distance transform");
  double *z = hv_malloc(((size_t)m + 1) * sizeof *z, "distance transform");
  int *v = hv_malloc((size_t)m * sizeof *v, "distance transform");
  for (int j = 0; j < ny; j++) {
    memcpy(in, f + (size_t)j * (size_t)nx, (size_t)nx * sizeof *in);
    dt1d(in, out, nx, v, z);
    memcpy(f + (size_t)j * (size_t)nx, out, (size_t)nx * sizeof *out);
  }
  for (int i = 0; i < nx; i++) {
    for (int j = 0; j < ny; j++) in[j] = f[(size_t)j * (size_t)nx + (size_t)i];
    dt1d(in, out, ny, v, z);
    for (int j = 0; j < ny; j++) f[(size_t)j * (size_t)nx + (size_t)i] = out[j];
  }
  free(in);
  free(out);
  free(z);
  free(v);
}

static int cell_lo(double a, double a0, double c) { return (int)ceil((a - a0) / c - 0.5); }
static int cell_hi(double a, double a0, double c) { return (int)floor((a - a0) / c - 0.5); }

/* The grid of the projection. */
struct pgrid {
  double u0, w0, c; /* lower corner [m], cell edge [m] */
  int nu, nw;
  unsigned char *occ; /* 0 empty, 1 material, 2 hole */
};

/* (u, w) lies in a hole cell. */
static int in_hole(const struct pgrid *G, double u, double w)
{
  const double a = floor((u - G->u0) / G->c), b = floor((w - G->w0) / G->c);
  if (!(a >= 0 && b >= 0 && a < G->nu && b < G->nw)) return 0;
  return G->occ[(size_t)b * (size_t)G->nu + (size_t)a] == 2;
}

/* Smallest distance from (u, w) to the edge of the points' footprints: min over k < n
 * of |(u, w) − (pts[2k], pts[2k+1])| − fp[k]. */
static double nearest(const double *pts, const double *fp, size_t n, double u, double w)
{
  double best = INFINITY;
  for (size_t k = 0; k < n; k++) {
    const double du = pts[2 * k] - u, dw = pts[2 * k + 1] - w;
    const double d = sqrt(du * du + dw * dw) - fp[k];
    if (d < best) best = d;
  }
  return best;
}

/* Compass search (16 directions, so that it can follow the ridge between two equally
 * near particles) for the largest nearest-point distance from the start (u, w), moving
 * only within the hole (so that it never climbs out through an open edge). */
static double compass(const struct pgrid *G, const double *pts, const double *fp, size_t n,
                      double *u, double *w)
{
  const double c = G->c;
  double best = nearest(pts, fp, n, *u, *w);
  double dir[16][2];
  for (int d = 0; d < 16; d++) {
    dir[d][0] = cos(d * (HV_MEAS_PI / 8));
    dir[d][1] = sin(d * (HV_MEAS_PI / 8));
  }
  for (double step = c; step > c / 256.0; step *= 0.5)
    for (int moves = 0; moves < 64; moves++) {
      int improved = 0;
      for (int d = 0; d < 16; d++) {
        const double tu = *u + step * dir[d][0], tw = *w + step * dir[d][1];
        if (!in_hole(G, tu, tw)) continue;
        const double r = nearest(pts, fp, n, tu, tw);
        if (r > best) {
          best = r;
          *u = tu;
          *w = tw;
          improved = 1;
        }
      }
      if (!improved) break;
    }
  return best;
}

struct cand {
  double r;
  size_t idx;
};

static int cand_cmp(const void *pa, const void *pb)
{
  const struct cand *a = pa, *b = pb;
  if (a->r > b->r) return -1;
  if (a->r < b->r) return 1;
  return a->idx < b->idx ? -1 : a->idx > b->idx;
}

/* Grows the 4-connected hole from cell `seed`; returns its size and sets its box and
 * whether it touches the grid's edge. */
static size_t flood(struct pgrid *G, size_t seed, int box[4], int *open)
{
  const size_t ncell = (size_t)G->nu * (size_t)G->nw;
  size_t *stack = hv_malloc((ncell + 1) * sizeof *stack, "hole fill");
  size_t top = 0, count = 0;
  box[0] = box[2] = G->nu;
  box[1] = box[3] = -1;
  *open = 0;
  G->occ[seed] = 2;
  stack[top++] = seed;
  while (top) {
    const size_t k = stack[--top];
    const int iu = (int)(k % (size_t)G->nu), iw = (int)(k / (size_t)G->nu);
    count++;
    if (iu < box[0]) box[0] = iu;
    if (iu > box[1]) box[1] = iu;
    if (iw < box[2]) box[2] = iw;
    if (iw > box[3]) box[3] = iw;
    if (iu == 0 || iw == 0 || iu == G->nu - 1 || iw == G->nw - 1) *open = 1;
    const int nb[4][2] = {{iu - 1, iw}, {iu + 1, iw}, {iu, iw - 1}, {iu, iw + 1}};
    for (int d = 0; d < 4; d++) {
      const int a = nb[d][0], b = nb[d][1];
      if (a < 0 || b < 0 || a >= G->nu || b >= G->nw) continue;
      const size_t q = (size_t)b * (size_t)G->nu + (size_t)a;
      if (G->occ[q] == 0) {
        G->occ[q] = 2;
        stack[top++] = q;
      }
    }
  }
  free(stack);
  return count;
}

static int check_params(const struct meas_geom *g, const struct meas_plate_params *par,
                        struct hv_error *err)
{
  if (!(g->spacing > 0 && isfinite(g->spacing)))
    return hv_error_set(err, HV_EXIT_INPUT, "plate measurement: spacing %g m must be positive",
                        g->spacing);
  if (!(par->tol > 0 && par->cell > 0 && par->footprint >= 0 && par->slab_front >= 0 &&
        par->slab_rear >= 0 && par->seed_radius >= 0 && par->r_max >= 0 && isfinite(par->tol) &&
        isfinite(par->cell) && isfinite(par->footprint) && isfinite(par->slab_front) &&
        isfinite(par->slab_rear) && isfinite(par->seed_radius) && isfinite(par->r_max)))
    return hv_error_set(err, HV_EXIT_INPUT,
                        "plate measurement: tol, cell (> 0), footprint, "
                        "slab margins, seed radius and r_max (>= 0) must be finite");
  if (!(g->thickness >= 0 && isfinite(g->thickness) && isfinite(g->x0) && isfinite(g->yc)))
    return hv_error_set(err, HV_EXIT_INPUT, "plate measurement: bad plate geometry");
  return 0;
}

/* The plate's particles: in the slab, of the body (and mask); with attached_only, only
 * those of the largest friends-of-friends group among them. Returns a new [p->n] mask
 * and the count left out as detached. */
static unsigned char *select_plate(const struct particles *p, const struct meas_geom *g,
                                   const struct meas_plate_params *par, size_t *ndetached,
                                   struct hv_error *err)
{
  const double xlo = g->x0 - par->slab_front, xhi = g->x0 + g->thickness + par->slab_rear;
  unsigned char *sel = hv_calloc(p->n + 1, 1, "plate selection");
  size_t nsel = 0;
  for (size_t i = 0; i < p->n; i++) {
    if (g->body >= 0 && p->body[i] != g->body) continue;
    if (par->mask && !par->mask[i]) continue;
    const double x = p->x[0][i], y = p->x[1][i], z = p->x[2][i];
    if (!(isfinite(x) && isfinite(y) && isfinite(z)) || x < xlo || x > xhi) continue;
    sel[i] = 1;
    nsel++;
  }
  *ndetached = 0;
  if (!par->attached_only || nsel == 0) return sel;
  if (meas_keep_largest_piece(p, g, par->scale, sel, err)) {
    free(sel);
    return NULL;
  }
  size_t after = 0;
  for (size_t i = 0; i < p->n; i++) after += sel[i] != 0;
  *ndetached = nsel - after;
  return sel;
}

/* Projected plate points (mirrored in a half model, at both planes in a quarter model):
 * returns their count (pairs in *pts, each point's scale Δ_i/Δ in *sc). */
static size_t project(const struct particles *p, const struct meas_geom *g,
                      const unsigned char *sel, const double *scale, double **pts, double **sc,
                      size_t *nplate)
{
  const size_t images = (size_t)meas_images(g->half_model, g->quarter_model);
  size_t np = 0, cnt = 0;
  double *q = hv_malloc((2 * images * p->n + 2) * sizeof *q, "plate points");
  double *f = hv_malloc((images * p->n + 1) * sizeof *f, "plate point scales");
  for (size_t i = 0; i < p->n; i++) {
    if (!sel[i]) continue;
    const double y = p->x[1][i], z = p->x[2][i], si = scale ? scale[i] : 1.0;
    cnt++;
    for (size_t c = 0; c < images; c++) { /* bit 0: −z, bit 1: −(y − yc) */
      q[2 * np] = c & 2u ? -(y - g->yc) : y - g->yc;
      q[2 * np + 1] = c & 1u ? -z : z;
      f[np++] = si;
    }
  }
  *pts = q;
  *sc = f;
  *nplate = cnt;
  return np;
}

/* Sets up the window and grid and marks the material cells. */
static void mark(struct pgrid *G, const double *pts, const double *sc, size_t np,
                 const struct meas_plate_params *par)
{
  double lo[2], hi[2];
  if (par->r_max > 0) {
    lo[0] = lo[1] = -par->r_max;
    hi[0] = hi[1] = par->r_max;
  } else {
    lo[0] = lo[1] = -par->seed_radius - par->cell;
    hi[0] = hi[1] = par->seed_radius + par->cell;
    for (size_t k = 0; k < np; k++)
      for (int d = 0; d < 2; d++) {
        lo[d] = fmin(lo[d], pts[2 * k + d] - sc[k] * par->tol);
        hi[d] = fmax(hi[d], pts[2 * k + d] + sc[k] * par->tol);
      }
  }
  double c = par->cell;
  const double span = fmax(hi[0] - lo[0], hi[1] - lo[1]);
  if (span / c > PLATE_MAX_CELLS) c = span / PLATE_MAX_CELLS;
  G->c = c;
  G->u0 = lo[0];
  G->w0 = lo[1];
  G->nu = (int)ceil((hi[0] - lo[0]) / c);
  G->nw = (int)ceil((hi[1] - lo[1]) / c);
  if (G->nu < 1) G->nu = 1;
  if (G->nw < 1) G->nw = 1;
  G->occ = hv_calloc((size_t)G->nu * (size_t)G->nw, 1, "plate projection");
  for (size_t k = 0; k < np; k++) {
    const double u = pts[2 * k], w = pts[2 * k + 1], tol = sc[k] * par->tol, t2 = tol * tol;
    int a0 = cell_lo(u - tol, G->u0, c), a1 = cell_hi(u + tol, G->u0, c);
    int b0 = cell_lo(w - tol, G->w0, c), b1 = cell_hi(w + tol, G->w0, c);
    if (a0 < 0) a0 = 0;
    if (b0 < 0) b0 = 0;
    if (a1 > G->nu - 1) a1 = G->nu - 1;
    if (b1 > G->nw - 1) b1 = G->nw - 1;
    for (int b = b0; b <= b1; b++) {
      const double dw = G->w0 + ((double)b + 0.5) * c - w;
      for (int a = a0; a <= a1; a++) {
        const double du = G->u0 + ((double)a + 0.5) * c - u;
        if (du * du + dw * dw <= t2) G->occ[(size_t)b * (size_t)G->nu + (size_t)a] = 1;
      }
    }
  }
}

/* The empty cell nearest (0, 0) within radius R; returns its index or SIZE_MAX. */
static size_t find_seed(const struct pgrid *G, double R)
{
  const double c = G->c;
  int a0 = cell_lo(-R, G->u0, c), a1 = cell_hi(R, G->u0, c);
  int b0 = cell_lo(-R, G->w0, c), b1 = cell_hi(R, G->w0, c);
  /* the cell holding the impact point is a candidate even when R < c/2 */
  const int ai = (int)floor((0.0 - G->u0) / c), bi = (int)floor((0.0 - G->w0) / c);
  if (ai < a0) a0 = ai;
  if (ai > a1) a1 = ai;
  if (bi < b0) b0 = bi;
  if (bi > b1) b1 = bi;
  size_t best = SIZE_MAX;
  double bd = INFINITY;
  for (int b = b0 < 0 ? 0 : b0; b <= b1 && b < G->nw; b++)
    for (int a = a0 < 0 ? 0 : a0; a <= a1 && a < G->nu; a++) {
      const size_t k = (size_t)b * (size_t)G->nu + (size_t)a;
      if (G->occ[k]) continue;
      const double du = G->u0 + ((double)a + 0.5) * c, dw = G->w0 + ((double)b + 0.5) * c;
      const double d = sqrt(du * du + dw * dw);
      const int inside = a == ai && b == bi;
      if ((d <= R || inside) && d < bd) {
        bd = d;
        best = k;
      }
    }
  return best;
}

/* Largest circle in the hole (steps 5 of the file header). */
static double largest_circle(const struct pgrid *G, const int box[4], const double *pts,
                             const double *sc, size_t np, const struct meas_plate_params *par,
                             double centre[2])
{
  const double c = G->c;
  double scmax = 1.0;
  for (size_t k = 0; k < np; k++) scmax = fmax(scmax, sc[k]);
  const int m = (int)ceil(scmax * par->tol / c) + 3;
  const int ru0 = box[0] - m, rw0 = box[2] - m;
  const int rnu = box[1] - box[0] + 1 + 2 * m, rnw = box[3] - box[2] + 1 + 2 * m;
  const size_t rn = (size_t)rnu * (size_t)rnw;
  double *dh = hv_malloc(rn * sizeof *dh, "hole distances"); /* to the non-hole cells */
  double *dr = hv_malloc(rn * sizeof *dr, "hole distances"); /* to the hole cells */
  for (int b = 0; b < rnw; b++)
    for (int a = 0; a < rnu; a++) {
      const int ga = ru0 + a, gb = rw0 + b;
      const int hole = ga >= 0 && gb >= 0 && ga < G->nu && gb < G->nw &&
                       G->occ[(size_t)gb * (size_t)G->nu + (size_t)ga] == 2;
      dh[(size_t)b * (size_t)rnu + (size_t)a] = hole ? (double)INFINITY : 0.0;
      dr[(size_t)b * (size_t)rnu + (size_t)a] = hole ? 0.0 : (double)INFINITY;
    }
  dt2d(dh, rnu, rnw);
  dt2d(dr, rnu, rnw);

  /* rim particles: within their tol + 3c of a hole cell centre; rfp their footprints */
  double *rim = hv_malloc((2 * np + 2) * sizeof *rim, "rim points");
  double *rfp = hv_malloc((np + 1) * sizeof *rfp, "rim footprints");
  size_t nrim = 0;
  for (size_t k = 0; k < np; k++) {
    const int a = (int)floor((pts[2 * k] - G->u0) / c) - ru0;
    const int b = (int)floor((pts[2 * k + 1] - G->w0) / c) - rw0;
    if (a < 0 || b < 0 || a >= rnu || b >= rnw) continue;
    if (sqrt(dr[(size_t)b * (size_t)rnu + (size_t)a]) * c > sc[k] * par->tol + 3.0 * c) continue;
    rim[2 * nrim] = pts[2 * k];
    rim[2 * nrim + 1] = pts[2 * k + 1];
    rfp[nrim++] = sc[k] * par->footprint;
  }

  /* candidates: the hole cells farthest from the hole's edge */
  struct cand best[PLATE_CANDIDATES];
  int nb = 0;
  for (size_t q = 0; q < rn; q++) {
    if (dh[q] == 0.0) continue;
    const struct cand cd = {sqrt(dh[q]) * c, q};
    if (nb < PLATE_CANDIDATES) {
      best[nb++] = cd;
      qsort(best, (size_t)nb, sizeof *best, cand_cmp);
    } else if (cand_cmp(&cd, &best[nb - 1]) < 0) {
      best[nb - 1] = cd;
      qsort(best, (size_t)nb, sizeof *best, cand_cmp);
    }
  }
  /* starts: the candidates, the hole's centroid, the impact point when it lies in the hole */
  double start[PLATE_CANDIDATES + 2][2];
  int nstart = 0;
  for (int k = 0; k < nb; k++) {
    const int a = (int)(best[k].idx % (size_t)rnu), b = (int)(best[k].idx / (size_t)rnu);
    start[nstart][0] = G->u0 + ((double)(ru0 + a) + 0.5) * c;
    start[nstart++][1] = G->w0 + ((double)(rw0 + b) + 0.5) * c;
  }
  double su = 0.0, sw = 0.0, sn = 0.0;
  for (int b = box[2]; b <= box[3]; b++)
    for (int a = box[0]; a <= box[1]; a++)
      if (G->occ[(size_t)b * (size_t)G->nu + (size_t)a] == 2) {
        su += G->u0 + ((double)a + 0.5) * c;
        sw += G->w0 + ((double)b + 0.5) * c;
        sn += 1.0;
      }
  if (sn > 0 && in_hole(G, su / sn, sw / sn)) {
    start[nstart][0] = su / sn;
    start[nstart++][1] = sw / sn;
  }
  if (in_hole(G, 0.0, 0.0)) {
    start[nstart][0] = 0.0;
    start[nstart++][1] = 0.0;
  }
  double r = -INFINITY;
  if (!nrim && nb) { /* no rim particle: the grid's estimate */
    const int a = (int)(best[0].idx % (size_t)rnu), b = (int)(best[0].idx / (size_t)rnu);
    r = best[0].r - 0.5 * c + par->tol - par->footprint;
    centre[0] = G->u0 + ((double)(ru0 + a) + 0.5) * c;
    centre[1] = G->w0 + ((double)(rw0 + b) + 0.5) * c;
  }
  for (int k = 0; nrim && k < nstart; k++) {
    double u = start[k][0], w = start[k][1];
    const double rk = compass(G, rim, rfp, nrim, &u, &w);
    if (rk > r) {
      r = rk;
      centre[0] = u;
      centre[1] = w;
    }
  }
  free(rim);
  free(rfp);
  free(dh);
  free(dr);
  return r;
}

int measure_plate(const struct particles *p, const struct meas_geom *g,
                  const struct meas_plate_params *par, struct meas_plate *out, struct hv_error *err)
{
  memset(out, 0, sizeof *out);
  if (check_params(g, par, err)) return -1;
  if (p->axisym && (g->yc != 0.0 || g->half_model))
    return hv_error_set(err, HV_EXIT_INPUT,
                        "plate measurement: the rings' axis is r = 0 (yc %g, half model %d)", g->yc,
                        g->half_model);
  unsigned char *sel = select_plate(p, g, par, &out->n_detached, err);
  if (!sel) return hv_error_prefix(err, "plate measurement: ");
  if (p->axisym) { /* rings: the hole about the axis directly (measure_rz.h) */
    measure_plate_rz(p, g, par, sel, out);
    free(sel);
    return 0;
  }
  double *pts, *sc;
  const size_t np = project(p, g, sel, par->scale, &pts, &sc, &out->n_plate);
  free(sel);
  struct pgrid G;
  mark(&G, pts, sc, np, par);
  out->cell = G.c;
  const size_t seed = find_seed(&G, par->seed_radius);
  if (seed != SIZE_MAX) {
    int box[4], open;
    const size_t count = flood(&G, seed, box, &open);
    out->perforated = 1;
    out->hole_open = open;
    out->area = (double)count * G.c * G.c;
    out->d_equiv = 2.0 * sqrt(out->area / HV_MEAS_PI) + 2.0 * (par->tol - par->footprint);
    double centre[2] = {0.0, 0.0};
    const double r = largest_circle(&G, box, pts, sc, np, par, centre);
    out->d_circle = 2.0 * fmax(r, 0.0);
    out->circle_center[0] = centre[0] + g->yc;
    out->circle_center[1] = centre[1];
    for (size_t k = 0; k < np; k++) sc[k] *= par->footprint; /* now the footprints */
    out->d_circle_impact = 2.0 * fmax(nearest(pts, sc, np, 0.0, 0.0), 0.0);
  }
  free(G.occ);
  free(pts);
  free(sc);
  return 0;
}
