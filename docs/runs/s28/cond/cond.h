/* cond.h — artificial conductivity (sph.conductivity.alpha = α_u > 0; Price 2008, JCP
 * 227:10040, "Modelling discontinuities and Kelvin–Helmholtz instabilities in SPH").
 *
 * SPH carries no heat flux, so where a shock or a stagnation point deposits heat in a
 * layer one particle thick (the "wall heating" of an impact plane, a rod's tip, the
 * centre of Noh's implosion) the layer keeps it: it stays hot and thin, at a pressure
 * that its neighbours do not share, and the pair forces across it see a jump of
 * pressure that the continuum does not have. The conductivity diffuses the specific
 * internal energy between neighbours where their pressures differ:
 *
 *   deᵢ/dt += Σⱼ mⱼ α_u v_u (eᵢ − eⱼ) (∂W/∂r)(rᵢⱼ, hᵢⱼ) / ρ̄ᵢⱼ,
 *   v_u = √(|pᵢ − pⱼ| / ρ̄ᵢⱼ),  ρ̄ᵢⱼ = ½(ρᵢ + ρⱼ),
 *
 * (∂W/∂r ≤ 0, so heat flows from the hotter particle). The pair's two terms are equal
 * and opposite per unit mass times mass (mᵢ mⱼ · the same symmetric factor), so the
 * total energy is kept exactly. v_u vanishes in a region at uniform pressure — a
 * contact in pressure balance is left alone — and is largest where a hot layer's
 * pressure stands out. The signal v_u enters the particle's time step (vsig += α_u
 * max v_u). Pairs of a gas and a condensed material do not conduct (their
 * interface rule gives the pair's work to the gas alone, sph_solid.c).
 *
 * Returns the pair's deᵢ/dt per unit mⱼ; dwdr = ∂W/∂r = r · kernel_f. */
#ifndef HV_COND_H
#define HV_COND_H

#include <math.h>

static inline double sph_pair_cond(double ac, double ei, double ej, double pi, double pj,
                                   double rhoi, double rhoj, double dwdr, double *vumax)
{
  const double rbar = 0.5 * (rhoi + rhoj);
  const double vu = sqrt(fabs(pi - pj) / rbar);
  if (vu > *vumax) *vumax = vu;
  return ac * vu * (ei - ej) * dwdr / rbar;
}

#endif
