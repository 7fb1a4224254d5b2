/* test_porous_impact.c — distended (expanded) aluminium striking solid aluminium at
 * 7 km/s, against the porous Hugoniot matched to the plate's
 * (examples/verification/porous-impact.yaml).
 *
 * A debris cloud meets the next plate of a shield as split material far below ρ₀ (W.P.3's
 * first cloud at the second bumper). What the plate takes from it is set by the contact's
 * density rate: a plate particle weighs each debris neighbour by its volume mⱼ/ρⱼ, at
 * most 2mⱼ/ρ₀ⱼ below ρ₀/2 (docs/models.md, "Contact between bodies"). Here a slab of
 * debris at f ρ₀ (f = 0.3, 0.1, 0.03), split (no tension, no strength; its lattice
 * spacing about the plate's times f^(-1/3), so its particles are about as heavy as the
 * plate's), strikes a plate at V = 7 km/s. Quasi-1D: periodic in y and z.
 *
 * Reference (written out here, independently of src/eos, with the paper's §2.1 EOS):
 *   debris, from (f ρ₀, E = 0, p = 0) at particle speed jump w:
 *     p = f ρ₀ w² ρ₁/(ρ₁ − f ρ₀),  E₁ = ½ w²,  p = max(p_MG(ρ₁, E₁), 0)
 *     (the cut: split material carries no tension), solved for ρ₁ by bisection;
 *   plate: sc_mg_hugoniot at particle speed u; impedance matching p_plate(u) =
 *   p_debris(V − u) for u by bisection. f = 0.3: u = 1.663 km/s, p = 35.37 GPa, plate
 *   at 1.278 ρ₀ with Us = 7.652 km/s, debris compacted to 0.913 ρ₀ (hot: below ρ₀);
 *   f = 0.1: 0.726 km/s, 13.07 GPa; f = 0.03: 0.247 km/s, 4.05 GPa.
 * Each case is set in the interface's frame (debris at V − u, plate at −u: --set), so
 * the shocked plate comes to rest and the contact plane stays at x = 0.
 *
 * Measured on the plate:
 *   - the force the debris exerts on it: the rate of the plate's x-momentum Σ m vₓ,
 *     fitted by a line over the outputs from T_FIT_START on, against p A (A the 1.8 mm
 *     square across): within FORCE_TOL at every f. This is the momentum a debris cloud
 *     hands the plate it strikes. The debris arrives as a train of particle layers (at
 *     f = 0.03 one every 44 ns), so the force is read over the whole run, not at one
 *     time. Without the bound on neighbours' volumes (today's code with its condition
 *     made false, for neighbours of either body) the test fails six checks: the force
 *     +86 % at f = 0.03 and +5.7 % at f = 0.1, the f = 0.03 shock speed +10.9 %, and
 *     180, 324 and 504 plate particles above 2 ρ₀ (up to 16 ρ₀). W.P.3's second bumper
 *     ran without it until a033786, 2026-11-25 (docs/validation.md at d88c065, "W.P.3's second cloud and
 *     backwall: the contact's density rate");
 *   - the shock speed relative to the plate ahead (layer means, the front where the mean
 *     velocity crosses half way, fitted by a line from T_FIT_START on): within
 *     SHOCK_SPEED_TOL (issue 3's 3 %) at every f;
 *   - at f = 0.3, where the debris is a continuum on the plate's scale, the shocked
 *     plateau (30–80 % of the way from the contact to the front at the last output, as
 *     in test_impedance.c): pressure within PRESSURE_TOL, velocity within INTERFACE_TOL
 *     of u. At f = 0.1 and 0.03 the plateau at one time carries the pulses of single
 *     debris layers (measured −5 % and +10 % in pressure): printed, not checked;
 *   - plate particles above 2 ρ₀ (the exact solution's highest density is 1.278 ρ₀) at
 *     any output: at most OVERCOMPRESSED_TOL of the plate. Where the two lattices meet
 *     some plate particles poke into the uncompacted debris and are squeezed (printed:
 *     the largest density and the count); the unbounded rule has them by the hundred.
 * Measured at the time of writing (hvsph, this commit, 1 thread): force +1.4 %, +3.8 %,
 * −2.5 % (f = 0.3, 0.1, 0.03); shock speed +0.25 %, −0.63 %, +0.41 %; f = 0.3's plateau
 * −2.6 % in pressure, 1.6 % of u in velocity; 36, 0, 0 plate particles above 2 ρ₀.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "solidcase.h"
#include "testlib.h"

/* al-alloy, data/materials.yaml (the paper's Tables 5 and 8) */
#define RHO0     2780.0 /* [kg/m3] */
#define C0       5612.0 /* [m/s] */
#define N_MURN   3.54   /* [-] */
#define GAMMA_G  1.176  /* [-] */
#define V_IMPACT 7000.0 /* [m/s] */

#define FORCE_TOL                                                                                  \
  0.05                       /* the plate's momentum rate / (p A): the debris arrives in
                                    layer pulses, the fit over 8 outputs reads them to a few
                                    % (measured 3.8 % at most; the unbounded rule 86 %) */
#define INTERFACE_TOL   0.02 /* plateau velocity / u (f = 0.3) */
#define AREA            (1.8e-3 * 1.8e-3) /* [m2] the periodic cross-section */
#define SHOCK_SPEED_TOL 0.03              /* issue 3 */
#define PRESSURE_TOL    0.03              /* issue 3 */
#define OVERCOMPRESSED_TOL                                                                         \
  0.01                     /* plate particles above 2 ρ₀, fraction of the plate
                                    (measured 0.32 % at f = 0.3; the unbounded rule 1.6-4.4 %) */
#define T_FIT_START 0.1e-6 /* [s] fit the front from here on */

/* The debris' shocked state at particle speed jump w from (f ρ₀, 0, 0). */
static void porous_hugoniot(double f, double w, double *rho1, double *Us, double *p1)
{
  const double r00 = f * RHO0;
  double a = r00 * (1.0 + 1e-9), b = 4.0 * RHO0; /* residual < 0 at a, > 0 at b */
  for (int k = 0; k < 200; k++) {
    const double r = 0.5 * (a + b);
    const double p = r00 * w * w * r / (r - r00);
    const double pe = fmax(sc_mg_pressure(RHO0, C0, N_MURN, GAMMA_G, r, 0.5 * w * w), 0.0);
    if (pe - p > 0)
      b = r;
    else
      a = r;
  }
  *rho1 = 0.5 * (a + b);
  *Us = w * *rho1 / (*rho1 - r00);
  *p1 = r00 * *Us * w;
}

struct exact {
  double u, p, rho_plate, us_plate, rho_debris;
};

static struct exact match(double f)
{
  double lo = 0.0, hi = V_IMPACT, r, us, ps, rd, ud, pd;
  for (int k = 0; k < 200; k++) {
    const double u = 0.5 * (lo + hi);
    sc_mg_hugoniot(RHO0, C0, N_MURN, GAMMA_G, u, &r, &us, &ps);
    porous_hugoniot(f, V_IMPACT - u, &rd, &ud, &pd);
    if (ps > pd)
      hi = u;
    else
      lo = u;
  }
  struct exact e;
  e.u = 0.5 * (lo + hi);
  sc_mg_hugoniot(RHO0, C0, N_MURN, GAMMA_G, e.u, &e.rho_plate, &e.us_plate, &e.p);
  porous_hugoniot(f, V_IMPACT - e.u, &e.rho_debris, &ud, &pd);
  CHECK(fabs(pd / e.p - 1.0) < 1e-9, "f = %g: impedance matching converged", f);
  return e;
}

static void one_case(double f, double density, double spacing_mm)
{
  const struct exact e = match(f);
  printf("f = %.2f: u = %.2f m/s, p = %.3f GPa, plate %.4f rho0 with Us = %.1f m/s, debris "
         "compacted to %.4f rho0\n",
         f, e.u, e.p * 1e-9, e.rho_plate / RHO0, e.us_plate, e.rho_debris / RHO0);
  char extra[512], out[32], label[64];
  snprintf(extra, sizeof extra,
           "--set bodies[0].density=\"%.6g kg/m3\" --set "
           "bodies[0].spacing=\"%g mm\" --set \"bodies[0].velocity=[%.7f m/s, 0, 0]\" "
           "--set \"bodies[1].velocity=[%.7f m/s, 0, 0]\"",
           density, spacing_mm, V_IMPACT - e.u, -e.u);
  snprintf(out, sizeof out, "porous_impact_%02d", (int)lround(100 * f));
  snprintf(label, sizeof label, "porous-impact.yaml at f = %g", f);
  int nsnap;
  const char *dir = sc_run_open("porous-impact", out, extra, label, 6, &nsnap);
  struct particles p0;
  int *layer[2], nl[2];
  if (!dir || sc_two_bodies(dir, &p0, layer, nl)) return;
  const size_t nid = p0.n;
  size_t nplate = 0;
  for (size_t i = 0; i < nid; i++) nplate += p0.body[i] == 1;
  double *X = malloc((size_t)nl[1] * sizeof *X), *V = malloc((size_t)nl[1] * sizeof *V);
  double *P = malloc((size_t)nl[1] * sizeof *P);
  double tt[64], xf[64], tm[64], pm[64], plat_p = NAN, plat_v = NAN, rho_max = 0.0;
  int nfit = 0, nmom = 0;
  size_t over_max = 0;
  for (int k = 1; k < nsnap && k < 64; k++) {
    struct particles p;
    double t;
    if (sc_read(dir, k, &p, &t)) break;
    size_t over = 0;
    double mom = 0.0; /* the plate's x-momentum */
    for (size_t i = 0; i < p.n; i++) {
      if (p.body[i] != 1) continue;
      rho_max = fmax(rho_max, p.rho[i]);
      over += p.rho[i] > 2.0 * RHO0;
      mom += p.m[i] * p.v[0][i];
    }
    if (over > over_max) over_max = over;
    if (t >= T_FIT_START) {
      tm[nmom] = t;
      pm[nmom++] = mom;
    }
    sc_layer_mean(&p, p.x[0], layer[1], nid, nl[1], X);
    sc_layer_mean(&p, p.v[0], layer[1], nid, nl[1], V);
    const double front = sc_front(X, V, nl[1], -0.5 * e.u, 1);
    if (t >= T_FIT_START && isfinite(front)) {
      tt[nfit] = t;
      xf[nfit++] = front;
    }
    if (k == nsnap - 1 && isfinite(front)) {
      sc_layer_mean(&p, p.p, layer[1], nid, nl[1], P);
      int c;
      plat_p = sc_plateau(X, P, nl[1], front, 0.3, 0.8, &c);
      plat_v = sc_plateau(X, V, nl[1], front, 0.3, 0.8, NULL);
      printf("  t = %.3e s: front at %+.4e m, plateau (%d layers) v = %+.2f m/s, p = %.3f GPa\n", t,
             front, c, plat_v, plat_p * 1e-9);
    }
    particles_free(&p);
  }
  CHECK(nmom >= 4 && nfit >= 4, "f = %g: %d momenta and %d front positions to fit", f, nmom, nfit);
  if (nmom >= 4 && nfit >= 4) {
    double rms;
    const double force = sc_linfit(tm, pm, nmom, NULL, NULL), want = e.p * AREA;
    const double slope = sc_linfit(tt, xf, nfit, NULL, &rms);
    const double Us = fabs(slope) + e.u; /* relative to the plate ahead (at −u) */
    printf("  force on the plate %.4g N vs p A = %.4g N (%+.2f%%); shock: front at %+.1f m/s "
           "(fit rms %.2e m), Us = %.1f m/s vs %.1f (%+.2f%%); plateau p = %.3f GPa vs %.3f "
           "(%+.2f%%), velocity %+.2f m/s (%.2f%% of u)\n",
           force, want, 100 * (force / want - 1), slope, rms, Us, e.us_plate,
           100 * (Us / e.us_plate - 1), plat_p * 1e-9, e.p * 1e-9, 100 * (plat_p / e.p - 1), plat_v,
           100 * fabs(plat_v) / e.u);
    CHECK(fabs(force / want - 1) < FORCE_TOL,
          "f = %g: the debris pushes the plate with %.4g N, "
          "within %.0f%% of the impedance match's p A = %.4g N",
          f, force, 100 * FORCE_TOL, want);
    CHECK(fabs(Us / e.us_plate - 1) < SHOCK_SPEED_TOL,
          "f = %g: shock speed %.1f m/s within "
          "%.0f%% of %.1f m/s",
          f, Us, 100 * SHOCK_SPEED_TOL, e.us_plate);
    if (f >= 0.3) { /* the debris a continuum on the plate's scale */
      CHECK(fabs(plat_v) < INTERFACE_TOL * e.u,
            "f = %g: the plate's plateau is at rest, %+.2f "
            "m/s (within %.0f%% of u = %.1f m/s)",
            f, plat_v, 100 * INTERFACE_TOL, e.u);
      CHECK(fabs(plat_p / e.p - 1) < PRESSURE_TOL,
            "f = %g: plateau pressure %.3f GPa within "
            "%.0f%% of %.3f GPa",
            f, plat_p * 1e-9, 100 * PRESSURE_TOL, e.p * 1e-9);
    }
  }
  printf("  plate: largest density %.3f rho0, at most %zu of %zu particles above 2 rho0 at "
         "one output\n",
         rho_max / RHO0, over_max, nplate);
  CHECK((double)over_max <= OVERCOMPRESSED_TOL * (double)nplate,
        "f = %g: %zu plate particles "
        "above 2 rho0 (at most %.0f%% of %zu)",
        f, over_max, 100 * OVERCOMPRESSED_TOL, nplate);
  for (int b = 0; b < 2; b++) free(layer[b]);
  free(X);
  free(V);
  free(P);
  particles_free(&p0);
}

int main(void)
{
  /* f, the debris' density [kg/m3] and spacing [mm] (0.1 mm × about f^(-1/3), whole
     layers across the 1.8 mm periodic width) */
  one_case(0.3, 0.3 * RHO0, 0.15);
  one_case(0.1, 0.1 * RHO0, 0.2);
  one_case(0.03, 0.03 * RHO0, 0.3);
  return test_finish();
}
