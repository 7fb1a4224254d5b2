/* recon.h — internal to src/sph (and its unit test): the approach speed a pair's
 * artificial viscosity sees under sph.viscosity.reconstruct.
 *
 * For a pair i, j (rᵢⱼ = xᵢ − xⱼ, approach speed vdx = (vᵢ − vⱼ)·rᵢⱼ < 0) the velocities
 * are reconstructed linearly from each particle to the pair's midpoint, vᵢ − ½Φ Gᵢ rᵢⱼ
 * and vⱼ + ½Φ Gⱼ rᵢⱼ (Gₖ = ∂v/∂x at k, row-major), which gives vdx − ½Φ (gᵢ + gⱼ) with
 * gₖ = rᵢⱼ·Gₖ rᵢⱼ. Φ = 4 gᵢ gⱼ / (gᵢ + gⱼ)² is van Leer's limiter in symmetric form:
 * 1 where the two slopes agree (the velocity is linear over the pair: no viscosity),
 * falling as they differ, 0 when they differ in sign or one is 0 (the viscosity sees the
 * whole difference) (Frontiere, Raskin & Owen 2017, J. Comput. Phys. 332:160).
 * Symmetric in i and j, so the pair force stays antisymmetric; clamped to [vdx, 0], so
 * it only removes viscosity.
 */
#ifndef HV_SPH_RECON_H
#define HV_SPH_RECON_H

static inline double sph_recon_approach(double vdx, const double *Gi, const double *Gj, double dx,
                                        double dy, double dz)
{
  const double r[3] = {dx, dy, dz};
  double gi = 0.0, gj = 0.0;
  for (int a = 0; a < 3; a++) {
    gi += r[a] * (Gi[3 * a] * dx + Gi[3 * a + 1] * dy + Gi[3 * a + 2] * dz);
    gj += r[a] * (Gj[3 * a] * dx + Gj[3 * a + 1] * dy + Gj[3 * a + 2] * dz);
  }
  const double prod = gi * gj, sum = gi + gj;
  if (!(prod > 0.0)) return vdx;
  const double w = vdx - 0.5 * (4.0 * prod / (sum * sum)) * sum;
  return w > 0.0 ? 0.0 : (w < vdx ? vdx : w);
}

#endif
