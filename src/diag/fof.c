/* fof.c — friends-of-friends fragments; see fof.h for the definition.
 *
 * 1. The selected particles with finite positions are copied, in slot order, into
 *    compact arrays (compact index k < k' iff slot i < i').
 * 2. A Morton cell grid with h_k = b_k/2 gives every pair that can be closer than
 *    (b_i + b_j)/2; each such pair with r² < ((b_i + b_j)/2)² is united.
 * 3. Union-find keeps the smaller index as the root of a merge, so every set's root
 *    is its smallest index whatever order the pairs come in: the labels, and all
 *    sums (taken in slot order), are deterministic.
 */
#include "diag/fof.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/snapshot.h"
#include "neighbours/grid.h"

void fof_result_init(struct fof_result *r) { memset(r, 0, sizeof *r); }

void fof_result_free(struct fof_result *r)
{
  free(r->frag);
  free(r->mat_mass);
  free(r->group);
  memset(r, 0, sizeof *r);
}

static uint32_t uf_find(uint32_t *parent, uint32_t k)
{
  while (parent[k] != k) {
    parent[k] = parent[parent[k]]; /* path halving */
    k = parent[k];
  }
  return k;
}

static void uf_union(uint32_t *parent, uint32_t a, uint32_t b)
{
  a = uf_find(parent, a);
  b = uf_find(parent, b);
  if (a == b) return;
  if (a < b)
    parent[b] = a;
  else
    parent[a] = b;
}

/* Sorting: full mass descending, then root ascending (a total order: roots differ). */
struct frag_key {
  double m;
  size_t root;
  size_t f;
};

static int frag_cmp(const void *pa, const void *pb)
{
  const struct frag_key *a = pa, *b = pb;
  if (a->m > b->m) return -1;
  if (a->m < b->m) return 1;
  return a->root < b->root ? -1 : a->root > b->root;
}

/* Unites every pair of the compact set closer than (b_i + b_j)/2 = h_i + h_j. */
static void link_pairs(const struct nbr_grid *g, const double *const xs[3], const double *hs,
                       uint32_t *parent)
{
  for (size_t c = 0; c < g->ncells; c++)
    for (uint32_t ii = g->cell_start[c]; ii < g->cell_start[c + 1]; ii++) {
      const uint32_t i = g->order[ii];
      const double xi = xs[0][i], yi = xs[1][i], zi = xs[2][i], hi = hs[i];
      for (uint32_t kk = g->nbr_start[c]; kk < g->nbr_start[c + 1]; kk++) {
        const int32_t nc = g->nbr_list[kk];
        for (uint32_t jj = g->cell_start[nc]; jj < g->cell_start[nc + 1]; jj++) {
          const uint32_t j = g->order[jj];
          if (j <= i) continue; /* each pair once */
          const double dx = xi - xs[0][j], dy = yi - xs[1][j], dz = zi - xs[2][j];
          const double reach = hi + hs[j];
          if (dx * dx + dy * dy + dz * dz < reach * reach) uf_union(parent, i, j);
        }
      }
    }
}

/* The working arrays of one fof_find: the selection's compact copy (positions, half
 * linking lengths), its union-find parents and its fragments before sorting. */
struct fof_work {
  size_t ns;          /* particles selected */
  uint32_t *sel;      /* their indices in the particles */
  double *xs[3], *hs; /* their positions, half linking lengths */
  double hmin, hmax;
  uint32_t *parent, *fid;  /* union-find parent; fragment of each, in slot order */
  size_t nf;               /* fragments */
  struct fof_fragment *fr; /* per fragment, in slot order */
  double *mm;              /* [nf][nmat] mass per material */
};

static void fof_work_free(struct fof_work *w)
{
  free(w->mm);
  free(w->fr);
  free(w->fid);
  free(w->parent);
  free(w->hs);
  for (int d = 0; d < 3; d++) free(w->xs[d]);
  free(w->sel);
}

/* 1. The selected particles with finite positions, copied compactly; out->b set.
 * Returns 0, or -1 with err set (a linking length not positive) and out freed. */
static int fof_select(const struct particles *p, const struct fof_params *par,
                      struct fof_result *out, struct fof_work *w, struct hv_error *err)
{
  const size_t n = p->n;
  size_t ns = 0;
  uint32_t *sel = w->sel = hv_malloc((n + 1) * sizeof *sel, "fof selection");
  double bmax = 0.0;
  for (size_t i = 0; i < n; i++) {
    if (par->mask && !par->mask[i]) continue;
    if (!(isfinite(p->x[0][i]) && isfinite(p->x[1][i]) && isfinite(p->x[2][i]))) {
      out->n_skipped++;
      continue;
    }
    const double bi = par->b_particle ? par->b_particle[i] : par->b;
    if (!(bi > 0.0 && isfinite(bi))) {
      free(sel);
      w->sel = NULL;
      fof_result_free(out);
      return hv_error_set(err, HV_EXIT_INPUT,
                          "friends-of-friends: linking length %g m of "
                          "particle %zu must be positive",
                          bi, i);
    }
    if (bi > bmax) bmax = bi;
    sel[ns++] = (uint32_t)i;
  }
  w->ns = ns;
  out->b = par->b_particle ? bmax : par->b;
  w->hs = hv_malloc((ns + 1) * sizeof *w->hs, "fof h");
  for (int d = 0; d < 3; d++) w->xs[d] = hv_malloc((ns + 1) * sizeof *w->xs[d], "fof positions");
  w->hmin = INFINITY;
  w->hmax = 0.0;
  for (size_t k = 0; k < ns; k++) {
    const size_t i = sel[k];
    for (int d = 0; d < 3; d++) w->xs[d][k] = p->x[d][i];
    w->hs[k] = 0.5 * (par->b_particle ? par->b_particle[i] : par->b);
    if (w->hs[k] < w->hmin) w->hmin = w->hs[k];
    if (w->hs[k] > w->hmax) w->hmax = w->hs[k];
  }
  return 0;
}

/* 2. Friends linked in w->parent through a neighbour grid of cell b. Returns 0 or the
 * error's code with err set (a span the grid cannot index). */
static int fof_link(struct fof_work *w, double b, struct hv_error *err)
{
  const size_t ns = w->ns;
  w->parent = hv_malloc((ns + 1) * sizeof *w->parent, "fof parents");
  for (size_t k = 0; k < ns; k++) w->parent[k] = (uint32_t)k;
  int rc = 0;
  if (ns > 1) { /* the grid indexes at most 2^21 cells a side: check before building it */
    for (int d = 0; d < 3 && !rc; d++) {
      double lo = INFINITY, hi = -INFINITY;
      for (size_t k = 0; k < ns; k++) {
        lo = fmin(lo, w->xs[d][k]);
        hi = fmax(hi, w->xs[d][k]);
      }
      const double cells = (hi - lo) / nbr_cell_size(w->hmin, w->hmax);
      if (!(cells < 2.0e6))
        rc = hv_error_set(err, HV_EXIT_RUN,
                          "friends-of-friends: the particles span %g m in %c, "
                          "%g linking lengths of %g m (at most 2e6)",
                          hi - lo, "xyz"[d], cells, b);
    }
  }
  if (ns > 1 && !rc) {
    struct nbr_grid g;
    nbr_grid_init(&g);
    char msg[256];
    if (nbr_grid_build(&g, (const double *const *)w->xs, w->hs, ns, nbr_cell_size(w->hmin, w->hmax),
                       msg, sizeof msg)) {
      rc =
          hv_error_set(err, HV_EXIT_RUN, "friends-of-friends with linking length %g m: %s", b, msg);
    } else {
      link_pairs(&g, (const double *const *)w->xs, w->hs, w->parent);
    }
    nbr_grid_free(&g);
  }
  return rc;
}

/* 3. The fragments labelled in slot order and summed: mass, centre of mass, velocity,
 * mass per material; in a half model one that touches the plane is doubled with its
 * mirror image, the others count twice; in a quarter model each plane it touches doubles
 * it (it is one piece with its image there) and each it does not touch doubles its
 * count (1, 2 or 4 fragments of the full picture). */
static void fof_sum(const struct particles *p, const struct fof_params *par, struct fof_work *w)
{
  const size_t ns = w->ns;
  const uint32_t *sel = w->sel;
  uint32_t *fid = w->fid = hv_malloc((ns + 1) * sizeof *fid, "fof ids");
  size_t nf = 0;
  for (size_t k = 0; k < ns; k++) {
    const uint32_t r = uf_find(w->parent, (uint32_t)k);
    fid[k] = r == k ? (uint32_t)nf++ : fid[r]; /* the root (smallest) comes first */
  }
  w->nf = nf;
  struct fof_fragment *fr = w->fr = hv_calloc(nf + 1, sizeof *fr, "fragments");
  double *mm = w->mm = hv_calloc(nf * (size_t)par->nmat + 1, sizeof *mm, "fragment materials");
  unsigned char *on_plane = hv_calloc(nf + 1, 1, "fof plane flags"); /* bit 0 z, bit 1 y */
  for (size_t k = 0; k < ns; k++) {
    const size_t i = sel[k];
    struct fof_fragment *f = &fr[fid[k]];
    const double m = p->m[i];
    if (f->count == 0) {
      f->root = i;
      f->root_id = p->id[i];
    }
    f->count++;
    f->m += m;
    for (int d = 0; d < 3; d++) {
      f->x[d] += m * p->x[d][i];
      f->v[d] += m * p->v[d][i];
    }
    const int mat = p->mat[i];
    if (mat >= 0 && mat < par->nmat) mm[fid[k] * (size_t)par->nmat + (size_t)mat] += m;
    if (par->half_model && p->x[2][i] < w->hs[k]) on_plane[fid[k]] |= 1;    /* z < b_i/2 */
    if (par->quarter_model && p->x[1][i] < w->hs[k]) on_plane[fid[k]] |= 2; /* y < b_i/2 */
  }
  for (size_t f = 0; f < nf; f++) {
    struct fof_fragment *q = &fr[f];
    for (int d = 0; d < 3; d++) {
      q->x[d] = q->m > 0 ? q->x[d] / q->m : 0.0;
      q->v[d] = q->m > 0 ? q->v[d] / q->m : 0.0;
    }
    q->multiplicity = 1;
    for (int d = 2; d >= 1; d--) {
      const int bit = d == 2 ? 1 : 2;
      if (!(d == 2 ? par->half_model : par->quarter_model)) continue;
      if (!(on_plane[f] & bit)) {
        q->multiplicity *= 2; /* a mirror twin across this plane */
        continue;
      }
      q->m *= 2.0;               /* one fragment with its mirror image across this plane */
      if (d == 1) q->count *= 2; /* the half model's particles: its image's too */
      q->x[d] = 0.0;
      q->v[d] = 0.0;
      for (int k = 0; k < par->nmat; k++) mm[f * (size_t)par->nmat + (size_t)k] *= 2.0;
    }
  }
  free(on_plane);
}

/* 4. The fragments sorted (frag_cmp) and renumbered into out. */
static void fof_sort(const struct fof_params *par, const struct fof_work *w, struct fof_result *out)
{
  const size_t nf = w->nf;
  const struct fof_fragment *fr = w->fr;
  struct frag_key *key = hv_malloc((nf + 1) * sizeof *key, "fof sort");
  for (size_t f = 0; f < nf; f++) key[f] = (struct frag_key){fr[f].m, fr[f].root, f};
  qsort(key, nf, sizeof *key, frag_cmp);
  uint32_t *rank = hv_malloc((nf + 1) * sizeof *rank, "fof ranks");
  out->frag = hv_malloc((nf + 1) * sizeof *out->frag, "fragments");
  out->mat_mass = hv_calloc(nf * (size_t)par->nmat + 1, sizeof *out->mat_mass, "fragments");
  for (size_t r = 0; r < nf; r++) {
    const size_t f = key[r].f;
    rank[f] = (uint32_t)r;
    out->frag[r] = fr[f];
    memcpy(out->mat_mass + r * (size_t)par->nmat, w->mm + f * (size_t)par->nmat,
           (size_t)par->nmat * sizeof *w->mm);
    out->n_full += (size_t)fr[f].multiplicity;
    out->m_total += fr[f].m * fr[f].multiplicity;
  }
  for (size_t k = 0; k < w->ns; k++) out->group[w->sel[k]] = (int32_t)rank[w->fid[k]];
  out->nfrag = nf;
  free(rank);
  free(key);
}

int fof_find(const struct particles *p, const struct fof_params *par, struct fof_result *out,
             struct hv_error *err)
{
  fof_result_init(out);
  const size_t n = p->n;
  if (!par->b_particle && !(par->b > 0.0 && isfinite(par->b)))
    return hv_error_set(err, HV_EXIT_INPUT,
                        "friends-of-friends: linking length %g m must be "
                        "positive",
                        par->b);
  if (par->nmat < 0)
    return hv_error_set(err, HV_EXIT_INPUT, "friends-of-friends: negative material count");
  out->n = n;
  out->nmat = par->nmat;
  out->group = hv_malloc((n + 1) * sizeof *out->group, "fof groups");
  for (size_t i = 0; i < n; i++) out->group[i] = -1;
  struct fof_work w = {0};
  if (fof_select(p, par, out, &w, err)) return -1;
  const int rc = fof_link(&w, out->b, err);
  if (rc) {
    fof_work_free(&w);
    fof_result_free(out);
    return rc;
  }
  fof_sum(p, par, &w);
  fof_sort(par, &w, out);
  fof_work_free(&w);
  return 0;
}

size_t fof_count_min(const struct fof_result *r, size_t nmin)
{
  size_t c = 0;
  for (size_t f = 0; f < r->nfrag; f++)
    if (r->frag[f].count >= nmin) c += (size_t)r->frag[f].multiplicity;
  return c;
}

/* A material name usable as a CSV column: no comma, quote or line break. */
static int name_ok(const char *s) { return s && *s && !strpbrk(s, ",\"\r\n") && strlen(s) < 56; }

int fof_write_csv(const char *path, const struct fof_result *r, double time,
                  const char *const *material_names, const char *comment, struct hv_error *err)
{
  enum { NFIX = 11 };
  static const char *const fixed[NFIX] = {"rank", "mass", "multiplicity", "count", "x",      "y",
                                          "z",    "vx",   "vy",           "vz",    "root_id"};
  const int ncols = NFIX + r->nmat;
  char(*names)[64] = hv_malloc(((size_t)r->nmat + 1) * sizeof *names, "fragment columns");
  const char **cols = hv_malloc((size_t)ncols * sizeof *cols, "fragment columns");
  for (int c = 0; c < NFIX; c++) cols[c] = fixed[c];
  for (int k = 0; k < r->nmat; k++) {
    const char *nm = material_names ? material_names[k] : NULL;
    if (name_ok(nm))
      snprintf(names[k], sizeof names[k], "m_%s", nm);
    else
      snprintf(names[k], sizeof names[k], "m_mat%d", k);
    cols[NFIX + k] = names[k];
  }
  double *rows = hv_malloc((r->nfrag * (size_t)ncols + 1) * sizeof *rows, "fragment rows");
  for (size_t f = 0; f < r->nfrag; f++) {
    const struct fof_fragment *q = &r->frag[f];
    double *row = rows + f * (size_t)ncols;
    row[0] = (double)f;
    row[1] = q->m;
    row[2] = q->multiplicity;
    row[3] = (double)q->count;
    for (int d = 0; d < 3; d++) {
      row[4 + d] = q->x[d];
      row[7 + d] = q->v[d];
    }
    row[10] = (double)q->root_id;
    for (int k = 0; k < r->nmat; k++) row[NFIX + k] = r->mat_mass[f * (size_t)r->nmat + (size_t)k];
  }
  size_t clen = (comment ? strlen(comment) : 0) + 512;
  char *text = hv_malloc(clen, "fragment comment");
  snprintf(text, clen,
           "%s%stime %.17g s; friends-of-friends linking length %.17g m; %zu "
           "fragments (%zu in the full picture), largest first; SI units; definitions in "
           "docs/measurements.md",
           comment ? comment : "", comment ? "\n" : "", time, r->b, r->nfrag, r->n_full);
  int rc = 0;
  if (r->nfrag > (size_t)0x7fffffff)
    rc = hv_error_set(err, HV_EXIT_RUN, "cannot write '%s': too many fragments", path);
  else
    rc = io_write_table_csv(path, cols, ncols, rows, (int)r->nfrag, text, err);
  free(text);
  free(rows);
  free(cols);
  free(names);
  return rc;
}
