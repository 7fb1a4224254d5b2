/* measure_rz.c — see measure_rz.h. */
#include "diag/measure_rz.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"

void measure_plate_rz(const struct particles *p, const struct meas_geom *g,
                      const struct meas_plate_params *par, const unsigned char *sel,
                      struct meas_plate *out)
{
  double rh = INFINITY, rfp = INFINITY, edge = 0.0;
  for (size_t i = 0; i < p->n; i++) {
    if (!sel[i]) continue;
    const double s = par->scale ? par->scale[i] : 1.0, r = p->x[1][i];
    if (par->r_max > 0.0 && r - s * par->tol >= par->r_max) continue; /* beyond the window */
    out->n_plate++;
    rh = fmin(rh, r - s * par->tol);
    rfp = fmin(rfp, r - s * par->footprint);
    edge = fmax(edge, r + s * par->tol);
  }
  const double W = par->r_max > 0.0 ? par->r_max : edge;
  out->cell = 0.0;         /* no grid */
  if (!(rh > 0.0)) return; /* material on the axis: no line of sight through the plate */
  out->perforated = 1;
  out->hole_open = !(rh < W);
  rh = fmin(rh, W);
  rfp = fmin(rfp, W + (par->tol - par->footprint));
  out->area = HV_MEAS_PI * rh * rh;
  out->d_equiv = 2.0 * rh + 2.0 * (par->tol - par->footprint);
  out->d_circle = out->d_circle_impact = 2.0 * fmax(rfp, 0.0);
  out->circle_center[0] = g->yc;
  out->circle_center[1] = 0.0;
}

size_t meas_rz_revolve(const struct particles *p, const unsigned char *sel, const double *scale,
                       double step, struct particles *q, double **qscale)
{
  particles_init(q);
  if (p->solid) particles_enable_solid(q);
  size_t total = 0;
  for (size_t i = 0; i < p->n; i++) {
    const double r = p->x[1][i], st = step * (scale ? scale[i] : 1.0);
    if ((sel && !sel[i]) || !(isfinite(r) && isfinite(p->x[0][i]))) continue;
    total += (size_t)fmax(1.0, ceil(2.0 * HV_MEAS_PI * r / st));
  }
  particles_add(q, total);
  double *qs = qscale ? hv_malloc((total + 1) * sizeof *qs, "revolved scales") : NULL;
  size_t k = 0;
  for (size_t i = 0; i < p->n; i++) {
    const double r = p->x[1][i], st = step * (scale ? scale[i] : 1.0);
    if ((sel && !sel[i]) || !(isfinite(r) && isfinite(p->x[0][i]))) continue;
    const size_t n = (size_t)fmax(1.0, ceil(2.0 * HV_MEAS_PI * r / st));
    for (size_t j = 0; j < n; j++, k++) {
      const double phi = 2.0 * HV_MEAS_PI * (double)j / (double)n, c = cos(phi), s = sin(phi);
      q->id[k] = p->id[i];
      q->body[k] = p->body[i];
      q->mat[k] = p->mat[i];
      q->m[k] = p->m[i] / (double)n;
      q->h[k] = p->h[i];
      q->rho[k] = p->rho[i];
      q->p[k] = p->p[i];
      q->e[k] = p->e[i];
      q->cs[k] = p->cs[i];
      q->x[0][k] = p->x[0][i];
      q->x[1][k] = r * c;
      q->x[2][k] = r * s;
      q->v[0][k] = p->v[0][i];
      q->v[1][k] = p->v[1][i] * c;
      q->v[2][k] = p->v[1][i] * s;
      if (p->solid) {
        q->damage[k] = p->damage[i];
        q->eps_p[k] = p->eps_p[i];
      }
      if (qs) qs[k] = scale ? scale[i] : 1.0;
    }
  }
  if (qscale) *qscale = qs;
  return total;
}

int measure_backwall_rz(const struct particles *p, const struct meas_geom *g,
                        const struct meas_backwall_params *par, struct meas_backwall *out,
                        struct hv_error *err)
{
  /* the wall's rings: the body and mask; points round each circle a spacing apart, so
     that every point of the circle lies within Δ/2 of one (the columns' tol is Δ) */
  unsigned char *sel = hv_calloc(p->n + 1, 1, "backwall rings");
  size_t nw = 0, nd = 0;
  const double xlo = g->x0 - par->margin_front;
  for (size_t i = 0; i < p->n; i++) {
    sel[i] = (g->body < 0 || p->body[i] == g->body) && (!par->mask || par->mask[i]);
    if (!sel[i] || !(p->x[0][i] >= xlo) || !isfinite(p->x[1][i])) continue;
    nw++; /* as measure.c's scan_wall counts them */
    if (p->solid && (p->damage[i] >= par->damage_min || p->eps_p[i] >= par->eps_p_min)) nd++;
  }
  struct particles q;
  double *qs = NULL;
  meas_rz_revolve(p, sel, par->scale, g->spacing, &q, par->scale ? &qs : NULL);
  free(sel);
  struct meas_geom gq = *g;
  gq.half_model = 0;
  struct meas_backwall_params pq = *par;
  pq.mask = NULL; /* the points are the wall's */
  pq.scale = qs;
  const int rc = measure_backwall(&q, &gq, &pq, out, err);
  free(qs);
  particles_free(&q);
  out->n_wall = nw;
  out->n_damaged = nd;
  return rc;
}
