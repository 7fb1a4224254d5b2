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
#include "sph/rz.h"
#include "sph/sph.h"

/* Replaces p->m by the area masses (into the buffer *mu, returned); the ring masses are
 * returned by area_masses_end. */
static double *area_masses_begin(struct particles *p)
{
  const size_t nall = p->n + p->n_ghost;
  double *mu = hv_malloc((nall + 1) * sizeof *mu, "area masses");
  const double *m = p->m, *r = p->x[1], *h = p->h;
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < nall; i++) mu[i] = m[i] / (2.0 * HV_KERNEL_PI * sph_rz_radius(r[i], h[i]));
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
  double *ring = area_masses_begin(p);
  sph_density_rate(p, g, sp, cache, mat, dt);
  area_masses_end(p, ring);
  /* continuity's hoop term: ∇·v = ∇₂·v + v_r/r */
  const double *r = p->x[1], *vr = p->v[1], *h = p->h, *rho = p->rho;
  double *drho = p->drho;
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < p->n; i++) drho[i] -= rho[i] * vr[i] / sph_rz_radius(r[i], h[i]);
}

void sph_rz_forces(struct particles *p, const struct nbr_grid *g, const struct sph_params *sp,
                   struct sph_cache *cache, const struct material *mat)
{
  double *ring = area_masses_begin(p);
  sph_forces(p, g, sp, cache, mat);
  area_masses_end(p, ring);
  /* the hoop terms: the deviator's force, the pressure's work */
  const double *r = p->x[1], *vr = p->v[1], *h = p->h, *rho = p->rho;
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < p->n; i++) {
    const double ir = 1.0 / (rho[i] * sph_rz_radius(r[i], h[i]));
    double pi = p->p[i];
    if (p->solid) {
      /* the stress the pair sums saw: σ' of a split particle without tension
         (partner.c), the deviator 0 where the first pass left none */
      double S[6];
      for (int k = 0; k < 6; k++) S[k] = p->S[k][i];
      const struct material *m = &mat[p->mat[i]];
      if (fracture_no_tension(&m->frac, p->fstate[i])) pi = fracture_effective(pi, S, S);
      p->a[0][i] += S[T_XY] * ir;
      p->a[1][i] += (S[T_YY] - S[T_ZZ]) * ir;
    }
    p->de[i] -= pi * vr[i] * ir;
  }
}
