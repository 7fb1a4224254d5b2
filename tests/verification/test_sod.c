/* test_sod.c — the Sod shock tube (examples/verification/sod.yaml) against the exact
 * Riemann solution (tests/support/exact.c, Toro 2009 ch. 4).
 *
 * Set-up: γ = 1.4, left (x < 0) ρ = 1, p = 1, right ρ = 0.125, p = 0.1, at rest, in a
 * tube periodic in y and z with walls at x = ±0.5; compared at t = 0.2, when no wave
 * has reached a wall.
 * Measures, over the particles with |x| < 0.4 (clear of the walls; the waves lie in
 * −0.24 < x < 0.36), each printed:
 *   L1(q) = (1/N) Σᵢ |qᵢ − q_exact(xᵢ/t)|   for q = ρ, vx, p (a mean over particles, so
 *           the dense left state weighs 8 times the right state per unit length);
 *   the star plateau: mean p and vx of the particles with 0.03 < x < 0.15 (between the
 *           rarefaction tail at −0.014 and the contact at 0.185, a smoothing length
 *           clear of both) against p* = 0.30313, u* = 0.92745.
 * The L1 sums are also printed split by wave region (undisturbed |x| outside the waves,
 * rarefaction −0.25 < x < −0.01, left star −0.01 < x < 0.17, contact 0.17 < x < 0.20,
 * right star 0.20 < x < 0.33, shock 0.33 < x < 0.37), to show where the error lies.
 * Writes $HVSPH_TMP/sod_profile.csv (x, ρ, ρ_exact, vx, vx_exact, p, p_exact per
 * particle) and sod_exact.csv (the exact solution on a fine grid) for
 * tools/figures/plot_verification.py.
 * Extra arguments are passed to `hvsph run` (a finer run for docs/verification.md:
 * test_sod --set bodies[0].spacing=0.0025 --set bodies[1].spacing=0.005); the
 * thresholds are for the CI resolution.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "exact.h"
#include "profile.h"
#include "testlib.h"

#define T_END 0.2
#define X_MAX 0.4 /* |x| < X_MAX: the region compared */

/* Thresholds. Measured at the CI resolution (Δ = 0.005 left / 0.01 right, Wendland C2,
 * η = 1.8, density by summation, 28 800 particles): L1(ρ) = 0.00568, L1(vx) = 0.01008,
 * L1(p) = 0.00668 (docs/verification.md, with the finer run). Each threshold is the
 * measured value plus about 45 %, room for round-off and small legitimate changes to
 * the scheme. The physics they guard (measured with the same test, extra --set):
 *   γ = 5/3 instead of 1.4:      L1 = 0.027 / 0.053 / 0.029, u* −9.6 %  → fails
 *   no viscosity (α = β = 0):    L1(vx) = 0.043 (post-shock ringing)    → fails
 *   cubic spline, η = 1.5, summation (too few layers along the stretched
 *   lattice): star pressure +6.0 %                                     → fails */
#define L1_RHO_MAX 0.0082
#define L1_VX_MAX  0.0146
#define L1_P_MAX   0.0097
/* Star plateau: measured p = 0.30740 (+1.41 %), vx = 0.92472 (−0.29 %); allowed 2.5 %
 * on p and 1 % on vx (γ = 5/3: exact u* = 0.8412, −9.3 %, measured −9.6 %; with the
 * viscosity switch u* is −0.44 %). */
#define PSTAR_RTOL 0.025
#define USTAR_RTOL 0.01

/* With sph.viscosity.switch: cullen-dehnen (ctest verification.test_sod_switch runs this
 * test with --set sph.viscosity.switch=cullen-dehnen; the thresholds above hold as they
 * are: measured L1 = 0.00549 / 0.01048 / 0.00648, p* +1.59 %, u* −0.44 %), the
 * particles' α at t = 0.2 by region. Measured: undisturbed left state (x < −0.3) max 0;
 * rarefaction mean 0.018; left star (0.03 < x < 0.15, gas from the initial jump, which
 * the switch met as a shock at t = 0 and has been decaying since) mean 0.164; at the
 * shock (0.33 < x < 0.37) mean 0.661. Thresholds: the undisturbed state has no source
 * (SW_REST_MAX); an expansion is no source either (SW_RAREF_MAX); the shock raises α
 * (SW_SHOCK_MIN) and it decays behind it (SW_STAR_MAX: without the decay the left star
 * would keep the value of the start's jump). */
#define SW_REST_MAX  1e-3
#define SW_RAREF_MAX 0.05
#define SW_SHOCK_MIN 0.5
#define SW_STAR_MAX  0.35

static void sod_switch(const struct particles *p)
{
  static const double lo[4] = {-0.5, -0.25, 0.03, 0.33}, hi[4] = {-0.3, -0.01, 0.15, 0.37};
  double sum[4] = {0}, mx[4] = {0};
  long cnt[4] = {0};
  for (size_t i = 0; i < p->n; i++)
    for (int k = 0; k < 4; k++)
      if (p->x[0][i] > lo[k] && p->x[0][i] < hi[k]) {
        sum[k] += p->alpha[i];
        cnt[k]++;
        if (p->alpha[i] > mx[k]) mx[k] = p->alpha[i];
      }
  double mean[4];
  for (int k = 0; k < 4; k++) mean[k] = cnt[k] ? sum[k] / (double)cnt[k] : -1.0;
  printf("  switch: alpha mean / max: rest %.4f / %.4f, rarefaction %.4f / %.4f, left star "
         "%.4f / %.4f, shock %.4f / %.4f\n",
         mean[0], mx[0], mean[1], mx[1], mean[2], mx[2], mean[3], mx[3]);
  CHECK(cnt[0] && mx[0] <= SW_REST_MAX, "switch: undisturbed gas keeps alpha <= %g (max %.4f)",
        SW_REST_MAX, mx[0]);
  CHECK(mean[1] <= SW_RAREF_MAX, "switch: rarefaction mean alpha %.4f <= %g", mean[1],
        SW_RAREF_MAX);
  CHECK(mean[3] >= SW_SHOCK_MIN, "switch: shock mean alpha %.4f >= %g", mean[3], SW_SHOCK_MIN);
  CHECK(mean[2] <= SW_STAR_MAX, "switch: left star mean alpha %.4f <= %g (decayed)", mean[2],
        SW_STAR_MAX);
}

int main(int argc, char **argv)
{
  const struct gas_state L = {1.0, 0.0, 1.0}, R = {0.125, 0.0, 0.1};
  const double gamma = 1.4;
  double wall;
  int rc = verif_run("sod", argc, argv, &wall);
  CHECK(rc == 0, "hvsph run sod.yaml exits with status 0 (got %d)", rc);
  if (rc != 0) return test_finish();

  struct particles p;
  particles_init(&p);
  double t;
  if (verif_read_last("sod", &p, &t)) {
    CHECK(0, "the last snapshot of the Sod run can be read");
    return test_finish();
  }
  CHECK(fabs(t - T_END) < 1e-9, "the last snapshot is at t = %g s (got %.12g)", T_END, t);

  double ps, us;
  exact_riemann_star(L, R, gamma, &ps, &us);
  double l1[3] = {0, 0, 0}, psum = 0.0, usum = 0.0;
  /* where the error lies: the L1 sums split by wave region (edges at t = 0.2) */
  enum { NREG = 6 };
  static const char *const reg_name[NREG] = {"undisturbed", "rarefaction", "left star",
                                             "contact",     "right star",  "shock"};
  static const double reg_edge[NREG - 1] = {-0.25, -0.01, 0.17, 0.20, 0.33};
  double reg[NREG][3] = {{0}};
  long n = 0, nstar = 0;
  char comment[512];
  snprintf(comment, sizeof comment,
           "sod t=%.6g n=%zu: particles vs the exact Riemann "
           "solution (gamma 1.4)",
           t, p.n);
  FILE *f = profile_open("sod_profile.csv", comment, "x,rho,rho_exact,vx,vx_exact,p,p_exact");
  for (size_t i = 0; i < p.n; i++) {
    const double x = p.x[0][i];
    struct gas_state e;
    exact_riemann(L, R, gamma, x / t, &e);
    fprintf(f, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", x, p.rho[i], e.rho, p.v[0][i], e.u, p.p[i],
            e.p);
    if (fabs(x) < X_MAX) {
      const double d[3] = {fabs(p.rho[i] - e.rho), fabs(p.v[0][i] - e.u), fabs(p.p[i] - e.p)};
      int k = 0;
      while (k < NREG - 1 && x >= reg_edge[k]) k++;
      if (k == NREG - 1 && x >= 0.37) k = 0; /* beyond the shock: undisturbed right state */
      for (int c = 0; c < 3; c++) {
        l1[c] += d[c];
        reg[k][c] += d[c];
      }
      n++;
    }
    if (x > 0.03 && x < 0.15) {
      psum += p.p[i];
      usum += p.v[0][i];
      nstar++;
    }
  }
  profile_close(f);
  /* the exact solution alone, finely sampled, for the plot's line */
  f = profile_open("sod_exact.csv", comment, "x,rho_exact,vx_exact,p_exact");
  for (int k = 0; k <= 4000; k++) {
    const double x = -0.5 + k / 4000.0;
    struct gas_state e;
    exact_riemann(L, R, gamma, x / t, &e);
    fprintf(f, "%.9g,%.9g,%.9g,%.9g\n", x, e.rho, e.u, e.p);
  }
  profile_close(f);
  CHECK(n > 0 && nstar > 0, "particles in the compared regions (%ld, %ld)", n, nstar);
  if (!n || !nstar) return test_finish();
  for (int k = 0; k < 3; k++) l1[k] /= (double)n;
  const double pm = psum / (double)nstar, um = usum / (double)nstar;

  printf("  Sod at t = %g: %zu particles, %ld with |x| < %g, wall %.1f s\n", t, p.n, n, X_MAX,
         wall);
  printf("  L1(rho) = %.5f  L1(vx) = %.5f  L1(p) = %.5f\n", l1[0], l1[1], l1[2]);
  printf("  L1 by region (share of the sums above): region: rho vx p\n");
  for (int k = 0; k < NREG; k++)
    printf("    %-12s %.5f %.5f %.5f\n", reg_name[k], reg[k][0] / (double)n, reg[k][1] / (double)n,
           reg[k][2] / (double)n);
  printf("  star plateau (0.03 < x < 0.15, %ld particles): p = %.5f (exact %.5f, %+.2f %%), "
         "vx = %.5f (exact %.5f, %+.2f %%)\n",
         nstar, pm, ps, 100 * (pm / ps - 1), um, us, 100 * (um / us - 1));
  printf("  MEASURED sod n=%zu wall=%.1f L1_rho=%.5f L1_vx=%.5f L1_p=%.5f pstar=%.5f "
         "ustar=%.5f\n",
         p.n, wall, l1[0], l1[1], l1[2], pm, um);

  CHECK(l1[0] <= L1_RHO_MAX, "L1(rho) = %.5f <= %.4f", l1[0], L1_RHO_MAX);
  CHECK(l1[1] <= L1_VX_MAX, "L1(vx) = %.5f <= %.4f", l1[1], L1_VX_MAX);
  CHECK(l1[2] <= L1_P_MAX, "L1(p) = %.5f <= %.4f", l1[2], L1_P_MAX);
  CHECK(fabs(pm / ps - 1.0) <= PSTAR_RTOL, "star pressure %.5f within %.1f %% of p* = %.5f", pm,
        100 * PSTAR_RTOL, ps);
  CHECK(fabs(um / us - 1.0) <= USTAR_RTOL, "star velocity %.5f within %.1f %% of u* = %.5f", um,
        100 * USTAR_RTOL, us);
  /* run with the switch (ctest verification.test_sod_switch passes --set
     sph.viscosity.switch=cullen-dehnen): the snapshot must carry each particle's alpha,
     or the switch checks below would be skipped silently and the test pass with nothing
     checked */
  int want_switch = 0;
  for (int a = 1; a < argc; a++)
    if (strstr(argv[a], "switch=cullen-dehnen")) want_switch = 1;
  if (want_switch)
    CHECK(p.av != 0, "run with the viscosity switch: the snapshot has the alpha column");
  if (p.av) sod_switch(&p);
  particles_free(&p);
  return test_finish();
}
