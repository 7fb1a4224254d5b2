/* pair.h — internal to src/sph: what the gas loops (sph.c) and the solid loops
 * (sph_solid.c) compute alike for a pair i, j: its geometry and kernel gradient, and
 * its artificial viscosity Πᵢⱼ (sph.h for the equations).
 *
 * Written once so that the two loops cannot drift apart. Every result must be the
 * same bits as the loops' earlier inline code: the expressions keep their operands
 * and their order (the build is ISO C, -std=c11, where gcc contracts no a·b + c into
 * an FMA, so inlining does not change the rounding either; docs/design.md).
 */
#ifndef HV_SPH_PAIR_H
#define HV_SPH_PAIR_H

#include <math.h>

#include "kernel/kernel.h"
#include "sph/recon.h"
#include "sph/sph.h"

/* A pair's geometry: rᵢⱼ = xᵢ − xⱼ, rᵢⱼ², rᵢⱼ, hᵢⱼ = ½(hᵢ + hⱼ) and the kernel factor f
 * with ∇ᵢWᵢⱼ = f rᵢⱼ (f ≤ 0). */
struct pair {
  double dx, dy, dz, r2, r, hij, f;
};

static inline struct pair pair_geometry(enum kernel_kind kk, double xi, double yi, double zi,
                                        double hi, double xj, double yj, double zj, double hj)
{
  struct pair q;
  q.dx = xi - xj;
  q.dy = yi - yj;
  q.dz = zi - zj;
  q.r2 = q.dx * q.dx + q.dy * q.dy + q.dz * q.dz;
  q.r = sqrt(q.r2);
  q.hij = 0.5 * (hi + hj);
  q.f = kernel_f(kk, q.r, q.hij);
  return q;
}

/* The viscosity's parameters: α, β, ε, and with the switch (av: αᵢ of every slot, else
 * NULL) β/α, a pair then taking ½(αᵢ + αⱼ) for α and ½(αᵢ + αⱼ) β/α for β. */
struct pair_visc {
  const double *av;
  double alpha, beta, bfac, eps;
};

static inline struct pair_visc pair_visc_params(const struct sph_params *sp, const double *av)
{
  return (struct pair_visc){av, sp->alpha, sp->beta, av ? sp->beta / sp->alpha : 0.0, sp->eps};
}

/* Πᵢⱼ of the pair i, j with approach term vdx = vᵢⱼ·rᵢⱼ: 0 unless it approaches
 * (vdx < 0). Raises *mumax to the whole jump's −μᵢⱼ (the time step must resolve it)
 * and, with the switch, *amax to the pair's α. With Gi (sph.viscosity.reconstruct: the
 * velocity gradients Gi, Gj of i and j) μᵢⱼ takes the reconstructed approach speed. */
static inline double pair_viscosity(const struct pair_visc *pv, size_t i, size_t j,
                                    const struct pair *q, double vdx, const double *Gi,
                                    const double *Gj, double ci, double cj, double rhoi,
                                    double rhoj, double *mumax, double *amax)
{
  if (!(vdx < 0.0)) return 0.0;
  const double hij = q->hij;
  double mu = hij * vdx / (q->r2 + pv->eps * hij * hij);
  if (-mu > *mumax) *mumax = -mu;
  if (Gi)
    mu = hij * sph_recon_approach(vdx, Gi, Gj, q->dx, q->dy, q->dz) / (q->r2 + pv->eps * hij * hij);
  if (pv->av) {
    const double aij = 0.5 * (pv->av[i] + pv->av[j]);
    if (aij > *amax) *amax = aij;
    return aij * (-0.5 * (ci + cj) * mu + pv->bfac * mu * mu) / (0.5 * (rhoi + rhoj));
  }
  return (-pv->alpha * 0.5 * (ci + cj) * mu + pv->beta * mu * mu) / (0.5 * (rhoi + rhoj));
}

#endif
