/* test_quarter_model.c — a quarter model (domain.symmetry: quarter: symmetry planes
 * y = 0 and z = 0 through the impact axis) against the half model of the same coarse
 * normal impact: an al-alloy sphere (radius 1 mm) at 5 km/s onto a 1 mm al-alloy plate
 * and a 1 mm wall 3 mm behind it, at 0.25 mm spacing (strength, fracture, contact,
 * artificial stress all on), run to 3 µs, when the plate is perforated and its debris
 * has cratered the wall.
 *
 * 1. At t = 0 the quarter's lattices are mirror-symmetric about both planes: every
 *    particle at y, z >= Δ/2 on the lattice (y/Δ − ½ and z/Δ − ½ whole numbers), and its
 *    four mirror images are exactly the full model's particles (a sphere, plates and a
 *    rod along x), so that the mirror ghosts stand where the full model's particles do.
 * 2. The half model's lattice is mirror-symmetric about y = 0 as well (the plate spans
 *    ±5 mm, 40 spacings; the sphere's lattice is centred on it), so the quarter holds
 *    exactly the half model's y > 0 particles, and its mirror ghosts across y = 0 carry
 *    what the half model's y < 0 reals compute. The two runs differ only in the order of
 *    floating-point operations, the same step sizes included (the step is a minimum over
 *    particles that the mirror halves share): measured 1e-15 to 1e-14 relative at 3 µs
 *    (562 steps) on every quantity below. The tolerances: QM_SUM_TOL = 1e-9 for the
 *    totals (momentum, kinetic and internal energy, × 4 against × 2) and QM_MEAS_TOL =
 *    1e-6 for the measurements (hole diameters, cloud mean and leading-edge velocity,
 *    cloud mass, the wall's crater depths, crater and damage radii, damaged mass; the
 *    quarter's wall columns are the half model's, measure_backwall; the largest
 *    fragment), and the fragment counts exactly equal, whose grids and quantiles turn a round-off shift into a step only when
 *    a particle sits on a cell edge; both far below what a broken quarter gives: a
 *    mirror without the shear reversal or the corner ghosts moves the totals by 1e-6 and
 *    more (test_half_model), a lattice off the planes changes the particle count, a
 *    measurement that counts the quarter's particles twice, not four times, is off by a
 *    factor 2.
 * The figures of the run are printed, with the wall time of each (docs/case-files.md,
 * domain, gives the measured cost).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "config/config.h"
#include "diag/fof.h"
#include "diag/measure.h"
#include "integrate/step.h"
#include "run/run.h"
#include "sim/sim.h"
#include "testlib.h"

#define QM_SUM_TOL  1e-9
#define QM_MEAS_TOL 1e-6
#define QM_T_END    3e-6 /* [s] */
#define QM_SPACING  0.25e-3

static const char *bodies =
    "bodies:\n"
    "  - {name: ball, material: al-alloy, spacing: 0.25 mm, velocity: [5 km/s, 0, 0],\n"
    "     shape: {type: sphere, center: [-1.25 mm, 0, 0], radius: 1 mm}}\n"
    "  - {name: plate, material: al-alloy, spacing: 0.25 mm,\n"
    "     shape: {type: box, min: [0, -5 mm, -5 mm], max: [1 mm, 5 mm, 5 mm]}}\n"
    "  - {name: wall, material: al-alloy, spacing: 0.25 mm,\n"
    "     shape: {type: box, min: [4 mm, -5 mm, -5 mm], max: [5 mm, 5 mm, 5 mm]}}\n";

/* The case: 0 full, 1 half, 2 quarter model; `rod` adds a rod along x behind the plate
 * (for the lattice check only). */
static void make_case(char *buf, size_t len, int model, int rod)
{
  static const char *dom[] = {
      "", "domain: {min: [-4 mm, -8 mm, 0], max: [12 mm, 8 mm, 8 mm], half_model: true}\n",
      "domain: {min: [-4 mm, 0, 0], max: [12 mm, 8 mm, 8 mm], symmetry: quarter}\n"};
  snprintf(buf, len, "time: {end: 3 us}\n%s%s%s", dom[model], bodies,
           rod ? "  - {name: rod, material: al-alloy, spacing: 0.2 mm,\n"
                 "     shape: {type: cylinder, center: [8 mm, 0, 0], axis: [1, 0, 0],\n"
                 "             radius: 0.9 mm, length: 3.1 mm}}\n"
               : "");
}

static int setup(struct sim *s, struct cfg **c, const char *yaml, struct hv_error *err)
{
  hv_error_clear(err);
  memset(s, 0, sizeof *s);
  *c = cfg_load_string(yaml, "quarter.yaml", err);
  return !*c || run_setup(s, *c, err);
}

static int cmp_pos(const void *a, const void *b)
{
  const long *p = a, *q = b;
  for (int k = 0; k < 4; k++)
    if (p[k] != q[k]) return p[k] < q[k] ? -1 : 1;
  return 0;
}

/* 1. The quarter's particles, mirrored four ways, against the full model's. */
static void test_lattice(void)
{
  char full[2048], quarter[2048];
  make_case(full, sizeof full, 0, 1);
  make_case(quarter, sizeof quarter, 2, 1);
  struct sim f, q;
  struct cfg *cf = NULL, *cq = NULL;
  struct hv_error err;
  const int rf = setup(&f, &cf, full, &err);
  CHECK(rf == 0, "full model set up (%s)", rf ? err.msg : "ok");
  const int rq = setup(&q, &cq, quarter, &err);
  CHECK(rq == 0, "quarter model set up (%s)", rq ? err.msg : "ok");
  if (!rf && !rq) {
    CHECK(f.p.n == 4 * q.p.n, "particles: full %zu = 4 x quarter %zu", f.p.n, q.p.n);
    size_t off = 0;
    for (size_t i = 0; i < q.p.n; i++) {
      const double d = q.body[q.p.body[i]].spacing;
      for (int k = 1; k < 3; k++) {
        const double u = q.p.x[k][i] / d - 0.5;
        if (!(q.p.x[k][i] > 0.0) || fabs(u - round(u)) > 1e-9) off++;
      }
    }
    CHECK(off == 0,
          "every quarter particle on the lattice at y, z = (k + 1/2) spacing > 0 "
          "(%zu coordinates off)",
          off);
    /* positions in units of 1e-9 spacing (the lattices are exact to far better), with
       the body, sorted: the quarter's four images must be the full model's points */
    const size_t n = f.p.n, nq = 4 * q.p.n;
    long *a = malloc(4 * (n + 1) * sizeof *a), *b = malloc(4 * (nq + 1) * sizeof *b);
    for (size_t i = 0; i < n; i++) {
      a[4 * i] = f.p.body[i];
      for (int k = 0; k < 3; k++) a[4 * i + 1 + k] = lround(f.p.x[k][i] / QM_SPACING * 1e9);
    }
    for (size_t i = 0; i < q.p.n; i++)
      for (int c = 0; c < 4; c++) {
        long *r = b + 4 * (4 * i + (size_t)c);
        r[0] = q.p.body[i];
        r[1] = lround(q.p.x[0][i] / QM_SPACING * 1e9);
        r[2] = lround((c & 2 ? -1 : 1) * q.p.x[1][i] / QM_SPACING * 1e9);
        r[3] = lround((c & 1 ? -1 : 1) * q.p.x[2][i] / QM_SPACING * 1e9);
      }
    size_t diff = n == nq ? 0 : n + nq;
    if (n == nq) {
      qsort(a, n, 4 * sizeof *a, cmp_pos);
      qsort(b, nq, 4 * sizeof *b, cmp_pos);
      for (size_t i = 0; i < n; i++) diff += cmp_pos(a + 4 * i, b + 4 * i) != 0;
    }
    CHECK(diff == 0,
          "the quarter's particles mirrored at y = 0 and z = 0 are the full model's "
          "(sphere, plate, rod; %zu differ)",
          diff);
    /* the mass of each: the full model's, the quarter's volume a quarter of the shape's */
    double mf = 0.0, mq = 0.0;
    for (size_t i = 0; i < n; i++) mf += f.p.m[i];
    for (size_t i = 0; i < q.p.n; i++) mq += q.p.m[i];
    CHECK(fabs(mf - 4.0 * mq) <= 1e-12 * mf, "mass: full %.9g kg = 4 x quarter %.9g kg", mf,
          4.0 * mq);
    free(a);
    free(b);
  }
  if (!rf) sim_free(&f);
  if (!rq) sim_free(&q);
  if (cf) cfg_free(cf);
  if (cq) cfg_free(cq);
}

struct result {
  size_t n;
  double px, ekin, eint, secs;
  struct meas_plate plate;
  struct meas_debris cloud;
  struct meas_backwall wall;
  size_t frag_n, frag_multi; /* fragments of the full picture; of >= 2 particles */
  double frag_m1;            /* [kg] the largest */
};

/* Runs the half (model 1) or quarter (2) model to QM_T_END and measures the plate. */
static int run_model(int model, struct result *out)
{
  char yaml[2048];
  make_case(yaml, sizeof yaml, model, 0);
  struct sim s;
  struct cfg *c = NULL;
  struct hv_error err;
  memset(out, 0, sizeof *out);
  struct timespec t0, t1;
  clock_gettime(CLOCK_MONOTONIC, &t0);
  int rc = setup(&s, &c, yaml, &err) || step_init(&s, &err);
  while (!rc && s.t < QM_T_END * (1.0 - 1e-12)) {
    if (s.t + s.dt > QM_T_END) s.dt = QM_T_END - s.t;
    rc = step_advance(&s, &err);
  }
  clock_gettime(CLOCK_MONOTONIC, &t1);
  out->secs = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
  if (!rc) {
    out->n = s.p.n;
    for (size_t i = 0; i < s.p.n; i++) {
      const double m = s.p.m[i], vx = s.p.v[0][i], vy = s.p.v[1][i], vz = s.p.v[2][i];
      out->px += m * vx;
      out->ekin += 0.5 * m * (vx * vx + vy * vy + vz * vz);
      out->eint += m * s.p.e[i];
    }
    const struct meas_geom g = {.body = 1,
                                .x0 = 0.0,
                                .thickness = 1e-3,
                                .yc = 0.0,
                                .spacing = QM_SPACING,
                                .half_model = s.bnd.half_model,
                                .quarter_model = s.bnd.quarter_model};
    struct meas_plate_params pp;
    meas_plate_defaults(&pp, &g);
    struct meas_debris_params dp;
    meas_debris_defaults(&dp, &g);
    dp.body = -1;      /* the cloud: the ball's and the plate's debris */
    dp.x_limit = 4e-3; /* up to the wall */
    const struct meas_geom gw = {.body = 2,
                                 .x0 = 4e-3,
                                 .thickness = 1e-3,
                                 .yc = 0.0,
                                 .spacing = QM_SPACING,
                                 .half_model = s.bnd.half_model,
                                 .quarter_model = s.bnd.quarter_model};
    struct meas_backwall_params bp;
    meas_backwall_defaults(&bp, &gw);
    rc = measure_plate(&s.p, &g, &pp, &out->plate, &err) ||
         measure_debris(&s.p, &dp, &out->cloud, &err) ||
         measure_backwall(&s.p, &gw, &bp, &out->wall, &err);
    struct fof_params fp = {.b = FOF_B_FACTOR * QM_SPACING,
                            .nmat = s.nmat,
                            .half_model = s.bnd.half_model,
                            .quarter_model = s.bnd.quarter_model};
    struct fof_result fr;
    fof_result_init(&fr);
    if (!rc) rc = fof_find(&s.p, &fp, &fr, &err);
    if (!rc) {
      out->frag_n = fr.n_full;
      out->frag_multi = fof_count_min(&fr, 2);
      out->frag_m1 = fr.nfrag ? fr.frag[0].m : 0.0;
    }
    fof_result_free(&fr);
  }
  if (rc) printf("  the %s model failed: %s\n", model == 1 ? "half" : "quarter", err.msg);
  sim_free(&s);
  if (c) cfg_free(c);
  return rc;
}

static void compare(const char *what, double half, double quarter, double scale, double tol)
{
  const double d = fabs(half - quarter) / scale;
  CHECK(d <= tol, "%s: half %.10g, quarter %.10g (relative difference %.1e, tolerance %.0e)", what,
        half, quarter, d, tol);
}

static void test_impact(void)
{
  struct result h, q;
  const int rh = run_model(1, &h), rq = run_model(2, &q);
  CHECK(rh == 0 && rq == 0, "half and quarter ran to %g us", 1e6 * QM_T_END);
  if (rh || rq) return;
  printf("  half model: %zu particles, %.1f s; quarter: %zu particles, %.1f s (1 run each)\n", h.n,
         h.secs, q.n, q.secs);
  CHECK(h.n == 2 * q.n, "particles: half %zu = 2 x quarter %zu", h.n, q.n);
  CHECK(h.plate.perforated && q.plate.perforated && h.cloud.count > 0,
        "the plate is perforated and a cloud is behind it (half %d, quarter %d, %zu particles)",
        h.plate.perforated, q.plate.perforated, h.cloud.count);
  const double p0 = fabs(2.0 * h.px), e0 = 2.0 * (h.ekin + h.eint);
  compare("x-momentum x 2 | x 4", 2.0 * h.px, 4.0 * q.px, p0, QM_SUM_TOL);
  compare("kinetic energy x 2 | x 4", 2.0 * h.ekin, 4.0 * q.ekin, e0, QM_SUM_TOL);
  compare("internal energy x 2 | x 4", 2.0 * h.eint, 4.0 * q.eint, e0, QM_SUM_TOL);
  compare("hole diameter (largest circle)", h.plate.d_circle, q.plate.d_circle, h.plate.d_circle,
          QM_MEAS_TOL);
  compare("hole diameter (equivalent area)", h.plate.d_equiv, q.plate.d_equiv, h.plate.d_equiv,
          QM_MEAS_TOL);
  compare("cloud mass (full picture)", h.cloud.m, q.cloud.m, h.cloud.m, QM_MEAS_TOL);
  compare("cloud mean velocity", h.cloud.v_mean, q.cloud.v_mean, fabs(h.cloud.v_mean), QM_MEAS_TOL);
  compare("cloud leading-edge velocity", h.cloud.v_lead, q.cloud.v_lead, fabs(h.cloud.v_lead),
          QM_MEAS_TOL);
  CHECK(h.wall.crater_depth > QM_SPACING, "the wall is cratered (%.3g mm)",
        1e3 * h.wall.crater_depth);
  compare("wall crater depth", h.wall.crater_depth, q.wall.crater_depth, h.wall.crater_depth,
          QM_MEAS_TOL);
  compare("wall local crater depth", h.wall.crater_depth_local, q.wall.crater_depth_local,
          h.wall.crater_depth, QM_MEAS_TOL);
  compare("wall crater radius", h.wall.r_crater, q.wall.r_crater, h.wall.r_crater, QM_MEAS_TOL);
  compare("wall damage radius", h.wall.r_damage, q.wall.r_damage, h.wall.r_damage, QM_MEAS_TOL);
  compare("wall damaged mass", h.wall.m_damaged, q.wall.m_damaged, h.wall.m_damaged, QM_MEAS_TOL);
  CHECK(h.frag_n == q.frag_n && h.frag_multi == q.frag_multi && h.frag_multi > 0,
        "fragments of the full picture: half %zu (%zu of >= 2 particles), quarter %zu (%zu)",
        h.frag_n, h.frag_multi, q.frag_n, q.frag_multi);
  compare("largest fragment's mass", h.frag_m1, q.frag_m1, h.frag_m1, QM_MEAS_TOL);
}

int main(void)
{
  test_lattice();
  test_impact();
  return test_finish();
}
