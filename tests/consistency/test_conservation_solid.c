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
 *     ENERGY_DRIFT_MAX = 2e-3 (1e-2 before; the five runs below measured 9.05e-4 to
 *     9.88e-4 when it was set, the largest with fracture.energy; 2e-3 rather than 3e-3
 *     so that the 2.8e-3 of the artificial stress before b8d59a7, below, would fail).
 *     Measured (2026-11-22 at b8d59a7): 9.2e-4 (max over the 100 steps; the gas test's
 *     is 7e-5), 9.1e-4 with the reconstructed viscosity, 9.2e-4 with
 *     sph.artificial_stress.epsilon = 0, 9.9e-4 without fracture, 9.3e-4 with al-alloy's
 *     fracture.split: no-tension (8ae01d7, 2026-11-24) and 9.7e-4 with split: crack
 *     (6fcaa47, 2026-12-05) — so it is the predictor–corrector, which is not exactly
 *     energy conserving, not the artificial stress (before its work entered the energy
 *     equation in b8d59a7 the drift was 2.8e-3, most of it that work). The bound catches a
 *     missing term: the plastic work here is of order Y ε_p V ~ 0.5 J of E0 = 3.1 J, so
 *     leaving out the heating S:ε̇/ρ would show as a drift of ~15%;
 *   - the test means something: plastic strain, splits and contact pairs occur, and
 *     the kinetic energy changes (below 99 % of the initial; above 0.1 %, so some motion
 *     is left: 1.0–1.7 % is).
 * Run five times: with the standard viscosity; with sph.viscosity.reconstruct (the pair's
 * velocity difference reconstructed to its midpoint; symmetric in i and j, so the
 * momentum must still be conserved to round-off); and with al-alloy's split particles
 * without tension (fracture.split: no-tension: the forces and the heating use σ with
 * its principal tensions removed; a heating on a different stress than the forces'
 * would show in the energy — the first version, which carried the EOS pressure with a
 * compensating trace in S, drifted by 3 % in a rod run where the split fluid drifted
 * by 4e-4); and with al-alloy split along cracks (fracture.split: crack: the crack's
 * opening strain takes the material's normal stress, the EOS sees the material's density
 * ρ e^{ε_c}; an opening that did work or a pressure that did not follow ε_c would show in
 * the energy); and with al-alloy opening before it splits (fracture.energy: the same
 * opening strain, along a cohesive softening line; 2 kJ/m2 on al's 0.25 mm particles
 * opens them through at w_u = 2G_f/(|σ_c| l) = 2.7 %: some open part way, some split).
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
#include "conserve.h"
#include "diag/conservation.h"
#include "fracture/fracture.h"
#include "integrate/step.h"
#include "run/run.h"
#include "sim/sim.h"
#include "solidcase.h"
#include "simtext.h"
#include "testlib.h"
#include <omp.h>

#define NSTEPS       100
#define MOMENTUM_MAX 1e-12 /* round-off: the brief's "relative 1e-12" */
#define ENERGY_DRIFT_MAX                                                                           \
  2e-3             /* measured 9.20e-4, 9.05e-4, 9.28e-4, 9.69e-4, 9.88e-4 in the
                                   five runs (was 1e-2; see the header) */
#define VMAX 200.0 /* [m/s] largest random velocity component */

/* 12 x 12 x 6 + 10 x 10 x 5 lattice points in a 3 mm box */
static const char *case_head =
    "name: conservation_solid\n"
    "domain: {min: [0, 0, 0], max: [3 mm, 3 mm, 3 mm],\n"
    "         boundary: {x: periodic, y: periodic, z: periodic}}\n"
    "materials:\n"
    "  al: {library: al-alloy"; /* + "" or ", fracture: {split: no-tension}" */
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
    "sph: {viscosity: {alpha: 1.0, beta: 2.0"; /* + "}}" or ", reconstruct: true}}" */

static void run_case(const char *al_more, const char *viscosity_more)
{
  char text[2048];
  snprintf(text, sizeof text, "%s%s%s%s}}\n", case_head, al_more, case_tail, viscosity_more);
  printf("== al-alloy: {library: al-alloy%s}, sph.viscosity: {alpha: 1.0, beta: 2.0%s}\n", al_more,
         viscosity_more);
  uint64_t rng = 0x9E3779B97F4A7C15ull;
  struct cfg *c;
  struct sim s;
  if (sim_from_text(text, "conservation_solid.yaml", &s, &c)) return;
  const size_t n0 = s.p.n;
  CHECK(n0 == 12 * 12 * 6 + 10 * 10 * 5, "particles: %zu (expected %d)", n0,
        12 * 12 * 6 + 10 * 10 * 5);
  CHECK(s.p.solid, "solid fields on (strength and fracture present)");
  if (!s.p.solid) return;

  for (size_t i = 0; i < s.p.n; i++)
    for (int k = 0; k < 3; k++) s.p.v[k][i] = 2.0 * VMAX * conserve_uniform(&rng);
  struct conserve_result r;
  conserve_steps(&s, NSTEPS, MOMENTUM_MAX, ENERGY_DRIFT_MAX, &r);
  if (!r.ok) { /* the failed step is reported; the checks below would only repeat it */
    sim_free(&s);
    cfg_free(c);
    return;
  }
  const struct totals t0 = r.t0, t = r.t;

  /* the physics this test is about must have been active */
  double epsmax = 0.0;
  size_t splits = 0, plastic = 0, cracked = 0, opening = 0;
  for (size_t i = 0; i < s.p.n; i++) {
    if (s.p.eps_p[i] > epsmax) epsmax = s.p.eps_p[i];
    plastic += s.p.eps_p[i] > 0;
    splits += s.p.fstate[i] >= FRACTURE_SPLIT;
    cracked += fracture_cracked(&s.mat[s.p.mat[i]].frac, s.p.fstate[i]);
    opening += s.p.fstate[i] == FRACTURE_OPENING;
  }
  printf("after %d steps: %zu particles yielded (max plastic strain %.4f), %zu split (%zu "
         "cracked once with split: crack), %zu opening (fracture.energy)\n",
         NSTEPS, plastic, epsmax, splits, cracked, opening);
  /* the explicit state (fstate) and the damage the snapshots show say the same: D = 1
     split, 2 split again, (0, 1) opening (fracture.h) */
  const size_t bad = fracture_check_states(&s.p, s.mat);
  CHECK(bad == (size_t)-1, "fracture state and damage agree (slot %zu: state %d, damage %g)", bad,
        bad < s.p.n ? (int)s.p.fstate[bad] : -1, bad < s.p.n ? s.p.damage[bad] : 0.0);
  if (strstr(al_more, "crack"))
    CHECK(cracked > 0, "split: crack: particles are cracked (%zu of %zu split)", cracked, splits);
  if (strstr(al_more, "energy"))
    CHECK(opening > 0, "fracture.energy: particles are opening (%zu; %zu split)", opening, splits);
  CHECK(plastic > n0 / 10, "plastic flow is active: %zu of %zu particles yielded", plastic, n0);
  CHECK(splits > 0, "fracture is active: %zu particles split", splits);
  CHECK(t.e_kin < 0.99 * t0.e_kin && t.e_kin > 0.001 * t0.e_kin,
        "the random motion is being converted: E_kin / E_kin0 = %.4f", t.e_kin / t0.e_kin);
  sim_free(&s);
  cfg_free(c);
}

int main(void)
{
  omp_set_num_threads(sc_threads()); /* `make check` runs two tests at a time on 2 cores */
  run_case("", "");
  run_case("", ", reconstruct: true");
  run_case(", fracture: {split: no-tension}", "");
  run_case(", fracture: {split: crack}", "");
  run_case(", fracture: {energy: 2 kJ/m2}", "");
  return test_finish();
}
