/* test_reconstruct.c — sph.viscosity.reconstruct (the solid pass): a smooth compression
 * must not be heated by the artificial viscosity, a jump must be.
 *
 * An aluminium block (library al-alloy, strength on), 4 mm on a side at spacing
 * 0.25 mm, no boundaries, unstressed, with the linear velocity field
 * v = −ε̇ (x − c) (uniform compression, ε̇ = 1e4 /s), stepped once with a fixed
 * Δt = 1e-9 s three times: without viscosity (α = β = 0), with the standard viscosity
 * (α = 1, β = 2) and with the same viscosity reconstructed. Over the particles more
 * than 1 mm inside the surface (where the velocity gradient is the exact one), the
 * viscous heating rate is the mean of de − de(α = β = 0):
 *   standard:       must be positive (the viscosity acts on every approaching pair);
 *   reconstructed:  at most RATIO_MAX of the standard's (the field is linear over every
 *                   pair, so the reconstructed approach speed is zero).
 * Then a kink: the same block with the compression only in its left half (v = 0 for
 * x > c): at the particles within 0.3 mm of the kink the reconstructed heating must stay
 * at least KINK_MIN of the standard's — the reconstruction is not a blanket switch-off
 * (an error that removed the viscosity of every approaching pair gives 0 here). What
 * this does not isolate is the slope limiter: with Φ = 1 everywhere (no limiter) the
 * kink keeps 0.27 instead of 0.34 and would pass too; the solid Hugoniot test
 * (test_hugoniot with --set sph.viscosity.reconstruct=true) also passes either way
 * (shock speed −0.56 %, pressure −0.52 %), its jump being fixed by conservation.
 * The limiter is checked pair by pair against hand results in tests/unit/test_recon.c
 * (it fails with Φ = 1).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "config/config.h"
#include "integrate/step.h"
#include "run/run.h"
#include "run/sim.h"
#include "simtext.h"
#include "testlib.h"

#define RATIO_MAX 1e-3  /* measured 1.9e-5; with the uncorrected gradient (the lattice sum
                           of a cubic lattice at η = 1.2 is about 0.98, not 1) 1.8e-2 */
#define KINK_MIN 0.25   /* measured 0.34; 0 if every approaching pair lost its viscosity */
#define EDOT 1e4        /* [1/s] */
#define C 2e-3          /* [m] centre of the block */

#define CASE_FMT \
    "name: reconstruct\n" \
    "domain: {min: [-10 mm, -10 mm, -10 mm], max: [14 mm, 14 mm, 14 mm]}\n" \
    "materials: {al: {library: al-alloy}}\n" \
    "bodies:\n" \
    "  - {name: block, material: al, spacing: 0.25 mm,\n" \
    "     shape: {type: box, min: [0, 0, 0], max: [4 mm, 4 mm, 4 mm]}}\n" \
    "time: {end: 1e30, dt_init: 1e-9, dt_max: 1e-9}\n" \
    "output: {vtu: false}\n" \
    "sph: {viscosity: {alpha: %g, beta: %g, reconstruct: %s}}\n"

/* One step of the block; de[i] by particle id (n entries) and x (id order). */
static int one_step(double alpha, double beta, int recon, int kink, double *de, double *x,
                    double *y, double *z, size_t *n)
{
  char text[2048];
  snprintf(text, sizeof text, CASE_FMT, alpha, beta, recon ? "true" : "false");
  struct hv_error err;
  hv_error_clear(&err);
  struct cfg *c;
  struct sim s;
  if (sim_from_text(text, "reconstruct.yaml", &s, &c)) return -1;
  int ok;
  struct particles *p = &s.p;
  for (size_t i = 0; i < p->n; i++)
    for (int k = 0; k < 3; k++) {
      const double xk = p->x[k][i] - C;
      p->v[k][i] = kink && p->x[0][i] > C ? 0.0 : -EDOT * xk;
    }
  ok = !step_init(&s, &err) && !step_advance(&s, &err);
  CHECK(ok, "one step (%s)", ok ? "ok" : err.msg);
  if (ok) {
    *n = p->n;
    for (size_t i = 0; i < p->n; i++) {
      const size_t id = (size_t)p->id[i];
      de[id] = p->de[i];
      x[id] = p->x[0][i];
      y[id] = p->x[1][i];
      z[id] = p->x[2][i];
    }
  }
  sim_free(&s);
  cfg_free(c);
  return ok ? 0 : -1;
}

int main(void)
{
  enum { NMAX = 20000 };
  double *d0 = calloc(NMAX, sizeof *d0), *ds = calloc(NMAX, sizeof *ds),
         *dr = calloc(NMAX, sizeof *dr);
  double *x = calloc(NMAX, sizeof *x), *y = calloc(NMAX, sizeof *y), *z = calloc(NMAX, sizeof *z);
  size_t n = 0;
  for (int kink = 0; kink < 2; kink++) {
    if (one_step(0, 0, 0, kink, d0, x, y, z, &n) || one_step(1, 2, 0, kink, ds, x, y, z, &n) ||
        one_step(1, 2, 1, kink, dr, x, y, z, &n))
      break;
    CHECK(n > 0 && n <= NMAX, "particles: %zu", n);
    double hs = 0.0, hr = 0.0;
    long cnt = 0;
    for (size_t i = 0; i < n; i++) {
      int in;
      if (!kink) {
        in = x[i] > 1e-3 && x[i] < 3e-3 && y[i] > 1e-3 && y[i] < 3e-3 && z[i] > 1e-3 &&
             z[i] < 3e-3;
      } else {
        in = fabs(x[i] - C) < 0.3e-3 && y[i] > 1e-3 && y[i] < 3e-3 && z[i] > 1e-3 &&
             z[i] < 3e-3;
      }
      if (!in) continue;
      hs += ds[i] - d0[i];
      hr += dr[i] - d0[i];
      cnt++;
    }
    hs /= (double)cnt;
    hr /= (double)cnt;
    printf("%s: %ld particles; viscous heating rate standard %.6e W/kg, reconstructed %.6e "
           "W/kg (ratio %.3e)\n", kink ? "kink, within 0.3 mm of it" : "uniform compression, "
           "interior", cnt, hs, hr, hr / hs);
    if (!kink) {
      CHECK(hs > 0, "the standard viscosity heats the uniform compression (%.3e W/kg)", hs);
      CHECK(fabs(hr) <= RATIO_MAX * hs, "reconstructed heating %.3e <= %.0e of the standard's",
            fabs(hr) / hs, RATIO_MAX);
    } else {
      CHECK(hs > 0 && hr >= KINK_MIN * hs, "at the kink the reconstruction keeps %.3f of the "
            "standard heating (>= %.2f)", hr / hs, KINK_MIN);
    }
  }
  free(d0);
  free(ds);
  free(dr);
  free(x);
  free(y);
  free(z);
  return test_finish();
}
