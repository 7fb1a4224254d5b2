/* test_rest_snap.c — sph.rest_tolerance (step.c, clamp_to_rest): material that no physical
 * signal can have reached is exactly at rest, so that sph.skip_resting can skip it, and
 * the material the wave has reached is not changed.
 *
 * A steel block (steel-bumper, 0.25 mm lattice) strikes the end of a steel bar at
 * 300 m/s; both at first at rest but for the striker's velocity, open boundaries. After
 * 1 µs the fastest wave of the bar's material, the elastic longitudinal one,
 * c_L = √((K + 4G/3)/ρ₀) = 5.75 km/s, has run 5.75 mm. The SPH stencil carries values
 * much farther: one kernel support (0.6 mm) per step, over 100 steps. Its values decay
 * ahead of the wave by a factor of about 30 per millimetre (measured here without the
 * tolerance: the largest |vₓ| 7 m/s at 5–6 mm, 0.04 at 8–9 mm, 1e-4 at 10–11 mm, 7e-12
 * at 14–15 mm, 1e-14 at 15–16 mm), so with the default 1e-14 (of c₀ = 4.4 km/s: 4.4e-11
 * m/s) the bar beyond FAR_MM = 14 mm must be exactly at rest
 * (v, e, p and S all 0) with the default tolerance, and must not be without it
 * (sph.rest_tolerance = 0: at most NOT_REST_MAX of those particles exactly at rest),
 * which shows the test measures something. Behind the wave (x < NEAR_MM) the two runs'
 * velocities must agree within VEL_REL of the largest. At the last step the run with
 * the tolerance skips more particles (sph.skip_resting) than the run without.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "config/config.h"
#include "integrate/step.h"
#include "sim/sim.h"
#include "particles/particles.h"
#include "simtext.h"
#include "testlib.h"

#define T_END        1e-6
#define FAR_MM       14.0 /* 5.75 mm of the wave plus 8.25 mm: see above */
#define NEAR_MM      4.0
#define NOT_REST_MAX 0.1   /* of the far particles exactly at rest without the tolerance */
#define VEL_REL      1e-12 /* measured 7e-14 */

static const char *const CASE =
    "name: rest-snap\n"
    "domain:\n"
    "  min: [-2 mm, -2 mm, -2 mm]\n"
    "  max: [17 mm, 2 mm, 2 mm]\n"
    "  boundary: {x_min: open, x_max: open, y: open, z: open}\n"
    "bodies:\n"
    "  - {name: striker, material: steel-bumper, velocity: [300 m/s, 0, 0], spacing: 0.25 mm,\n"
    "     shape: {type: box, min: [-1.05 mm, -1 mm, -1 mm], max: [-0.05 mm, 1 mm, 1 mm]}}\n"
    "  - {name: bar, material: steel-bumper, spacing: 0.25 mm,\n"
    "     shape: {type: box, min: [0, -1 mm, -1 mm], max: [16 mm, 1 mm, 1 mm]}}\n"
    "sph: {rest_tolerance: %s}\n"
    "time: {end: 1 s}\n"
    "output: {vtu: false}\n";

static int run(struct sim *s, struct cfg **c, const char *tol)
{
  char text[2048];
  struct hv_error err;
  hv_error_clear(&err);
  snprintf(text, sizeof text, CASE, tol);
  if (sim_from_text(text, "rest-snap.yaml", s, c)) return -1;
  int ok = !step_init(s, &err);
  while (ok && s->t < T_END) ok = !step_advance(s, &err);
  CHECK(ok, "rest_tolerance %s: the run (%s)", tol, ok ? "ok" : err.msg);
  return ok ? 0 : -1;
}

static int at_rest(const struct particles *p, size_t i)
{
  int r = p->e[i] == 0.0 && p->p[i] == 0.0;
  for (int k = 0; k < 3; k++) r = r && p->v[k][i] == 0.0;
  for (int k = 0; k < 6; k++) r = r && p->S[k][i] == 0.0;
  return r;
}

int main(void)
{
  struct sim a, b;
  struct cfg *ca, *cb;
  if (run(&a, &ca, "1e-14") || run(&b, &cb, "0")) return test_finish();
  CHECK(a.p.n == b.p.n && a.step == b.step, "the same particles and steps (%zu/%zu, %ld/%ld)",
        a.p.n, b.p.n, a.step, b.step);
  size_t far = 0, rest_a = 0, rest_b = 0;
  double vmax = 0.0, dv = 0.0;
  /* the two runs order their particles by cells sized from h, which the snap can touch in
     its last bits: pair them by id */
  int64_t idmax = 0;
  for (size_t i = 0; i < b.p.n; i++) idmax = b.p.id[i] > idmax ? b.p.id[i] : idmax;
  size_t *of = calloc((size_t)idmax + 1, sizeof *of);
  for (size_t i = 0; of && i < b.p.n; i++) of[b.p.id[i]] = i;
  for (size_t i = 0; of && i < a.p.n && a.p.n == b.p.n; i++) {
    const size_t j = a.p.id[i] <= idmax ? of[a.p.id[i]] : 0;
    if (a.p.body[i] != 1) continue;
    const double x = a.p.x[0][i] * 1e3;
    if (x > FAR_MM) {
      far++;
      rest_a += at_rest(&a.p, i);
      rest_b += at_rest(&b.p, j);
    } else if (x < NEAR_MM) {
      for (int k = 0; k < 3; k++) {
        vmax = fmax(vmax, fabs(b.p.v[k][j]));
        dv = fmax(dv, fabs(a.p.v[k][i] - b.p.v[k][j]));
      }
    }
  }
  free(of);
  printf("  %ld steps to %.4g s; beyond %.1f mm %zu bar particles, exactly at rest: %zu with "
         "the tolerance, %zu without; behind the wave largest |v| %.4g m/s, largest "
         "difference %.3g m/s; skipped at the last step %ld / %ld\n",
         a.step, a.t, FAR_MM, far, rest_a, rest_b, vmax, dv, a.cache.rested, b.cache.rested);
  CHECK(far >= 500 && rest_a == far,
        "beyond the wave's reach every particle exactly at rest "
        "(%zu of %zu)",
        rest_a, far);
  CHECK(rest_b <= NOT_REST_MAX * far,
        "without the tolerance the stencil's precursor reaches "
        "them: %zu of %zu exactly at rest (at most %.2f)",
        rest_b, far, NOT_REST_MAX);
  CHECK(vmax > 10.0 && dv <= VEL_REL * vmax,
        "behind the wave the velocities agree: %.3g of "
        "%.4g m/s (at most %.0e of it)",
        dv, vmax, VEL_REL);
  CHECK(a.cache.rested > b.cache.rested,
        "more particles skipped with the tolerance (%ld "
        "against %ld)",
        a.cache.rested, b.cache.rested);
  sim_free(&a);
  sim_free(&b);
  cfg_free(ca);
  cfg_free(cb);
  return test_finish();
}
