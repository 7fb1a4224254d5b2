/* test_timestep.c — the CFL limit of a particle with and without neighbours
 * (docs/models.md, "Time step"), stepped through the library.
 *
 * A block of gas at rest (8 × 8 × 8 particles, p = 1, ρ = 1: c = 1.18 m/s) and one
 * hot particle of the same gas (p = 1000: c = 37.4 m/s) moving at 0.5 m/s.
 *  1. Far from the block (no neighbour): its signal speed must be its own speed,
 *     vsig = |v| = 0.5 m/s exactly, and the step is set by the block (its limit names
 *     the block); with the rule before session 11 (vsig = c(1 + 1.2α), 82 m/s) the
 *     lone particle would have set a step 30 times shorter.
 *  2. Next to the block's face (within reach of its particles): its sound speed counts,
 *     vsig ≥ c(1 + 1.2α), and it sets the step.
 *  3. Case 1 again with al-alloy (the solid force pass): vsig = |v| exactly.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "config/config.h"
#include "integrate/step.h"
#include "run/sim.h"
#include "simtext.h"
#include "testlib.h"

#define NSTEPS 3

#define CASE_FMT                                                                          \
  "name: timestep\n"                                                                        \
  "materials: {gas: {eos: ideal-gas, gamma: 1.4}}\n"                                         \
  "bodies:\n"                                                                               \
  "  - {name: block, material: gas, spacing: 0.125, density: 1.0, pressure: 1.0,\n"         \
  "     shape: {type: box, min: [0, 0, 0], max: [1, 1, 1]}}\n"                              \
  "  - {name: lone, material: gas, spacing: 0.125, density: 1.0, pressure: 1000.0,\n"       \
  "     velocity: [0.5, 0, 0],\n"                                                           \
  "     shape: {type: box, min: [%g, 0.4375, 0.4375], max: [%g, 0.5625, 0.5625]}}\n"        \
  "time: {end: 1e30}\n"

/* The same with an elastic-plastic solid (the solid force pass, sph_solid.c): al-alloy
 * at rest, the lone particle of it moving at 0.5 m/s far away. */
#define SOLID_FMT                                                                         \
  "name: timestep-solid\n"                                                                  \
  "bodies:\n"                                                                               \
  "  - {name: block, material: al-alloy, spacing: 0.125,\n"                                 \
  "     shape: {type: box, min: [0, 0, 0], max: [1, 1, 1]}}\n"                              \
  "  - {name: lone, material: al-alloy, spacing: 0.125, velocity: [0.5, 0, 0],\n"           \
  "     shape: {type: box, min: [%g, 0.4375, 0.4375], max: [%g, 0.5625, 0.5625]}}\n"        \
  "time: {end: 1e30}\n"

/* Runs NSTEPS steps with the lone particle's box starting at x0; returns its vsig, and
 * *limit_body the body whose limit set the last proposed step (-1 on failure). */
static double run(int solid, double x0, int *limit_body, double *c_lone)
{
  char text[1024];
  if (solid) snprintf(text, sizeof text, SOLID_FMT, x0, x0 + 0.125);
  else snprintf(text, sizeof text, CASE_FMT, x0, x0 + 0.125);
  struct sim s;
  struct cfg *c;
  struct hv_error err = {0};
  *limit_body = -1;
  if (sim_from_text(text, "timestep.yaml", &s, &c)) return NAN;
  int ok = !step_init(&s, &err);
  for (int k = 0; k < NSTEPS && ok; k++) ok = !step_advance(&s, &err);
  CHECK(ok, "x0 = %g: %d steps (%s)", x0, NSTEPS, ok ? "ok" : err.msg);
  double vsig = NAN;
  for (size_t i = 0; i < s.p.n; i++)
    if (s.p.body[i] == 1) {
      vsig = s.p.vsig[i];
      *c_lone = s.p.cs[i];
    }
  *limit_body = s.dt_limit_body;
  printf("%s, x0 = %g: lone particle vsig = %.6g m/s (c = %.4g m/s); step %.4g s set by body %d "
         "(%s)\n", solid ? "solid" : "gas", x0, vsig, *c_lone, s.dt, s.dt_limit_body, step_limit_name(s.dt_limit));
  sim_free(&s);
  cfg_free(c);
  return vsig;
}

int main(void)
{
  int body;
  double c = NAN;
  const double far = run(0, 3.0, &body, &c);
  CHECK(far == 0.5, "no neighbour: vsig = |v| = 0.5 m/s (got %.17g)", far);
  CHECK(body == 0, "no neighbour: the block sets the step (body %d)", body);
  /* against the block's face: the block ends at x = 1, spacing 0.125, h = 0.15 */
  const double near = run(0, 1.0, &body, &c);
  CHECK(near >= c * (1.0 + 1.2 * 1.0), "with neighbours: vsig = %.4g >= c (1 + 1.2 alpha) = %.4g",
        near, c * 2.2);
  CHECK(body == 1, "with neighbours: the hot particle sets the step (body %d)", body);
  const double far_solid = run(1, 3.0, &body, &c);
  CHECK(far_solid == 0.5, "solid, no neighbour: vsig = |v| = 0.5 m/s (got %.17g; c = %.4g m/s)",
        far_solid, c);
  CHECK(body == 0, "solid, no neighbour: the block sets the step (body %d)", body);
  return test_finish();
}
