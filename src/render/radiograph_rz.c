/* radiograph_rz.c — pictures of an axisymmetric run (p->axisym: rings in the (x, r)
 * half-plane, x the axis, m the ring's mass; particles.h).
 *
 * The picture is taken across the axis: x to the right, the radius up, the line of sight
 * z. Any line of sight perpendicular to the axis gives the same picture, so --axis y and
 * z are one view (y's box ranges are read with up = its z range) and --axis x, along the
 * axis, is refused.
 *
 * Particles mode: every ring drawn at (x, r) and, mirrored about the axis, at (x, −r)
 * (render_rz_halves; --no-mirror: the upper half only), as the cut of the body by a plane
 * through its axis. The slab along the line of sight (the --box's depth range) is not
 * used: every ring lies in the cut.
 *
 * Radiograph: the areal density σ(x, y) = ∫ρ dz through the body revolved about its axis,
 * the Abel projection of the rings' density field,
 *   σ(x, y) = 2 ∫_|y|^∞ ρ(x, r) r dr / √(r² − y²).
 * The field: each ring's mass spread evenly round its circle and smoothed in 3D by the
 * M4 kernel with the ring's h (so a ring near the axis is a blob on it, of its mass).
 * Rings with r < RZ_NEAR h are projected as that: np >= 8 points round the circle, at
 * most h apart, each of mass m/np, deposited exactly as a 3D particle of radiograph.c
 * (the kernel column F(s)/h² at (x, r cos φ)); equal steps in φ of a smooth periodic
 * function: the cylinder below moved by under 0.0002 when they were h/2 apart, which took
 * 1.27 times as long (216,030 rings at 1200 pixels, medians of 3 alternated runs, 3.24 s
 * and 2.56 s, measured 2026-12-07 at 8f45b28).
 * Farther rings (most of a body's) go through the meridional plane: a ring of radius
 * r ≫ h smoothed in 3D has the cross-section F(s)/h² (the kernel integrated along the
 * circle), so its mass is deposited, mass-conserving, with F onto cells of the picture's
 * pixel edge in x and r (r bins [k, k+1) pixels from the axis; what reaches across the
 * axis is folded back). Each cell k of a column is an annulus of volume π(2k + 1) pix³
 * and uniform density; the projection of that field is exact: the mean chord of a pixel
 * row [y0, y1) through annulus k is (area of the annulus ∩ the strip y0 <= y < y1 in the
 * (y, z) plane) / (y1 − y0), with the areas from
 *   ∫ 2√(R² − t²) dt = t√(R² − t²) + R² asin(t/R).
 * So Σ σ pix² is the rings' mass wherever the picture spans the body (rounding only).
 * Error (test_render: a solid cylinder of rings, R = 20 Δ, 60 Δ long, against
 * 2ρ√(R² − y²) in its middle, over |y| <= R − 3h): at most 0.9 % for h from Δ to 2Δ and
 * pixels from Δ/4 to Δ (0.5-0.6 % on the axis, 0.5 % at h = 1.3 Δ, pixel Δ/2); pixels
 * of 2Δ: 1.7 %, a pixel's mean against the profile at its centre near the edge. Within
 * 3h of the edge the smoothing of the boundary dominates, as in 3D.
 * Cells: the grid holds at most RZ_MAX_CELLS (nu columns × the bins up to the farthest
 * ring's r + 2h): a --box far smaller than the body cannot make a grid of the whole
 * body at its pixels, and rings beyond the grid's last bin are left out (their mass is
 * reported, and the picture's description says so).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "render/render_internal.h"

#define RZ_MAX_CELLS (1u << 23) /* 64 MiB of doubles for the (x, r) grid and the chords */
#define RZ_NEAR      4.0        /* rings with r < RZ_NEAR h: points around the ring */

int render_rz_options(const struct render_options *o, struct render_options *orz,
                      struct hv_error *err)
{
  if (o->axis == 0)
    return hv_error_set(err, HV_EXIT_USAGE,
                        "an axisymmetric snapshot is seen across its axis x: --axis y or z "
                        "(the same picture: x right, the radius up)");
  *orz = *o;
  orz->axis = 2;
  orz->mirror = 0; /* the halves are made by render_rz_halves */
  if (o->have_box) {
    if (o->axis == 1) { /* seen along y: up is z */
      orz->box[2] = o->box[4];
      orz->box[3] = o->box[5];
    }
    orz->box[4] = -HUGE_VAL; /* every ring lies in the cut z = 0 */
    orz->box[5] = HUGE_VAL;
  }
  return 0;
}

void render_rz_halves(const struct particles *p, int both, struct particles *q)
{
  particles_init(q);
  if (p->solid) particles_enable_solid(q);
  if (p->av) particles_enable_av(q);
  if (p->cracks) particles_enable_crack(q);
  const size_t n = p->n;
  particles_add(q, both ? 2 * n : n);
  struct pfield fp[HV_MAX_FIELDS], fq[HV_MAX_FIELDS];
  const int nf = particles_fields_all((struct particles *)p, fp);
  particles_fields_all(q, fq);
  for (int k = 0; k < nf; k++)
    for (int c = 0; c < fp[k].ncomp; c++) {
      if (!fp[k].comp[c] || !fq[k].comp[c]) continue;
      const size_t s = pf_type_size(fp[k].type);
      for (int copy = 0; copy <= both; copy++)
        if (n) memcpy((char *)fq[k].comp[c] + copy * n * s, fp[k].comp[c], n * s);
    }
  for (size_t i = n; both && i < 2 * n; i++) { /* the mirror image across y = 0 */
    q->x[1][i] = -q->x[1][i];
    q->v[1][i] = -q->v[1][i];
    if (q->solid) {
      q->S[T_XY][i] = -q->S[T_XY][i];
      q->S[T_YZ][i] = -q->S[T_YZ][i];
    }
  }
}

/* ∫_{-R}^{t} 2√(R² − s²) ds − (the same to 0): t√(R² − t²) + R² asin(t/R), t clamped to
   [−R, R]. */
static double chord_area(double t, double R)
{
  if (R <= 0.0) return 0.0;
  t = fmax(-R, fmin(R, t));
  return t * sqrt(fmax(R * R - t * t, 0.0)) + R * R * asin(t / R);
}

double render_areal_density_rz(const struct particles *p, const struct render_view *v,
                               double *sigma)
{
  const size_t nu = (size_t)v->nu, nv = (size_t)v->nv;
  memset(sigma, 0, nu * nv * sizeof *sigma);
  /* the bins: up to the farthest ring (with its support) whose kernel reaches the
     picture's columns; below the axis as far as a kernel reaches across it */
  double rtop = 0.0, below = 0.0;
  for (size_t i = 0; i < p->n; i++) {
    const double x = p->x[0][i], r = p->x[1][i], R = 2.0 * fabs(p->h[i]);
    if (!(p->m[i] > 0.0) || !(x + R > v->u0 && x - R < v->u1) || !isfinite(r)) continue;
    rtop = fmax(rtop, r + R);
    below = fmax(below, R - r);
  }
  size_t nr = (size_t)ceil(rtop / v->pix) + 1, nf = (size_t)ceil(below / v->pix) + 2;
  const size_t cap = RZ_MAX_CELLS / (nu > nv ? nu : nv);
  if (nr > cap / 2) nr = cap / 2;
  if (nf > cap - nr) nf = cap - nr;
  const size_t nrow = nf + nr;
  double *acc = hv_calloc(nrow * nu, sizeof *acc, "axisymmetric radiograph cells");
  struct render_columns *ct = render_columns_new();
  double left_out = 0.0;
  for (size_t i = 0; i < p->n; i++) {
    const double x = p->x[0][i], r = p->x[1][i], hp = fabs(p->h[i]) / v->pix;
    if (!(p->m[i] > 0.0)) continue;
    const double fu = (x - v->u0) / v->pix - 0.5, fv = r / v->pix - 0.5 + (double)nf;
    const double R = 2.0 * hp + 1.0;
    if (!(fu > -R && fu < (double)nu + R)) continue; /* outside the picture's columns; NaN */
    if (r < RZ_NEAR * fabs(p->h[i])) {               /* near the axis: the ring as points, in 3D */
      const int np = (int)fmax(8.0, ceil(2.0 * HV_RENDER_PI * r / fabs(p->h[i])));
      for (int k = 0; k < np; k++) {
        const double y = r * cos(2.0 * HV_RENDER_PI * (k + 0.5) / np);
        render_columns_deposit(ct, sigma, (int)nu, (int)nv, fu, (v->v1 - y) / v->pix - 0.5, hp,
                               p->m[i] / np);
      }
      continue;
    }
    if (!(fv - R < (double)nrow)) { /* beyond the grid */
      left_out += p->m[i];
      continue;
    }
    render_columns_deposit(ct, acc, (int)nu, (int)nrow, fu, fv, hp, p->m[i]);
  }
  free(ct);
  for (size_t k = 0; k < nf && k < nr; k++) /* fold: bin k takes its mirror, row nf-1-k */
    for (size_t i = 0; i < nu; i++) acc[(nf + k) * nu + i] += acc[(nf - 1 - k) * nu + i];
  /* w[k * nv + j]: the chord area of annulus k in pixel row j over the annulus' area
     π(2k + 1), in pixels: σ(i, j) pix² = Σ_k M_k w[k][j] */
  double *w = hv_malloc(nr * nv * sizeof *w, "axisymmetric radiograph chords");
  for (size_t k = 0; k < nr; k++)
    for (size_t j = 0; j < nv; j++) {
      const double y1 = v->v1 / v->pix - (double)j, y0 = y1 - 1.0; /* row j, pixel units */
      const double a = (double)k, b = a + 1.0;
      const double area =
          (chord_area(y1, b) - chord_area(y0, b)) - (chord_area(y1, a) - chord_area(y0, a));
      w[k * nv + j] = fmax(area, 0.0) / (HV_RENDER_PI * (2.0 * a + 1.0));
    }
  double *col = hv_malloc(nv * sizeof *col, "axisymmetric radiograph column");
  const double inv_area = 1.0 / (v->pix * v->pix);
  for (size_t i = 0; i < nu; i++) {
    int any = 0;
    memset(col, 0, nv * sizeof *col);
    for (size_t k = 0; k < nr; k++) {
      const double M = acc[(nf + k) * nu + i];
      if (M == 0.0) continue;
      any = 1;
      const double *wk = w + k * nv;
      for (size_t j = 0; j < nv; j++) col[j] += M * wk[j];
    }
    for (size_t j = 0; j < nv; j++) /* with the near rings' mass deposited there */
      sigma[j * nu + i] = (sigma[j * nu + i] + (any ? col[j] : 0.0)) * inv_area;
  }
  free(col);
  free(w);
  free(acc);
  return left_out;
}
