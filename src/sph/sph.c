/* sph.c — continuity and momentum/energy sums; see sph.h for the equations.
 *
 * These are the gas loops (no strength); sph_solid.c has the loops with stress.
 * Neighbours come from the neighbour search (nsearch.c); a pair's geometry and its
 * viscosity from pair.h, shared with the solid loops.
 */
#include "sph/sph.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "sph/avswitch.h"
#include "sph/nsearch.h"
#include "sph/pair.h"
#include "sph/rz.h"

void sph_density_rate(struct particles *p, const struct nbr_grid *g, const struct sph_params *sp,
                      struct sph_cache *cache, const struct material *mat, double dt)
{
  if (p->axisym == 1) { /* axisymmetric: these loops on area masses (sph_rz.c) */
    sph_rz_density_rate(p, g, sp, cache, mat, dt);
    return;
  }
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
  const enum kernel_kind kk = sp->kernel;
  const int summation = sp->summation, massform = sp->continuity_mass && !summation;
  if (!massform) { /* the volume form's weights (the mass form weighs by mⱼ) */
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < nall; i++) vol[i] = p->m[i] / rho[i];
  }
  const double *m = p->m;
  double *rhow = p->rho; /* summation: written for i only; neighbours read vol */
  const int sw = p->av;  /* the viscosity switch (avswitch.h) */
  const int32_t *act = p->active;

#pragma omp parallel
  {
    struct nsearch cd = {0};
#pragma omp for schedule(dynamic, 8)
    for (size_t c = 0; c < g->ncells; c++) {
      int gathered = 0;
      for (uint32_t ii = g->cell_start[c]; ii < g->cell_start[c + 1]; ii++) {
        const uint32_t i = g->order[ii];
        if (i >= n || (act && !act[i])) continue; /* a ghost, or inactive (step.h) */
        const size_t nsel = nsearch_neighbours(&cd, &gathered, g, c, ii, p, NULL, cache);
        const double xi = x[i], yi = y[i], zi = z[i], hi = h[i];
        const double vxi = vx[i], vyi = vy[i], vzi = vz[i];
        double sum = 0.0, rsum = 0.0, Lsw[9] = {0}, Asw[9] = {0};
        for (size_t k = 0; k < nsel; k++) {
          const uint32_t q = cd.sel[k], j = cd.j[q];
          const struct pair pq =
              pair_geometry(kk, xi, yi, zi, hi, cd.x[q], cd.y[q], cd.z[q], cd.h[q]);
          const double dx = pq.dx, dy = pq.dy, dz = pq.dz, f = pq.f;
          const double vdx = (vxi - vx[j]) * dx + (vyi - vy[j]) * dy + (vzi - vz[j]) * dz;
          sum += (massform ? m[j] : vol[j]) * vdx * f;
          if (summation) rsum += m[j] * kernel_w(kk, pq.r, pq.hij);
          if (sw) /* with Vⱼ = mⱼ/ρⱼ (vol: before a summation writes ρ) */
            avsw_add(Lsw, Asw, (massform ? m[j] / rho[j] : vol[j]) * f, dx, dy, dz, vx[j] - vxi,
                     vy[j] - vyi, vz[j] - vzi);
        }
        if (sw)
          p->alpha[i] =
              avsw_update(sp, Lsw, Asw, p->alpha[i], p->divv[i], hi, p->cs[i], dt, &p->divv[i]);
        if (summation) {
          const double rs = rsum + m[i] * kernel_w(kk, 0.0, hi);
          drho[i] = rs * sum;
          rhow[i] = rs;
        } else {
          drho[i] = massform ? sum : rho[i] * sum;
        }
        p->de[i] = 0.0;
      }
    }
    nsearch_free(&cd);
  }
  if (cache) cache->valid = 1;
}

void sph_forces(struct particles *p, const struct nbr_grid *g, const struct sph_params *sp,
                struct sph_cache *cache, const struct material *mat)
{
  if (p->axisym == 1) { /* axisymmetric: these loops on area masses (sph_rz.c) */
    sph_rz_forces(p, g, sp, cache, mat);
    return;
  }
  if (p->solid) {
    sph_forces_solid(p, g, sp, cache, mat);
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
  const double alpha = sp->alpha, beta = sp->beta;
  const double *av = p->av ? p->alpha : NULL; /* the switch: αᵢ of every slot */
  const struct pair_visc pv = pair_visc_params(sp, av);
  const int32_t *act = p->active;

#pragma omp parallel
  {
    struct nsearch cd = {0};
#pragma omp for schedule(dynamic, 8)
    for (size_t c = 0; c < g->ncells; c++) {
      int gathered = 0;
      for (uint32_t ii = g->cell_start[c]; ii < g->cell_start[c + 1]; ii++) {
        const uint32_t i = g->order[ii];
        if (i >= n || (act && !act[i])) continue; /* a ghost, or inactive (step.h) */
        const size_t nsel = nsearch_neighbours(&cd, &gathered, g, c, ii, p, cache, NULL);
        const double xi = x[i], yi = y[i], zi = z[i], hi = h[i];
        const double vxi = vx[i], vyi = vy[i], vzi = vz[i];
        const double Pi = pr2[i], ci = cs[i], rhoi = rho[i];
        double sx = 0.0, sy = 0.0, sz = 0.0, se = 0.0, mumax = 0.0;
        double amax = av ? av[i] : alpha; /* the largest pair α (time step) */
        for (size_t k = 0; k < nsel; k++) {
          const uint32_t j = cd.j[cd.sel[k]];
          const struct pair pq = pair_geometry(kk, xi, yi, zi, hi, x[j], y[j], z[j], h[j]);
          const double dx = pq.dx, dy = pq.dy, dz = pq.dz, f = pq.f;
          const double vdx = (vxi - vx[j]) * dx + (vyi - vy[j]) * dy + (vzi - vz[j]) * dz;
          const double visc = pair_viscosity(&pv, i, j, &pq, vdx, NULL, NULL, ci, cs[j], rhoi,
                                             rho[j], &mumax, &amax);
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
        /* with the switch the α c part takes the largest pair α, and the β μ part stays
           whole: it follows the approach speed, which the step must resolve whatever α
           (Noh's first step, every α still 0, crossed particles with it scaled too) */
        vsig[i] = sph_signal_speed(nsel > 0, ci, amax, beta, mumax, /* amax = α without it */
                                   sqrt(vxi * vxi + vyi * vyi + vzi * vzi));
      }
    }
    nsearch_free(&cd);
  }
}

/* A minimum that any order of the threads' writes leaves the same. */
static inline void atomic_min_i32(int32_t *a, int32_t v)
{
  int32_t cur = __atomic_load_n(a, __ATOMIC_RELAXED);
  while (v < cur &&
         !__atomic_compare_exchange_n(a, &cur, v, 1, __ATOMIC_RELAXED, __ATOMIC_RELAXED)) {}
}

void sph_step_exchange(const struct particles *p, const struct nbr_grid *g, const int32_t *set,
                       const int32_t *len, int32_t *cap, int32_t *wake)
{
  const size_t n = p->n;
#pragma omp parallel
  {
    struct nsearch cd = {0};
#pragma omp for schedule(dynamic, 8)
    for (size_t c = 0; c < g->ncells; c++) {
      int gathered = 0;
      for (uint32_t ii = g->cell_start[c]; ii < g->cell_start[c + 1]; ii++) {
        const uint32_t i = g->order[ii];
        if (i >= n || !set[i]) continue;
        const size_t nsel = nsearch_neighbours(&cd, &gathered, g, c, ii, p, NULL, NULL);
        int32_t m = INT32_MAX;
        for (size_t k = 0; k < nsel; k++) {
          const uint32_t j = cd.j[cd.sel[k]];
          if (j >= n || j == i) continue; /* a ghost mirrors a real that is near by itself */
          if (len[j] < m) m = len[j];
          atomic_min_i32(&wake[j], len[i]);
        }
        cap[i] = m;
      }
    }
    nsearch_free(&cd);
  }
}

int sph_count_neighbours(const struct particles *p, const struct nbr_grid *g, size_t i)
{
  for (size_t c = 0; c < g->ncells; c++)
    for (uint32_t ii = g->cell_start[c]; ii < g->cell_start[c + 1]; ii++) {
      if (g->order[ii] != i) continue;
      struct nsearch cd = {0};
      nsearch_gather(&cd, g, c, p);
      int count =
          (int)nsearch_select(&cd, (uint32_t)i, p->x[0][i], p->x[1][i], p->x[2][i], p->h[i]);
      nsearch_free(&cd);
      return count;
    }
  return -1;
}
