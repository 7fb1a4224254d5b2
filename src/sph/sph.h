/* sph.h — the loops over neighbours: the SPH sums, in gather form.
 *
 * Each real particle sums over its own neighbours in the fixed order given by the
 * cell grid, so results are bitwise independent of the number of threads. These
 * loops are the only place with OpenMP parallel regions over pairs.
 *
 *   continuity   dρᵢ/dt = ρᵢ Σⱼ (mⱼ/ρⱼ) vᵢⱼ·∇ᵢWᵢⱼ   (volume form; sph.continuity: mass,
 *                gas only: Σⱼ mⱼ vᵢⱼ·∇ᵢWᵢⱼ, the rate the energy equation's pdV work uses)
 *   momentum     dvᵢ/dt = −Σⱼ mⱼ (pᵢ/ρᵢ² + pⱼ/ρⱼ² + Πᵢⱼ) ∇ᵢWᵢⱼ
 *   energy       deᵢ/dt =  Σⱼ mⱼ (pᵢ/ρᵢ² + Πᵢⱼ/2) vᵢⱼ·∇ᵢWᵢⱼ
 *   viscosity    Πᵢⱼ = (−α c̄ᵢⱼ μᵢⱼ + β μᵢⱼ²)/ρ̄ᵢⱼ  if vᵢⱼ·xᵢⱼ < 0, else 0
 *                μᵢⱼ = hᵢⱼ vᵢⱼ·xᵢⱼ / (rᵢⱼ² + ε hᵢⱼ²)   (Monaghan & Gingold 1983)
 * with Wᵢⱼ = W(rᵢⱼ, hᵢⱼ), hᵢⱼ = (hᵢ + hⱼ)/2 (Monaghan 1992, Ann. Rev. A&A 30:543).
 */
#ifndef HV_SPH_H
#define HV_SPH_H

#include "kernel/kernel.h"
#include "material/material.h"
#include "neighbours/grid.h"
#include "particles/particles.h"

struct sph_params {
  enum kernel_kind kernel;
  double eta;          /* [-] h = eta (m/ρ)^(1/3) */
  double h_min, h_max; /* [m] bounds on h (0 in the case file: automatic, 1/10 and
                          10 times the initial extremes) */
  double alpha, beta;  /* [-] artificial viscosity (with the switch: α_max and β/α) */
  int av_switch;       /* sph.viscosity.switch: 1 for cullen-dehnen (avswitch.h): each
                          particle carries its own αᵢ ∈ [av_min, alpha], a pair uses
                          ½(αᵢ + αⱼ) and β ½(αᵢ + αⱼ)/α */
  double av_min;       /* [-] the switch's floor */
  double av_decay;     /* [-] ℓ: αᵢ decays over τ = 2hᵢ/(2ℓ cᵢ) */
  double eps;          /* [-] ε in μᵢⱼ */
  /* artificial stress (Monaghan 2000; Gray, Monaghan & Swift 2001) for solids:
     Rᵢ from the tensile principal stresses, pair term (Rᵢ + Rⱼ) (W(r)/W(Δp))ⁿ */
  double as_eps;       /* [-] ε, 0 switches it off */
  double as_n;         /* [-] n */
  int grad_correction; /* normalise the velocity gradient by the kernel-gradient
                          correction matrix (Randles & Libersky 1996) */
  int continuity_mass; /* gas loops: dρᵢ/dt = Σⱼ mⱼ vᵢⱼ·∇ᵢWᵢⱼ (the rate the energy
                          equation's pdV work assumes) instead of the volume form */
  int reconstruct;     /* solids: the viscosity of a pair of one body, both with
                          strength, sees the velocity difference reconstructed linearly
                          to the pair's midpoint (slope-limited); see sph_forces_solid */
  int reconstruct_contact;  /* with reconstruct: pairs of different pieces (contact)
                          too, each particle reconstructed by its own piece's gradient */
  double density_diffusion; /* solids: δ of the continuity rate's density diffusion
                          (Molteni & Colagrossi 2009), δ cᵢ Σⱼ hᵢⱼ Vⱼ ψᵢⱼ·∇ᵢWᵢⱼ,
                          ψᵢⱼ = 2(ρⱼ − ρᵢ)(xⱼ − xᵢ)/rᵢⱼ², over the pairs of one piece
                          and one condensed material, both at ρ ≥ ρ₀/2; 0: off */
  const int32_t *piece;     /* solids: piece[b] is the body that body b is part of
                          (bodies[i].part_of); pairs of one piece interact as within
                          one body (stress, tension, velocity gradient), pairs of
                          different pieces as contact. NULL: every body its own piece */
  int summation;            /* gas-only cases: density by summation at mid-step, ρᵢ =
                          Σⱼ mⱼ W(rᵢⱼ, hᵢⱼ) (self included), instead of integrating
                          the continuity equation; see sph_density_rate */
  int skip_resting;         /* solids: a cell whose neighbour cells hold only particles at
                          rest and free of stress (v = 0, p = 0, S = 0, R = 0, exactly)
                          is not computed: its rates are exactly zero, so the results
                          are the same bits (rest.c); not with the switch, whose
                          αᵢ decays at rest */
  double rest_tol;          /* solids: a particle of a condensed material (ρ₀, K₀ > 0)
                          whose v, a, e, ė, ρ − ρ₀ and S are all within rest_tol of
                          their scales (c = √(K₀/ρ₀), c², ρ₀, K₀) at the end of a step
                          is set exactly at rest (step.c, clamp_to_rest); 0: never */
  double rz_rmax;           /* axisymmetric runs: the radius of a mirror face r_max (wall,
                          symmetry), HUGE_VAL without one: its ghosts weigh as their
                          sources, at 2 r_max − r (sph_rz.c) */
  double rz_stretch_max;    /* axisymmetric runs: h follows a ring's hoop stretch r/r₀
                          up to this (p->r0; step.c, update_h; 0: all of it): a ring
                          carried outward keeps its axial extent while its area, and
                          the h taken from it, shrink as 1/r */
};

/* The neighbours found by one pass, kept for the next pass over the same grid: one
 * bit per candidate (a particle of a neighbour cell) for every particle — about 50
 * bytes per particle instead of 4 bytes per neighbour. */
enum { SPH_PARTNER_LEN = 24 }; /* doubles in a partner record of the solid force pass */

struct sph_cache {
  uint64_t *mask;       /* rows of bits */
  size_t cap;           /* words allocated */
  size_t *cell_off;     /* [ncells+1] first word of each cell's rows */
  uint32_t *cell_words; /* [ncells] words per row in each cell */
  size_t ccap;
  int valid; /* filled for the current grid */
  /* sph.viscosity.reconstruct: velocity gradient Gᵢ[a][b] = ∂v_a/∂x_b of every slot
     (reals from the first pass, 0 without strength; ghosts from
     boundary_refresh_gradv), 9 per slot, row-major */
  double *gradv;
  size_t gcap;     /* slots allocated */
  int gradv_valid; /* filled in this step's first pass, ghosts included */
  /* the solid force pass's partner records (sph_forces_solid), kept between steps:
     allocating and freeing them every step made glibc move its mmap threshold up and
     the heap grow by their size at every step (hvsph bench --solid with the
     reconstruction: peak RSS 2 705 bytes per particle after 10 steps, 988 with a fixed
     threshold) */
  double *partner;      /* SPH_PARTNER_LEN doubles per slot (partner.h, PR_*) */
  int32_t *partner_tag; /* per slot: piece × 2, + 1 when its artificial stress R ≠ 0 */
  size_t partner_cap;   /* slots allocated */
  /* sph.skip_resting: per cell, whether it holds only particles at rest (quiet) and
     whether the first pass skipped it (rest: every neighbour cell quiet) */
  uint8_t *quiet, *rest;
  size_t rcap; /* cells allocated */
  long rested; /* reals the last second pass skipped */
};

/* The signal speed of a real after the force pass: cᵢ(1 + 0.6 α) + 1.2 β μ_max, with α
 * the largest pair α (the switch) and μ_max the largest approach term; a particle with
 * no neighbour carries no signal, and only its own speed limits the step (so it moves at
 * most C_CFL h per step towards what it will meet). One place for both loops and for
 * the particles sph.skip_resting leaves out.
 * The α term takes Monaghan's (1992) 0.6 rather than his 1989 form's 1.2: the linear
 * viscosity acts as a diffusion much slower than the sound's crossing of h, and the
 * larger factor only shortened the step. The β μ term keeps 1.2: it holds the step as a
 * pair closes (the Mach 50 wall approach of test_timestep needs it), and dropping the α
 * term altogether breaks the energy bound of test_conservation_solid (figures in
 * docs/models.md, "Time step"). */
static inline double sph_signal_speed(int has_neighbour, double ci, double amax, double beta,
                                      double mumax, double speed)
{
  return has_neighbour ? ci + 0.6 * amax * ci + 1.2 * beta * mumax : speed;
}

void sph_cache_free(struct sph_cache *c);
/* Bytes held. */
size_t sph_cache_bytes(const struct sph_cache *c);

/* First pass of a step of length dt: drho for the reals, from x, v, m, rho, h of
 * all slots (reals and ghosts); fills the cache (if not NULL) with the neighbours it
 * found. With sp->summation (gas only) it also writes the summed density into rho
 * (the continuity rate drho is still computed: it carries ρ from mid-step to the end
 * of the step). With solids (p->solid), also the velocity gradient of each strength
 * particle and from it (strength.h) the mid-step deviatoric stress S (written to S),
 * the end-of-step stress S1, the plastic strain, and the deviatoric heating rate
 * S:ε̇/ρ (written to de; 0 for the others). */
void sph_density_rate(struct particles *p, const struct nbr_grid *g, const struct sph_params *sp,
                      struct sph_cache *cache, const struct material *mat, double dt);
/* Second pass: a, de (added to what the first pass wrote) and the signal speed
 * vsig for the reals, from x, v, m, rho, p, cs, h (and S, R, body with solids);
 * uses the cache when it is valid for this grid (else searches). */
void sph_forces(struct particles *p, const struct nbr_grid *g, const struct sph_params *sp,
                struct sph_cache *cache, const struct material *mat);
/* The artificial stress R of every real strength particle from its p and S. */
void sph_artificial_stress(struct particles *p, const struct sph_params *sp,
                           const struct material *mat);

/* Solid versions (sph_solid.c), called by the functions above when p->solid. */
void sph_density_rate_solid(struct particles *p, const struct nbr_grid *g,
                            const struct sph_params *sp, struct sph_cache *cache,
                            const struct material *mat, double dt);
void sph_forces_solid(struct particles *p, const struct nbr_grid *g, const struct sph_params *sp,
                      struct sph_cache *cache, const struct material *mat);
/* Neighbour count of particle i (diagnostics, tests). */
int sph_count_neighbours(const struct particles *p, const struct nbr_grid *g, size_t i);

#endif
