/* sph.c — continuity and momentum/energy sums; see sph.h for the equations.
 *
 * These are the gas loops (no strength); sph_solid.c has the loops with stress.
 * Neighbours come from the candidate machinery in cand.c.
 */
#include "sph/sph.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "sph/cand.h"

void sph_density_rate(struct particles *p, const struct nbr_grid *g,
                      const struct sph_params *sp, struct sph_cache *cache,
                      const struct material *mat, double dt)
{
  if (p->solid) {
    sph_density_rate_solid(p, g, sp, cache, mat, dt);
    return;
  }
  if (cache) cache_layout(cache, g);
  const size_t n = p->n, nall = p->n + p->n_ghost;
  const double *x = p->x[0], *y = p->x[1], *z = p->x[2];
  const double *vx = p->v[0], *vy = p->v[1], *vz = p->v[2];
  const double *rho = p->rho, *h = p->h;
  double *drho = p->drho, *vol = p->vol;
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < nall; i++) vol[i] = p->m[i] / rho[i];
  const enum kernel_kind kk = sp->kernel;
  const int summation = sp->summation;
  const double *m = p->m;
  double *rhow = p->rho;   /* summation: written for i only; neighbours read vol */
  double *gradv = NULL;    /* sph.reconstruct: Gᵢ = Σⱼ Vⱼ (vⱼ − vᵢ) ⊗ ∇ᵢWᵢⱼ */
  if (sp->reconstruct && cache) {
    if (nall > cache->gcap) {
      cache->gcap = nall + nall / 4 + 64;
      free(cache->gradv);
      cache->gradv = hv_malloc(cache->gcap * 9 * sizeof *cache->gradv, "velocity gradients");
    }
    gradv = cache->gradv;
    cache->gradv_valid = 0;
  }

#pragma omp parallel
  {
    struct cand cd = {0};
#pragma omp for schedule(dynamic, 8)
    for (size_t c = 0; c < g->ncells; c++) {
      int gathered = 0;
      for (uint32_t ii = g->cell_start[c]; ii < g->cell_start[c + 1]; ii++) {
        const uint32_t i = g->order[ii];
        if (i >= n) continue;
        const size_t nsel = cand_neighbours(&cd, &gathered, g, c, ii, p, NULL, cache);
        const double xi = x[i], yi = y[i], zi = z[i], hi = h[i];
        const double vxi = vx[i], vyi = vy[i], vzi = vz[i];
        double sum = 0.0, rsum = 0.0, G[9] = {0};
        for (size_t k = 0; k < nsel; k++) {
          const uint32_t q = cd.sel[k], j = cd.j[q];
          const double dx = xi - cd.x[q], dy = yi - cd.y[q], dz = zi - cd.z[q];
          const double r = sqrt(dx * dx + dy * dy + dz * dz), hij = 0.5 * (hi + cd.h[q]);
          const double f = kernel_f(kk, r, hij);
          const double dvx = vxi - vx[j], dvy = vyi - vy[j], dvz = vzi - vz[j];
          const double vdx = dvx * dx + dvy * dy + dvz * dz;
          sum += vol[j] * vdx * f;
          if (summation) rsum += m[j] * kernel_w(kk, r, hij);
          if (gradv) {   /* (vⱼ − vᵢ) ⊗ ∇ᵢW, ∇ᵢW = f (xᵢ − xⱼ) */
            const double w = -vol[j] * f;
            G[0] += w * dvx * dx; G[1] += w * dvx * dy; G[2] += w * dvx * dz;
            G[3] += w * dvy * dx; G[4] += w * dvy * dy; G[5] += w * dvy * dz;
            G[6] += w * dvz * dx; G[7] += w * dvz * dy; G[8] += w * dvz * dz;
          }
        }
        if (gradv)
          for (int t = 0; t < 9; t++) gradv[9 * (size_t)i + t] = G[t];
        if (summation) {
          const double rs = rsum + m[i] * kernel_w(kk, 0.0, hi);
          drho[i] = rs * sum;
          rhow[i] = rs;
        } else {
          drho[i] = rho[i] * sum;
        }
        p->de[i] = 0.0;
      }
    }
    cand_free_all(&cd);
  }
  if (cache) cache->valid = 1;
}

/* The approach speed of a pair, (vᵢ − vⱼ)·rᵢⱼ (< 0), with the velocities reconstructed
 * linearly from each particle to the pair's midpoint: vᵢ − ½Φ Gᵢ rᵢⱼ and vⱼ + ½Φ Gⱼ rᵢⱼ,
 * so (Δv)·r = vdx − ½Φ (gᵢ + gⱼ) with gₖ = rᵢⱼ·Gₖ rᵢⱼ. The limiter
 * Φ = 4 gᵢ gⱼ / (gᵢ + gⱼ)² (van Leer's, in the symmetric form, 0 when the two slopes
 * differ in sign) is 1 where the flow is linear over the pair and falls to 0 across
 * a jump, where the viscosity then sees the whole difference. Symmetric in i and j,
 * so the pair force stays antisymmetric. The result is clamped to [vdx, 0]: the
 * reconstruction only removes viscosity, never adds it or turns it into cooling. */
static inline double reconstructed(double vdx, const double *Gi, const double *Gj, double dx,
                                   double dy, double dz)
{
  const double r[3] = {dx, dy, dz};
  double gi = 0.0, gj = 0.0;
  for (int a = 0; a < 3; a++) {
    const double ti = Gi[3 * a] * dx + Gi[3 * a + 1] * dy + Gi[3 * a + 2] * dz;
    const double tj = Gj[3 * a] * dx + Gj[3 * a + 1] * dy + Gj[3 * a + 2] * dz;
    gi += r[a] * ti;
    gj += r[a] * tj;
  }
  const double prod = gi * gj, s = gi + gj;
  if (!(prod > 0.0)) return vdx;
  const double phi = 4.0 * prod / (s * s);
  const double w = vdx - 0.5 * phi * s;
  return w > 0.0 ? 0.0 : (w < vdx ? vdx : w);
}

void sph_forces(struct particles *p, const struct nbr_grid *g, const struct sph_params *sp,
                const struct sph_cache *cache)
{
  if (p->solid) {
    sph_forces_solid(p, g, sp, cache);
    return;
  }
  const size_t n = p->n, nall = p->n + p->n_ghost;
  const double *x = p->x[0], *y = p->x[1], *z = p->x[2];
  const double *vx = p->v[0], *vy = p->v[1], *vz = p->v[2];
  const double *m = p->m, *rho = p->rho, *h = p->h, *cs = p->cs;
  double *pr2 = p->pr2;
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < nall; i++) pr2[i] = p->p[i] / (rho[i] * rho[i]);
  double *ax = p->a[0], *ay = p->a[1], *az = p->a[2], *de = p->de, *vsig = p->vsig;
  const enum kernel_kind kk = sp->kernel;
  const double alpha = sp->alpha, beta = sp->beta, eps = sp->eps;
  const double *gradv = sp->reconstruct && cache && cache->gradv_valid ? cache->gradv : NULL;

#pragma omp parallel
  {
    struct cand cd = {0};
#pragma omp for schedule(dynamic, 8)
    for (size_t c = 0; c < g->ncells; c++) {
      int gathered = 0;
      for (uint32_t ii = g->cell_start[c]; ii < g->cell_start[c + 1]; ii++) {
        const uint32_t i = g->order[ii];
        if (i >= n) continue;
        const size_t nsel = cand_neighbours(&cd, &gathered, g, c, ii, p, cache, NULL);
        const double xi = x[i], yi = y[i], zi = z[i], hi = h[i];
        const double vxi = vx[i], vyi = vy[i], vzi = vz[i];
        const double Pi = pr2[i], ci = cs[i], rhoi = rho[i];
        const double *Gi = gradv ? gradv + 9 * (size_t)i : NULL;
        double sx = 0.0, sy = 0.0, sz = 0.0, se = 0.0, mumax = 0.0;
        for (size_t k = 0; k < nsel; k++) {
          const uint32_t q = cd.sel[k], j = cd.j[q];
          const double dx = xi - x[j], dy = yi - y[j], dz = zi - z[j];
          const double r2 = dx * dx + dy * dy + dz * dz, hij = 0.5 * (hi + h[j]);
          const double f = kernel_f(kk, sqrt(r2), hij);
          const double vdx = (vxi - vx[j]) * dx + (vyi - vy[j]) * dy + (vzi - vz[j]) * dz;
          double visc = 0.0;
          if (vdx < 0.0) {
            double mu = hij * vdx / (r2 + eps * hij * hij);
            if (-mu > mumax) mumax = -mu;   /* the time step sees the full jump */
            if (Gi) mu = hij * reconstructed(vdx, Gi, gradv + 9 * (size_t)j, dx, dy, dz) /
                         (r2 + eps * hij * hij);
            visc = (-alpha * 0.5 * (ci + cs[j]) * mu + beta * mu * mu) / (0.5 * (rhoi + rho[j]));
          }
          const double fac = m[j] * (Pi + pr2[j] + visc) * f;
          sx -= fac * dx;
          sy -= fac * dy;
          sz -= fac * dz;
          se += m[j] * (Pi + 0.5 * visc) * vdx * f;
        }
        ax[i] = sx;
        ay[i] = sy;
        az[i] = sz;
        de[i] += se;
        vsig[i] = ci + 1.2 * (alpha * ci + beta * mumax);
      }
    }
    cand_free_all(&cd);
  }
}

int sph_count_neighbours(const struct particles *p, const struct nbr_grid *g, size_t i)
{
  for (size_t c = 0; c < g->ncells; c++)
    for (uint32_t ii = g->cell_start[c]; ii < g->cell_start[c + 1]; ii++) {
      if (g->order[ii] != i) continue;
      struct cand cd = {0};
      cand_gather(&cd, g, c, p);
      int count = (int)cand_select(&cd, (uint32_t)i, p->x[0][i], p->x[1][i], p->x[2][i], p->h[i]);
      cand_free_all(&cd);
      return count;
    }
  return -1;
}
