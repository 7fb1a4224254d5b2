/* sph.c — continuity and momentum/energy sums; see sph.h for the equations. */
#include "sph/sph.h"

#include <math.h>


void sph_density_rate(struct particles *p, const struct nbr_grid *g,
                      const struct sph_params *sp)
{
  const size_t n = p->n;
  const uint32_t *order = g->order;
  const double *x = p->x[0], *y = p->x[1], *z = p->x[2];
  const double *vx = p->v[0], *vy = p->v[1], *vz = p->v[2];
  const double *m = p->m, *rho = p->rho, *h = p->h;
  double *drho = p->drho;
  const enum kernel_kind kk = sp->kernel;

#pragma omp parallel for schedule(dynamic, 8)
  for (size_t c = 0; c < g->ncells; c++) {
    const int32_t *nb = g->cell_nbr + 27 * c;
    for (uint32_t ii = g->cell_start[c]; ii < g->cell_start[c + 1]; ii++) {
      const uint32_t i = order[ii];
      if (i >= n) continue;
      const double xi = x[i], yi = y[i], zi = z[i], hi = h[i];
      const double vxi = vx[i], vyi = vy[i], vzi = vz[i];
      double sum = 0.0;
      for (int k = 0; k < 27; k++) {
        if (nb[k] < 0) continue;
        const uint32_t j0 = g->cell_start[nb[k]], j1 = g->cell_start[nb[k] + 1];
        for (uint32_t jj = j0; jj < j1; jj++) {
          const uint32_t j = order[jj];
          const double dx = xi - x[j], dy = yi - y[j], dz = zi - z[j];
          const double r2 = dx * dx + dy * dy + dz * dz, s = hi + h[j];
          if (r2 >= s * s || j == i) continue;
          const double r = sqrt(r2), f = kernel_f(kk, r, 0.5 * s);
          const double vdx = (vxi - vx[j]) * dx + (vyi - vy[j]) * dy + (vzi - vz[j]) * dz;
          sum += m[j] / rho[j] * vdx * f;
        }
      }
      drho[i] = rho[i] * sum;
    }
  }
}

void sph_forces(struct particles *p, const struct nbr_grid *g, const struct sph_params *sp)
{
  const size_t n = p->n;
  const uint32_t *order = g->order;
  const double *x = p->x[0], *y = p->x[1], *z = p->x[2];
  const double *vx = p->v[0], *vy = p->v[1], *vz = p->v[2];
  const double *m = p->m, *rho = p->rho, *h = p->h, *pr = p->p, *cs = p->cs;
  double *ax = p->a[0], *ay = p->a[1], *az = p->a[2], *de = p->de, *vsig = p->vsig;
  const enum kernel_kind kk = sp->kernel;
  const double alpha = sp->alpha, beta = sp->beta, eps = sp->eps;

#pragma omp parallel for schedule(dynamic, 8)
  for (size_t c = 0; c < g->ncells; c++) {
    const int32_t *nb = g->cell_nbr + 27 * c;
    for (uint32_t ii = g->cell_start[c]; ii < g->cell_start[c + 1]; ii++) {
      const uint32_t i = order[ii];
      if (i >= n) continue;
      const double xi = x[i], yi = y[i], zi = z[i], hi = h[i];
      const double vxi = vx[i], vyi = vy[i], vzi = vz[i];
      const double Pi = pr[i] / (rho[i] * rho[i]), ci = cs[i], rhoi = rho[i];
      double sx = 0.0, sy = 0.0, sz = 0.0, se = 0.0, mumax = 0.0;
      for (int k = 0; k < 27; k++) {
        if (nb[k] < 0) continue;
        const uint32_t j0 = g->cell_start[nb[k]], j1 = g->cell_start[nb[k] + 1];
        for (uint32_t jj = j0; jj < j1; jj++) {
          const uint32_t j = order[jj];
          const double dx = xi - x[j], dy = yi - y[j], dz = zi - z[j];
          const double r2 = dx * dx + dy * dy + dz * dz, s = hi + h[j];
          if (r2 >= s * s || j == i) continue;
          const double hij = 0.5 * s, r = sqrt(r2), f = kernel_f(kk, r, hij);
          const double vdx = (vxi - vx[j]) * dx + (vyi - vy[j]) * dy + (vzi - vz[j]) * dz;
          double visc = 0.0;
          if (vdx < 0.0) {
            const double mu = hij * vdx / (r2 + eps * hij * hij);
            visc = (-alpha * 0.5 * (ci + cs[j]) * mu + beta * mu * mu) / (0.5 * (rhoi + rho[j]));
            if (-mu > mumax) mumax = -mu;
          }
          const double Pj = pr[j] / (rho[j] * rho[j]);
          const double fac = m[j] * (Pi + Pj + visc) * f;
          sx -= fac * dx;
          sy -= fac * dy;
          sz -= fac * dz;
          se += m[j] * (Pi + 0.5 * visc) * vdx * f;
        }
      }
      ax[i] = sx;
      ay[i] = sy;
      az[i] = sz;
      de[i] = se;
      vsig[i] = ci + 1.2 * (alpha * ci + beta * mumax);
    }
  }
}

int sph_count_neighbours(const struct particles *p, const struct nbr_grid *g, size_t i)
{
  int count = 0;
  for (size_t c = 0; c < g->ncells; c++)
    for (uint32_t ii = g->cell_start[c]; ii < g->cell_start[c + 1]; ii++) {
      if (g->order[ii] != i) continue;
      const int32_t *nb = g->cell_nbr + 27 * c;
      for (int k = 0; k < 27; k++) {
        if (nb[k] < 0) continue;
        for (uint32_t jj = g->cell_start[nb[k]]; jj < g->cell_start[nb[k] + 1]; jj++) {
          uint32_t j = g->order[jj];
          double dx = p->x[0][i] - p->x[0][j], dy = p->x[1][i] - p->x[1][j],
                 dz = p->x[2][i] - p->x[2][j], s = p->h[i] + p->h[j];
          if (j != i && dx * dx + dy * dy + dz * dz < s * s) count++;
        }
      }
      return count;
    }
  return -1;
}
