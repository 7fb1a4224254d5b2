/* test_reconstruct.c — the viscosity's linear reconstruction (sph.viscosity.reconstruct):
 *
 *   1. Ghosts carry their source's velocity gradient, mirrored: for a ghost mirrored
 *      across the planes normal to a set of axes, G'_ab = m_a m_b G_ab with m_d = −1
 *      for a mirrored axis (the reflection M G M). Checked component by component
 *      on the corner, edge and face ghosts of an octant with walls on its three
 *      coordinate planes, against a gradient with nine different entries.
 *   2. A uniform compression v = −x (the Noh problem's inflow without its curvature)
 *      of cold gas in that octant: the flow is linear, so with the reconstruction the
 *      viscosity must vanish up to the lattice's gradient error, while the standard
 *      viscosity heats every particle (β μ² with μ ≈ −h). Measured over the particles
 *      away from the open faces after one step: the mean heating rate with the
 *      reconstruction against without must be below HEAT_RATIO_MAX. A wrong sign of
 *      the reconstruction, or a limiter that switches it off where both slopes agree,
 *      leaves the ratio at 1.
 * Momentum conservation with the reconstruction (the limiter must be symmetric in
 * the pair) is checked in test_conservation; the Noh problem in test_noh.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "boundary/boundary.h"
#include "config/config.h"
#include "integrate/step.h"
#include "run/run.h"
#include "run/sim.h"
#include "testlib.h"

#define HEAT_RATIO_MAX 1e-3   /* measured 5.4e-4 (cubic spline, η = 1.2, spacing 0.05) */

#define OCTANT \
    "name: octant\n" \
    "domain: {min: [0, 0, 0], max: [1, 1, 1],\n" \
    "         boundary: {x_min: wall, y_min: wall, z_min: wall}}\n" \
    "materials: {gas: {eos: ideal-gas, gamma: 1.6666666666666667}}\n" \
    "bodies:\n" \
    "  - {name: gas, material: gas, spacing: 0.05, density: 1.0, pressure: 1e-12,\n" \
    "     shape: {type: box, min: [0, 0, 0], max: [1, 1, 1]}}\n" \
    "time: {end: 1e30, dt_init: 1e-4}\n" \
    "output: {vtu: false}\n" \
    "sph: {density: summation, viscosity: {alpha: 1.0, beta: 2.0, reconstruct: %s}}\n"

static int setup(struct sim *s, struct cfg **c, const char *reconstruct)
{
  char text[2048];
  struct hv_error err;
  hv_error_clear(&err);
  snprintf(text, sizeof text, OCTANT, reconstruct);
  *c = cfg_load_string(text, "octant.yaml", &err);
  memset(s, 0, sizeof *s);
  int ok = *c && !run_setup(s, *c, &err) && !cfg_check_unused(*c, &err);
  CHECK(ok, "octant case (reconstruct: %s) sets up: %s", reconstruct, ok ? "ok" : err.msg);
  return ok;
}

static void ghost_gradients(void)
{
  struct sim s;
  struct cfg *c;
  if (!setup(&s, &c, "true")) return;
  struct particles *p = &s.p;
  char msg[256];
  int ok = boundary_make_ghosts(&s.bnd, p, 0.15, msg, sizeof msg) == 0;
  CHECK(ok && p->n_ghost > 0, "ghosts made: %zu", p->n_ghost);
  const size_t nt = p->n + p->n_ghost;
  double *G = malloc(9 * nt * sizeof *G);
  for (size_t i = 0; i < p->n; i++)
    for (int t = 0; t < 9; t++) G[9 * i + t] = (double)(t + 1) * (1.0 + 1e-3 * (double)i);
  boundary_refresh_gradv(&s.bnd, p->n, p->n_ghost, G);
  size_t bad = 0, kinds[4] = {0};
  for (size_t k = 0; k < p->n_ghost; k++) {
    const size_t g = p->n + k;
    size_t r = s.bnd.src[k];
    while (r >= p->n) r = s.bnd.src[r - p->n];   /* the real particle at the root */
    double m[3];
    int mirrors = 0;
    for (int d = 0; d < 3; d++) {
      m[d] = fabs(p->x[d][g] - p->x[d][r]) > 1e-12 ? -1.0 : 1.0;
      mirrors += m[d] < 0;
    }
    kinds[mirrors]++;
    for (int a = 0; a < 3; a++)
      for (int b = 0; b < 3; b++)
        if (G[9 * g + 3 * a + b] != m[a] * m[b] * G[9 * r + 3 * a + b]) bad++;
  }
  CHECK(bad == 0 && kinds[1] > 0 && kinds[2] > 0 && kinds[3] > 0,
        "ghost gradients are the mirrored source's (M G M): %zu wrong entries; ghosts "
        "behind one face %zu, an edge %zu, the corner %zu", bad, kinds[1], kinds[2], kinds[3]);
  free(G);
  p->n_ghost = 0;
  sim_free(&s);
  cfg_free(c);
}

/* Mean heating rate de of the particles away from the open faces after one step of
 * v = −x. */
static double compression_heating(const char *reconstruct, size_t *count)
{
  struct sim s;
  struct cfg *c;
  *count = 0;
  if (!setup(&s, &c, reconstruct)) return NAN;
  struct hv_error err;
  hv_error_clear(&err);
  for (size_t i = 0; i < s.p.n; i++)
    for (int d = 0; d < 3; d++) s.p.v[d][i] = -s.p.x[d][i];
  int ok = !step_init(&s, &err) && !step_advance(&s, &err);
  CHECK(ok, "one step of the compression (reconstruct: %s): %s", reconstruct, ok ? "ok" : err.msg);
  double sum = 0.0;
  for (size_t i = 0; ok && i < s.p.n; i++) {
    int inside = 1;
    for (int d = 0; d < 3; d++) inside &= s.p.x[d][i] < 0.7;
    if (!inside) continue;
    sum += s.p.de[i];
    (*count)++;
  }
  sim_free(&s);
  cfg_free(c);
  return *count ? sum / (double)*count : (double)NAN;
}

int main(void)
{
  ghost_gradients();
  size_t n0, n1;
  const double plain = compression_heating("false", &n0);
  const double recon = compression_heating("true", &n1);
  printf("uniform compression v = -x, cold gas, %zu particles away from the open faces:\n"
         "  mean heating rate without reconstruction %.6e, with %.6e (ratio %.3e)\n",
         n0, plain, recon, recon / plain);
  CHECK(plain > 1e-3, "the standard viscosity heats a uniform compression: %.4g (> 1e-3)", plain);
  CHECK(fabs(recon) < HEAT_RATIO_MAX * plain, "the reconstructed viscosity does not: ratio "
        "%.3e < %.0e", fabs(recon) / plain, HEAT_RATIO_MAX);
  return test_finish();
}
