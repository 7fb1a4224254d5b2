/* avswitch.h — the artificial viscosity's switch (sph.viscosity.switch: cullen-dehnen),
 * after Cullen & Dehnen 2010 (MNRAS 408:669, "Inviscid SPH"), written for hvsph's
 * Monaghan–Gingold viscosity (sph.h).
 *
 * Each particle carries its own coefficient αᵢ ∈ [α_min, α_max] (α_max =
 * sph.viscosity.alpha); a pair uses αᵢⱼ = ½(αᵢ + αⱼ) and βᵢⱼ = β αᵢⱼ/α_max, so the
 * switch scales the whole viscosity of a pair between its full value and α_min/α_max
 * of it. At every step's first pass (mid-step) each real particle i:
 *   Gᵢ = ∇v from its neighbours, corrected to be exact for linear fields
 *        (Gᵢ = Lᵢ Aᵢ⁻¹, Lᵢ = Σⱼ Vⱼ (vⱼ − vᵢ) ⊗ ∇ᵢWᵢⱼ, Aᵢ = Σⱼ Vⱼ (xⱼ − xᵢ) ⊗ ∇ᵢWᵢⱼ; the
 *        neighbours are those of its continuity sum, other bodies included: an impact's
 *        first shock is between two bodies);
 *   dᵢ = tr Gᵢ, and its rate ḋᵢ = (dᵢ − dᵢ')/Δt from the value dᵢ' of the last step
 *        (one mid-step back; Δt the step's length);
 *   ξᵢ = (2dᵢ)² / ((2dᵢ)² + Sᵢ:Sᵢ), Sᵢ the trace-free symmetric part of Gᵢ — 1 for
 *        compression along every axis, 6/7 for a plane shock, 0 for a shear or a
 *        volume-keeping strain (the stagnation flow ahead of a penetrator);
 *   Aᵢ = ξᵢ max(−ḋᵢ, 0): compression growing along the particle's path, as ahead of
 *        a shock; a steady compression (ḋ = 0) and an expansion do not raise it;
 *   α_loc = α_max H²Aᵢ / (H²Aᵢ + cᵢ²), H = 2hᵢ the kernel's support radius;
 *   αᵢ ← α_loc if α_loc > αᵢ (at once), else α_loc + (αᵢ − α_loc) e^(−Δt/τ),
 *        τ = H/(2ℓ cᵢ) (ℓ = sph.viscosity.decay, 0.05: about ten crossings of H at
 *        the sound speed), and at least α_min.
 * Differences from the paper: the rate ḋ from consecutive steps, not from the
 * divergence of the acceleration; no R factor in ξ (the sign-weighted neighbour
 * fraction), whose neighbour sums need the divergences of the whole step; cᵢ instead of
 * the largest pairwise signal speed in α_loc and τ; the Monaghan–Gingold pair term
 * (with β) instead of the signal-velocity form.
 */
#ifndef HV_AVSWITCH_H
#define HV_AVSWITCH_H

#include <math.h>
#include <stddef.h>

#include "sph/sph.h"

/* L ← L · A⁻¹ with A = Σ Vⱼ (xⱼ − xᵢ) ⊗ ∇ᵢWᵢⱼ, which is I for a full, regular
 * neighbourhood: the corrected gradient is exact for linear velocity fields.
 * Left unchanged where A is nearly singular (a particle with few neighbours). */
static inline void sph_correct_gradient(double L[9], const double A[9])
{
  const double det = A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
                     A[2] * (A[3] * A[7] - A[4] * A[6]);
  if (!(fabs(det) > 1e-3)) return;
  double B[9]; /* B = A⁻¹ */
  B[0] = (A[4] * A[8] - A[5] * A[7]) / det;
  B[1] = (A[2] * A[7] - A[1] * A[8]) / det;
  B[2] = (A[1] * A[5] - A[2] * A[4]) / det;
  B[3] = (A[5] * A[6] - A[3] * A[8]) / det;
  B[4] = (A[0] * A[8] - A[2] * A[6]) / det;
  B[5] = (A[2] * A[3] - A[0] * A[5]) / det;
  B[6] = (A[3] * A[7] - A[4] * A[6]) / det;
  B[7] = (A[1] * A[6] - A[0] * A[7]) / det;
  B[8] = (A[0] * A[4] - A[1] * A[3]) / det;
  /* L = Σ Vⱼ (vⱼ − vᵢ) ⊗ ∇W estimates ∇v · A, so ∇v = L · A⁻¹ */
  double M[9];
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++)
      M[3 * a + b] = L[3 * a] * B[b] + L[3 * a + 1] * B[3 + b] + L[3 * a + 2] * B[6 + b];
  for (int k = 0; k < 9; k++) L[k] = M[k];
}

/* Adds one neighbour to L = Σ Vⱼ (vⱼ − vᵢ) ⊗ ∇ᵢWᵢⱼ: w = Vⱼ f (∇ᵢWᵢⱼ = f (xᵢ − xⱼ)),
 * d = xᵢ − xⱼ, u = vⱼ − vᵢ. The one place these sums are written (the switch's and the
 * strength's gradients), so that both add the same terms in the same order. */
static inline void sph_grad_add_L(double L[9], double w, double dx, double dy, double dz, double ux,
                                  double uy, double uz)
{
  L[0] += w * ux * dx;
  L[1] += w * ux * dy;
  L[2] += w * ux * dz;
  L[3] += w * uy * dx;
  L[4] += w * uy * dy;
  L[5] += w * uy * dz;
  L[6] += w * uz * dx;
  L[7] += w * uz * dy;
  L[8] += w * uz * dz;
}

/* Adds one neighbour to A = Σ Vⱼ (xⱼ − xᵢ) ⊗ ∇ᵢWᵢⱼ (w and d as sph_grad_add_L). */
static inline void sph_grad_add_A(double A[9], double w, double dx, double dy, double dz)
{
  A[0] -= w * dx * dx;
  A[1] -= w * dx * dy;
  A[2] -= w * dx * dz;
  A[3] -= w * dy * dx;
  A[4] -= w * dy * dy;
  A[5] -= w * dy * dz;
  A[6] -= w * dz * dx;
  A[7] -= w * dz * dy;
  A[8] -= w * dz * dz;
}

/* Accumulates one neighbour into the switch's sums L and A (as sph_grad_add_L). */
static inline void avsw_add(double L[9], double A[9], double w, double dx, double dy, double dz,
                            double ux, double uy, double uz)
{
  sph_grad_add_L(L, w, dx, dy, dz, ux, uy, uz);
  sph_grad_add_A(A, w, dx, dy, dz);
}

/* The limiter ξ of a velocity gradient G (row-major, G[3a+b] = ∂v_a/∂x_b). */
static inline double avsw_xi(const double G[9])
{
  const double d = G[0] + G[4] + G[8], d3 = d / 3.0;
  const double sxx = G[0] - d3, syy = G[4] - d3, szz = G[8] - d3;
  const double sxy = 0.5 * (G[1] + G[3]), syz = 0.5 * (G[5] + G[7]), sxz = 0.5 * (G[2] + G[6]);
  const double ss = sxx * sxx + syy * syy + szz * szz + 2.0 * (sxy * sxy + syz * syz + sxz * sxz);
  const double d2 = 4.0 * d * d;
  return d2 > 0.0 ? d2 / (d2 + ss) : 0.0;
}

/* The new αᵢ from the raw sums L, A of particle i (A is consumed), its last αᵢ and
 * divergence, its h and sound speed c, and the step dt; writes the new divergence. */
static inline double avsw_update(const struct sph_params *sp, double L[9], const double A[9],
                                 double alpha_old, double divv_old, double h, double c, double dt,
                                 double *divv_new)
{
  sph_correct_gradient(L, A);
  const double d = L[0] + L[4] + L[8];
  *divv_new = d;
  const double ddot = dt > 0.0 ? (d - divv_old) / dt : 0.0;
  const double Ai = ddot < 0.0 ? -ddot * avsw_xi(L) : 0.0;
  const double H = 2.0 * h, H2A = H * H * Ai, c2 = c * c;
  const double aloc = H2A > 0.0 ? sp->alpha * H2A / (H2A + c2) : 0.0;
  double a;
  if (aloc >= alpha_old) {
    a = aloc;
  } else {
    const double tau = c > 0.0 ? H / (2.0 * sp->av_decay * c) : HUGE_VAL;
    a = aloc + (alpha_old - aloc) * exp(-dt / tau);
  }
  if (a < sp->av_min) a = sp->av_min;
  if (a > sp->alpha) a = sp->alpha;
  return a;
}

#endif
