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
/* [-] the default of sph.rz_stretch_max: a ring's h follows its hoop stretch r/r₀ up to 2.
 * A ring carried outward keeps its axial extent while its cross-section m/(2π r ρ)
 * shrinks as 1/r: at constant density the h taken from it (step.c, update_h) fell from
 * 0.79 to 0.16 mm on rod-5841 at 4 rings per radius by 40 µs, the first rows of the
 * target pushed from r ≈ Δ/2 to the cavity wall, 10–25 times further out: a support
 * of 0.4 Δ along the axis, where the neighbours are a Δ apart, and the step fell with it.
 * Capping the stretch at 2 keeps h ≥ h₀/√2 at a ring's initial density (a support of
 * 1.7 Δ along the axis with η = 1.2); compression still shrinks h (spherical Noh's
 * 64-fold), and a ring moving inward is not capped (docs/models.md, "Axisymmetric
 * (RZ)"). */
#define RZ_STRETCH_MAX 2.0

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
