/* scatter.c — particles mode: each particle a disc, far ones first.
 *
 * Disc radius 0.6 h on the picture (with h = 1.2 Δ that is 0.72 Δ, just over the 0.71 Δ
 * that closes the diagonal gaps of a cubic lattice seen face on), at least 0.7 pixel so
 * that lone fragments stay visible; edges are anti-aliased by pixel coverage, and discs of
 * 3 pixels or more get a darker rim so that single particles can be told apart in a dense
 * body. The viewer sits on the
 * negative side of the view axis: discs are drawn in order of decreasing depth
 * (painter's algorithm; equal depths by particle order, so pictures are reproducible).
 */
#include <limits.h>
#include <math.h>
#include <stdlib.h>

#include "render/render_internal.h"

struct disc {
  double depth;  /* [m] along the line of sight */
  double fu, fv; /* picture position [px], integers at pixel centres */
  double r;      /* [px] */
  double value;  /* colour quantity (SI), or material index */
  size_t order;  /* tie-break */
};

static int disc_cmp(const void *a, const void *b)
{
  const struct disc *x = a, *y = b;
  if (x->depth != y->depth) return x->depth > y->depth ? -1 : 1;
  return x->order < y->order ? -1 : x->order > y->order;
}

static double particle_value(const struct particles *p, size_t i, enum render_color c)
{
  switch (c) {
  case RENDER_COLOR_DAMAGE: return p->damage ? p->damage[i] : 0.0;
  case RENDER_COLOR_VELOCITY:
    return sqrt(p->v[0][i] * p->v[0][i] + p->v[1][i] * p->v[1][i] + p->v[2][i] * p->v[2][i]);
  case RENDER_COLOR_PRESSURE: return p->p[i];
  case RENDER_COLOR_DENSITY: return p->rho[i];
  case RENDER_COLOR_ALPHA: return p->alpha ? p->alpha[i] : 0.0;
  case RENDER_COLOR_DT: return p->dt[i] > 0.0 ? log10(p->dt[i]) : (double)NAN; /* not drawn */
  case RENDER_COLOR_MATERIAL: break;
  }
  return (double)p->mat[i];
}

static void draw_disc(struct canvas *c, const struct render_view *v, const struct disc *d,
                      const unsigned char rgb[3])
{
  unsigned char rim[3] = {(unsigned char)(0.62 * rgb[0]), (unsigned char)(0.62 * rgb[1]),
                          (unsigned char)(0.62 * rgb[2])};
  int rimmed = d->r >= 3.0;
  /* clipped to the plot area before the conversion to int (a disc may span more than
   * INT_MAX pixels) */
  const int i0 = (int)fmax(floor(d->fu - d->r - 1), 0.0),
            i1 = (int)fmin(ceil(d->fu + d->r + 1), v->nu - 1.0);
  const int j0 = (int)fmax(floor(d->fv - d->r - 1), 0.0),
            j1 = (int)fmin(ceil(d->fv + d->r + 1), v->nv - 1.0);
  for (int j = j0; j <= j1; j++)
    for (int i = i0; i <= i1; i++) {
      double dist = hypot(i - d->fu, j - d->fv);
      double a = d->r + 0.5 - dist; /* coverage of the pixel, roughly */
      if (a <= 0.0) continue;
      canvas_blend(c, i, j, rimmed && dist > d->r - 1.0 ? rim : rgb, a);
    }
}

void render_material_first_body(const struct particles *p, int nmat, int *first)
{
  for (size_t i = 0; i < p->n; i++) {
    const int m = p->mat[i], b = p->body[i];
    if (m >= 0 && m < nmat && b >= 0 && b < first[m]) first[m] = b;
  }
}

void render_material_rank(const int *first, int nmat, int *slot)
{
  for (int m = 0; m < nmat; m++) { /* rank: materials ahead of m by (first body, index) */
    slot[m] = 0;
    for (int k = 0; k < nmat; k++)
      if (first[k] < first[m] || (first[k] == first[m] && k < m)) slot[m]++;
  }
}

void render_material_slots(const struct particles *p, int nmat, int *slot)
{
  int *first = hv_malloc((size_t)nmat * sizeof *first, "material slots");
  for (int m = 0; m < nmat; m++) first[m] = INT_MAX;
  render_material_first_body(p, nmat, first);
  render_material_rank(first, nmat, slot);
  free(first);
}

/* The disc of particle i (copy 1: its mirror image across z = 0; 2, 3: across y = 0 as
 * well, render_copy_pos) in view v; 0 when it is not drawn (a mirror that is off,
 * outside the slab, off the picture, or not finite). */
static int make_disc(const struct particles *p, size_t i, int copy, const struct render_view *v,
                     enum render_color color, struct disc *q)
{
  double x[3];
  if (!render_copy_pos(p, i, copy, v, x)) return 0;
  double depth = x[v->axis];
  if (!(depth >= v->d0 && depth <= v->d1)) return 0;
  q->depth = depth;
  q->fu = (x[v->iu] - v->u0) / v->pix - 0.5;
  q->fv = (v->v1 - x[v->iv]) / v->pix - 0.5;
  q->r = fmax(0.6 * fabs(p->h[i]) / v->pix, 0.7);
  if (!(q->fu > -q->r - 1 && q->fv > -q->r - 1 && q->fu < v->nu + q->r + 1 &&
        q->fv < v->nv + q->r + 1))
    return 0; /* off the picture, or not finite */
  q->value = particle_value(p, i, color);
  return 1;
}

void render_color_extend(const struct particles *p, const struct render_view *v,
                         const struct render_options *o, double *lo, double *hi)
{
  struct disc q;
  for (size_t i = 0; i < p->n; i++)
    for (int copy = 0; copy < RENDER_COPIES; copy++)
      if (make_disc(p, i, copy, v, o->color, &q) && isfinite(q.value)) {
        *lo = fmin(*lo, q.value);
        *hi = fmax(*hi, q.value);
      }
}

void render_color_limits(const struct render_options *o, double *lo, double *hi)
{
  if (o->have_range) {
    *lo = o->range[0];
    *hi = o->range[1];
  } else if (o->color == RENDER_COLOR_DAMAGE || !(*lo <= *hi)) {
    *lo = 0.0;
    *hi = 1.0;
  } else if (*hi - *lo <= 1e-12 * fmax(fabs(*lo), fabs(*hi))) {
    double pad = *lo != 0.0 ? 0.05 * fabs(*lo) : 1.0; /* one value: a band around it */
    *lo -= pad;
    *hi += pad;
  }
}

size_t render_discs(struct canvas *c, const struct particles *p, const struct render_view *v,
                    const struct render_options *o, double *lo, double *hi, unsigned char *present,
                    const int *slot, int nmat_present)
{
  size_t cap = p->n * (size_t)((v->mirror + 1) * (v->mirror_y + 1)), n = 0;
  struct disc *d = hv_malloc((cap ? cap : 1) * sizeof *d, "particle discs");
  double vmin = HUGE_VAL, vmax = -HUGE_VAL;
  for (size_t i = 0; i < p->n; i++)
    for (int copy = 0; copy < RENDER_COPIES; copy++) {
      struct disc *q = &d[n];
      if (!make_disc(p, i, copy, v, o->color, q)) continue;
      q->order = n;
      if (o->color == RENDER_COLOR_MATERIAL) {
        if (p->mat[i] >= 0 && p->mat[i] < nmat_present) present[p->mat[i]] = 1;
      } else if (isfinite(q->value)) {
        vmin = fmin(vmin, q->value);
        vmax = fmax(vmax, q->value);
      }
      n++;
    }
  render_color_limits(o, &vmin, &vmax);
  qsort(d, n, sizeof *d, disc_cmp);
  for (size_t k = 0; k < n; k++) {
    unsigned char rgb[3];
    if (o->color == RENDER_COLOR_MATERIAL) {
      const int m = (int)d[k].value;
      render_palette(m >= 0 && m < nmat_present ? slot[m] : m, rgb);
    } else
      render_colormap((d[k].value - vmin) / (vmax - vmin), rgb);
    draw_disc(c, v, &d[k], rgb);
  }
  free(d);
  *lo = vmin;
  *hi = vmax;
  return n;
}
