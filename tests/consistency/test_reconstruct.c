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
 *
 * sph.viscosity.reconstruct_contact: the same block cut into two bodies at x = c (the
 * pairs across the cut are contact pairs). In the uniform compression the particles
 * within 0.3 mm of the cut are heated by the reconstruction without it at least
 * CUT_MIN of the standard's (the contact pairs keep the standard viscosity), with it at
 * most RATIO_CUT_MAX (each side's own corrected gradient is exact for the linear
 * field). And two bodies closing at a jump (each at a uniform velocity, ±v0 along x)
 * keep the standard viscosity with it: each body's gradient is 0 but where the first
 * half step has bent it, so the limiter returns the whole difference (at least
 * JUMP_MIN of the standard heating).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "config/config.h"
#include "integrate/step.h"
#include "run/run.h"
#include "sim/sim.h"
#include "simtext.h"
#include "testlib.h"

#define RATIO_MAX                                                                                  \
  1e-3                /* measured 1.9e-5; with the uncorrected gradient (the lattice sum
                           of a cubic lattice at η = 1.2 is about 0.98, not 1) 1.8e-2 */
#define KINK_MIN 0.25 /* measured 0.34; 0 if every approaching pair lost its viscosity */
#define EDOT     1e4  /* [1/s] */
#define C        2e-3 /* [m] centre of the block */

#define RATIO_CUT_MAX 1e-3 /* measured 1.9e-5 */
#define CUT_MIN       0.1  /* measured 0.304: the contact pairs' share of the heating there */
#define JUMP_MIN                                                                                   \
  0.95          /* measured 0.9956: the predictor's half step has already bent the
                           velocity near the cut; 0 if the jump lost its viscosity */
#define V0 10.0 /* [m/s] each body's speed towards the cut in the jump */

#define CASE_FMT                                                                                   \
  "name: reconstruct\n"                                                                            \
  "domain: {min: [-10 mm, -10 mm, -10 mm], max: [14 mm, 14 mm, 14 mm]}\n"                          \
  "materials: {al: {library: al-alloy}}\n"                                                         \
  "bodies:\n%s"                                                                                    \
  "time: {end: 1e30, dt_init: 1e-9, dt_max: 1e-9}\n"                                               \
  "output: {vtu: false}\n"                                                                         \
  "sph: {viscosity: {alpha: %g, beta: %g, reconstruct: %s, reconstruct_contact: %s}}\n"
#define ONE_BODY                                                                                   \
  "  - {name: block, material: al, spacing: 0.25 mm,\n"                                            \
  "     shape: {type: box, min: [0, 0, 0], max: [4 mm, 4 mm, 4 mm]}}\n"
#define TWO_BODIES                                                                                 \
  "  - {name: left, material: al, spacing: 0.25 mm,\n"                                             \
  "     shape: {type: box, min: [0, 0, 0], max: [2 mm, 4 mm, 4 mm]}}\n"                            \
  "  - {name: right, material: al, spacing: 0.25 mm,\n"                                            \
  "     shape: {type: box, min: [2 mm, 0, 0], max: [4 mm, 4 mm, 4 mm]}}\n"

enum field { UNIFORM, KINK, JUMP };

/* One step of the block (two bodies cut at x = c: `cut`); de[i] by particle id (n
 * entries) and x (id order). recon: 0 standard, 1 reconstructed, 2 reconstructed with
 * reconstruct_contact. */
static int one_step(double alpha, double beta, int recon, enum field kink, int cut, double *de,
                    double *x, double *y, double *z, size_t *n)
{
  char text[2048];
  snprintf(text, sizeof text, CASE_FMT, cut ? TWO_BODIES : ONE_BODY, alpha, beta,
           recon ? "true" : "false", recon == 2 ? "true" : "false");
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
      if (kink == JUMP)
        p->v[k][i] = k ? 0.0 : (p->x[0][i] > C ? -V0 : V0);
      else
        p->v[k][i] = kink == KINK && p->x[0][i] > C ? 0.0 : -EDOT * xk;
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
    if (one_step(0, 0, 0, (enum field)kink, 0, d0, x, y, z, &n) ||
        one_step(1, 2, 0, (enum field)kink, 0, ds, x, y, z, &n) ||
        one_step(1, 2, 1, (enum field)kink, 0, dr, x, y, z, &n))
      break;
    CHECK(n > 0 && n <= NMAX, "particles: %zu", n);
    double hs = 0.0, hr = 0.0;
    long cnt = 0;
    for (size_t i = 0; i < n; i++) {
      int in;
      if (!kink) {
        in = x[i] > 1e-3 && x[i] < 3e-3 && y[i] > 1e-3 && y[i] < 3e-3 && z[i] > 1e-3 && z[i] < 3e-3;
      } else {
        in = fabs(x[i] - C) < 0.3e-3 && y[i] > 1e-3 && y[i] < 3e-3 && z[i] > 1e-3 && z[i] < 3e-3;
      }
      if (!in) continue;
      hs += ds[i] - d0[i];
      hr += dr[i] - d0[i];
      cnt++;
    }
    hs /= (double)cnt;
    hr /= (double)cnt;
    printf("%s: %ld particles; viscous heating rate standard %.6e W/kg, reconstructed %.6e "
           "W/kg (ratio %.3e)\n",
           kink ? "kink, within 0.3 mm of it"
                : "uniform compression, "
                  "interior",
           cnt, hs, hr, hr / hs);
    if (!kink) {
      CHECK(hs > 0, "the standard viscosity heats the uniform compression (%.3e W/kg)", hs);
      CHECK(fabs(hr) <= RATIO_MAX * hs, "reconstructed heating %.3e <= %.0e of the standard's",
            fabs(hr) / hs, RATIO_MAX);
    } else {
      CHECK(hs > 0 && hr >= KINK_MIN * hs,
            "at the kink the reconstruction keeps %.3f of the "
            "standard heating (>= %.2f)",
            hr / hs, KINK_MIN);
    }
  }
  /* the block cut in two: the contact pairs across the cut */
  double *dc = calloc(NMAX, sizeof *dc);
  for (int f = UNIFORM; f <= JUMP; f += JUMP - UNIFORM) { /* the kink is the one-body loop's */
    const enum field fl = (enum field)f;
    if (one_step(0, 0, 0, fl, 1, d0, x, y, z, &n) || one_step(1, 2, 0, fl, 1, ds, x, y, z, &n) ||
        one_step(1, 2, 1, fl, 1, dr, x, y, z, &n) || one_step(1, 2, 2, fl, 1, dc, x, y, z, &n))
      break;
    double hs = 0.0, hr = 0.0, hc = 0.0;
    long cnt = 0;
    for (size_t i = 0; i < n; i++) {
      if (!(fabs(x[i] - C) < 0.3e-3 && y[i] > 1e-3 && y[i] < 3e-3 && z[i] > 1e-3 && z[i] < 3e-3))
        continue;
      hs += ds[i] - d0[i];
      hr += dr[i] - d0[i];
      hc += dc[i] - d0[i];
      cnt++;
    }
    printf("two bodies, %s, within 0.3 mm of the cut: %ld particles; viscous heating rate "
           "standard %.6e, reconstructed %.6e (ratio %.3e), with reconstruct_contact %.6e "
           "(ratio %.3e) W/kg\n",
           f == UNIFORM ? "uniform compression" : "closing at a jump", cnt, hs / cnt, hr / cnt,
           hr / hs, hc / cnt, hc / hs);
    CHECK(cnt > 0 && hs > 0, "the standard viscosity heats the cut (%ld particles)", cnt);
    if (f == UNIFORM) {
      CHECK(hr >= CUT_MIN * hs,
            "without reconstruct_contact the contact pairs keep their "
            "viscosity: %.3f of the standard heating (>= %.2f)",
            hr / hs, CUT_MIN);
      CHECK(fabs(hc) <= RATIO_CUT_MAX * hs,
            "with reconstruct_contact the smooth compression "
            "across the cut is not heated: %.3e of the standard (<= %.0e)",
            fabs(hc) / hs, RATIO_CUT_MAX);
    } else {
      CHECK(hc >= JUMP_MIN * hs,
            "with reconstruct_contact a jump between bodies keeps its "
            "viscosity: %.4f of the standard heating (>= %.2f)",
            hc / hs, JUMP_MIN);
    }
  }
  free(dc);
  free(d0);
  free(ds);
  free(dr);
  free(x);
  free(y);
  free(z);
  return test_finish();
}
