/* test_rz_vs_3d.c — one normal impact run in RZ and in 3D (issue 74, item 3):
 * examples/verification/impact_rz.yaml and impact_3d.yaml, an aluminium sphere
 * (al-alloy, d = 5 mm) at 6.5 km/s on a 1.5 mm al-alloy disc of radius 15 mm (W.P.1's
 * bumper impact, the plate cut to what the hole and the cloud need), to t = 4 us. The
 * same material, speed, geometry, kernel, eta, viscosity and spacing Δ in both; the 3D
 * run is the half model (z >= 0), the RZ run its meridional plane.
 *
 * Both runs are made at Δ = 0.5 mm and at Δ = 0.375 mm (5 and 6.7 particles per
 * projectile radius; 3 and 4 layers through the plate; 3D: 4 518 and 10 652 particles,
 * RZ: 130 and 230 rings), and compared through measurements.csv, written during the run
 * by the functions `hvsph measure` uses (test_paper_coarse checks that `hvsph measure`
 * rewrites the same rows from the snapshots): at 4 us, hole_diameter (the plate's) and
 * the debris cloud behind it: cloud_velocity_mean (mass mean of v_x), cloud_mass, and
 * cloud_velocity_lead (the 0.99 mass quantile of v_x).
 *
 * Tolerances, from each quantity's own resolution error (RZ at Δ = 0.5, 0.375, 0.3,
 * 0.25, 0.1875, 0.125 mm: 130-2069 rings; 3D at 0.5, 0.375, 0.3, 0.25 mm: 4 518-36 000
 * particles; 1 thread, measured 2026-12-07 with rz-engine at a89cdb0 merged, 15ba0c8):
 *  - hole_diameter: |RZ - 3D| <= 0.8 mm (7 %). The RZ hole scatters without trend over
 *    its six spacings, 10.45-11.23 mm (a spread of 0.78 mm: the hole's edge is a ring of
 *    particles whose place is known to about Δ/2 on each side, measurements.md); the 3D
 *    hole reads 11.03, 10.83, 10.79, 10.86 mm. Measured: 11.23 vs 11.03 mm (Δ 0.5) and
 *    10.45 vs 10.83 mm (Δ 0.375); at 0.25 mm 10.54 vs 10.86.
 *  - cloud_velocity_mean: within 5 % of the 3D value. 3D over its four spacings spans
 *    3269-3369 m/s (3 %), RZ over its six 3213-3440 m/s (7 %, +-3.5 % about its mean):
 *    5 % is about the two combined. Measured: 3279 vs 3269 m/s, 3366 vs 3369 m/s; at
 *    0.25 mm 3399 vs 3310 (+2.7 %).
 *  - cloud_mass: within 5 % of the 3D value (3D spans 0.387-0.399 g, 3 %; RZ 0.376-0.413 g,
 *    rising with resolution from 0.25 mm on, 0.38-0.39 g at these two). Measured: 0.392
 *    vs 0.399 g, 0.382 vs 0.387 g; at 0.25 mm 0.382 vs 0.397 (-3.7 %).
 *  - cloud_velocity_lead: at Δ = 0.375 only, within 4 % of the 3D value. At Δ = 0.5 the
 *    3D lead, the fastest 1 % of 588 particles' mass, is 5825 m/s, 4-5 % above its value
 *    at the finer spacings (5549, 5570, 5612 m/s), where RZ reads 5464-5570 m/s at all
 *    six: the coarse 3D quantile, not the RZ solver, is off there, and it is printed, not
 *    checked. 4 %: the RZ spread (1.9 %) and 3D's spread from 0.375 mm on (1.1 %), plus
 *    a margin. Measured: 5465 vs 5825 m/s (Δ 0.5, -6.2 %), 5464 vs 5549 m/s (Δ 0.375,
 *    -1.5 %); at 0.25 mm 5536 vs 5612 (-1.3 %).
 * Also: both plates perforated; the RZ total mass equals twice the half model's (each
 * ring carries its true 3D mass) within 1 %: the bodies are the same. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diag/measure_table.h"
#include "solidcase.h"
#include "testlib.h"

#define T_END     4e-6   /* [s] the time compared */
#define HOLE_TOL  0.8e-3 /* [m] |RZ - 3D| of hole_diameter */
#define MEAN_TOL  0.05   /* relative, cloud_velocity_mean */
#define MASS_TOL  0.05   /* relative, cloud_mass */
#define LEAD_TOL  0.04   /* relative, cloud_velocity_lead at the finer spacing */
#define LEAD_FROM 0.4e-3 /* [m] the lead is checked at spacings finer than this */

struct impact {
  double hole, vmean, vlead, cmass, perforated, seconds;
};

/* the value of a quantity at time t (within 1 ns) in measurements.csv; NAN if none */
static double at(const struct meas_table *t, double time, const char *quantity, const char *object)
{
  for (size_t k = 0; k < t->n; k++)
    if (fabs(t->rows[k].time - time) < 1e-9 && !strcmp(t->rows[k].quantity, quantity) &&
        !strcmp(t->rows[k].object, object))
      return t->rows[k].value;
  return NAN;
}

/* runs examples/verification/impact_<geom>.yaml at spacing dx [m]; 0 on success */
static int run_impact(const char *geom, double dx, struct impact *r)
{
  char name[64], extra[512], path[4400];
  snprintf(name, sizeof name, "impact_%s_%g", geom, 1e3 * dx);
  snprintf(extra, sizeof extra,
           "--set 'bodies[0].spacing=%.17g mm' --set 'bodies[1].spacing=%.17g mm' "
           "--set 'time.end=%g us' --set 'output.every=%g us' --set output.csv=false",
           1e3 * dx, 1e3 * dx, 1e6 * T_END, 1e6 * T_END);
  char example[32];
  snprintf(example, sizeof example, "impact_%s", geom);
  if (sc_run(example, name, extra, &r->seconds)) return -1;
  snprintf(path, sizeof path, "%s/measurements.csv", sc_outdir(name));
  struct meas_table t;
  struct hv_error err = {0};
  meas_table_init(&t);
  int rc = meas_table_read(&t, path, &err);
  if (rc)
    printf("  cannot read %s: %s\n", path, err.msg);
  else {
    r->perforated = at(&t, T_END, "perforated", "plate");
    r->hole = at(&t, T_END, "hole_diameter", "plate");
    r->vmean = at(&t, T_END, "cloud_velocity_mean", "cloud:plate");
    r->vlead = at(&t, T_END, "cloud_velocity_lead", "cloud:plate");
    r->cmass = at(&t, T_END, "cloud_mass", "cloud:plate");
  }
  meas_table_free(&t);
  return rc;
}

/* the total mass in the first row of summary.csv's data */
static double total_mass(const char *name)
{
  char path[4400];
  snprintf(path, sizeof path, "%s/summary.csv", sc_outdir(name));
  char *s = test_slurp(path, NULL);
  double m = NAN;
  const char *l = s;
  for (int k = 0; l && k < 2; k++) /* skip the comment and the header */
    if ((l = strchr(l, '\n'))) l++;
  if (l) { /* step,time,dt,n,mass,... */
    int col = 0;
    for (const char *c = l; *c && *c != '\n' && col < 4; c++)
      if (*c == ',' && ++col == 4) m = atof(c + 1);
  }
  free(s);
  return m;
}

int main(void)
{
  const double spacings[2] = {0.5e-3, 0.375e-3};
  double seconds = 0;
  for (int s = 0; s < 2; s++) {
    const double dx = spacings[s];
    struct impact rz = {NAN, NAN, NAN, NAN, NAN, 0}, d3 = rz;
    int st = run_impact("rz", dx, &rz);
    CHECK(st == 0, "the RZ run at %g mm runs and is measured", 1e3 * dx);
    st = run_impact("3d", dx, &d3);
    CHECK(st == 0, "the 3D run at %g mm runs and is measured", 1e3 * dx);
    seconds += rz.seconds + d3.seconds;
    printf("  MEASURED rz_vs_3d spacing=%g mm hole %.3f / %.3f mm, cloud_velocity_mean %.0f / "
           "%.0f m/s, cloud_mass %.4f / %.4f g, cloud_velocity_lead %.0f / %.0f m/s (RZ / 3D); "
           "wall %.1f / %.1f s\n",
           1e3 * dx, 1e3 * rz.hole, 1e3 * d3.hole, rz.vmean, d3.vmean, 1e3 * rz.cmass,
           1e3 * d3.cmass, rz.vlead, d3.vlead, rz.seconds, d3.seconds);
    char nrz[64], n3d[64];
    snprintf(nrz, sizeof nrz, "impact_rz_%g", 1e3 * dx);
    snprintf(n3d, sizeof n3d, "impact_3d_%g", 1e3 * dx);
    const double mrz = total_mass(nrz), m3d = total_mass(n3d);
    CHECK(fabs(mrz - 2 * m3d) <= 0.01 * 2 * m3d,
          "%g mm: the RZ rings' mass %.5g g is twice the half model's %.5g g within 1 %%", 1e3 * dx,
          1e3 * mrz, 1e3 * m3d);
    CHECK(rz.perforated == 1.0 && d3.perforated == 1.0, "%g mm: both plates perforated (%g, %g)",
          1e3 * dx, rz.perforated, d3.perforated);
    CHECK(fabs(rz.hole - d3.hole) <= HOLE_TOL,
          "%g mm: hole %.3f mm (RZ) vs %.3f mm (3D) within %g mm", 1e3 * dx, 1e3 * rz.hole,
          1e3 * d3.hole, 1e3 * HOLE_TOL);
    CHECK(fabs(rz.vmean - d3.vmean) <= MEAN_TOL * d3.vmean,
          "%g mm: cloud mean velocity %.0f m/s (RZ) vs %.0f m/s (3D) within %g %%", 1e3 * dx,
          rz.vmean, d3.vmean, 100 * MEAN_TOL);
    CHECK(fabs(rz.cmass - d3.cmass) <= MASS_TOL * d3.cmass,
          "%g mm: cloud mass %.4f g (RZ) vs %.4f g (3D) within %g %%", 1e3 * dx, 1e3 * rz.cmass,
          1e3 * d3.cmass, 100 * MASS_TOL);
    if (dx < LEAD_FROM)
      CHECK(fabs(rz.vlead - d3.vlead) <= LEAD_TOL * d3.vlead,
            "%g mm: cloud lead velocity %.0f m/s (RZ) vs %.0f m/s (3D) within %g %%", 1e3 * dx,
            rz.vlead, d3.vlead, 100 * LEAD_TOL);
  }
  printf("  the four runs took %.1f s\n", seconds);
  return test_finish();
}
