/* rz.h — the axisymmetric (RZ) form of the SPH loops (sph_rz.c; docs/models.md,
 * "Axisymmetric (RZ)").
 *
 * A particle of an axisymmetric run (particles.h, p->axisym) stands for a ring: x[0] the
 * axial coordinate, x[1] = r ≥ 0, m the ring's (true 3D) mass, ρ its true density. The
 * loops are the area-weighted form of Petschek & Libersky (1993, J. Comput. Phys.
 * 109:76) and Brookshaw (2003, ANZIAM J. 44(E):C114), as in Spheral's
 * SolidSPHHydroBaseRZ: the ordinary pair sums of the 3D loops over the meridional plane,
 * with the 2D kernel (kernel.h, KERNEL_2D) and each neighbour weighed by its area mass
 * μⱼ = mⱼ/(2π|rⱼ|) in place of mⱼ, plus the hoop terms of the continuum equations, which
 * are local to each particle:
 *   dρᵢ/dt  += −ρᵢ v_r,ᵢ/rᵢ                         (continuity: ∇·v = ∇₂·v + v_r/r)
 *   ε̇_θθ,ᵢ   = v_r,ᵢ/rᵢ  (the velocity gradient's zz, the hoop component; the stress
 *              update, its radial return and the deviatoric heating then act on all
 *              four components S_xx, S_rr, S_θθ = S_zz, S_xr)
 *   dv_x,ᵢ/dt += S_xr,ᵢ/(ρᵢ rᵢ),  dv_r,ᵢ/dt += (S_rr,ᵢ − S_θθ,ᵢ)/(ρᵢ rᵢ)
 *              (the pressure's hoop terms cancel: σ_rr − σ_θθ = S_rr − S_θθ)
 *   deᵢ/dt  += −pᵢ v_r,ᵢ/(ρᵢ rᵢ)
 * Each 1/r takes r no smaller than RZ_R_FLOOR hᵢ (sph_rz_radius): the lattice's first
 * row stands at Δ/2 ≈ 0.42 h, and only a particle pushed onto the axis meets the floor.
 */
#ifndef HV_SPH_RZ_H
#define HV_SPH_RZ_H

#include <math.h>

#include "material/material.h"
#include "neighbours/grid.h"
#include "particles/particles.h"

struct sph_params;
struct sph_cache;

#define RZ_R_FLOOR 0.1 /* [-] the smallest r of the 1/r terms, in units of h */

/* The radius the 1/r terms of a particle at r (ghost: r < 0) with smoothing length h
 * take: |r|, not below RZ_R_FLOOR h. */
static inline double sph_rz_radius(double r, double h)
{
  const double a = fabs(r), f = RZ_R_FLOOR * h;
  return a > f ? a : f;
}

/* The radius particle j weighs with (its ring's): r for a real, |r| for a ghost across
 * the axis, 2 r_max − r for a ghost across a mirror face at r_max — the radius of its
 * source, whose ring mass it carries — not below the floor. */
static inline double sph_rz_weight_radius(double r, double h, double rmax)
{
  return sph_rz_radius(r > rmax ? 2.0 * rmax - r : r, h);
}

/* The passes of sph.h for an axisymmetric store (p->axisym == 1): the 3D loops on area
 * masses, with the hoop terms. */
void sph_rz_density_rate(struct particles *p, const struct nbr_grid *g, const struct sph_params *sp,
                         struct sph_cache *cache, const struct material *mat, double dt);
void sph_rz_forces(struct particles *p, const struct nbr_grid *g, const struct sph_params *sp,
                   struct sph_cache *cache, const struct material *mat);

#endif
