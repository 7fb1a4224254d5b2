/* test_split_friction.c — the plastic wave in split (broken) material with friction,
 * against the Rankine–Hugoniot solution with the friction-limited stress
 * (examples/verification/split_friction.yaml; docs/models.md, fracture.friction).
 *
 * Two plates of split al-alloy (damage 1) collide at ±UP (quasi-1D, periodic in y and
 * z: uniaxial strain). With friction μ a split particle's deviatoric stress is limited
 * by Y_d = min(Y₀, μ max(p, 0)). Here μp < Y₀ and 2G > μK, so the material yields from
 * the start and behind the wave S_xx = −⅔ μ p (von Mises in uniaxial strain:
 * √(3J₂) = (3/2)|S_xx|): the longitudinal stress is σ_xx = −k p with k = 1 + 2μ/3.
 *
 * Reference: the jump conditions with that stress, from rest ahead (ρ₀, p = 0, E = 0):
 *   ρ₀ Us = ρ₁ (Us − up),   k p₁ = ρ₀ Us up,   E₁ = ½ k p₁ (1/ρ₀ − 1/ρ₁)
 * (E is the whole specific internal energy, which takes the deviatoric work as well),
 * closed by p₁ = p_EOS(ρ₁, E₁) (the paper's §2.1 EOS written out again here), solved
 * for ρ₁ by bisection. μ = 0.3: k = 1.2, Us = 6.21 km/s; μ = 0 (the paper's rule:
 * split material carries no deviatoric stress): k = 1, Us = 5.67 km/s — 9.5 % apart.
 *
 * Measured, on each plate, as in test_hugoniot.c: the front (layer-mean x-velocity
 * half way between ∓up and 0) fitted over the outputs from T_FIT_START on; the plateau
 * (layers 30–80 % of the way from the contact to the front at the last output):
 * pressure, and −S_xx/p, which must be ⅔μ.
 * Thresholds: wave speed and pressure within 3 % (issue 3's criterion for shocks);
 * −S_xx/p within RATIO_TOL = 3 % of ⅔μ; the ratio of the two runs' wave speeds (which
 * share the weak front's smearing) within 1 % of the reference's 1.095. Measured at
 * the time of writing (μ = 0.3): Us −1.9 %, p₁ −0.3 %, −S_xx/p = 0.197 (−1.5 %); μ = 0:
 * Us −1.8 %, p₁ −0.4 %, S ≡ 0; speed ratio 1.0933 (−0.16 %).
 * What a wrong model does: without the friction (split particles as fluid) the wave
 * is 9 % slower and S_xx = 0; a friction limit on √(J₂) instead of √(3J₂) would give
 * −S_xx/p = 0.35 instead of 0.2.
 *
 * Split without tension (fracture.split: no-tension, friction 0): in compression the
 * split plates behave as intact al-alloy. The wave's front is the elastic precursor
 * (the collision's 50 m/s is just above the Hugoniot elastic limit's 47.9 m/s): the
 * deviator grows as S_xx = −(4/3) G ln(ρ/ρ₀) until √(3J₂) = (3/2)|S_xx| reaches Y₀,
 * at ln(ρ₁/ρ₀) = Y₀/(2G); there σ_xx = −(p₁ + ⅔Y₀), p₁ = p_EOS(ρ₁, E₁) with
 * E₁ = ½|σ_xx|(1/ρ₀ − 1/ρ₁), and the jump gives U_H² = |σ_xx| / (ρ₀ (1 − ρ₀/ρ₁)) =
 * 6.70 km/s against the fluid's 5.67. Checked: the front speed within 3 % of U_H and
 * the plateau's −S_xx within NT_STRESS_TOL = 1 % of ⅔Y₀ (3 % before; the split fluid
 * has 0, friction 0.3 has 0.13 GPa). Measured at the time of writing: front −2.1 %
 * (6 559 m/s; the fluid's −1.8 %), −S_xx = 0.2549 GPa (−0.16 %).
 * In tension the same material carries nothing: both plates at rest, stretched to
 * ρ = 2750 kg/m³ (EOS tension −0.94 GPa), stay at rest (largest |v_x| below STRETCH_VMAX
 * = 1 mm/s at 0.8 µs; measured 0). Without the projection (checked by removing it)
 * their free faces are pulled in at 57.9 m/s (estimate 2|p|/(ρ c_L) ≈ 100 m/s).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "solidcase.h"
#include "testlib.h"

/* al-alloy, data/materials.yaml (the paper's Tables 5 and 8) */
#define RHO0    2780.0    /* [kg/m3] */
#define C0      5612.0    /* [m/s] */
#define N_MURN  3.54      /* [-] Murnaghan exponent */
#define GAMMA_G 1.176     /* [-] Grüneisen coefficient */
#define UP      50.0      /* [m/s] the case's ±50 m/s: each plate is brought to rest */
#define MU      0.3       /* [-] the case's fracture.friction */
#define G_SHEAR 26.6136e9 /* [Pa] al-alloy's G (Poisson 0.362; hvsph materials al-alloy) */
#define Y0      0.383e9   /* [Pa] al-alloy's yield stress */

#define SPEED_TOL     0.03 /* wave speed within 3 % */
#define PRESSURE_TOL  0.03 /* plateau pressure within 3 % */
#define RATIO_TOL     0.03 /* −S_xx/p within 3 % of ⅔μ */
#define NT_STRESS_TOL 0.01 /* no-tension: −S_xx within 1 % of ⅔Y₀ (measured −0.16 %; was 3 %) */
#define RATIO_US_TOL  0.01 /* the ratio of the two runs' wave speeds within 1 % */
#define T_FIT_START   0.25e-6
#define STRETCH_VMAX  1e-3 /* [m/s] stretched split plates stay at rest */

static double eos_p(double rho, double E)
{
  return sc_mg_pressure(RHO0, C0, N_MURN, GAMMA_G, rho, E);
}

static double rh_residual(double rho1, double k)
{
  const double Us = UP * rho1 / (rho1 - RHO0);
  const double p1 = RHO0 * Us * UP / k;
  const double E1 = 0.5 * k * p1 * (1.0 / RHO0 - 1.0 / rho1);
  return eos_p(rho1, E1) - p1;
}

static void rankine_hugoniot(double k, double *Us, double *p1)
{
  double a = RHO0 * (1.0 + 1e-7), b = 1.5 * RHO0; /* residual < 0 at a, > 0 at b */
  for (int it = 0; it < 200; it++) {
    const double m = 0.5 * (a + b);
    if (rh_residual(m, k) > 0)
      b = m;
    else
      a = m;
  }
  const double rho1 = 0.5 * (a + b);
  *Us = UP * rho1 / (rho1 - RHO0);
  *p1 = RHO0 * *Us * UP / k;
}

/* The elastic precursor of intact al-alloy in uniaxial strain (header): its speed. */
static double hel_speed(void)
{
  const double rho1 = RHO0 * exp(Y0 / (2.0 * G_SHEAR));
  double sig = Y0; /* |σ_xx|, iterated with E₁ = ½|σ_xx|(1/ρ₀ − 1/ρ₁) */
  for (int it = 0; it < 50; it++)
    sig = eos_p(rho1, 0.5 * sig * (1.0 / RHO0 - 1.0 / rho1)) + 2.0 * Y0 / 3.0;
  return sqrt(sig / (RHO0 * (1.0 - RHO0 / rho1)));
}

/* Runs the case with friction mu (or split: no-tension) and checks it against its
 * solution: for friction, the shock with k = 1 + 2mu/3; without tension, the elastic
 * precursor and −S_xx = ⅔Y₀. *us_mean gets the measured wave speed, the mean of the two
 * plates (NAN if none). */
static void check_case(double mu, int no_tension, const char *outname, double *us_mean)
{
  *us_mean = (double)NAN;
  const double k = 1.0 + 2.0 * mu / 3.0;
  double Us, p1;
  rankine_hugoniot(k, &Us, &p1);
  if (no_tension) {
    Us = hel_speed();
    p1 = (double)NAN;
    printf("split: no-tension: elastic precursor U_H = %.1f m/s, -S_xx = %.4f GPa\n", Us,
           2.0 * Y0 / 3.0 * 1e-9);
  } else {
    printf("friction %.2f: Rankine-Hugoniot Us = %.1f m/s, p1 = %.4f GPa, -S_xx/p = %.4f\n", mu, Us,
           p1 * 1e-9, 2.0 * mu / 3.0);
  }
  char label[32], extra[160];
  snprintf(label, sizeof label, no_tension ? "split: no-tension" : "friction %g", mu);
  snprintf(extra, sizeof extra, "--set materials.al.fracture.friction=%g%s", mu,
           no_tension ? " --set materials.al.fracture.split=no-tension" : "");
  char what[64];
  snprintf(what, sizeof what, "split_friction.yaml (%s)", label);
  int nsnap;
  const char *dir = sc_run_open("split_friction", outname, extra, what, 6, &nsnap);
  struct particles p0;
  int *layer[2], nl[2];
  if (!dir || sc_two_bodies(dir, &p0, layer, nl)) return;
  const size_t nid = p0.n;
  const int nmax = nl[0] > nl[1] ? nl[0] : nl[1];
  double *X = malloc((size_t)nmax * sizeof *X), *V = malloc((size_t)nmax * sizeof *V);
  double *P = malloc((size_t)nmax * sizeof *P), *SX = malloc((size_t)nmax * sizeof *SX);
  double *sxx = malloc(nid * sizeof *sxx);
  double tt[2][64], xf[2][64], plateau_p[2] = {(double)NAN, (double)NAN},
                               plateau_r[2] = {(double)NAN, (double)NAN};
  int nfit[2] = {0, 0};
  double smax = 0.0; /* largest |S| anywhere (μ = 0: must be 0) */
  long intact = 0;   /* particles that are not split (must stay 0) */
  for (int s = 1; s < nsnap && s < 64; s++) {
    struct particles p;
    double t;
    if (sc_read(dir, s, &p, &t)) break;
    for (size_t i = 0; i < p.n; i++) {
      intact += p.damage[i] < 1.0;
      for (int c = 0; c < 6; c++) smax = fmax(smax, fabs(p.S[c][i]));
      sxx[i] = p.S[T_XX][i];
    }
    for (int b = 0; b < 2; b++) {
      sc_layer_mean(&p, p.x[0], layer[b], nid, nl[b], X);
      sc_layer_mean(&p, p.v[0], layer[b], nid, nl[b], V);
      sc_layer_mean(&p, p.p, layer[b], nid, nl[b], P);
      sc_layer_mean(&p, sxx, layer[b], nid, nl[b], SX);
      const double ahead = b ? -UP : UP;
      const double front = sc_front(X, V, nl[b], 0.5 * ahead, b == 1);
      if (t >= T_FIT_START && isfinite(front)) {
        tt[b][nfit[b]] = t;
        xf[b][nfit[b]++] = front;
      }
      if (s == nsnap - 1 && isfinite(front)) {
        int c;
        plateau_p[b] = sc_plateau(X, P, nl[b], front, 0.3, 0.8, &c);
        plateau_r[b] = -sc_plateau(X, SX, nl[b], front, 0.3, 0.8, NULL) /
                       (no_tension ? 2.0 * Y0 / 3.0 : plateau_p[b]);
        printf("  %s plate, t = %.2e s: front at %+.4e m; plateau (%d layers) p = %.4f GPa, "
               "-S_xx/%s = %.4f\n",
               b ? "right" : "left ", t, front, c, plateau_p[b] * 1e-9,
               no_tension ? "(2Y0/3)" : "p", plateau_r[b]);
      }
    }
    particles_free(&p);
  }
  CHECK(intact == 0, "%s: every particle stays split (%ld intact particle-snapshots)", label,
        intact);
  if (mu == 0.0 && !no_tension)
    CHECK(smax == 0.0,
          "friction 0: split particles carry no deviatoric stress (largest |S| "
          "%g Pa)",
          smax);
  double us_sum = 0.0;
  for (int b = 0; b < 2; b++) {
    const char *name = b ? "right" : "left";
    CHECK(nfit[b] >= 4, "%s plate: %d front positions to fit", name, nfit[b]);
    if (nfit[b] < 4) continue;
    const double us = fabs(sc_linfit(tt[b], xf[b], nfit[b], NULL, NULL)) + UP;
    us_sum += us;
    CHECK(fabs(us / Us - 1) < SPEED_TOL,
          "%s, %s plate: wave speed %.1f m/s within "
          "%.0f%% of %.1f m/s (%+.2f%%)",
          label, name, us, 100 * SPEED_TOL, Us, 100 * (us / Us - 1));
    if (no_tension) {
      CHECK(fabs(plateau_r[b] - 1) < NT_STRESS_TOL,
            "split: no-tension, %s plate: -S_xx = "
            "%.4f GPa within %.0f%% of 2Y0/3 = %.4f GPa (%+.2f%%)",
            name, plateau_r[b] * 2 * Y0 / 3e9, 100 * NT_STRESS_TOL, 2 * Y0 / 3e9,
            100 * (plateau_r[b] - 1));
      continue;
    }
    CHECK(fabs(plateau_p[b] / p1 - 1) < PRESSURE_TOL,
          "friction %g, %s plate: pressure %.4f "
          "GPa within %.0f%% of %.4f GPa (%+.2f%%)",
          mu, name, plateau_p[b] * 1e-9, 100 * PRESSURE_TOL, p1 * 1e-9,
          100 * (plateau_p[b] / p1 - 1));
    if (mu > 0.0) {
      const double want = 2.0 * mu / 3.0;
      CHECK(fabs(plateau_r[b] / want - 1) < RATIO_TOL,
            "friction %g, %s plate: -S_xx/p = %.4f "
            "within %.0f%% of 2mu/3 = %.4f (%+.2f%%)",
            mu, name, plateau_r[b], 100 * RATIO_TOL, want, 100 * (plateau_r[b] / want - 1));
    }
  }
  if (nfit[0] >= 4 && nfit[1] >= 4) *us_mean = 0.5 * us_sum;
  for (int b = 0; b < 2; b++) free(layer[b]);
  free(X);
  free(V);
  free(P);
  free(SX);
  free(sxx);
  particles_free(&p0);
}

/* split: no-tension in tension: plates of split al-alloy at rest, stretched (ρ = 2750
 * kg/m³, 1.1 % below ρ₀: the EOS gives p = −0.94 GPa), carry no stress and stay at
 * rest. With the EOS's tension (the projection left out) every free face is pulled in
 * (57.9 m/s measured; 2|p|/(ρ c_L) ≈ 100 m/s as an estimate). */
static void check_stretched(void)
{
  double secs;
  const int rc = sc_run("split_friction", "no_tension_stretched",
                        "--set materials.al.fracture.friction=0 "
                        "--set materials.al.fracture.split=no-tension "
                        "'--set=bodies[0].velocity=[0, 0, 0]' '--set=bodies[1].velocity=[0, 0, 0]' "
                        "--set 'bodies[0].density=2750 kg/m3' "
                        "--set 'bodies[1].density=2750 kg/m3'",
                        &secs);
  CHECK(rc == 0, "stretched split plates run (exit status %d, %.1f s)", rc, secs);
  if (rc) return;
  const char *dir = sc_outdir("no_tension_stretched");
  const int last = sc_count_snapshots(dir) - 1;
  struct particles p;
  double t;
  if (last < 1 || sc_read(dir, last, &p, &t)) {
    CHECK(0, "a last snapshot readable");
    return;
  }
  double vmax = 0.0, pmin = 0.0;
  for (size_t i = 0; i < p.n; i++) {
    vmax = fmax(vmax, fabs(p.v[0][i]));
    pmin = fmin(pmin, p.p[i]);
  }
  CHECK(pmin < -0.5e9, "the plates are stretched (EOS pressure %.3f GPa)", pmin * 1e-9);
  CHECK(vmax < STRETCH_VMAX,
        "split: no-tension, stretched plates stay at rest: largest "
        "|v_x| %.3g m/s at %.2e s below %g m/s",
        vmax, t, STRETCH_VMAX);
  particles_free(&p);
}

int main(void)
{
  double Us0, p0, Us1, p1;
  rankine_hugoniot(1.0, &Us0, &p0);
  rankine_hugoniot(1.0 + 2.0 * MU / 3.0, &Us1, &p1);
  CHECK(fabs(rh_residual(RHO0 * (1 + UP / (Us1 - UP)), 1.0 + 2.0 * MU / 3.0)) < 1e-3 * p1,
        "Rankine-Hugoniot solution converged");
  /* the case must be in the friction-limited regime the reference assumes */
  CHECK(MU * p1 < 0.383e9, "mu p1 = %.3f GPa below al-alloy's Y0 = 0.383 GPa", MU * p1 * 1e-9);
  double us1, us0;
  check_case(MU, 0, "friction", &us1);
  check_case(0.0, 0, "no_friction", &us0);
  /* the two runs share the front's smearing: the ratio of their speeds is sharper */
  const double want = Us1 / Us0, got = us1 / us0;
  CHECK(fabs(got / want - 1) < RATIO_US_TOL,
        "wave speed with friction %g over without: %.4f "
        "within %.0f%% of %.4f (%+.2f%%)",
        MU, got, 100 * RATIO_US_TOL, want, 100 * (got / want - 1));
  double us_nt;
  check_case(0.0, 1, "no_tension", &us_nt);
  check_stretched();
  return test_finish();
}
