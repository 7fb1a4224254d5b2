/* test_hugoniot.c — planar shock in al-alloy against the Rankine–Hugoniot solution of
 * the same Mie–Grüneisen/Murnaghan EOS (issue 3, item 6; examples/verification/hugoniot.yaml).
 *
 * Two al-alloy plates collide at +1 km/s and −1 km/s (quasi-1D: periodic in y and z),
 * so each is brought to rest by a shock of particle speed up = 1 km/s running out of
 * the contact plane x = 0. The case runs hydrodynamically (yield 0, see the case file).
 *
 * Reference: the jump conditions from the state (ρ₀, p₀ = 0, E₀ = 0) at rest ahead
 * (in the frame of the unshocked plate)
 *   ρ₀ Us = ρ₁ (Us − up),   p₁ = ρ₀ Us up,   E₁ = ½ (p₀ + p₁)(1/ρ₀ − 1/ρ₁),
 * closed by p₁ = p_EOS(ρ₁, E₁) with the paper's §2.1 EOS (written out again here,
 * independently of src/eos: sc_mg_hugoniot), solved for ρ₁ by bisection:
 *   p₁(ρ₁) = ρ₀ up² ρ₁/(ρ₁ − ρ₀) must equal p_c(ρ₁) + Γρ₁(E₁ − E_c(ρ₁)).
 * For al-alloy: ρ₁ = 3258.7 kg/m³, Us = 6.807 km/s, p₁ = 18.92 GPa.
 *
 * Measured, on each plate separately:
 *   - shock speed: the front is where the mean x-velocity of a lattice layer of the
 *     plate crosses half way between the states ahead (∓up) and behind (0); its
 *     position at every output time from T_FIT_START on is fitted by a line; the
 *     shock speed relative to the material ahead is |slope| + up;
 *   - post-shock pressure: the mean pressure of the layers between 30% and 80% of the
 *     way from the contact plane to the front at the last output (away from the
 *     wall-heating layer at the contact and from the front's smeared width).
 * Thresholds: 3% each (SHOCK_SPEED_TOL, PRESSURE_TOL: issue 3's criterion). Measured
 * at the time of writing: Us within −0.6%, p₁ within −0.5% at the CI resolution
 * (2026-12-07: −0.50 % and −0.40 %).
 * What a wrong model does: a wrong c₀ or n moves the solution by more than 3% (the
 * reference itself, solved with n = 4.54 instead of 3.54, gives Us +3.6%, p₁ +3.6%);
 * the Grüneisen term alone moves them by only 0.6% at this strength (Γ = 0 gives
 * Us = 6.770 km/s), so this test does not see Γ — tests/unit/test_eos.c does.
 * Also checked: the post-shock density (the mean density of the same layers as the
 * pressure) within 0.25% of ρ₁ (DENSITY_TOL; measured −0.076% on each plate). ρ₁ moves
 * little with the EOS (ρ₁ = ρ₀ Us/(Us − up): dρ₁/ρ₁ = −0.17 dUs/Us), so the band is
 * narrow: with n = 4.54 in the run (HVSPH_CASE_ARGS="--set 'materials.al={library:
 * al-alloy, n: 4.54, strength: {yield: 0}}'") ρ₁ = 3237.1 kg/m³, −0.66% → fails (a 1%
 * band would not see it).
 * Also checked: no particle splits (nothing is in tension before the release waves
 * from the free ends arrive at t ≈ 0.88 µs, after the end of the run).
 *
 * `test_hugoniot --rz` (ctest verification.test_hugoniot_rz; issue 74, item 3) runs the same
 * shock along the axis of a cylinder of rings (examples/verification/hugoniot_rz.yaml):
 * Two al-alloy cylinders (radius 0.6 mm, 6 rows of rings at 0.1 mm; a wall at r_max,
 * whose mirror ghosts keep the strain uniaxial) collide at ±1 km/s, hydrodynamically
 * (yield 0). The exact solution is the 1D one (test_hugoniot.c: ρ₁ = 3258.7 kg/m³,
 * Us = 6.807 km/s, p₁ = 18.92 GPa), with no structure in r.
 * Measured as test_hugoniot.c does, on the lattice layers (columns of rings) of each
 * plate: the shock speed from the front's positions, the post-shock pressure and
 * density from the layers 30–80 % of the way from the contact to the front, against
 * the jump conditions (3 %, 3 %, 0.5 %: SHOCK_SPEED_TOL, PRESSURE_TOL, DENSITY_TOL; the
 * density's band is twice the 3D test's, for the first row below). Then the radial
 * structure, which the exact solution does not have: the same plateau's pressure row by
 * row (the rings at r = (j + ½) Δ):
 *   the first row (next to the axis) within ROW0_TOL = 6 % of p₁, every other row within
 *   ROW_TOL = 2 % — measured (2026-12-07, cdd7dd4): rows 0–5 of the right plate −4.2,
 *   −1.4, −1.1, −0.4, −0.1, +0.3 %; the first row's density −1.1 %, its mean radial
 *   speed 0.3 m/s (the axis balance of the hoop force: a uniform pressure of 19 GPa left
 *   in imbalance by 1 % of p/(ρ r) would drive it at 10⁹ m/s²). The deficit of the first
 *   row is the axis's share of the wall heating at the shock (in 3D the layer at the
 *   contact plane shows it): that is what the looser band admits.
 * Also: no ring splits; every ring keeps z = 0; the total energy of summary.csv is kept
 * within ENERGY_TOL = 10⁻³ (measured −1.5 × 10⁻⁴): the ghosts of the wall at r_max weigh
 * with their sources' radius, so that their pairs stay reciprocal in the η-form; with
 * ring masses scaled to the ghosts' own radius the energy rose by +0.75 % in this run
 * with the right cylinder at −0.5 km/s (docs/models.md, "Axisymmetric (RZ)").
 * Measured 2026-12-07 (after the wall's fix): Us +0.09 %, p₁ −1.13 %, ρ₁ −0.24 %; rows
 * −4.22, −1.35, −1.09, −0.35, −0.07, +0.32 %.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "solidcase.h"
#include "testlib.h"

/* al-alloy, data/materials.yaml (the paper's Tables 5 and 8) */
#define RHO0    2780.0 /* [kg/m3] */
#define C0      5612.0 /* [m/s] */
#define N_MURN  3.54   /* [-] Murnaghan exponent */
#define GAMMA_G 1.176  /* [-] Grüneisen coefficient */
#define UP      1000.0 /* [m/s] particle speed behind the shock (the case's ±1 km/s) */

#define SHOCK_SPEED_TOL 0.03 /* issue 3: shock speed within 3% */
#define PRESSURE_TOL    0.03 /* issue 3: post-shock pressure within 3% */
#define DENSITY_TOL                                                                                \
  0.0025                     /* post-shock density within 0.25% (measured −0.076% on
                                  each plate; see the header) */
#define DENSITY_TOL_RZ 0.005 /* RZ: twice the band, for the first row (see the header) */
#define ROW0_TOL       0.06  /* RZ: the first row's pressure against p1 */
#define ROW_TOL        0.02  /* RZ: every other row's */
#define DR_ROW         1e-4  /* [m] RZ: the lattice spacing: rows at (j + 1/2) DR_ROW */
#define NROW           6
#define ENERGY_TOL     1e-3 /* RZ: total energy of summary.csv */
#define T_FIT_START                                                                                \
  0.25e-6 /* [s] fit the front from here on (the shock has formed:
                                  ~25 spacings behind it at the CI resolution) */

static double eos_p(double rho, double E)
{
  return sc_mg_pressure(RHO0, C0, N_MURN, GAMMA_G, rho, E);
}

/* Hugoniot mismatch at ρ₁ for the particle speed up. */
static double rh_residual(double rho1, double up)
{
  const double p1 = RHO0 * up * up * rho1 / (rho1 - RHO0);
  const double E1 = 0.5 * p1 * (1.0 / RHO0 - 1.0 / rho1);
  return eos_p(rho1, E1) - p1;
}

/* RZ: the plateau of plate b row by row, the rings between 30 and 80 % of the way from the
 * contact to the front, each row's mean pressure against p1. */
static void check_rows(const struct particles *p, int b, double front, double p1)
{
  double rp[NROW] = {0}, rn[NROW] = {0};
  for (size_t i = 0; i < p->n; i++) {
    const double x = p->x[0][i];
    const int row = (int)floor(p->x[1][i] / DR_ROW);
    if (p->body[i] != b || row < 0 || row >= NROW) continue;
    if (!(fabs(x) > 0.3 * fabs(front) && fabs(x) < 0.8 * fabs(front))) continue;
    rp[row] += p->p[i];
    rn[row] += 1.0;
  }
  for (int j = 0; j < NROW; j++) {
    const double pj = rn[j] > 0 ? rp[j] / rn[j] : (double)NAN, tol = j ? ROW_TOL : ROW0_TOL;
    CHECK(rn[j] > 0 && fabs(pj / p1 - 1) < tol,
          "%s plate, row %d (r = %.2f mm, %.0f rings): plateau pressure %.4f GPa within "
          "%.0f%% of p1 = %.4f GPa (%+.2f%%)",
          b ? "right" : "left", j, (j + 0.5) * DR_ROW * 1e3, rn[j], pj * 1e-9, 100 * tol, p1 * 1e-9,
          100 * (pj / p1 - 1));
  }
}

int main(int argc, char **argv)
{
  const int rz = argc > 1 && strcmp(argv[1], "--rz") == 0; /* the axisymmetric case */
  const double density_tol = rz ? DENSITY_TOL_RZ : DENSITY_TOL;
  double rho1, Us, p1;
  sc_mg_hugoniot(RHO0, C0, N_MURN, GAMMA_G, UP, &rho1, &Us, &p1);
  printf("Rankine-Hugoniot (al-alloy, up = %.0f m/s): rho1 = %.2f kg/m3, Us = %.2f m/s, "
         "p1 = %.4f GPa, E1 = %.0f J/kg (residual %.2e Pa)\n",
         UP, rho1, Us, p1 * 1e-9, 0.5 * UP * UP, rh_residual(rho1, UP));
  CHECK(fabs(rh_residual(rho1, UP)) < 1e-3 * p1, "Rankine-Hugoniot solution converged");

  int nsnap;
  const char *dir =
      rz ? sc_run_open("hugoniot_rz", "hugoniot_rz", NULL, "hugoniot_rz.yaml", 6, &nsnap)
         : sc_run_open("hugoniot", "hugoniot", NULL, "hugoniot.yaml", 6, &nsnap);
  struct particles p0;
  int *layer[2], nl[2];
  if (!dir || sc_two_bodies(dir, &p0, layer, nl)) return test_finish();
  const size_t nid = p0.n;
  printf("particles: %zu; layers: left %d, right %d\n", nid, nl[0], nl[1]);

  double *X = malloc((size_t)(nl[0] + nl[1]) * sizeof *X);
  double *V = malloc((size_t)(nl[0] + nl[1]) * sizeof *V);
  double *P = malloc((size_t)(nl[0] + nl[1]) * sizeof *P);
  double *R = malloc((size_t)(nl[0] + nl[1]) * sizeof *R);
  double tt[2][64], xf[2][64];
  int nfit[2] = {0, 0};
  double plateau_p[2] = {(double)NAN, (double)NAN}, plateau_rho[2] = {(double)NAN, (double)NAN};
  long splits = 0, offplane = 0;
  for (int k = 1; k < nsnap && k < 64; k++) {
    struct particles p;
    double t;
    if (sc_read(dir, k, &p, &t)) break;
    for (size_t i = 0; i < p.n; i++) {
      splits += p.damage[i] >= 1.0;
      offplane += rz && p.x[2][i] != 0.0; /* RZ: every ring in the plane z = 0 */
    }
    for (int b = 0; b < 2; b++) {
      /* layers of the right plate (b = 1) are ahead of the shock at large x; the left
         plate's at small x: scan from the undisturbed side */
      sc_layer_mean(&p, p.x[0], layer[b], nid, nl[b], X);
      sc_layer_mean(&p, p.v[0], layer[b], nid, nl[b], V);
      sc_layer_mean(&p, p.p, layer[b], nid, nl[b], P);
      sc_layer_mean(&p, p.rho, layer[b], nid, nl[b], R);
      const double ahead = b ? -UP : UP;
      const double front = sc_front(X, V, nl[b], 0.5 * ahead, b == 1);
      printf("  t = %.3e s  %s plate: front at x = %+.4e m\n", t, b ? "right" : "left ", front);
      if (t >= T_FIT_START && isfinite(front)) {
        tt[b][nfit[b]] = t;
        xf[b][nfit[b]++] = front;
      }
      if (k == nsnap - 1 && isfinite(front)) {
        int c;
        plateau_p[b] = sc_plateau(X, P, nl[b], front, 0.3, 0.8, &c);
        plateau_rho[b] = sc_plateau(X, R, nl[b], front, 0.3, 0.8, NULL);
        printf("  plateau (%d layers): p = %.4f GPa, rho = %.2f kg/m3\n", c, plateau_p[b] * 1e-9,
               plateau_rho[b]);
        if (rz) check_rows(&p, b, front, p1);
      }
    }
    particles_free(&p);
  }
  CHECK(splits == 0, "no particle splits in the compressed plates (%ld split-snapshots)", splits);
  if (rz) {
    double e0 = 0.0, e1 = 0.0;
    const int erc = test_summary_energy_span(dir, &e0, &e1);
    CHECK(erc == 0 && fabs(e1 / e0 - 1) < ENERGY_TOL, "total energy kept within %.0e (%+.2e)",
          ENERGY_TOL, e1 / e0 - 1);
    CHECK(offplane == 0, "every ring keeps z = 0 (%ld off the plane)", offplane);
  }
  for (int b = 0; b < 2; b++) {
    const char *name = b ? "right" : "left";
    CHECK(nfit[b] >= 4, "%s plate: %d front positions to fit", name, nfit[b]);
    if (nfit[b] < 4) continue;
    double rms;
    const double slope = sc_linfit(tt[b], xf[b], nfit[b], NULL, &rms);
    const double us = fabs(slope) + UP;
    printf("%s plate: lab shock speed %.1f m/s (fit rms %.2e m over %d times), "
           "Us = %.1f m/s vs %.1f m/s (%+.2f%%); p1 = %.4f GPa vs %.4f GPa (%+.2f%%); "
           "rho1 = %.2f vs %.2f kg/m3 (%+.2f%%)\n",
           name, fabs(slope), rms, nfit[b], us, Us, 100 * (us / Us - 1), plateau_p[b] * 1e-9,
           p1 * 1e-9, 100 * (plateau_p[b] / p1 - 1), plateau_rho[b], rho1,
           100 * (plateau_rho[b] / rho1 - 1));
    CHECK(fabs(us / Us - 1) < SHOCK_SPEED_TOL,
          "%s plate: shock speed %.1f m/s within %.0f%% "
          "of %.1f m/s",
          name, us, 100 * SHOCK_SPEED_TOL, Us);
    CHECK(fabs(plateau_p[b] / p1 - 1) < PRESSURE_TOL,
          "%s plate: post-shock pressure %.4f GPa "
          "within %.0f%% of %.4f GPa",
          name, plateau_p[b] * 1e-9, 100 * PRESSURE_TOL, p1 * 1e-9);
    CHECK(fabs(plateau_rho[b] / rho1 - 1) < density_tol,
          "%s plate: post-shock density %.2f "
          "kg/m3 within %.2f%% of rho1 = %.2f kg/m3 (%+.3f%%)",
          name, plateau_rho[b], 100 * density_tol, rho1, 100 * (plateau_rho[b] / rho1 - 1));
  }
  for (int b = 0; b < 2; b++) free(layer[b]);
  free(X);
  free(V);
  free(P);
  free(R);
  particles_free(&p0);
  return test_finish();
}
