/* test_conservation_solid.c — conservation with strength, fracture, artificial stress and
 * contact on (issue 3, item 6): like test_conservation.c, but two solid slabs, al-alloy
 * and copper from the library (von Mises strength, linear hardening for copper, Tresca
 * fracture for al-alloy, Monaghan–Gray artificial stress at its default ε = 0.3), in a
 * box periodic in x, y and z, with random velocities; stepped NSTEPS times through the
 * library (run_setup, step_init, step_advance):
 *
 *   - particle count and every particle's mass (by id) unchanged, bit for bit; total
 *     mass bitwise equal to the initial one (summed in id order and by diag_totals);
 *   - linear momentum conserved to round-off: |Δp| / Σ m|v| < MOMENTUM_MAX at every step.
 *     Every pair term is antisymmetric: the stress term (σᵢ/ρᵢ² + σⱼ/ρⱼ²)·∇ᵢWᵢⱼ, the
 *     artificial stress (Rᵢ + Rⱼ)fᵢⱼⁿ·∇ᵢWᵢⱼ, the viscosity, and the compression-only
 *     contact between the slabs (max(pᵢ,0)/ρᵢ² + max(pⱼ,0)/ρⱼ²);
 *   - total energy E = Σ m (v²/2 + e) (plastic work and viscosity heat the material):
 *     the drift |E − E0|/E0 is reported every tenth step and must stay below
 *     ENERGY_DRIFT_MAX = 1e-2. Measured (2026-11-22, session 5): 9.2e-4 (max over the
 *     100 steps; the gas test's is 7e-5), 9.1e-4 with the reconstructed viscosity,
 *     9.2e-4 with sph.artificial_stress.epsilon = 0, 9.9e-4 without fracture and 9.3e-4
 *     with al-alloy's fracture.split: no-tension (session 18) — so
 *     it is the predictor–corrector, which is not exactly energy conserving, not the
 *     artificial stress (before its pair factor was made resolution-independent in
 *     session 4 the drift was 2.8e-3, most of it the artificial stress's work). The bound catches a
 *     missing term: the plastic work here is of order Y ε_p V ~ 0.5 J of E0 = 3.1 J, so
 *     leaving out the heating S:ε̇/ρ would show as a drift of ~15%;
 *   - the test means something: plastic strain, splits and contact pairs occur, and
 *     the kinetic energy changes (below 99 % of the initial; above 0.1 %, so some motion
 *     is left: 1.0–1.7 % is).
 * Run three times: with the standard viscosity; with sph.viscosity.reconstruct (the pair's
 * velocity difference reconstructed to its midpoint; symmetric in i and j, so the
 * momentum must still be conserved to round-off); and with al-alloy's split particles
 * without tension (fracture.split: no-tension: the forces and the heating use σ with
 * its principal tensions removed; a heating on a different stress than the forces'
 * would show in the energy — the first version, which carried the EOS pressure with a
 * compensating trace in S, drifted by 3 % in a rod run where the split fluid drifted
 * by 4e-4).
 *
 * Velocities: up to ±VMAX per component, drawn from a fixed generator; 200 m/s in
 * aluminium gives stresses ρ c_L v ~ 3.7 GPa, far beyond the yield (0.383 GPa) and the
 * Tresca limit (0.59 GPa), so plastic flow and splitting are active.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "config/config.h"
#include "diag/conservation.h"
#include "integrate/step.h"
#include "run/run.h"
#include "run/sim.h"
#include "solidcase.h"
#include "simtext.h"
#include "testlib.h"
#include <omp.h>

#define NSTEPS 100
#define MOMENTUM_MAX 1e-12      /* round-off: the brief's "relative 1e-12" */
#define ENERGY_DRIFT_MAX 1e-2   /* reported; generous (see the header) */
#define VMAX 200.0              /* [m/s] largest random velocity component */

/* 12 x 12 x 6 + 10 x 10 x 5 lattice points in a 3 mm box */
static const char *case_head =
    "name: conservation_solid\n"
    "domain: {min: [0, 0, 0], max: [3 mm, 3 mm, 3 mm],\n"
    "         boundary: {x: periodic, y: periodic, z: periodic}}\n"
    "materials:\n"
    "  al: {library: al-alloy";   /* + "" or ", fracture: {split: no-tension}" */
static const char *case_tail =
    "}\n"
    "  cu: {library: copper}\n"
    "bodies:\n"
    "  - {name: al, material: al, spacing: 0.25 mm,\n"
    "     shape: {type: box, min: [0, 0, 0], max: [3 mm, 3 mm, 1.5 mm]}}\n"
    "  - {name: cu, material: cu, spacing: 0.3 mm,\n"
    "     shape: {type: box, min: [0, 0, 1.5 mm], max: [3 mm, 3 mm, 3 mm]}}\n"
    "time: {end: 1e30}\n"
    "output: {vtu: false}\n"
    "sph: {viscosity: {alpha: 1.0, beta: 2.0";   /* + "}}" or ", reconstruct: true}}" */

/* xorshift64*: the same numbers on every platform (unlike rand()) */
static uint64_t rng_state = 0x9E3779B97F4A7C15ull;
static double uniform(void) /* [-0.5, 0.5) */
{
  rng_state ^= rng_state >> 12;
  rng_state ^= rng_state << 25;
  rng_state ^= rng_state >> 27;
  return (double)((rng_state * 0x2545F4914F6CDD1Dull) >> 11) * 0x1.0p-53 - 0.5;
}

static double mass_by_id(const struct particles *p, double *m_by_id, size_t nid)
{
  for (size_t k = 0; k < nid; k++) m_by_id[k] = (double)NAN;
  for (size_t i = 0; i < p->n; i++)
    if (p->id[i] >= 0 && (size_t)p->id[i] < nid) m_by_id[p->id[i]] = p->m[i];
  double sum = 0.0;
  for (size_t k = 0; k < nid; k++) sum += m_by_id[k];
  return sum;
}

static double momentum_scale(const struct particles *p)
{
  double s = 0.0;
  for (size_t i = 0; i < p->n; i++)
    s += p->m[i] * sqrt(p->v[0][i] * p->v[0][i] + p->v[1][i] * p->v[1][i] +
                        p->v[2][i] * p->v[2][i]);
  return s;
}

static void run_case(const char *al_more, const char *viscosity_more)
{
  struct hv_error err;
  hv_error_clear(&err);
  char text[2048];
  snprintf(text, sizeof text, "%s%s%s%s}}\n", case_head, al_more, case_tail, viscosity_more);
  printf("== al-alloy: {library: al-alloy%s}, sph.viscosity: {alpha: 1.0, beta: 2.0%s}\n",
         al_more, viscosity_more);
  rng_state = 0x9E3779B97F4A7C15ull;
  struct cfg *c;
  struct sim s;
  if (sim_from_text(text, "conservation_solid.yaml", &s, &c)) return;
  int ok;
  const size_t n0 = s.p.n;
  CHECK(n0 == 12 * 12 * 6 + 10 * 10 * 5, "particles: %zu (expected %d)", n0,
        12 * 12 * 6 + 10 * 10 * 5);
  CHECK(s.p.solid, "solid fields on (strength and fracture present)");
  if (!s.p.solid) return;

  for (size_t i = 0; i < s.p.n; i++)
    for (int k = 0; k < 3; k++) s.p.v[k][i] = 2.0 * VMAX * uniform();
  double *m0 = malloc(n0 * sizeof *m0), *m1 = malloc(n0 * sizeof *m1);
  const double mass0_id = mass_by_id(&s.p, m0, n0);
  struct totals t0, t;
  diag_totals(&s.p, &t0);
  const double scale0 = momentum_scale(&s.p);
  printf("initial: n = %zu, mass = %.17g kg, p = (%.6e, %.6e, %.6e) kg m/s, "
         "sum m|v| = %.6e kg m/s, E = %.17g J (kinetic %.6e, internal %.6e)\n",
         n0, t0.mass, t0.mom[0], t0.mom[1], t0.mom[2], scale0, t0.e_total, t0.e_kin, t0.e_int);

  ok = !step_init(&s, &err);
  CHECK(ok, "step_init (%s)", ok ? "ok" : err.msg);
  if (!ok) return;

  double worst_dp = 0.0, worst_de = 0.0;
  int mass_diag_same = 1, mass_id_same = 1, masses_same = 1, count_same = 1;
  long worst_dp_step = 0;
  for (int k = 1; k <= NSTEPS && ok; k++) {
    ok = !step_advance(&s, &err);
    if (!ok) break;
    diag_totals(&s.p, &t);
    double dp = sqrt((t.mom[0] - t0.mom[0]) * (t.mom[0] - t0.mom[0]) +
                     (t.mom[1] - t0.mom[1]) * (t.mom[1] - t0.mom[1]) +
                     (t.mom[2] - t0.mom[2]) * (t.mom[2] - t0.mom[2])) /
                momentum_scale(&s.p);
    double de = fabs(t.e_total - t0.e_total) / t0.e_total;
    if (dp > worst_dp) {
      worst_dp = dp;
      worst_dp_step = k;
    }
    if (de > worst_de) worst_de = de;
    count_same &= s.p.n == n0;
    mass_diag_same &= t.mass == t0.mass;
    mass_id_same &= mass_by_id(&s.p, m1, n0) == mass0_id;
    masses_same &= !memcmp(m0, m1, n0 * sizeof *m0);
    if (k % 10 == 0)
      printf("step %3d  t = %.6e s  dt = %.3e s  |dp|/sum m|v| = %.3e  (E - E0)/E0 = %+.3e  "
             "E_kin/E_kin0 = %.4f  E_int = %.4e J\n", k, s.t, s.dt, dp,
             (t.e_total - t0.e_total) / t0.e_total, t.e_kin / t0.e_kin, t.e_int);
  }
  CHECK(ok, "%d steps run (%s)", NSTEPS, ok ? "ok" : err.msg);
  CHECK(count_same, "particle count stays %zu", n0);
  CHECK(masses_same, "every particle's mass (by id) is bitwise unchanged");
  CHECK(mass_id_same, "total mass summed in id order is bitwise the initial %.17g kg", mass0_id);
  CHECK(mass_diag_same, "total mass from diag_totals is bitwise the initial %.17g kg (last %.17g)",
        t0.mass, t.mass);
  CHECK(worst_dp < MOMENTUM_MAX, "momentum: max |dp| / sum m|v| = %.3e (step %ld) < %.0e",
        worst_dp, worst_dp_step, MOMENTUM_MAX);
  CHECK(worst_de < ENERGY_DRIFT_MAX, "energy: max |E - E0| / E0 = %.3e < %.0e (reported; "
        "the scheme is not exactly energy conserving)", worst_de, ENERGY_DRIFT_MAX);

  /* the physics this test is about must have been active */
  double epsmax = 0.0;
  size_t splits = 0, plastic = 0;
  for (size_t i = 0; i < s.p.n; i++) {
    if (s.p.eps_p[i] > epsmax) epsmax = s.p.eps_p[i];
    plastic += s.p.eps_p[i] > 0;
    splits += s.p.damage[i] >= 1.0;
  }
  printf("after %d steps: %zu particles yielded (max plastic strain %.4f), %zu split\n", NSTEPS,
         plastic, epsmax, splits);
  CHECK(plastic > n0 / 10, "plastic flow is active: %zu of %zu particles yielded", plastic, n0);
  CHECK(splits > 0, "fracture is active: %zu particles split", splits);
  CHECK(t.e_kin < 0.99 * t0.e_kin && t.e_kin > 0.001 * t0.e_kin,
        "the random motion is being converted: E_kin / E_kin0 = %.4f", t.e_kin / t0.e_kin);
  free(m0);
  free(m1);
  sim_free(&s);
  cfg_free(c);
}

int main(void)
{
  omp_set_num_threads(sc_threads()); /* `make check` runs two tests at a time on 2 cores */
  run_case("", "");
  run_case("", ", reconstruct: true");
  run_case(", fracture: {split: no-tension}", "");
  return test_finish();
}
