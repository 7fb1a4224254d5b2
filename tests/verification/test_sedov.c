/* test_sedov.c — the 3D Sedov–Taylor blast (examples/verification/sedov.yaml) against
 * the self-similar solution (tests/support/exact.c; Sedov 1959).
 *
 * Set-up: energy E = 1 released at the origin of a uniform cold gas (γ = 5/3,
 * ρ₀ = 1); the octant x, y, z > 0 is simulated with walls on the coordinate planes,
 * so it holds E/8 = 0.125; compared at t = 0.05, when r_s = ξ₀ (E t²/ρ₀)^(1/5) =
 * 0.3475 (ξ₀ = 1.1517) and the strong-shock density is (γ+1)/(γ−1) = 4.
 * Measures (mass-weighted mean density in spherical bins of width DR), each printed:
 *   shock radius  the outer half-height point of the binned density profile: the
 *                 outermost radius where it falls through (ρ_peak + 1)/2, half-way
 *                 between the peak and the undisturbed density, linearly interpolated
 *                 between bin centres; against r_s. SPH spreads the jump over ~2h, and
 *                 the half-height point of the smeared jump estimates where the
 *                 discontinuity is; the peak itself sits ~2h behind it (its radius is
 *                 printed too, and checked against a looser bound);
 *   peak density  the largest binned density; against 4. At finite resolution the
 *                 smeared peak is lower, so the check is a band around the measured
 *                 value (which excludes what γ = 1.4, jump 6, gives).
 * Energies: the kinetic and internal energy against the exact profile's, and the
 * internal energy within r < 0.3 r_s (the hot centre). Measured at the CI resolution:
 * kinetic 0.0379 + internal 0.0869 = 0.1248 J against the octant's E/8 = 0.125 J
 * (−0.14 %); kinetic against the exact 0.0353 J: +7.3 %; within r < 0.3 r_s 0.0052 J
 * (exact 0.0016 J: the excess heat SPH leaves at the centre of the blast). Checked: the
 * total within 1 % of E/8 (ETOT_RTOL: energy conservation of the blast), the kinetic
 * within 10 % of the exact (EKIN_RTOL: the partition between kinetic and internal), the
 * centre below ECORE_MAX = 0.01 J (the excess heat at the centre must not grow: about
 * twice today's value, six times the exact). Measured with the same test, extra --set:
 * γ = 1.4: kinetic −13.9 %, centre 0.0135 J → both fail; α = β = 0: kinetic +225 %
 * → fails. Both keep the total (−0.08 %, +0.52 %): that check guards the energy
 * bookkeeping of the scheme (energy equation, time integration), not the physics.
 * Writes $HVSPH_TMP/sedov_profile.csv (r, ρ, ρ_exact, v_r, v_r_exact, p, p_exact per
 * particle) and sedov_exact.csv (the exact solution on a fine grid) for
 * tools/figures/plot_verification.py. Extra arguments are passed to `hvsph run` (finer
 * runs).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "exact.h"
#include "profile.h"
#include "testlib.h"

#define T_END   0.05
#define GAMMA   (5.0 / 3.0)
#define E_BLAST 1.0  /* [J] the whole sphere; the octant holds E/8 */
#define DR      0.01 /* [m] bin width */
#define NB      60

/* Thresholds. Measured at the CI resolution (Δ = 0.015, R = 0.06, η = 1.5, density by
 * summation, 27 000 particles): half-height radius 0.3587 (+3.2 %), peak radius 0.3429
 * (−1.3 %), peak density 2.73 (docs/verification.md; the finer run comes closer to r_s
 * and to 4). Radius: 5.5 % on the half-height point, 4 % on the peak (the measured
 * offsets plus ~2.5 points). Peak density: [2.45, 2.95], the measured 2.73 ± ~8 %.
 * The physics they guard (measured with the same test, extra --set):
 *   γ = 1.4 (r_s −10 %, jump 6):  half-height −6.1 %, peak radius −10.8 %, peak 3.04
 *                                                                      → fails
 *   no viscosity (α = β = 0):     half-height −39 %, peak radius −50 %  → fails
 *   continuity density (sph.density: continuity): peak radius −8.8 %   → fails */
#define RADIUS_RTOL 0.055 /* |r_half/r_s − 1| */
#define RPEAK_RTOL  0.04  /* |r_peak/r_s − 1| */
#define PEAK_LO     2.45
#define PEAK_HI     2.95
#define ETOT_RTOL   0.01 /* |(E_kin + E_int)/(E/8) − 1|; measured −0.14 % */
#define EKIN_RTOL   0.10 /* |E_kin/E_kin,exact − 1|; measured +7.3 % */
#define ECORE_MAX   0.01 /* [J] internal energy within r < 0.3 r_s; measured 0.0052 */

int main(int argc, char **argv)
{
  static struct sedov_solution sol;
  exact_sedov_solve(GAMMA, &sol);
  double wall;
  int rc = verif_run("sedov", argc, argv, &wall);
  CHECK(rc == 0, "hvsph run sedov.yaml exits with status 0 (got %d)", rc);
  if (rc != 0) return test_finish();

  struct particles p;
  particles_init(&p);
  double t;
  if (verif_read_last("sedov", &p, &t)) {
    CHECK(0, "the last snapshot of the Sedov run can be read");
    return test_finish();
  }
  CHECK(fabs(t - T_END) < 1e-9, "the last snapshot is at t = %g s (got %.12g)", T_END, t);

  double *r = profile_radii(&p);
  const double rs = exact_sedov_radius(sol.xi0, E_BLAST, 1.0, t);
  char comment[512];
  snprintf(comment, sizeof comment,
           "sedov t=%.6g n=%zu: particles vs the Sedov-Taylor "
           "solution (gamma 5/3, E = 1, xi0 = %.5f, shock at r = %.4g)",
           t, p.n, sol.xi0, rs);
  FILE *f = profile_open("sedov_profile.csv", comment, "r,rho,rho_exact,vr,vr_exact,p,p_exact");
  for (size_t i = 0; i < p.n; i++) {
    struct gas_state e;
    exact_sedov(&sol, E_BLAST, 1.0, t, r[i], &e);
    double vr = 0.0;
    for (int k = 0; k < 3; k++) vr += p.v[k][i] * p.x[k][i];
    vr = r[i] > 0 ? vr / r[i] : 0.0;
    fprintf(f, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", r[i], p.rho[i], e.rho, vr, e.u, p.p[i], e.p);
  }
  profile_close(f);
  f = profile_open("sedov_exact.csv", comment, "r,rho_exact,vr_exact,p_exact");
  for (int k = 0; k <= 4500; k++) {
    const double rr = 0.45 * k / 4500.0;
    struct gas_state e;
    exact_sedov(&sol, E_BLAST, 1.0, t, rr, &e);
    fprintf(f, "%.9g,%.9g,%.9g,%.9g\n", rr, e.rho, e.u, e.p);
  }
  profile_close(f);

  /* where the energy is: kinetic and internal, in all and within λ = r/r_s < 0.3,
   * against the exact profile integrated over the octant (dV = (π/2) r² dr) */
  double ek = 0.0, ei = 0.0, ei_in = 0.0, xk = 0.0, xi = 0.0, xi_in = 0.0;
  long n_in = 0;
  for (size_t i = 0; i < p.n; i++) {
    double v2 = p.v[0][i] * p.v[0][i] + p.v[1][i] * p.v[1][i] + p.v[2][i] * p.v[2][i];
    ek += 0.5 * p.m[i] * v2;
    ei += p.m[i] * p.e[i];
    if (r[i] < 0.3 * rs) {
      ei_in += p.m[i] * p.e[i];
      n_in++;
    }
  }
  for (int k = 0; k < 20000; k++) {
    const double rr = (k + 0.5) * rs / 20000.0,
                 dv = 0.5 * 3.14159265358979323846 * rr * rr * rs / 20000.0;
    struct gas_state e;
    exact_sedov(&sol, E_BLAST, 1.0, t, rr, &e);
    xk += 0.5 * e.rho * e.u * e.u * dv;
    xi += e.p / (GAMMA - 1.0) * dv;
    if (rr < 0.3 * rs) xi_in += e.p / (GAMMA - 1.0) * dv;
  }
  printf("  energy [J]: kinetic %.4f (exact %.4f), internal %.4f (exact %.4f); kinetic "
         "fraction %.3f (exact %.3f)\n",
         ek, xk, ei, xi, ek / (ek + ei), xk / (xk + xi));
  printf("  internal energy within r < 0.3 r_s: %.4f in %ld particles (exact %.4f)\n", ei_in, n_in,
         xi_in);
  CHECK(fabs((ek + ei) / (E_BLAST / 8) - 1.0) <= ETOT_RTOL,
        "total energy %.5f J within %.0f %% "
        "of the octant's E/8 = %.3f J (%+.2f %%)",
        ek + ei, 100 * ETOT_RTOL, E_BLAST / 8, 100 * ((ek + ei) / (E_BLAST / 8) - 1.0));
  CHECK(fabs(ek / xk - 1.0) <= EKIN_RTOL,
        "kinetic energy %.5f J within %.0f %% of the exact "
        "%.5f J (%+.2f %%)",
        ek, 100 * EKIN_RTOL, xk, 100 * (ek / xk - 1.0));
  CHECK(ei_in < ECORE_MAX, "internal energy within r < 0.3 r_s %.5f J < %.2f J (exact %.5f J)",
        ei_in, ECORE_MAX, xi_in);

  double mean[NB];
  long count[NB];
  profile_bin(r, p.m, p.rho, p.n, DR, NB, mean, count);
  int bp = -1;
  for (int b = 0; b < NB; b++)
    if (count[b] && (bp < 0 || mean[b] > mean[bp])) bp = b;
  CHECK(bp > 0 && bp < NB - 1, "the density peak lies inside the binned range (bin %d)", bp);
  if (bp <= 0 || bp >= NB - 1) return test_finish();
  /* parabola through (bp−1, bp, bp+1) */
  const double y0 = mean[bp - 1], y1 = mean[bp], y2 = mean[bp + 1];
  double off = 0.0, den = y0 - 2.0 * y1 + y2;
  if (den < 0.0) off = 0.5 * (y0 - y2) / den;
  if (off > 0.5) off = 0.5;
  if (off < -0.5) off = -0.5;
  const double rpeak = (bp + 0.5 + off) * DR, peak = y1;
  /* outer half-height point */
  const double half = 0.5 * (peak + 1.0);
  double rhalf = (double)NAN;
  for (int b = bp; b < NB - 1; b++)
    if (mean[b] >= half && mean[b + 1] < half) {
      rhalf = (b + 0.5) * DR + (mean[b] - half) / (mean[b] - mean[b + 1]) * DR;
      break;
    }
  printf("  binned density (width %g):", DR);
  for (int b = 0; b < 45; b++)
    printf("%s%.3f:%.2f", b % 6 ? "  " : "\n    ", (b + 0.5) * DR, mean[b]);
  printf("\n");
  printf("  Sedov at t = %g: %zu particles, wall %.1f s\n", t, p.n, wall);
  printf("  exact shock radius %.4f (xi0 = %.5f)\n", rs, sol.xi0);
  printf("  peak of the binned density: r = %.4f (%+.1f %%), rho = %.3f (exact jump 4)\n", rpeak,
         100 * (rpeak / rs - 1), peak);
  printf("  outer half-height point (rho = %.3f): r = %.4f (%+.1f %%)\n", half, rhalf,
         100 * (rhalf / rs - 1));
  printf("  MEASURED sedov n=%zu wall=%.1f rpeak=%.4f peak=%.3f rhalf=%.4f\n", p.n, wall, rpeak,
         peak, rhalf);

  CHECK(fabs(rhalf / rs - 1.0) <= RADIUS_RTOL,
        "shock radius (outer half-height point) %.4f "
        "within %.1f %% of %.4f",
        rhalf, 100 * RADIUS_RTOL, rs);
  CHECK(fabs(rpeak / rs - 1.0) <= RPEAK_RTOL,
        "radius of the density peak %.4f within %.0f %% "
        "of %.4f",
        rpeak, 100 * RPEAK_RTOL, rs);
  CHECK(peak >= PEAK_LO && peak <= PEAK_HI, "peak density %.3f in [%.2f, %.2f]", peak, PEAK_LO,
        PEAK_HI);
  free(r);
  particles_free(&p);
  return test_finish();
}
