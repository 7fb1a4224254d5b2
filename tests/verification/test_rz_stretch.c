/* test_rz_stretch.c — the cap on the hoop stretch a ring's h follows
 * (sph.rz_stretch_max; src/integrate/step.c, update_h; docs/models.md, "Axisymmetric
 * (RZ)").
 *
 * examples/verification/rod_stretch_rz.yaml: a tungsten-alloy rod (r = 1 mm, 2.37 km/s)
 * into steel, 4 rings per rod radius (Δ = 0.25 mm), to 8 µs; run with the default cap
 * (2) and without it (sph.rz_stretch_max = 0). Each ring's h, normalised to its initial
 * density, g = h √(ρ/ρ₀) / h₀ (h₀, ρ₀ from snapshot 0, followed by id), is what the
 * stretch does to it: h = η (m/(2π r ρ))^(1/2) gives g = (r₀/r)^(1/2) exactly.
 *
 *  - With the cap, every ring has g ≥ 1/√2 (r taken no larger than 2 r₀), to 1e-9 (the
 *    rounding of the CSV's 17 digits and of the square roots).
 *  - Without it, some ring has g < 0.5 (measured 2026-12-07: 0.250, 118 rings below 0.5):
 *    the rings of the cavity wall do stretch more than 4-fold here, so the first check
 *    is not empty.
 *  - The cap saves steps: at least 1.25 times fewer (measured 1 411 against 2 036, 1.44;
 *    on rod-5841 at 4 rings per radius to 40 µs 2 881 against 5 737): the step is set by
 *    those rings' h.
 *  - The cavity is the same: penetration depth and cavity_diameter_wall within one ring
 *    spacing Δ of each other (a surface's place is known to about Δ/2 on each side:
 *    docs/measurements.md). Measured: depth 9.876 against 9.719 mm, cavity wall 6.334
 *    against 6.338 mm.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diag/measure_table.h"
#include "solidcase.h"
#include "testlib.h"

#define SPACING   0.25e-3 /* [m] the case's Δ */
#define T_END     8e-6    /* [s] */
#define STEP_GAIN 1.25    /* steps without the cap / steps with it, at least */

struct run {
  double gmin;  /* smallest h √(ρ/ρ₀)/h₀ of the last snapshot */
  long below;   /* rings with it below 0.5 */
  double steps; /* steps to T_END */
  double depth; /* penetration_depth at T_END [m] */
  double wall;  /* cavity_diameter_wall at T_END [m] */
};

static double at(const struct meas_table *t, const char *quantity)
{
  for (size_t k = 0; k < t->n; k++)
    if (fabs(t->rows[k].time - T_END) < 1e-9 && !strcmp(t->rows[k].quantity, quantity))
      return t->rows[k].value;
  return NAN;
}

/* the step of summary.csv's last row */
static double last_step(const char *dir)
{
  char path[4400];
  snprintf(path, sizeof path, "%s/summary.csv", dir);
  char *s = test_slurp(path, NULL);
  double step = NAN;
  if (s) {
    size_t n = strlen(s);
    while (n > 0 && s[n - 1] == '\n') s[--n] = '\0';
    const char *l = strrchr(s, '\n');
    if (l) step = atof(l + 1);
  }
  free(s);
  return step;
}

static int run_case(const char *name, const char *extra, struct run *r)
{
  int nsnap = 0;
  const char *dir = sc_run_open("rod_stretch_rz", name, extra, name, 3, &nsnap);
  if (!dir) return -1;
  struct particles p0, p1;
  double t1 = 0;
  if (sc_read(dir, 0, &p0, NULL) || sc_read(dir, nsnap - 1, &p1, &t1)) return -1;
  CHECK(fabs(t1 - T_END) < 1e-9, "%s: the last snapshot is at %g s", name, t1);
  size_t nid = 0;
  for (size_t i = 0; i < p0.n; i++)
    if ((size_t)p0.id[i] + 1 > nid) nid = (size_t)p0.id[i] + 1;
  size_t *slot0 = sc_slots_by_id(&p0, nid);
  r->gmin = HUGE_VAL;
  r->below = 0;
  for (size_t i = 0; i < p1.n; i++) {
    const size_t j = slot0[p1.id[i]];
    if (j == SIZE_MAX) continue;
    const double g = p1.h[i] * sqrt(p1.rho[i] / p0.rho[j]) / p0.h[j];
    if (g < r->gmin) r->gmin = g;
    if (g < 0.5) r->below++;
  }
  free(slot0);
  particles_free(&p0);
  particles_free(&p1);
  r->steps = last_step(dir);
  char path[4400];
  snprintf(path, sizeof path, "%s/measurements.csv", dir);
  struct meas_table t;
  struct hv_error err = {0};
  meas_table_init(&t);
  if (meas_table_read(&t, path, &err)) {
    printf("  cannot read %s: %s\n", path, err.msg);
    meas_table_free(&t);
    return -1;
  }
  r->depth = at(&t, "penetration_depth");
  r->wall = at(&t, "cavity_diameter_wall");
  meas_table_free(&t);
  printf("  MEASURED %s: h sqrt(rho/rho0)/h0 >= %.4f (%ld rings below 0.5), %.0f steps, depth "
         "%.3f mm, cavity_diameter_wall %.3f mm\n",
         name, r->gmin, r->below, r->steps, 1e3 * r->depth, 1e3 * r->wall);
  return 0;
}

int main(void)
{
  struct run cap, free_ = {0};
  int ok = run_case("capped", NULL, &cap) == 0;
  CHECK(ok, "the case runs with the default cap and is read back");
  int ok2 = run_case("uncapped", "--set sph.rz_stretch_max=0", &free_) == 0;
  CHECK(ok2, "the case runs without the cap and is read back");
  if (!ok || !ok2) return test_finish();
  CHECK(cap.gmin >= (1.0 - 1e-9) / sqrt(2.0),
        "with the cap every ring's h sqrt(rho/rho0)/h0 is at least 1/sqrt(2) (smallest %.6f)",
        cap.gmin);
  CHECK(free_.gmin < 0.5,
        "without it the cavity's rings stretch more than 4-fold (smallest %.4f, %ld rings "
        "below 0.5)",
        free_.gmin, free_.below);
  CHECK(free_.steps >= STEP_GAIN * cap.steps,
        "the cap saves steps: %.0f without it, %.0f with it (at least %.2f times fewer)",
        free_.steps, cap.steps, STEP_GAIN);
  CHECK(fabs(cap.depth - free_.depth) <= SPACING,
        "the same penetration: %.3f mm with the cap, %.3f mm without, within %g mm",
        1e3 * cap.depth, 1e3 * free_.depth, 1e3 * SPACING);
  CHECK(fabs(cap.wall - free_.wall) <= SPACING,
        "the same cavity wall: %.3f mm with the cap, %.3f mm without, within %g mm", 1e3 * cap.wall,
        1e3 * free_.wall, 1e3 * SPACING);
  return test_finish();
}
