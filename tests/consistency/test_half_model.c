/* test_half_model.c — a half model (symmetry plane z = 0: mirror ghosts with the normal
 * velocity and the xz, yz shear stresses reversed) against the full model of the same
 * small impact: an al-alloy sphere at 800 m/s onto an al-alloy plate (strength,
 * fracture, contact, artificial stress all on), 60 steps.
 *
 * The full model's lattice is mirror-symmetric about z = 0, so the half model holds
 * exactly its z > 0 particles and must reproduce them: the same particle count × 2, and
 * (doubled) the same projectile and plate momenta, kinetic and internal energies, within
 * HALF_TOL relative. The two runs differ only in the order of floating-point operations
 * (ghost images instead of real partners), so the measured differences are round-off
 * growing over the steps (printed: about 1e-15). Leaving out the reversal of the
 * mirrored shear stresses changes them by 1e-6 to 2e-5 after these 60 steps (measured
 * by breaking src/boundary/boundary.c on purpose), far above the tolerance.
 *
 * Then the edge where a wall meets the symmetry plane: a box projectile on the plate,
 * symmetric about z = 0 and about y = 0 (x = 0 for the same case turned to run along
 * y), against its quarter, z > 0 with y > 0 (x > 0) behind a wall at y = 0 (x = 0),
 * a frictionless wall being an exact mirror too. The impact is on the edge itself, so
 * the quarter needs the corner ghosts (a wall ghost mirrored again in z) with the shear
 * signs of both mirrors. Its energies and its momentum along the wall × 4 are the full
 * model's within HALF_TOL (round-off, about 1e-16); breaking on purpose a single sign
 * of mirror_flip for x or y, the corner ghosts' combined flips, or the copying of
 * earlier ghosts in later dimensions changes them by 1e-9 to 2e-4.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "config/config.h"
#include "integrate/step.h"
#include "run/run.h"
#include "sim/sim.h"
#include "testlib.h"

#define NSTEPS   60
#define HALF_TOL 1e-10

static const char *full_case =
    "bodies:\n"
    "  - {name: ball, material: al-alloy, spacing: 0.5 mm, velocity: [800, 0, 0],\n"
    "     shape: {type: sphere, center: [-3.25 mm, 0, 0], radius: 3 mm}}\n"
    "  - {name: plate, material: al-alloy, spacing: 0.5 mm,\n"
    "     shape: {type: box, min: [0, -6 mm, -6 mm], max: [2 mm, 6 mm, 6 mm]}}\n"
    "time: {end: 1}\n";
static const char *half_case =
    "domain: {min: [-10 mm, -10 mm, 0], max: [10 mm, 10 mm, 10 mm], half_model: true}\n"
    "bodies:\n"
    "  - {name: ball, material: al-alloy, spacing: 0.5 mm, velocity: [800, 0, 0],\n"
    "     shape: {type: sphere, center: [-3.25 mm, 0, 0], radius: 3 mm}}\n"
    "  - {name: plate, material: al-alloy, spacing: 0.5 mm,\n"
    "     shape: {type: box, min: [0, -6 mm, -6 mm], max: [2 mm, 6 mm, 6 mm]}}\n"
    "time: {end: 1}\n";

struct body_sums {
  double px, py, ekin, eint; /* per body 0/1 */
};

static int run(const char *yaml, double dt_fixed, struct body_sums out[2], size_t *n)
{
  struct hv_error err;
  hv_error_clear(&err);
  struct cfg *c = cfg_load_string(yaml, "half.yaml", &err);
  struct sim s;
  memset(&s, 0, sizeof s);
  int rc = !c || run_setup(&s, c, &err) || step_init(&s, &err);
  for (int k = 0; k < NSTEPS && !rc; k++) {
    s.dt = dt_fixed; /* the same steps in both runs */
    rc = step_advance(&s, &err);
  }
  if (rc) printf("  run failed: %s\n", err.msg);
  memset(out, 0, 2 * sizeof *out);
  for (size_t i = 0; i < s.p.n && !rc; i++) {
    struct body_sums *b = &out[s.p.body[i]];
    const double m = s.p.m[i], vx = s.p.v[0][i], vy = s.p.v[1][i], vz = s.p.v[2][i];
    b->px += m * vx;
    b->py += m * vy;
    b->ekin += 0.5 * m * (vx * vx + vy * vy + vz * vz);
    b->eint += m * s.p.e[i];
  }
  *n = s.p.n;
  sim_free(&s);
  if (c) cfg_free(c);
  return rc;
}

static void compare_k(const char *what, double full, double part, double k, double scale)
{
  const double d = fabs(full - k * part) / scale;
  CHECK(d < HALF_TOL, "%s: full %.10g, %g x part %.10g (relative difference %.2e)", what, full, k,
        k * part, d);
}

static void compare(const char *what, double full, double half, double scale)
{
  compare_k(what, full, half, 2.0, scale);
}

/* A box projectile along x (along y when `along_y`) onto the plate, both cut by the
 * planes of the quarter when `quarter` (the lattices are anchored at the boxes' corners,
 * so the quarter holds exactly the full model's particles there). */
static void quarter_case(char *buf, size_t len, int along_y, int quarter)
{
  const char *lo = quarter ? "0" : "-2 mm", *plo = quarter ? "0" : "-6 mm";
  const char *dom = !quarter  ? ""
                    : along_y ? "domain: {min: [0, -10 mm, 0], max: [10 mm, 10 mm, 10 mm], "
                                "half_model: true, boundary: {x_min: wall}}\n"
                              : "domain: {min: [-10 mm, 0, 0], max: [10 mm, 10 mm, 10 mm], "
                                "half_model: true, boundary: {y_min: wall}}\n";
  if (along_y)
    snprintf(buf, len,
             "%sbodies:\n"
             "  - {name: ball, material: al-alloy, spacing: 0.5 mm, velocity: [0, 800, 0],\n"
             "     shape: {type: box, min: [%s, -4.25 mm, -2 mm], max: [2 mm, -0.25 mm, 2 mm]}}\n"
             "  - {name: plate, material: al-alloy, spacing: 0.5 mm,\n"
             "     shape: {type: box, min: [%s, 0, -6 mm], max: [6 mm, 2 mm, 6 mm]}}\n"
             "time: {end: 1}\n",
             dom, lo, plo);
  else
    snprintf(buf, len,
             "%sbodies:\n"
             "  - {name: ball, material: al-alloy, spacing: 0.5 mm, velocity: [800, 0, 0],\n"
             "     shape: {type: box, min: [-4.25 mm, %s, -2 mm], max: [-0.25 mm, 2 mm, 2 mm]}}\n"
             "  - {name: plate, material: al-alloy, spacing: 0.5 mm,\n"
             "     shape: {type: box, min: [0, %s, -6 mm], max: [2 mm, 6 mm, 6 mm]}}\n"
             "time: {end: 1}\n",
             dom, lo, plo);
}

static void test_quarter(void)
{
  const double dt = 2e-9;
  for (int along_y = 0; along_y < 2; along_y++) {
    char full[1024], quarter[1024];
    struct body_sums f[2] = {0}, q[2] = {0}; /* read below even when a run failed */
    size_t nf = 0, nq = 0;
    quarter_case(full, sizeof full, along_y, 0);
    quarter_case(quarter, sizeof quarter, along_y, 1);
    printf("  quarter model behind a wall at %c = 0:\n", along_y ? 'x' : 'y');
    CHECK(run(full, dt, f, &nf) == 0 && run(quarter, dt, q, &nq) == 0 && nf == 4 * nq,
          "full and quarter ran, particles: full %zu = 4 x quarter %zu", nf, nq);
    /* the momentum along the wall (the wall takes the normal one) */
    const double pf0 = along_y ? f[0].py : f[0].px, pf1 = along_y ? f[1].py : f[1].px;
    const double pq0 = along_y ? q[0].py : q[0].px, pq1 = along_y ? q[1].py : q[1].px;
    const double p0 = fabs(pf0 + pf1), e0 = f[0].ekin + f[0].eint + f[1].ekin + f[1].eint;
    CHECK(pf1 > 1e-3 * p0, "the plate has taken momentum (%.3g of %.3g kg m/s)", pf1, p0);
    compare_k("ball momentum along the impact", pf0, pq0, 4.0, p0);
    compare_k("plate momentum along the impact", pf1, pq1, 4.0, p0);
    compare_k("ball kinetic energy", f[0].ekin, q[0].ekin, 4.0, e0);
    compare_k("plate kinetic energy", f[1].ekin, q[1].ekin, 4.0, e0);
    compare_k("ball internal energy", f[0].eint, q[0].eint, 4.0, e0);
    compare_k("plate internal energy", f[1].eint, q[1].eint, 4.0, e0);
  }
}

int main(void)
{
  struct body_sums f[2] = {0}, h[2] = {0};
  size_t nf = 0, nh = 0;
  const double dt = 2e-9; /* [s] below the CFL step of 0.5 mm aluminium (~1e-8 s) */
  CHECK(run(full_case, dt, f, &nf) == 0, "full model ran %d steps", NSTEPS);
  CHECK(run(half_case, dt, h, &nh) == 0, "half model ran %d steps", NSTEPS);
  CHECK(nf == 2 * nh, "particles: full %zu = 2 x half %zu", nf, nh);
  const double p0 = fabs(f[0].px + f[1].px), e0 = f[0].ekin + f[0].eint + f[1].ekin + f[1].eint;
  CHECK(f[1].px > 1e-3 * p0, "the plate has taken momentum (%.3g of %.3g kg m/s)", f[1].px, p0);
  compare("ball x-momentum", f[0].px, h[0].px, p0);
  compare("plate x-momentum", f[1].px, h[1].px, p0);
  compare("ball y-momentum", f[0].py, h[0].py, p0);
  compare("ball kinetic energy", f[0].ekin, h[0].ekin, e0);
  compare("plate kinetic energy", f[1].ekin, h[1].ekin, e0);
  compare("ball internal energy", f[0].eint, h[0].eint, e0);
  compare("plate internal energy", f[1].eint, h[1].eint, e0);
  test_quarter();
  return test_finish();
}
