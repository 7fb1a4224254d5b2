/* sph_rz.c — the SPH passes of an axisymmetric run; see rz.h for the equations.
 *
 * The pair sums are the 3D loops' (sph.c, sph_solid.c), run over the meridional plane
 * with the 2D kernel (sph_params.kernel carries KERNEL_2D) on area masses: for the
 * length of a pass p->m holds μ = m/(2π r) of every slot, ghosts included (a mirror
 * ghost at −r weighs as its source; a wall ghost at r_max was given the ring mass that
 * keeps its source's μ, boundary/axis.c), and p->axisym is 2, so that sph.c's dispatch
 * runs the 3D loops and sph_solid.c adds the hoop strain rate before the stress update.
 * The ring masses are back in p->m when a pass returns. The hoop terms that are local to
 * a particle are added here after the pair sums. The one hook inside the loops is the
 * hoop strain rate, which the stress update needs before it runs (sph_solid.c,
 * density_rate_particle).
 */
#include <math.h>
#include <stdlib.h>

#include "core/error.h"
#include "fracture/fracture.h"
#include "sph/nsearch.h"
#include "sph/partner.h"
#include "sph/rz.h"
#include "sph/sph.h"

/* Replaces p->m by the area masses (into the buffer *mu, returned); the ring masses are
 * returned by area_masses_end. */
static double *area_masses_begin(struct particles *p, double rmax)
{
  const size_t nall = p->n + p->n_ghost;
  double *mu = hv_malloc((nall + 1) * sizeof *mu, "area masses");
  const double *m = p->m, *r = p->x[1], *h = p->h;
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < nall; i++)
    mu[i] = m[i] / (2.0 * HV_KERNEL_PI * sph_rz_weight_radius(r[i], h[i], rmax));
  double *ring = p->m;
  p->m = mu;
  p->axisym = 2;
  return ring;
}

static void area_masses_end(struct particles *p, double *ring)
{
  free(p->m);
  p->m = ring;
  p->axisym = 1;
}

void sph_rz_density_rate(struct particles *p, const struct nbr_grid *g, const struct sph_params *sp,
                         struct sph_cache *cache, const struct material *mat, double dt)
{
  double *ring = area_masses_begin(p, sp->rz_rmax);
  sph_density_rate(p, g, sp, cache, mat, dt);
  area_masses_end(p, ring);
  /* continuity's hoop term: ∇·v = ∇₂·v + v_r/r */
  const double *r = p->x[1], *vr = p->v[1], *h = p->h, *rho = p->rho;
  double *drho = p->drho;
  double *de = p->de;
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < p->n; i++) {
    drho[i] -= rho[i] * vr[i] / sph_rz_radius(r[i], h[i]);
    /* the deviator's heating S:ε̇/ρ of the first pass is replaced by the work of the
       force pass's own pair forces (sph_rz_forces), so that the energy is kept exactly:
       the first pass's area-weighted gradient and the η-form's forces differ near the
       axis by rⱼ/rᵢ, and a copper bar at 227 m/s gained 5 % of its energy in 80 us */
    de[i] = 0.0;
  }
}

/* The hoop correction cᵢ of every real: 1 + Σⱼ (μⱼ/ρⱼ)(r̃ⱼ − rⱼ) ∂ᵢWᵢⱼ/∂rᵢ over its ghosts
 * j that weigh with a radius r̃ⱼ other than their own rⱼ (sph_rz_weight_radius: |r| across
 * the axis, 2 r_max − r across a mirror at r_max). The η-form's pair sum of a uniform
 * pressure p on particle i is −(p/ρ²)[(1/rᵢ) Σⱼ Mⱼ ∇ᵢWᵢⱼ + Σⱼ μⱼ ∇ᵢWᵢⱼ], Mⱼ = μⱼ r̃ⱼ: the
 * second sum is the 2D SPH gradient of a constant (0 to the lattice's accuracy), the
 * first (ρ/rᵢ) times the SPH slope of r̃, which is 1 in the bulk (0.99 on a square
 * lattice with η = 1.2) and flatter where the ghosts fold it: at the axis (|r| has its
 * kink there; 0.48 on the first row) and at a mirror at r_max. The sum above is the
 * fold's part, so that the hoop force cᵢ p/(ρᵢ rᵢ) balances the pair sum there; away from
 * them cᵢ = 1, also at a free surface, where the truncated slope of the first sum is the
 * ordinary SPH surface force (as in 3D) and no hoop effect. The discrete balance on the
 * first row is then within 0.01 p/(ρ r) (the lattice's own error, 1 − 0.99); the full
 * slope as cᵢ balanced it exactly but turned free surfaces unstable (a Taylor bar's rim:
 * cᵢ ≈ −r/h). At the axis this is the correction function f1 of García-Senz et al.
 * (2009), computed from the particles instead of tabulated for a regular lattice.
 * Also the deviator's work of the force pass (dev; see sph_rz_forces). Run while p->m
 * holds the area masses. */
static void hoop_correction(const struct particles *p, const struct nbr_grid *g,
                            const struct sph_params *sp, const struct sph_cache *cache,
                            const struct material *mat, double *corr, double *dev)
{
  const enum kernel_kind kk = sp->kernel;
  const double *x = p->x[0], *r = p->x[1], *h = p->h, *mu = p->m, *rho = p->rho;
  const double *vx = p->v[0], *vr = p->v[1], rmax = sp->rz_rmax;
  /* the first pass's neighbours, but for the cells it skipped at rest (rest.c) */
  const int skipped = cache && sp->skip_resting && !p->av && cache->rest;
#pragma omp parallel
  {
    struct nsearch ns = {0};
#pragma omp for schedule(dynamic, 8)
    for (size_t c = 0; c < g->ncells; c++) {
      const struct sph_cache *load =
          cache && cache->valid && !(skipped && (cache->rest[c] & 1)) ? cache : NULL;
      int gathered = 0;
      for (uint32_t ii = g->cell_start[c]; ii < g->cell_start[c + 1]; ii++) {
        const uint32_t i = g->order[ii];
        if (i >= p->n) continue;
        const size_t nsel = nsearch_neighbours(&ns, &gathered, g, c, ii, p, load, NULL);
        /* the deviator's work needs i's stress as the force pass sees it (partner.c) */
        double Si[6] = {0, 0, 0, 0, 0, 0};
        const int strong = p->solid && mat[p->mat[i]].str.enabled;
        if (strong) {
          for (int k = 0; k < 6; k++) Si[k] = p->S[k][i];
          if (fracture_no_tension(&mat[p->mat[i]].frac, p->fstate[i]))
            fracture_effective(p->p[i], Si, Si);
        }
        const int32_t pi = sph_piece_of(sp->piece, p->body[i]);
        double sum = 0.0, Q[4] = {0, 0, 0, 0};
        for (size_t k = 0; k < nsel; k++) {
          const uint32_t j = ns.j[ns.sel[k]];
          const double dx = x[i] - x[j], dy = r[i] - r[j];
          const double hij = 0.5 * (h[i] + h[j]);
          const double f = kernel_f(kk, sqrt(dx * dx + dy * dy), hij);
          /* a ghost that weighs with its source's radius rw ≠ r: its share of the kink */
          const double rw = r[j] > rmax ? 2.0 * rmax - r[j] : fabs(r[j]);
          if (rw != r[j]) sum += mu[j] / rho[j] * (rw - r[j]) * f * dy;
          if (strong && sph_piece_of(sp->piece, p->body[j]) == pi) {
            /* Σⱼ Mⱼ vᵢⱼ ⊗ ∇ᵢWᵢⱼ, Mⱼ = μⱼ r̂ⱼ = mⱼ/(2π) */
            const double w = mu[j] * sph_rz_weight_radius(r[j], h[j], rmax) * f;
            const double ux = vx[i] - vx[j], uy = vr[i] - vr[j];
            Q[0] += w * ux * dx;
            Q[1] += w * ux * dy;
            Q[2] += w * uy * dx;
            Q[3] += w * uy * dy;
          }
        }
        corr[i] = 1.0 + sum;
        /* −(Sᵢ/(r̂ᵢ ρᵢ²)):Σⱼ Mⱼ vᵢⱼ ⊗ ∇ᵢWᵢⱼ, in the plane; the hoop part is added with cᵢ */
        const double ri = sph_rz_radius(r[i], h[i]);
        dev[i] = strong ? -(Si[T_XX] * Q[0] + Si[T_XY] * (Q[1] + Q[2]) + Si[T_YY] * Q[3]) /
                              (ri * rho[i] * rho[i])
                        : 0.0;
      }
    }
    nsearch_free(&ns);
  }
}

/* A scaled copy of array a of n slots: a[i] · r̂ᵢ^e (e = 1 or −1), r̂ᵢ = |rᵢ| not below
 * the floor of rz.h. */
static double *scaled(const double *a, const double *r, const double *h, size_t n, int e,
                      double rmax)
{
  double *b = hv_malloc((n + 1) * sizeof *b, "axisymmetric pass");
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < n; i++) {
    const double ar = sph_rz_weight_radius(r[i], h[i], rmax);
    b[i] = e > 0 ? a[i] * ar : a[i] / ar;
  }
  return b;
}

void sph_rz_forces(struct particles *p, const struct nbr_grid *g, const struct sph_params *sp,
                   struct sph_cache *cache, const struct material *mat)
{
  const size_t n = p->n, nall = p->n + p->n_ghost;
  double *corr = hv_malloc((n + 1) * sizeof *corr, "hoop correction");
  double *dev = hv_malloc((n + 1) * sizeof *dev, "deviatoric work");
  double *ring = area_masses_begin(p, sp->rz_rmax);
  hoop_correction(p, g, sp, cache, mat, corr, dev);
  /* the η-form as 2D SPH of the meridional plane: mass M = m/(2π), density r ρ, stress
     r σ (p, S; the artificial stress R = −ε σ/ρ² as R/r), the viscosity's density r ρ */
  const double *r = p->x[1];
  for (size_t i = 0; i < nall; i++) p->m[i] = ring[i] / (2.0 * HV_KERNEL_PI);
  double *rho = p->rho, *pr = p->p, *S[6] = {0}, *R[6] = {0};
  p->rho = scaled(rho, r, p->h, nall, 1, sp->rz_rmax);
  p->p = scaled(pr, r, p->h, nall, 1, sp->rz_rmax);
  if (p->solid)
    for (int k = 0; k < 6; k++) {
      S[k] = p->S[k];
      R[k] = p->R[k];
      p->S[k] = scaled(S[k], r, p->h, nall, 1, sp->rz_rmax);
      p->R[k] = scaled(R[k], r, p->h, nall, -1, sp->rz_rmax);
    }
  sph_forces(p, g, sp, cache, mat);
  free(p->rho);
  free(p->p);
  p->rho = rho;
  p->p = pr;
  if (p->solid)
    for (int k = 0; k < 6; k++) {
      free(p->S[k]);
      free(p->R[k]);
      p->S[k] = S[k];
      p->R[k] = R[k];
    }
  area_masses_end(p, ring);
  /* the hoop terms: −c σ_θθ/(ρ r) in r, its work −c p v_r/(ρ r) (the deviator's hoop
     work is the first pass's, S_θθ v_r/r among S:ε̇) */
  const double *vr = p->v[1], *h = p->h;
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < n; i++) {
    const double cr = corr[i] / (rho[i] * sph_rz_radius(r[i], h[i]));
    double pi = p->p[i], stt = 0.0;
    if (p->solid) {
      /* the stress the pair sums saw: σ' of a split particle without tension
         (partner.c), the deviator 0 where the first pass left none */
      double Si[6];
      for (int k = 0; k < 6; k++) Si[k] = p->S[k][i];
      const struct material *m = &mat[p->mat[i]];
      if (fracture_no_tension(&m->frac, p->fstate[i])) pi = fracture_effective(pi, Si, Si);
      stt = Si[T_ZZ];
    }
    p->a[1][i] += (pi - stt) * cr;
    /* the work of exactly these forces: the pair sums' (pressure and viscosity in the
       loops, the deviator in dev) and the hoop force's, c σ_θθ v_r/(ρ r) */
    p->de[i] += dev[i] + (stt - pi) * vr[i] * cr;
  }
  free(corr);
  free(dev);
}
