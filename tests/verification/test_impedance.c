/* test_impedance.c — two materials of different density in contact: a planar impact of
 * tungsten alloy on steel (the paper's Table 2) against impedance matching of their
 * Rankine–Hugoniot curves (examples/verification/impedance.yaml).
 *
 * The rods of §2.2 are the paper's contact problem: a tungsten tip on steel at 17.78
 * against 7.81 g/cm³. Here it is in one dimension at rod-5844's speed V = 4.46 km/s
 * (quasi-1D: periodic in y and z), hydrodynamic (yield 0). Each plate is shocked from
 * the contact plane; both shocked states have the same pressure p and the same particle
 * speed u (lab frame, the steel at rest ahead):
 *   steel:    p = ρ₀ˢ Usˢ u,          ρ₀ˢ Usˢ = ρ₁ˢ (Usˢ − u)
 *   tungsten: p = ρ₀ʷ Usʷ (V − u),    ρ₀ʷ Usʷ = ρ₁ʷ (Usʷ − (V − u))
 * each closed by E₁ = ½ p (1/ρ₀ − 1/ρ₁) and the paper's §2.1 EOS (sc_mg_pressure, written
 * out independently of src/eos), solved for u by bisection: u = 2.785 km/s, p = 201.1 GPa,
 * Usˢ = 9.243 km/s, Usʷ = 6.752 km/s. The case is set in the interface's frame
 * (tungsten at V − u, steel at −u), so both shocked plates must come to rest and the
 * contact plane stays at x = 0.
 *
 * Measured on each plate, as in test_hugoniot.c (layer means, the front where the mean
 * velocity crosses half way, fitted by a line from T_FIT_START on, the plateau over 30–80 %
 * of the way from the contact to the front at the last output):
 *   - the plateau's velocity, which is the error of the interface speed: within
 *     INTERFACE_TOL = 0.5 % of u (1 % before; measured 0.028 % tungsten, 0.158 %
 *     steel, i.e. +0.79 and −4.39 m/s). A wrong mismatch shows here: the exact
 *     solution with the steel's n = 3.5 instead of 4.5 moves u by +1.8 %, with its
 *     Γ = 0 by +1.4 % (this test sees Γ: at 200 GPa the thermal pressure is large),
 *     with the tungsten's density set to the steel's by −23 %; a contact that
 *     transmitted the pressure wrongly between unequal densities would too;
 *   - the shock speeds relative to the material ahead and the plateau pressures: within
 *     3 % (SHOCK_SPEED_TOL, PRESSURE_TOL: issue 3's criterion, as for the one-material
 *     Hugoniot test).
 * Measured at the time of writing (hvsph 4fe3785, the CI resolution, 0.1 mm): plateau
 * velocities below 1 m/s, pressures 200.5 GPa (tungsten, −0.3 %) and 201.7 GPa (steel,
 * +0.3 %); when INTERFACE_TOL was tightened: +0.79 m/s and −4.39 m/s, 200.5 GPa (−0.27 %)
 * and 202.2 GPa (+0.58 %). The steel's layer at the contact holds 5.4 MJ/kg where the
 * plateau holds 3.9 (= ½u²): the wall heating of SPH at a contact, reported, not tested.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "solidcase.h"
#include "testlib.h"

/* the paper's Table 2, data/materials.yaml */
static const double MW[4] = {17780.0, 4612.0, 3.54, 1.66}; /* tungsten alloy: ρ₀, c₀, n, Γ */
static const double MS[4] = {7810.0, 4900.0, 4.5, 1.8};    /* steel (target) */
#define V_IMPACT 4460.0                                    /* [m/s] rod-5844 */
#define U_CASE   2785.3471275 /* [m/s] the interface speed the case file is set in */

#define INTERFACE_TOL                                                                              \
  0.005                         /* plateau velocity / u; measured 2.8e-4 (tungsten) and 1.58e-3
                                  (steel) (was 0.01) */
#define SHOCK_SPEED_TOL 0.03    /* issue 3: shock speed within 3% */
#define PRESSURE_TOL    0.03    /* issue 3: post-shock pressure within 3% */
#define T_FIT_START     0.15e-6 /* [s] fit the fronts from here on */

/* Shocked state of material m at particle speed jump up: ρ₁, Us, p. */
static void hugoniot(const double m[4], double up, double *rho1, double *Us, double *p1)
{
  sc_mg_hugoniot(m[0], m[1], m[2], m[3], up, rho1, Us, p1);
}

int main(void)
{
  double lo = 0.0, hi = V_IMPACT, rs, us, ps, rw, uw, pw;
  for (int k = 0; k < 200; k++) {
    const double u = 0.5 * (lo + hi);
    hugoniot(MS, u, &rs, &us, &ps);
    hugoniot(MW, V_IMPACT - u, &rw, &uw, &pw);
    if (ps > pw)
      hi = u;
    else
      lo = u;
  }
  const double u = 0.5 * (lo + hi);
  hugoniot(MS, u, &rs, &us, &ps);
  hugoniot(MW, V_IMPACT - u, &rw, &uw, &pw);
  printf("impedance matching at V = %.0f m/s: u = %.2f m/s, p = %.3f / %.3f GPa; steel rho1 = "
         "%.1f kg/m3, Us = %.1f m/s; tungsten rho1 = %.1f kg/m3, Us = %.1f m/s\n",
         V_IMPACT, u, ps * 1e-9, pw * 1e-9, rs, us, rw, uw);
  CHECK(fabs(ps / pw - 1) < 1e-9, "impedance matching converged");
  CHECK(fabs(u / U_CASE - 1) < 1e-6,
        "the case file is set in the interface's frame (u = %.4f "
        "m/s, the case's %.4f)",
        u, U_CASE);

  int nsnap;
  const char *dir = sc_run_open("impedance", "impedance", NULL, "impedance.yaml", 6, &nsnap);
  struct particles p0;
  int *layer[2], nl[2];
  if (!dir || sc_two_bodies(dir, &p0, layer, nl)) return test_finish();
  const size_t nid = p0.n;
  printf("particles: %zu; layers: tungsten %d, steel %d\n", nid, nl[0], nl[1]);

  const int nmax = nl[0] > nl[1] ? nl[0] : nl[1];
  double *X = malloc((size_t)nmax * sizeof *X), *V = malloc((size_t)nmax * sizeof *V);
  double *P = malloc((size_t)nmax * sizeof *P), *E = malloc((size_t)nmax * sizeof *E);
  double tt[2][64], xf[2][64];
  int nfit[2] = {0, 0};
  double plat_p[2] = {NAN, NAN}, plat_v[2] = {NAN, NAN}, first_e[2] = {NAN, NAN};
  const double ahead[2] = {V_IMPACT - u, -u}; /* each plate's speed ahead of its shock */
  long splits = 0;
  for (int k = 1; k < nsnap && k < 64; k++) {
    struct particles p;
    double t;
    if (sc_read(dir, k, &p, &t)) break;
    for (size_t i = 0; i < p.n; i++) splits += p.damage[i] >= 1.0;
    for (int b = 0; b < 2; b++) {
      sc_layer_mean(&p, p.x[0], layer[b], nid, nl[b], X);
      sc_layer_mean(&p, p.v[0], layer[b], nid, nl[b], V);
      /* the tungsten's undisturbed layers are at small x, the steel's at large x */
      const double front = sc_front(X, V, nl[b], 0.5 * ahead[b], b == 1);
      if (t >= T_FIT_START && isfinite(front)) {
        tt[b][nfit[b]] = t;
        xf[b][nfit[b]++] = front;
      }
      if (k == nsnap - 1 && isfinite(front)) {
        sc_layer_mean(&p, p.p, layer[b], nid, nl[b], P);
        sc_layer_mean(&p, p.e, layer[b], nid, nl[b], E);
        int c;
        plat_p[b] = sc_plateau(X, P, nl[b], front, 0.3, 0.8, &c);
        plat_v[b] = sc_plateau(X, V, nl[b], front, 0.3, 0.8, NULL);
        first_e[b] = E[b ? 0 : nl[b] - 1]; /* the layer at the contact */
        printf("  t = %.3e s  %s: front at %+.4e m, plateau (%d layers) v = %+.2f m/s, "
               "p = %.3f GPa, e = %.0f J/kg at the contact against %.0f J/kg (1/2 du^2)\n",
               t, b ? "steel   " : "tungsten", front, c, plat_v[b], plat_p[b] * 1e-9, first_e[b],
               0.5 * ahead[b] * ahead[b]);
      }
    }
    particles_free(&p);
  }
  CHECK(splits == 0, "no particle splits in the compressed plates (%ld split-snapshots)", splits);
  const double Usx[2] = {uw, us}, pref[2] = {pw, ps};
  for (int b = 0; b < 2; b++) {
    const char *name = b ? "steel" : "tungsten";
    CHECK(nfit[b] >= 4, "%s: %d front positions to fit", name, nfit[b]);
    if (nfit[b] < 4) continue;
    double rms;
    const double slope = sc_linfit(tt[b], xf[b], nfit[b], NULL, &rms);
    const double Us = fabs(slope) + fabs(ahead[b]); /* relative to the material ahead */
    printf("%s: front at %+.1f m/s (fit rms %.2e m over %d times), Us = %.1f m/s vs %.1f "
           "(%+.2f%%); p = %.3f GPa vs %.3f (%+.2f%%); plateau velocity %+.2f m/s (%.3f%% of u)\n",
           name, slope, rms, nfit[b], Us, Usx[b], 100 * (Us / Usx[b] - 1), plat_p[b] * 1e-9,
           pref[b] * 1e-9, 100 * (plat_p[b] / pref[b] - 1), plat_v[b], 100 * fabs(plat_v[b]) / u);
    CHECK(fabs(plat_v[b]) < INTERFACE_TOL * u,
          "%s: the shocked plateau is at rest, %+.2f m/s "
          "(within %.1f%% of u = %.1f m/s): the interface speed is the impedance match's",
          name, plat_v[b], 100 * INTERFACE_TOL, u);
    CHECK(fabs(Us / Usx[b] - 1) < SHOCK_SPEED_TOL,
          "%s: shock speed %.1f m/s within %.0f%% of "
          "%.1f m/s",
          name, Us, 100 * SHOCK_SPEED_TOL, Usx[b]);
    CHECK(fabs(plat_p[b] / pref[b] - 1) < PRESSURE_TOL,
          "%s: post-shock pressure %.3f GPa "
          "within %.0f%% of %.3f GPa",
          name, plat_p[b] * 1e-9, 100 * PRESSURE_TOL, pref[b] * 1e-9);
  }
  for (int b = 0; b < 2; b++) free(layer[b]);
  free(X);
  free(V);
  free(P);
  free(E);
  particles_free(&p0);
  return test_finish();
}
