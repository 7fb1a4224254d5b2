/* test_elastic_wave.c — longitudinal elastic wave speed in al-alloy (issue 3, item 6;
 * examples/verification/elastic_wave.yaml).
 *
 * A bar moving at −1 m/s hits a rigid wall (x_min); periodic in y and z, so the strain is
 * uniaxial and the compression front runs into the bar at the P-wave speed
 *   c_L = √((K + 4G/3)/ρ₀),  K = ρ₀c₀²,  G = 3K(1 − 2ν)/(2(1 + ν))
 * (al-alloy: ρ₀ = 2780 kg/m³, c₀ = 5612 m/s, ν = 0.362: c_L = 6652.7 m/s; without the
 * shear term it would be c₀ = 5612 m/s, 16% less).
 *
 * Measured: the front (where the mean x-velocity of a lattice layer crosses −up/2,
 * half way between the bar's −1 m/s ahead and 0 behind) at every output time from
 * T_FIT_START on, fitted by a line: the wave speed relative to the material ahead is
 * slope + up (the material ahead moves at −up). Threshold: 3% (WAVE_SPEED_TOL, issue 3).
 *
 * Also checked, behind the front (layers between 20% and 70% of the way to it, last
 * output): the longitudinal stress −σ_xx = p − S_xx against the impedance relation
 * ρ₀ c_L up (STRESS_TOL), and the ratio of deviatoric to mean stress of uniaxial elastic
 * strain, −S_xx/p = 4G/(3K) (RATIO_TOL); and that nothing yielded (ε_p = 0).
 * Then the same case again with sph.gradient_correction: true (see GC_SPEED_REF below).
 *
 * A known discretisation offset (docs/verification-solids.md): with the cubic spline at
 * η = 1.2 on a cubic lattice the SPH sum Σⱼ Vⱼ (xⱼ − xᵢ)⊗∇ᵢWᵢⱼ is 0.982 I instead of I,
 * which scales both the divergence in the continuity equation and the force by 0.982:
 * waves run 1.8% slow at every resolution (the same offset appears for the pure
 * hydrodynamic wave: 5507 m/s instead of c₀ = 5612 m/s). The measured speed at the time
 * of writing is 6529 m/s (−1.9%).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "solidcase.h"
#include "testlib.h"

/* al-alloy, data/materials.yaml (the paper's Tables 5 and 8) */
#define RHO0 2780.0 /* [kg/m3] */
#define C0   5612.0 /* [m/s] */
#define NU   0.362  /* [-] Poisson's ratio */
#define UP   1.0    /* [m/s] the bar's speed towards the wall (the case's velocity) */

#define WAVE_SPEED_TOL 0.03  /* issue 3: longitudinal wave speed within 3% */
#define STRESS_TOL     0.005 /* −σ_xx = ρ₀ c_L up within 0.5% (measured −0.05%) */
#define RATIO_TOL      0.005 /* −S_xx/p = 4G/(3K) within 0.5% (measured −0.03%) */
/* The same case with sph.gradient_correction: true (docs/models.md; the correction matrix
 * is applied to the velocity gradient of the stress rate only, not to the continuity
 * equation or the force). Measured today: wave speed 6546.53 m/s (−1.60% from c_L; the
 * value docs/verification-solids.md §2 quotes, 6546.5 m/s), 17.65 m/s faster than
 * without the correction (6528.88 m/s); −σ_xx +0.22%; −S_xx/p = 0.41272, +1.83% from
 * 4G/(3K): the corrected gradient gives S the full strain rate while the pressure (from
 * the uncorrected continuity sum) keeps the lattice factor 0.982 (see the note above),
 * so the ratio is 4G/(3K)/0.982 (+1.83%, matching). Checked: the speed within 0.5% of
 * GC_SPEED_REF; the gain over the default run above GC_GAIN_MIN (the speed check alone
 * would pass without the correction: 6528.9 is −0.27% from 6546.5); the stress within
 * STRESS_TOL of ρ₀ c_L up; the ratio within RATIO_TOL of 4G/(3K)/GC_LATTICE. */
#define GC_SPEED_REF 6546.5 /* [m/s] measured today, = docs/verification-solids.md §2 */
#define GC_SPEED_TOL 0.005  /* measured +0.000% */
#define GC_GAIN_MIN  7.0    /* [m/s] measured 17.65 m/s */
#define GC_LATTICE   0.982 /* Σⱼ Vⱼ (xⱼ − xᵢ)⊗∇ᵢWᵢⱼ = 0.982 I (cubic spline, η = 1.2) */
#define T_FIT_START  0.2e-6 /* [s] fit from here on (front ~13 spacings from the wall) */

struct wave_result {
  double c, sig, ratio; /* wave speed [m/s], −σ_xx [Pa], −S_xx/p; NAN: not measured */
};

/* Runs elastic_wave.yaml (extra: more `hvsph run` arguments, or NULL) into outname and
 * checks it; returns the measured values in *res. */
static void run_case(const char *outname, const char *extra, const char *label, double K, double G,
                     double cL, double ratio_scale, struct wave_result *res)
{
  res->c = res->sig = res->ratio = (double)NAN;
  printf("case %s\n", label);
  double secs;
  int rc = sc_run("elastic_wave", outname, extra, &secs);
  CHECK(rc == 0, "%s: elastic_wave.yaml runs (exit status %d, %.1f s)", label, rc, secs);
  if (rc) return;
  const char *dir = sc_outdir(outname);
  const int nsnap = sc_count_snapshots(dir);
  CHECK(nsnap >= 6, "%s: %d snapshots", label, nsnap);
  if (nsnap < 6) return;

  struct particles p0;
  if (sc_read(dir, 0, &p0, NULL)) {
    CHECK(0, "%s: snapshot 0 readable", label);
    return;
  }
  const size_t nid = p0.n;
  unsigned char *sel = malloc(nid);
  for (size_t i = 0; i < nid; i++) sel[i] = 1;
  int *layer = malloc(nid * sizeof *layer);
  const int nl = sc_layers(&p0, sel, 0, 0.2 * p0.h[0], layer, nid);
  printf("particles: %zu, layers: %d\n", nid, nl);

  double *X = malloc((size_t)nl * sizeof *X), *V = malloc((size_t)nl * sizeof *V);
  double *P = malloc((size_t)nl * sizeof *P), *S = malloc((size_t)nl * sizeof *S);
  double tt[64], xf[64], sig = (double)NAN, ratio = (double)NAN, epsmax = 0.0;
  int nfit = 0;
  for (int k = 1; k < nsnap && k < 64; k++) {
    struct particles p;
    double t;
    if (sc_read(dir, k, &p, &t)) break;
    for (size_t i = 0; i < p.n; i++)
      if (p.eps_p[i] > epsmax) epsmax = p.eps_p[i];
    sc_layer_mean(&p, p.x[0], layer, nid, nl, X);
    sc_layer_mean(&p, p.v[0], layer, nid, nl, V);
    sc_layer_mean(&p, p.p, layer, nid, nl, P);
    sc_layer_mean(&p, p.S[0], layer, nid, nl, S); /* S_xx */
    const double front = sc_front(X, V, nl, -0.5 * UP, 1);
    double sp = 0, ss = 0;
    int c = 0;
    for (int l = 0; l < nl; l++)
      if (X[l] > 0.2 * front && X[l] < 0.7 * front) {
        sp += P[l];
        ss += S[l];
        c++;
      }
    sig = c ? (sp - ss) / c : (double)NAN;
    ratio = c ? -ss / sp : (double)NAN;
    printf("  t = %.3e s: front at x = %.5e m; behind it (%d layers): p = %.4f MPa, "
           "S_xx = %.4f MPa, -sigma_xx = %.4f MPa\n",
           t, front, c, c ? sp / c * 1e-6 : 0.0, c ? ss / c * 1e-6 : 0.0, sig * 1e-6);
    if (t >= T_FIT_START && isfinite(front)) {
      tt[nfit] = t;
      xf[nfit++] = front;
    }
    particles_free(&p);
  }
  CHECK(nfit >= 4, "%s: %d front positions to fit", label, nfit);
  if (nfit >= 4) {
    double rms;
    const double c = sc_linfit(tt, xf, nfit, NULL, &rms) + UP;
    printf("%s: wave speed %.2f m/s (fit rms %.2e m over %d times) vs c_L = %.2f m/s "
           "(%+.2f%%)\n",
           label, c, rms, nfit, cL, 100 * (c / cL - 1));
    CHECK(fabs(c / cL - 1) < WAVE_SPEED_TOL,
          "%s: longitudinal wave speed %.1f m/s within "
          "%.0f%% of sqrt((K + 4G/3)/rho0) = %.1f m/s",
          label, c, 100 * WAVE_SPEED_TOL, cL);
    res->c = c;
  }
  const double sig_ref = RHO0 * cL * UP, ratio_ref = 4 * G / (3 * K) * ratio_scale;
  CHECK(fabs(sig / sig_ref - 1) < STRESS_TOL,
        "%s: stress behind the front -sigma_xx = %.4f "
        "MPa within %.1f%% of rho0 c_L up = %.4f MPa (%+.3f%%)",
        label, sig * 1e-6, 100 * STRESS_TOL, sig_ref * 1e-6, 100 * (sig / sig_ref - 1));
  CHECK(fabs(ratio / ratio_ref - 1) < RATIO_TOL,
        "%s: uniaxial elastic strain: -S_xx/p = "
        "%.5f within %.1f%% of 4G/(3K)/%.3f = %.5f (%+.3f%%)",
        label, ratio, 100 * RATIO_TOL, 1 / ratio_scale, ratio_ref, 100 * (ratio / ratio_ref - 1));
  CHECK(epsmax == 0.0, "%s: the bar stays elastic: max plastic strain %.3e", label, epsmax);
  res->sig = sig;
  res->ratio = ratio;
  free(X);
  free(V);
  free(P);
  free(S);
  free(layer);
  free(sel);
  particles_free(&p0);
}

int main(void)
{
  const double K = RHO0 * C0 * C0;
  const double G = 3.0 * K * (1.0 - 2.0 * NU) / (2.0 * (1.0 + NU));
  const double cL = sqrt((K + 4.0 * G / 3.0) / RHO0);
  printf("al-alloy: K = %.4e Pa, G = %.4e Pa, c_L = %.2f m/s (bulk c0 = %.0f m/s), "
         "rho0 c_L up = %.4f MPa, 4G/(3K) = %.4f\n",
         K, G, cL, C0, RHO0 * cL * UP * 1e-6, 4 * G / (3 * K));

  struct wave_result plain, gc;
  run_case("elastic_wave", NULL, "default", K, G, cL, 1.0, &plain);
  run_case("elastic_wave_gc", "--set sph.gradient_correction=true", "gradient correction", K, G, cL,
           1.0 / GC_LATTICE, &gc);
  CHECK(fabs(gc.c / GC_SPEED_REF - 1) < GC_SPEED_TOL,
        "gradient correction: wave speed %.2f m/s "
        "within %.1f%% of the reference %.1f m/s (%+.3f%%)",
        gc.c, 100 * GC_SPEED_TOL, GC_SPEED_REF, 100 * (gc.c / GC_SPEED_REF - 1));
  CHECK(gc.c - plain.c > GC_GAIN_MIN,
        "gradient correction is applied: it speeds the wave up "
        "by %.2f m/s (> %.1f m/s) over the default's %.2f m/s",
        gc.c - plain.c, GC_GAIN_MIN, plain.c);
  return test_finish();
}
