/* test_density_diffusion.c — sph.density_diffusion (the solid pass's continuity rate):
 * the term δ cᵢ Σⱼ hᵢⱼ Vⱼ ψᵢⱼ·∇ᵢWᵢⱼ, ψᵢⱼ = 2(ρⱼ − ρᵢ)(xⱼ − xᵢ)/rᵢⱼ² (Molteni &
 * Colagrossi 2009) is a discrete Laplacian: for a density ρ₀(1 + A sin kx) it adds
 * −δ h c k² ρ₀ A sin kx to dρ/dt.
 *
 * An aluminium block (library al-alloy) 8 × 3 × 3 mm at spacing 0.25 mm, at rest, its
 * density set to ρ₀(1 + A sin k(x − x₀)) with A = 10⁻³ and a wavelength of 4 mm
 * (k h ≈ 0.47), stepped once (Δt = 10⁻¹⁰ s) with δ = 0 and with δ = 0.1. Both runs see
 * the same positions and velocities, so the difference of their density rates is the
 * diffusion term alone. Over the particles more than 0.8 mm inside the surface:
 *   - the least-squares ratio of that difference to −δ hᵢ cᵢ k² ρ₀ A sin k(xᵢ − x₀) must
 *     lie within RATIO_TOL of 1 (the lattice's Laplacian of a sine at this k h);
 *   - a uniform density gets no diffusion anywhere in the block (to 10⁻⁹ of the sine's rate);
 *   - two bodies of different uniform densities in contact (the block cut at its
 *     middle, one half at 1.001 ρ₀): no diffusion across the cut (the pairs of two
 *     pieces are left out), so the rates of the particles beside the cut are the
 *     δ = 0 run's;
 *   - one body whose right half is expanded to 0.01 ρ₀ (debris): no diffusion at all —
 *     the term acts between condensed states only (ρ ≥ ρ₀/2 on both sides), where it
 *     was tested.
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

#define RATIO_TOL                                                                                  \
  0.10 /* measured 0.966; an error of a factor 2 in the term
                            (h for 2h, or the pair counted once) fails */
#define PI     3.14159265358979323846
#define AMP    1e-3
#define LAMBDA 4e-3 /* [m] */
#define X0     0.0
#define DELTA  0.1

#define CASE_FMT                                                                                   \
  "name: density-diffusion\n"                                                                      \
  "domain: {min: [-10 mm, -10 mm, -10 mm], max: [18 mm, 13 mm, 13 mm]}\n"                          \
  "materials: {al: {library: al-alloy}}\n"                                                         \
  "bodies:\n%s"                                                                                    \
  "time: {end: 1e30, dt_init: 1e-10, dt_max: 1e-10}\n"                                             \
  "output: {vtu: false}\n"                                                                         \
  "sph: {density_diffusion: %g, skip_resting: false}\n"
#define ONE_BODY                                                                                   \
  "  - {name: block, material: al, spacing: 0.25 mm,\n"                                            \
  "     shape: {type: box, min: [0, 0, 0], max: [8 mm, 3 mm, 3 mm]}}\n"
#define TWO_BODIES                                                                                 \
  "  - {name: left, material: al, spacing: 0.25 mm,\n"                                             \
  "     shape: {type: box, min: [0, 0, 0], max: [4 mm, 3 mm, 3 mm]}}\n"                            \
  "  - {name: right, material: al, spacing: 0.25 mm,\n"                                            \
  "     shape: {type: box, min: [4 mm, 0, 0], max: [8 mm, 3 mm, 3 mm]}}\n"

enum field { SINE, UNIFORM, CUT, EXPANDED };

/* One step; drho, h, cs and x by particle id (n entries). */
static int one_step(double delta, enum field f, double *drho, double *h, double *cs, double *x,
                    double *y, double *z, size_t *n, double *rho0)
{
  char text[2048];
  snprintf(text, sizeof text, CASE_FMT, f == CUT ? TWO_BODIES : ONE_BODY, delta);
  struct hv_error err;
  hv_error_clear(&err);
  struct cfg *c;
  struct sim s;
  if (sim_from_text(text, "density_diffusion.yaml", &s, &c)) return -1;
  struct particles *p = &s.p;
  const double k = 2.0 * PI / LAMBDA;
  *rho0 = s.mat[p->mat[0]].rho0;
  for (size_t i = 0; i < p->n; i++) {
    double r = 1.0;
    if (f == SINE) r += AMP * sin(k * (p->x[0][i] - X0));
    if (f == CUT && p->x[0][i] > 4e-3) r += AMP;
    if (f == EXPANDED && p->x[0][i] > 4e-3) r = 0.01;
    p->rho[i] = *rho0 * r;
  }
  int ok = !step_init(&s, &err) && !step_advance(&s, &err);
  CHECK(ok, "one step (%s)", ok ? "ok" : err.msg);
  if (ok) {
    *n = p->n;
    for (size_t i = 0; i < p->n; i++) {
      const size_t id = (size_t)p->id[i];
      drho[id] = p->drho[i];
      h[id] = p->h[i];
      cs[id] = p->cs[i];
      x[id] = p->x[0][i];
      y[id] = p->x[1][i];
      z[id] = p->x[2][i];
    }
  }
  sim_free(&s);
  cfg_free(c);
  return ok ? 0 : -1;
}

static int inside(double x, double y, double z)
{
  return x > 0.8e-3 && x < 7.2e-3 && y > 0.8e-3 && y < 2.2e-3 && z > 0.8e-3 && z < 2.2e-3;
}

int main(void)
{
  enum { NMAX = 20000, NA = 9 };
  double *a[NA];
  for (int t = 0; t < NA; t++) a[t] = calloc(NMAX, sizeof(double));
  double *d0 = a[0], *d1 = a[1], *h = a[2], *cs = a[3], *x = a[4], *y = a[5], *z = a[6];
  double *dc0 = a[7], *dc1 = a[8];
  size_t n = 0, n2 = 0;
  double rho0 = 0.0;
  const double k = 2.0 * PI / LAMBDA;
  if (!one_step(0.0, SINE, d0, h, cs, x, y, z, &n, &rho0) &&
      !one_step(DELTA, SINE, d1, h, cs, x, y, z, &n, &rho0)) {
    CHECK(n > 0 && n <= NMAX, "particles: %zu", n);
    double sxy = 0.0, sxx = 0.0, smax = 0.0;
    long cnt = 0;
    for (size_t i = 0; i < n; i++) {
      if (!inside(x[i], y[i], z[i])) continue;
      const double want = -DELTA * h[i] * cs[i] * k * k * rho0 * AMP * sin(k * (x[i] - X0));
      const double got = d1[i] - d0[i];
      sxy += got * want;
      sxx += want * want;
      if (fabs(want) > smax) smax = fabs(want);
      cnt++;
    }
    const double ratio = sxx > 0 ? sxy / sxx : 0.0;
    printf("sine: %ld particles inside, diffusion rate / -delta h c k^2 rho0 A sin kx = %.4f "
           "(largest expected rate %.4e kg/m3/s)\n",
           cnt, ratio, smax);
    CHECK(cnt > 100, "particles inside: %ld", cnt);
    CHECK(fabs(ratio - 1.0) <= RATIO_TOL,
          "the diffusion is the Laplacian's within %.0f %% "
          "(ratio %.4f)",
          100 * RATIO_TOL, ratio);

    /* no diffusion at all, anywhere in the block: a uniform density; two pieces of
       different densities in contact (nothing across the cut, each half uniform); one
       body whose right half is expanded to 0.01 ρ₀ (nothing with expanded material, the
       dense half uniform) */
    static const struct {
      enum field f;
      const char *what;
    } none[] = {{UNIFORM, "a uniform density"},
                {CUT, "two pieces of different densities (across the cut)"},
                {EXPANDED, "a body half expanded to 0.01 rho0 (with expanded material)"}};
    for (size_t t = 0; t < sizeof none / sizeof none[0]; t++) {
      if (one_step(0.0, none[t].f, dc0, h, cs, x, y, z, &n2, &rho0) ||
          one_step(DELTA, none[t].f, dc1, h, cs, x, y, z, &n2, &rho0))
        continue;
      double big = 0.0;
      for (size_t i = 0; i < n2; i++) big = fmax(big, fabs(dc1[i] - dc0[i]));
      printf("%s: largest diffusion rate %.3e kg/m3/s\n", none[t].what, big);
      CHECK(big <= 1e-9 * smax, "no diffusion for %s (%.3e)", none[t].what, big);
    }
  }
  for (int t = 0; t < NA; t++) free(a[t]);
  return test_finish();
}
