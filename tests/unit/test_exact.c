/* test_exact.c — the exact solutions used by the verification tests (tests/support/exact.c)
 * against published values.
 *
 * Riemann: Toro (2009), "Riemann Solvers and Numerical Methods for Fluid Dynamics",
 * 3rd ed., Table 4.3 (exact p*, u*, ρ*L, ρ*R to 5-6 significant figures; γ = 1.4):
 *   test 1 (Sod)     L (1, 0, 1)         R (0.125, 0, 0.1)  p* 0.30313 u* 0.92745
 *                                                           ρ*L 0.42632 ρ*R 0.26557
 *   test 2 ("123")   L (1, −2, 0.4)      R (1, 2, 0.4)      p* 0.00189 u* 0 ρ* 0.02185
 *   test 3           L (1, 0, 1000)      R (1, 0, 0.01)     p* 460.894 u* 19.5975
 *                                                           ρ*L 0.57506 ρ*R 5.99924
 * (states written (ρ, u, p)). The tolerances are half a unit in the last published
 * digit (plus rounding of the table), so a wrong γ, a wrong shock/rarefaction branch
 * or a sign error fails.
 * Noh: ρ = 64 inside r_s = t/3 for γ = 5/3, (1 + t/r)² outside (Noh 1987, §V).
 * Sedov: ξ₀ = 1.1517 for γ = 5/3 and 1.0328 for γ = 1.4 (Sedov 1959; Kamm & Timmes
 * 2007, LA-UR-07-2849, give 1.15167 and 1.03275), the strong-shock jump (γ+1)/(γ−1),
 * and the known ratio of central to post-shock pressure for γ = 1.4 (0.3655...).
 */
#include <math.h>
#include <stdio.h>

#include "exact.h"
#include "testlib.h"

static const double G14 = 1.4;

/* The exact state just left and right of the contact, sampled at ξ = u* ∓ tiny. */
static void star_densities(struct gas_state L, struct gas_state R, double *rl, double *rr)
{
  double ps, us;
  struct gas_state o;
  exact_riemann_star(L, R, G14, &ps, &us);
  exact_riemann(L, R, G14, us - 1e-9, &o);
  *rl = o.rho;
  exact_riemann(L, R, G14, us + 1e-9, &o);
  *rr = o.rho;
}

static void test_toro1_sod(void)
{
  struct gas_state L = {1.0, 0.0, 1.0}, R = {0.125, 0.0, 0.1};
  double ps, us, rl, rr;
  exact_riemann_star(L, R, G14, &ps, &us);
  CHECK_CLOSE(ps, 0.30313, 0.5e-5, "Toro test 1 (Sod): p*");
  CHECK_CLOSE(us, 0.92745, 0.5e-5, "Toro test 1 (Sod): u*");
  star_densities(L, R, &rl, &rr);
  CHECK_CLOSE(rl, 0.42632, 0.5e-5, "Toro test 1 (Sod): rho*L");
  CHECK_CLOSE(rr, 0.26557, 0.5e-5, "Toro test 1 (Sod): rho*R");
  /* the wave pattern at t = 0.2: undisturbed left of the rarefaction head x = −c_L t,
   * rarefaction fan, the star plateaus, the shock at x = S t with S = 1.75216 (Toro
   * eq. 4.59 with the values above), undisturbed right of it */
  struct gas_state o;
  const double cL = sqrt(1.4), t = 0.2;
  exact_riemann(L, R, G14, (-cL * t - 1e-6) / t, &o);
  CHECK(o.rho == 1.0 && o.u == 0.0 && o.p == 1.0, "Sod: left state left of the head");
  exact_riemann(L, R, G14, -0.5 * cL, &o); /* inside the fan: isentropic, J+ constant */
  double c = sqrt(1.4 * o.p / o.rho);
  CHECK_CLOSE(o.p / pow(o.rho, 1.4), 1.0, 1e-12, "Sod fan: p/rho^gamma = left value");
  CHECK_CLOSE(o.u + 2.0 * c / 0.4, 2.0 * cL / 0.4, 1e-12, "Sod fan: Riemann invariant J+");
  exact_riemann(L, R, G14, 1.75216 - 1e-4, &o);
  CHECK_CLOSE(o.rho, 0.26557, 0.5e-5, "Sod: post-shock density just behind the shock");
  exact_riemann(L, R, G14, 1.75216 + 1e-4, &o);
  CHECK(o.rho == 0.125 && o.p == 0.1, "Sod: right state just ahead of the shock");
  /* a wrong γ gives a star state far outside the tolerances above */
  double ps5, us5;
  exact_riemann_star(L, R, 5.0 / 3.0, &ps5, &us5);
  CHECK(fabs(ps5 - 0.30313) > 100 * 0.5e-5, "gamma = 5/3 gives a different p* (%.5f)", ps5);
}

static void test_toro2_123(void)
{
  struct gas_state L = {1.0, -2.0, 0.4}, R = {1.0, 2.0, 0.4};
  double ps, us, rl, rr;
  exact_riemann_star(L, R, G14, &ps, &us);
  CHECK_CLOSE(ps, 0.00189, 0.5e-5, "Toro test 2 (123 problem): p*");
  CHECK_CLOSE(us, 0.0, 1e-12, "Toro test 2 (123 problem): u* (symmetric)");
  star_densities(L, R, &rl, &rr);
  CHECK_CLOSE(rl, 0.02185, 0.5e-5, "Toro test 2: rho*L");
  CHECK_CLOSE(rr, 0.02185, 0.5e-5, "Toro test 2: rho*R");
}

static void test_toro3(void)
{
  struct gas_state L = {1.0, 0.0, 1000.0}, R = {1.0, 0.0, 0.01};
  double ps, us, rl, rr;
  exact_riemann_star(L, R, G14, &ps, &us);
  CHECK_CLOSE(ps, 460.894, 0.5e-3, "Toro test 3: p*");
  CHECK_CLOSE(us, 19.5975, 0.5e-4, "Toro test 3: u*");
  star_densities(L, R, &rl, &rr);
  CHECK_CLOSE(rl, 0.57506, 0.5e-5, "Toro test 3: rho*L");
  CHECK_CLOSE(rr, 5.99924, 0.5e-5, "Toro test 3: rho*R");
}

static void test_noh(void)
{
  const double g = 5.0 / 3.0, t = 0.6;
  CHECK_CLOSE(exact_noh_shock_radius(t, g), 0.2, 1e-15, "Noh: shock radius t/3 at t = 0.6");
  CHECK_CLOSE(exact_noh_density(0.1, t, g, 1.0), 64.0, 1e-12, "Noh: plateau 64 (gamma = 5/3)");
  CHECK_CLOSE(exact_noh_density(0.19999, t, g, 1.0), 64.0, 1e-12, "Noh: 64 just inside r_s");
  CHECK_CLOSE(exact_noh_density(0.2 + 1e-12, t, g, 1.0), 16.0, 1e-9,
              "Noh: (1 + t/r)^2 = 16 just outside r_s");
  CHECK_CLOSE(exact_noh_density(0.6, t, g, 1.0), 4.0, 1e-12, "Noh: (1 + t/r)^2 = 4 at r = t");
  CHECK_CLOSE(exact_noh_density(0.1, t, 1.4, 2.0), 2.0 * 216.0, 1e-9,
              "Noh: rho0 ((g+1)/(g-1))^3 = 2 x 216 for gamma = 1.4");
  /* mass conservation: the shocked sphere holds what fell through r_s,
   * (4/3)π r_s³ 64 = ∫ over the initial ball of radius r_s + t of ρ₀ */
  const double rs = 0.2, mass_in = 4.0 / 3.0 * 64.0 * rs * rs * rs;
  CHECK_CLOSE(mass_in, 4.0 / 3.0 * pow(rs + t, 3.0), 1e-12, "Noh: mass balance across r_s");
}

static void test_sedov(void)
{
  static struct sedov_solution s;
  CHECK_CLOSE(exact_sedov_radius(1.1517, 1.0, 1.0, 0.05), 1.1517 * pow(0.0025, 0.2), 1e-15,
              "Sedov: r_s = xi0 (E t^2/rho)^(1/5)");
  CHECK_CLOSE(exact_sedov_radius(1.1517, 1.0, 1.0, 0.05), 0.347478, 1e-6,
              "Sedov: r_s = 0.3475 at t = 0.05 (E = 1, rho = 1, gamma = 5/3)");
  /* r_s scales as E^(1/5) t^(2/5) rho^(-1/5) */
  CHECK_CLOSE(exact_sedov_radius(1.0, 32.0, 1.0, 1.0), 2.0, 1e-14, "Sedov: E^(1/5)");
  CHECK_CLOSE(exact_sedov_radius(1.0, 1.0, 1.0, 32.0), 4.0, 1e-14, "Sedov: t^(2/5)");

  exact_sedov_solve(5.0 / 3.0, &s);
  printf("  xi0(gamma = 5/3) = %.6f\n", s.xi0);
  CHECK_CLOSE(s.xi0, 1.1517, 2e-4, "Sedov: xi0 from the energy integral, gamma = 5/3");
  struct gas_state o;
  const double rs = exact_sedov_radius(s.xi0, 1.0, 1.0, 0.05);
  exact_sedov(&s, 1.0, 1.0, 0.05, rs * (1.0 - 1e-9), &o);
  CHECK_CLOSE(o.rho, 4.0, 1e-6, "Sedov: strong-shock density 4 just behind the shock");
  CHECK_CLOSE(o.u, 2.0 / (5.0 / 3.0 + 1.0) * 0.4 * rs / 0.05, 1e-6,
              "Sedov: post-shock velocity 2D/(gamma+1), D = (2/5) r_s/t");
  exact_sedov(&s, 1.0, 1.0, 0.05, rs * 1.001, &o);
  CHECK(o.rho == 1.0 && o.u == 0.0 && o.p == 0.0, "Sedov: undisturbed gas ahead of the shock");
  exact_sedov(&s, 1.0, 1.0, 0.05, rs * 0.5, &o);
  CHECK(o.rho > 0.0 && o.rho < 0.1, "Sedov: evacuated interior, rho(r_s/2) = %.4f", o.rho);

  exact_sedov_solve(1.4, &s);
  printf("  xi0(gamma = 1.4) = %.6f\n", s.xi0);
  CHECK_CLOSE(s.xi0, 1.0328, 2e-4, "Sedov: xi0 from the energy integral, gamma = 1.4");
  struct gas_state c, sh;
  exact_sedov(&s, 1.0, 1.0, 1.0, 0.0, &c);
  exact_sedov(&s, 1.0, 1.0, 1.0, s.xi0 * (1.0 - 1e-9), &sh);
  CHECK_CLOSE(sh.rho, 6.0, 1e-5, "Sedov: strong-shock density 6 for gamma = 1.4");
  CHECK_CLOSE(c.p / sh.p, 0.3655, 1e-3, "Sedov: central / post-shock pressure, gamma = 1.4");
}

int main(void)
{
  test_toro1_sod();
  test_toro2_123();
  test_toro3();
  test_noh();
  test_sedov();
  return test_finish();
}
