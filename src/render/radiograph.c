/* radiograph.c — simulated flash radiograph: areal density and film.
 *
 * Areal density. A particle of mass m and smoothing length h at (u, v) contributes
 *   σ(u', v') = m Σ(R, h),  Σ(R, h) = F(R/h) / h²,  R = |(u', v') − (u, v)|,
 *   F(s) = ∫ W₁(√(s² + t²)) dt   (W₁: the M4 cubic spline of kernel.h with h = 1),
 * the kernel integrated along the line of sight, so that Σ over all particles is the
 * column integral ∫ρ dl of the SPH density field. F is tabulated (Simpson's rule, 2048
 * intervals in s, 512 in t) for every picture. Deposition onto the pixels conserves mass:
 *   - footprint (radius 2h) under 1 pixel: the mass goes to the four nearest pixel
 *     centres with bilinear (cloud-in-cell) weights;
 *   - 1 to 12 pixels: F sampled at 4 × 4 (under 4 px) or 2 × 2 points per pixel over the
 *     whole footprint and the weights normalised to sum to one;
 *   - wider: F at the pixel centres times pix²/h² (the midpoint rule of ∫Σ dA = 1).
 * The pixel then holds mass / pix² [kg/m²]. Mass whose kernel reaches past the picture
 * edge is lost there only.
 *
 * Film. The fraction of the x-ray beam transmitted through the column is
 *   T = exp(−μ σ),
 * with one mass attenuation coefficient μ for every material (grey approximation). The
 * grey level is 255·T: white where nothing absorbs, dark where the column is dense, like
 * a print of a flash radiograph.
 *
 * Exposure. A fixed μ suits one kind of scene only: 0.05 m²/kg (iron near 90 keV) shows a
 * steel plate but leaves a 1.5 mm aluminium bumper at T = 0.82 and its debris, a tenth
 * of that column, at T = 0.98: white on white. So unless --mu gives it, μ is picked per
 * picture as an exposure is picked for an experiment: the lower quartile of the areal
 * densities of the pixels that hold a particle's centre gets T = 1/2, mid grey
 * (render_auto_mu, render_occupied). A quarter of the material's columns are then
 * lighter than mid grey, three quarters darker; 8 bits resolve columns from a tenth of
 * the quartile (T = 0.93, 17 grey levels below white) to eight times it (T = 1/256).
 *   - A quantile, not the mean or the peak: one dense column (a plate seen edge on)
 *     must not decide the exposure of a picture that is mostly debris.
 *   - The lower quartile, not the median: the thin material is what a fixed exposure
 *     loses and what the picture is for (debris); the dense parts are dark at any
 *     exposure. Plates seen edge on can fill nearly half of the occupied pixels (the
 *     demo's W.P.1: docs/rendering.md, "Radiograph mode"): a median would jump onto
 *     them where they fill over half, the lower quartile stays in the debris until they
 *     fill three quarters.
 *   - Pixels, not particles, so that a plate seen edge on, many particles deep, counts
 *     by its area, not by its particles.
 *   - Pixels holding a particle's centre, not every pixel with σ > 0, because the
 *     kernels' rims are thin: over the footprint of a lone particle the median column is
 *     1/24.5 of the one through its centre (the column-integrated M4 kernel at 1.41 h
 *     against 0), so a picture of scattered debris exposed by all its non-empty pixels
 *     shows every particle black.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "kernel/kernel.h"
#include "render/render_internal.h"

#define COL_N  2048 /* table intervals for s in [0, 2] */
#define COL_NT 512  /* Simpson intervals along the line of sight */
#define NARROW 12   /* [px] footprint radius up to which weights are normalised numerically */

double render_kernel_column(double s)
{
  s = fabs(s);
  if (s >= 2.0) return 0.0;
  double L = sqrt(4.0 - s * s), dt = L / COL_NT, sum = 0.0;
  for (int k = 0; k <= COL_NT; k++) {
    double t = k * dt, w = kernel_w(KERNEL_CUBIC_SPLINE, sqrt(s * s + t * t), 1.0);
    sum += w * (k == 0 || k == COL_NT ? 1.0 : (k % 2 ? 4.0 : 2.0));
  }
  return 2.0 * sum * dt / 3.0; /* both halves of the line */
}

struct column_table {
  double f[COL_N + 2];
};

static void column_table_fill(struct column_table *c)
{
  for (int k = 0; k <= COL_N; k++) c->f[k] = render_kernel_column(2.0 * k / COL_N);
  c->f[COL_N + 1] = 0.0;
}

/* F(s) by linear interpolation in the table. */
static double column_at(const struct column_table *c, double s)
{
  double x = s * (COL_N / 2.0);
  if (!(x < COL_N)) return 0.0;
  int k = (int)x;
  double f = x - k;
  return c->f[k] + f * (c->f[k + 1] - c->f[k]);
}

/* Spreads mass m at picture position (fu, fv) [pixel units; integers are pixel centres]
 * into acc (mass per pixel). hp = h / pix. */
static void deposit(double *acc, int nu, int nv, const struct column_table *ct, double fu,
                    double fv, double hp, double m)
{
  double R = 2.0 * hp;
  if (R < 1.0) { /* cloud in cell */
    double fi = floor(fu), fj = floor(fv), a = fu - fi, b = fv - fj;
    double w[4] = {(1 - a) * (1 - b), a * (1 - b), (1 - a) * b, a * b};
    for (int k = 0; k < 4; k++) {
      double i = fi + (k & 1), j = fj + (k >> 1);
      if (i >= 0 && j >= 0 && i < nu && j < nv) acc[(size_t)j * (size_t)nu + (size_t)i] += m * w[k];
    }
    return;
  }
  if (R >= NARROW) { /* wide kernel: midpoint rule, normalised analytically */
    /* the pixel range clipped to the picture before it becomes an int: a kernel may span
     * more than INT_MAX pixels */
    const int i0 = (int)fmax(floor(fu - R), 0.0), i1 = (int)fmin(ceil(fu + R), nu - 1.0),
              j0 = (int)fmax(floor(fv - R), 0.0), j1 = (int)fmin(ceil(fv + R), nv - 1.0);
    double scale = m / (hp * hp), inv = 1.0 / hp, R2 = R * R;
    for (int j = j0; j <= j1; j++) {
      double dv2 = (j - fv) * (j - fv);
      double *row = acc + (size_t)j * (size_t)nu;
      for (int i = i0; i <= i1; i++) {
        double r2 = (i - fu) * (i - fu) + dv2;
        if (r2 < R2) row[i] += scale * column_at(ct, sqrt(r2) * inv);
      }
    }
    return;
  }
  /* narrow kernel: weights on a sub-sampled grid over the whole footprint, normalised */
  const int i0 = (int)floor(fu - R), i1 = (int)ceil(fu + R), j0 = (int)floor(fv - R),
            j1 = (int)ceil(fv + R);
  double w[(2 * NARROW + 4) * (2 * NARROW + 4)];
  int ns = R < 4.0 ? 4 : 2, wi = i1 - i0 + 1;
  double total = 0.0, inv = 1.0 / hp;
  for (int j = j0; j <= j1; j++)
    for (int i = i0; i <= i1; i++) {
      double sum = 0.0;
      for (int sj = 0; sj < ns; sj++)
        for (int si = 0; si < ns; si++) {
          double du = i + (si + 0.5) / ns - 0.5 - fu, dv = j + (sj + 0.5) / ns - 0.5 - fv;
          sum += column_at(ct, sqrt(du * du + dv * dv) * inv);
        }
      w[(j - j0) * wi + (i - i0)] = sum;
      total += sum;
    }
  if (!(total > 0.0)) return; /* cannot happen for R >= 1; kept for safety */
  double scale = m / total;
  for (int j = j0 < 0 ? 0 : j0; j <= j1 && j < nv; j++)
    for (int i = i0 < 0 ? 0 : i0; i <= i1 && i < nu; i++)
      acc[(size_t)j * (size_t)nu + (size_t)i] += scale * w[(j - j0) * wi + (i - i0)];
}

void render_areal_density(const struct particles *p, const struct render_view *view, double *sigma)
{
  const struct render_view *v = view;
  size_t npix = (size_t)v->nu * (size_t)v->nv;
  memset(sigma, 0, npix * sizeof *sigma);
  struct column_table *ct = hv_malloc(sizeof *ct, "kernel column table");
  column_table_fill(ct);
  for (size_t i = 0; i < p->n; i++)
    for (int copy = 0; copy < RENDER_COPIES; copy++) {
      double x[3];
      if (!render_copy_pos(p, i, copy, v, x)) continue;
      double d = x[v->axis];
      if (!(d >= v->d0 && d <= v->d1) || !(p->m[i] > 0.0)) continue;
      double fu = (x[v->iu] - v->u0) / v->pix - 0.5, fv = (v->v1 - x[v->iv]) / v->pix - 0.5;
      double hp = fabs(p->h[i]) / v->pix, R = 2.0 * hp + 1.0;
      if (!(fu > -R && fv > -R && fu < v->nu + R && fv < v->nv + R)) continue; /* NaN too */
      deposit(sigma, v->nu, v->nv, ct, fu, fv, hp, p->m[i]);
    }
  free(ct);
  double inv_area = 1.0 / (v->pix * v->pix);
  for (size_t k = 0; k < npix; k++) sigma[k] *= inv_area;
}

static int cmp_double(const void *a, const void *b)
{
  const double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

double render_auto_mu(const double *sigma, const unsigned char *occupied, size_t npix,
                      double *quartile)
{
  size_t n = 0;
  for (size_t k = 0; k < npix; k++) n += sigma[k] > 0.0 && (!occupied || occupied[k]);
  *quartile = 0.0;
  if (n == 0) return RENDER_MU_FALLBACK;
  double *s = hv_malloc(n * sizeof *s, "areal densities");
  n = 0;
  for (size_t k = 0; k < npix; k++)
    if (sigma[k] > 0.0 && (!occupied || occupied[k])) s[n++] = sigma[k];
  qsort(s, n, sizeof *s, cmp_double);
  const double q = s[(n - 1) / 4]; /* the lower quartile (nearest rank) */
  free(s);
  const double mu = log(2.0) / q;
  if (!(mu > 0.0 && isfinite(mu))) return RENDER_MU_FALLBACK; /* σ of 1e-320: underflow */
  *quartile = q;
  return mu;
}

void render_occupied(const struct particles *p, const struct render_view *v,
                     unsigned char *occupied)
{
  memset(occupied, 0, (size_t)v->nu * (size_t)v->nv);
  for (size_t i = 0; i < p->n; i++)
    for (int copy = 0; copy < RENDER_COPIES; copy++) {
      double x[3];
      if (!render_copy_pos(p, i, copy, v, x)) continue;
      if (!(x[v->axis] >= v->d0 && x[v->axis] <= v->d1) || !(p->m[i] > 0.0)) continue;
      const double fu = (x[v->iu] - v->u0) / v->pix, fv = (v->v1 - x[v->iv]) / v->pix;
      if (!(fu >= 0.0 && fv >= 0.0 && fu < v->nu && fv < v->nv)) continue; /* NaN too */
      occupied[(size_t)fv * (size_t)v->nu + (size_t)fu] = 1;
    }
}

void render_film(struct canvas *c, const struct render_view *view, const double *sigma, double mu)
{
  for (int j = 0; j < view->nv && j < c->h; j++)
    for (int i = 0; i < view->nu && i < c->w; i++) {
      double T = exp(-mu * sigma[(size_t)j * (size_t)view->nu + (size_t)i]);
      unsigned char g = (unsigned char)lround(255.0 * T);
      unsigned char *q = c->rgb + 3 * ((size_t)j * (size_t)c->w + (size_t)i);
      q[0] = q[1] = q[2] = g;
    }
}

/* The column table and deposition above, for the axisymmetric radiograph
 * (radiograph_rz.c), which spreads each ring over the meridional plane with them. */
struct render_columns {
  struct column_table t;
};

struct render_columns *render_columns_new(void)
{
  struct render_columns *c = hv_malloc(sizeof *c, "kernel column table");
  column_table_fill(&c->t);
  return c;
}

void render_columns_deposit(const struct render_columns *c, double *acc, int nu, int nv, double fu,
                            double fv, double hp, double m)
{
  deposit(acc, nu, nv, &c->t, fu, fv, hp, m);
}
