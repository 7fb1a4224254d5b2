/* test_skip_resting.c — sph.skip_resting (docs/performance.md, "Particles at rest")
 * gives the same bits as computing every particle.
 *
 * A small Whipple shield, stepped through the library twice, with sph.skip_resting
 * true and false: a steel sphere (r = 0.8 mm, 4 km/s) through a steel bumper (0.6 mm),
 * its debris across a 1.4 mm gap into an aluminium backwall (0.75 mm), half model (symmetry
 * plane z = 0) with rigid walls in y and z and an absorbing face behind; the viscosity
 * reconstruction and the paper's fracture on (library materials). At the start
 * everything but the projectile is at rest and unstressed: the skip leaves out most of
 * the particles, and the shock in the bumper and then the debris on the backwall wake
 * them cell by cell. One particle at rest has no neighbour at all (its signal speed is
 * 0, not its sound speed, where it is computed). After every step, every allocated field
 * of every particle (particles_fields: x, v, ρ, e, p, c, S, S₁, R, ε_p, damage, h, a, ρ̇,
 * ė, v_sig, ids and order ...), the particle count and the next step must be equal
 * (doubles by ==, so +0 and −0 count as equal: a skipped particle keeps its S where the
 * update would write S + ½Δt·0). The test also checks that the skip happened and
 * changed: at least SKIP_FIRST_MIN of the particles skipped at the first step, and
 * fewer at the last than at the first (particles woke up), so that equal results mean
 * something. With the viscosity switch, whose αᵢ decays at rest, nothing is skipped.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "config/config.h"
#include "integrate/step.h"
#include "sim/sim.h"
#include "particles/particles.h"
#include "simtext.h"
#include "testlib.h"

#define STEPS          240 /* to 0.87 µs: the debris strikes the backwall */
#define SKIP_FIRST_MIN 0.5 /* measured 0.90 at the first step */

/* %s: skip_resting; %s: the viscosity switch */
static const char *const CASE =
    "name: skip-resting\n"
    "domain:\n"
    "  min: [-3 mm, -5 mm, 0]\n"
    "  max: [4 mm, 5 mm, 5 mm]\n"
    "  half_model: true\n"
    "  boundary: {x_min: wall, x_max: absorbing, y: wall, z_max: wall}\n"
    "bodies:\n"
    "  - {name: projectile, material: steel-projectile, velocity: [4 km/s, 0, 0],\n"
    "     shape: {type: sphere, center: [-1 mm, 0, 0], radius: 0.8 mm}, spacing: 0.2 mm}\n"
    "  - {name: bumper, material: steel-bumper, spacing: 0.2 mm,\n"
    "     shape: {type: box, min: [0, -4 mm, -4 mm], max: [0.6 mm, 4 mm, 4 mm]}}\n"
    "  - {name: backwall, material: al-alloy, spacing: 0.25 mm,\n"
    "     shape: {type: box, min: [2 mm, -5 mm, -5 mm], max: [2.75 mm, 5 mm, 5 mm]}}\n"
    "  - {name: lone, material: al-alloy, spacing: 0.25 mm,\n"
    "     shape: {type: box, min: [-2.625 mm, 2.875 mm, 2.875 mm], max: [-2.375 mm, 3.125 mm, 3.125 mm]}}\n"
    "sph: {skip_resting: %s, viscosity: {alpha: 1.0, beta: 2.0, reconstruct: true%s}}\n"
    "time: {end: 1 s}\n"
    "output: {vtu: false}\n";

static int setup(struct sim *s, struct cfg **c, int skip, int sw)
{
  char text[4096];
  snprintf(text, sizeof text, CASE, skip ? "true" : "false", sw ? ", switch: cullen-dehnen" : "");
  return sim_from_text(text, "skip-resting.yaml", s, c);
}

/* Number of slots where component k of field f differs between the two stores: doubles
 * by == (NaN never expected: check_state stops a run), integers by value. */
static size_t differ(const struct pfield *fa, const struct pfield *fb, int k, size_t n)
{
  size_t d = 0;
  if (fa->type == PF_DOUBLE) {
    const double *x = fa->comp[k], *y = fb->comp[k];
    for (size_t i = 0; i < n; i++) d += !(x[i] == y[i]);
  } else if (fa->type == PF_INT64) {
    const int64_t *x = fa->comp[k], *y = fb->comp[k];
    for (size_t i = 0; i < n; i++) d += x[i] != y[i];
  } else {
    const int32_t *x = fa->comp[k], *y = fb->comp[k];
    for (size_t i = 0; i < n; i++) d += x[i] != y[i];
  }
  return d;
}

/* Compares every allocated particle field (particles_fields: the state, the rates, the
 * signal speed, the per-step scratch) of the reals, the clock and the next step; returns
 * the number of differing values and names the first field that differs. */
static size_t compare(struct sim *a, struct sim *b, long step)
{
  if (a->p.n != b->p.n) {
    CHECK(0, "step %ld: particle counts %zu and %zu", step, a->p.n, b->p.n);
    return 1;
  }
  struct pfield fa[HV_MAX_FIELDS], fb[HV_MAX_FIELDS];
  const int nf = particles_fields(&a->p, fa);
  if (particles_fields(&b->p, fb) != nf) {
    CHECK(0, "step %ld: the two runs allocate different fields", step);
    return 1;
  }
  size_t total = 0;
  for (int f = 0; f < nf; f++)
    for (int k = 0; k < fa[f].ncomp; k++) {
      const size_t d = differ(&fa[f], &fb[f], k, a->p.n);
      if (d && !total)
        CHECK(0, "step %ld: field %s[%d] differs at %zu of %zu particles", step, fa[f].name, k, d,
              a->p.n);
      total += d;
    }
  if (!total && !(a->dt == b->dt && a->t == b->t)) {
    CHECK(0, "step %ld: t %.17g / %.17g, next dt %.17g / %.17g", step, a->t, b->t, a->dt, b->dt);
    total++;
  }
  return total;
}

int main(void)
{
  struct sim a, b;
  struct cfg *ca, *cb;
  struct hv_error err;
  hv_error_clear(&err);
  if (setup(&a, &ca, 1, 0) || setup(&b, &cb, 0, 0)) return test_finish();
  int ok = !step_init(&a, &err) && !step_init(&b, &err);
  CHECK(ok, "step_init (%s)", ok ? "ok" : err.msg);
  double first = -1.0, last = -1.0, wmin = 1.0;
  long skipped = 0, steps = 0;
  size_t bad = 0;
  for (long k = 0; ok && k < STEPS && !bad; k++) {
    ok = !step_advance(&a, &err) && !step_advance(&b, &err);
    CHECK(ok, "step %ld (%s)", k, ok ? "ok" : err.msg);
    if (!ok) break;
    bad = compare(&a, &b, k);
    const double frac = (double)a.cache.rested / (double)a.p.n;
    if (first < 0) first = frac;
    last = frac;
    if (frac < wmin) wmin = frac;
    skipped += a.cache.rested;
    steps++;
    CHECK(b.cache.rested == 0, "step %ld: with skip_resting false nothing is skipped (%ld)", k,
          b.cache.rested);
  }
  printf("  %ld steps to t = %.4g s, %zu particles at the end; skipped at the first step "
         "%.3f, at the last %.3f, least %.3f; %ld particle-steps skipped\n",
         steps, a.t, a.p.n, first, last, wmin, skipped);
  CHECK(steps == STEPS && bad == 0, "%d steps with the same bits (%ld equal, %zu values differ)",
        STEPS, steps - (bad != 0), bad);
  CHECK(first >= SKIP_FIRST_MIN, "first step: %.3f of the particles skipped, at least %.2f", first,
        SKIP_FIRST_MIN);
  double vbw = 0.0; /* the debris has reached the backwall (body 2) */
  for (size_t i = 0; i < a.p.n; i++)
    if (a.p.body[i] == 2) {
      const double v =
          sqrt(a.p.v[0][i] * a.p.v[0][i] + a.p.v[1][i] * a.p.v[1][i] + a.p.v[2][i] * a.p.v[2][i]);
      if (v > vbw) vbw = v;
    }
  CHECK(vbw > 10.0,
        "the debris has struck the backwall: its fastest particle at %.4g m/s "
        "(> 10 m/s)",
        vbw);
  size_t nlone = 0; /* the lone particle (body 3): skipped, with no signal speed */
  for (size_t i = 0; i < a.p.n; i++)
    if (a.p.body[i] == 3) {
      nlone++;
      CHECK(a.p.vsig[i] == 0.0 && a.p.cs[i] > 0.0,
            "the lone particle: signal speed %g m/s "
            "(0: no neighbour), sound speed %g m/s",
            a.p.vsig[i], a.p.cs[i]);
    }
  CHECK(nlone == 1, "one lone particle (%zu)", nlone);
  CHECK(last < first, "fewer skipped at the last step (%.3f) than at the first (%.3f)", last,
        first);
  sim_free(&a);
  sim_free(&b);
  cfg_free(ca);
  cfg_free(cb);

  /* the switch: nothing skipped */
  if (setup(&a, &ca, 1, 1)) return test_finish();
  ok = !step_init(&a, &err);
  for (int k = 0; ok && k < 3; k++) ok = !step_advance(&a, &err);
  CHECK(ok && a.cache.rested == 0, "with the viscosity switch nothing is skipped (%ld)",
        a.cache.rested);
  sim_free(&a);
  cfg_free(ca);
  return test_finish();
}
