/* test_measure_cloud.c — debris cloud, gas shock front, backwall craters and damage,
 * and the pressure at the backwall's centre, on constructed particle sets with known
 * answers.
 *
 * Cloud: 100 equal particles behind a plate on rays of known angle θ_k = 0.4° (k + 1)
 * from the axis and known velocities v_k = 1000 + 10 k m/s: mass mean 1495 m/s, the 99 %
 * quantile 1980 m/s, the 90 % cone 36°; particles in front of the margin or beyond the
 * next plate, and particles of other bodies, do not count.
 * Front: a bubble and a ring of rim ejecta: the cone over the cloud's front leaves the
 * ring out (27° against 63.4°).
 * Gas: a lattice at density ρ₀ (with 2 % noise) compressed to 2 ρ₀ inside a hemisphere of
 * radius R about the entry point: the front is found at R within one spacing, axially,
 * radially and in distance.
 * Backwall: two flat-bottomed craters of known depth, damage inside a known radius: the
 * deepest crater and the damaged radius within one spacing; a bulge adds to the depth, a
 * drift of the whole wall does not (wall_shift); below its own surroundings
 * (crater_depth_local) the crater reads 4.4Δ on the flat, moved and bulged wall alike;
 * spall behind a hole is not wall (no crater; 11.5Δ if every particle were taken); an
 * intact wall of six layers whose rear layer's edge row lies 0.3Δ further out than the
 * others reads no crater (its rim's columns are not read: 5Δ with them, the rear layer
 * alone within tol of the outermost column).
 * Pressure: layers of known pressure at the front face; through a case file, the
 * averaging disc and depth of `measure.pressure_radius` / `pressure_depth` (default 2Δ
 * each), and both refused without a backwall.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "config/config.h"
#include "core/error.h"
#include "diag/measure.h"
#include "particles/particles.h"
#include "run/measure_run.h"
#include "run/run.h"
#include "sim/sim.h"
#include "testlib.h"
#include "testparticles.h"

static const double S = 1e-3; /* [m] lattice spacing Δ */
static const double DEG = HV_MEAS_PI / 180.0;

static size_t add_particle(struct particles *p, double x, double y, double z, double m, int body)
{
  return tp_add(p, x, y, z, m, 1.2 * S, 1.0, body);
}

static void test_debris(void)
{
  struct particles p;
  particles_init(&p);
  const double x0 = 0.02, th = 2 * S, yc = 0.005, xr = x0 + th;
  for (int k = 0; k < 100; k++) { /* spread over azimuths in z >= 0, at 10 to 40 mm */
    const double th_k = 0.4 * (k + 1) * DEG, phi = HV_MEAS_PI * (k % 10) / 9.0;
    const double d = 0.01 + 0.0003 * ((k * 37) % 100);
    const size_t i = add_particle(&p, xr + d * cos(th_k), yc + d * sin(th_k) * cos(phi),
                                  d * sin(th_k) * sin(phi), 1e-4, k % 2 ? 1 : 2);
    p.v[0][i] = 1000.0 + 10.0 * k;
    p.v[1][i] = 300.0;
  }
  const size_t n_cloud = p.n;
  /* not cloud: just behind the rear face (inside the margin), beyond the next plate, in front */
  size_t i = add_particle(&p, xr + 0.5 * S, yc, 0.01, 1.0, 1);
  p.v[0][i] = 9000.0;
  i = add_particle(&p, 0.5, yc, 0.0, 1.0, 1);
  p.v[0][i] = 9000.0;
  i = add_particle(&p, x0 - 0.01, yc, 0.0, 1.0, 1);
  p.v[0][i] = -9000.0;
  struct meas_geom g = {
      .body = 0, .x0 = x0, .thickness = th, .yc = yc, .spacing = S, .half_model = 1};
  struct meas_debris_params par;
  meas_debris_defaults(&par, &g);
  par.x_limit = 0.3; /* the next plate's front face */
  struct meas_debris r;
  struct hv_error err;
  hv_error_clear(&err);
  CHECK(measure_debris(&p, &par, &r, &err) == 0, "debris measurement runs: %s", err.msg);
  CHECK(r.count == n_cloud, "cloud: %zu particles (%zu)", r.count, n_cloud);
  CHECK_CLOSE(r.m, 2 * 100 * 1e-4, 1e-15, "cloud mass, mirrored (half model)");
  CHECK_CLOSE(r.v_mean, 1495.0, 1e-9, "mass-mean axial velocity");
  CHECK_CLOSE(r.v_lead, 1980.0, 0.0, "leading edge: 99 % mass quantile of v_x");
  CHECK_CLOSE(r.v_max, 1990.0, 0.0, "largest v_x");
  CHECK_CLOSE(r.half_angle / DEG, 36.0, 1e-9, "half spray angle: 90 % of the mass within 36°");
  CHECK(r.x_lead > 0.01 && r.x_lead < 0.04, "leading edge 10..40 mm behind the face (%.4g m)",
        r.x_lead);
  par.q_angle = 0.5;
  CHECK(measure_debris(&p, &par, &r, &err) == 0, "runs");
  CHECK_CLOSE(r.half_angle / DEG, 20.0, 1e-9, "half of the mass within 20°");
  par.q_angle = 0.9;
  par.body = 1; /* the odd ones only: k = 1, 3, ..., 99 */
  CHECK(measure_debris(&p, &par, &r, &err) == 0 && r.count == 50, "one body's cloud: 50");
  CHECK_CLOSE(r.v_mean, 1500.0, 1e-9, "its mean velocity");
  par.body = -1;
  par.x_limit = INFINITY;
  CHECK(measure_debris(&p, &par, &r, &err) == 0 && r.count == n_cloud + 1,
        "without x_limit the "
        "particle beyond the next plate joins");
  par.x_rear = xr + 1.0;
  CHECK(measure_debris(&p, &par, &r, &err) == 0 && r.count == 0 && isnan(r.v_mean) && r.m == 0,
        "empty cloud: count 0, NaN velocities");
  par.q_lead = 1.5;
  hv_error_clear(&err);
  CHECK(measure_debris(&p, &par, &r, &err) == -1 && err.code == HV_EXIT_INPUT,
        "quantile 1.5: an error (%s)", err.msg);
  particles_free(&p);
}

/* A bubble and the ejecta of the hole's rim: ten particles of 7 mass units 20 mm behind
 * the rear face at 3°, 6°, ..., 30° from the axis, and a ring of 30 units 2 mm behind it
 * at 4 mm from the axis (63.4°). The cone of 90 % of the mass takes in the ring (63.4°);
 * the front (beyond half the leading-edge distance, 20 mm) is the ten particles alone,
 * whose 90 % cone is 27°. */
static void test_debris_front(void)
{
  struct particles p;
  particles_init(&p);
  const double x0 = 0.0, th = 2 * S, xr = x0 + th;
  for (int k = 1; k <= 10; k++) {
    const double a = 3.0 * k * DEG, phi = HV_MEAS_PI * (k % 4) / 6.0;
    add_particle(&p, xr + 0.02, 0.02 * tan(a) * cos(phi), 0.02 * tan(a) * sin(phi), 7.0, 1);
  }
  for (int k = 0; k < 6; k++) {
    const double phi = HV_MEAS_PI * k / 5.0;
    add_particle(&p, xr + 0.002, 0.004 * cos(phi), 0.004 * sin(phi), 5.0, 1);
  }
  struct meas_geom g = {
      .body = 0, .x0 = x0, .thickness = th, .yc = 0.0, .spacing = S, .half_model = 1};
  struct meas_debris_params par;
  meas_debris_defaults(&par, &g);
  par.margin = 0.001;
  struct meas_debris r;
  struct hv_error err;
  hv_error_clear(&err);
  CHECK(measure_debris(&p, &par, &r, &err) == 0 && r.count == 16, "front cloud: 16 particles");
  CHECK_CLOSE(r.x_lead, 0.02, 1e-15, "leading edge 20 mm behind the face");
  CHECK_CLOSE(r.half_angle / DEG, atan2(4.0, 2.0) / DEG, 1e-9,
              "90 % cone over the whole cloud takes in the rim's ring (63.4°)");
  CHECK_CLOSE(r.half_angle_front / DEG, 27.0, 1e-9,
              "90 % cone over the front (x >= x_lead/2): 27°");
  par.front_fraction = 0.0;
  CHECK(measure_debris(&p, &par, &r, &err) == 0 && fabs(r.half_angle_front - r.half_angle) < 1e-15,
        "front fraction 0: the whole cloud");
  par.front_fraction = 1.0;
  hv_error_clear(&err);
  CHECK(measure_debris(&p, &par, &r, &err) == -1 && err.code == HV_EXIT_INPUT,
        "front fraction 1: an error (%s)", err.msg);
  particles_free(&p);
}

static void test_gas(void)
{
  struct particles p;
  particles_init(&p);
  const double rho0 = 13.125, R = 23.7 * S, o[3] = {0.0015, 0.0, 0.0};
  uint64_t s = 12345;
  for (int k = 0; k < 40; k++)
    for (int j = -40; j < 40; j++)
      for (int i = 0; i < 45; i++) {
        const double x = o[0] + (i + 0.5) * S, y = (j + 0.5) * S, z = (k + 0.5) * S;
        const size_t q = add_particle(&p, x, y, z, 1e-9, 3);
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        const double noise = 0.02 * ((double)(s >> 11) / 9007199254740992.0 - 0.5);
        const double r = sqrt((x - o[0]) * (x - o[0]) + y * y + z * z);
        p.rho[q] = (r < R ? 2.0 : 1.0 + noise) * rho0;
      }
  const double far[3] = {0.1, 0.0, 0.0};
  add_particle(&p, far[0], far[1], far[2], 1.0, 0); /* a dense metal particle: not gas */
  p.rho[p.n - 1] = 2700;
  struct meas_gas_params par;
  meas_gas_defaults(&par, 3, rho0, o, S);
  struct meas_gas_front r;
  struct hv_error err;
  hv_error_clear(&err);
  CHECK(measure_gas_front(&p, &par, &r, &err) == 0, "gas front measurement runs: %s", err.msg);
  CHECK(r.n_shocked > 1000, "shocked particles: %zu", r.n_shocked);
  CHECK(fabs(r.x_axial - R) <= S, "axial front %.3fΔ at R = %.1fΔ within Δ", r.x_axial / S, R / S);
  CHECK(fabs(r.r_radial - R) <= S, "radial front %.3fΔ within Δ", r.r_radial / S);
  CHECK(fabs(r.r_max - R) <= S, "front distance %.3fΔ within Δ", r.r_max / S);
  /* the shocked hemisphere with its core on the axis at rest: shocked gas, none within
     r_axis (2Δ) of the axis — the axial front is undefined, not 0 */
  for (size_t q = 0; q + 1 < p.n; q++)
    if (hypot(p.x[1][q], p.x[2][q]) <= 3.0 * S) p.rho[q] = rho0;
  CHECK(measure_gas_front(&p, &par, &r, &err) == 0 && r.n_shocked > 1000 && isnan(r.x_axial) &&
            fabs(r.r_radial - R) <= S,
        "nothing shocked on the axis: axial front NaN (%g), radial %.3fΔ, %zu shocked", r.x_axial,
        r.r_radial / S, r.n_shocked);
  par.factor = 2.5;
  CHECK(measure_gas_front(&p, &par, &r, &err) == 0 && r.n_shocked == 0 && r.r_max == 0 &&
            r.x_axial == 0,
        "factor 2.5: nothing shocked, all 0");
  par.factor = 1.1;
  par.rho_ref = 0;
  hv_error_clear(&err);
  CHECK(measure_gas_front(&p, &par, &r, &err) == -1 && err.code == HV_EXIT_INPUT,
        "rho_ref 0: an error");
  particles_free(&p);
}

/* A backwall 8Δ thick at x0 = 0.2 m, |y| <= 30Δ, 0 <= z <= 30Δ (half model), with two
 * flat-bottomed cylindrical craters: depth 4.4Δ radius 3.2Δ at the centre, depth 2.3Δ
 * radius 3.2Δ at y = 20Δ. Damage 1 within ρ < 15.5Δ, plastic strain 0.3 at ρ in
 * [18.2Δ, 19Δ). */
static void backwall(struct particles *p, double shift)
{
  const double x0 = 0.2;
  particles_enable_solid(p);
  for (int k = 0; k < 30; k++)
    for (int j = -30; j < 30; j++)
      for (int i = 0; i < 8; i++) {
        const double x = x0 + (i + 0.5) * S, y = (j + 0.5) * S, z = (k + 0.5) * S;
        const double r1 = hypot(y, z), r2 = hypot(y - 20 * S, z);
        if (r1 < 3.2 * S && x < x0 + 4.4 * S) continue;
        if (r2 < 3.2 * S && x < x0 + 2.3 * S) continue;
        const size_t q = add_particle(p, x + shift, y, z, 1e-6, 4);
        if (r1 < 15.5 * S) p->damage[q] = 1.0;
        if (r1 >= 18.2 * S && r1 < 19 * S) p->eps_p[q] = 0.3;
      }
}

static void test_backwall(void)
{
  struct particles p;
  particles_init(&p);
  backwall(&p, 0.0);
  const double x0 = 0.2;
  struct meas_geom g = {
      .body = 4, .x0 = x0, .thickness = 8 * S, .yc = 0.0, .spacing = S, .half_model = 1};
  struct meas_backwall_params par;
  meas_backwall_defaults(&par, &g);
  struct meas_backwall r;
  struct hv_error err;
  hv_error_clear(&err);
  CHECK(measure_backwall(&p, &g, &par, &r, &err) == 0, "backwall measurement runs: %s", err.msg);
  CHECK(fabs(r.crater_depth - 4.4 * S) <= S, "deepest crater 4.4Δ: %.3fΔ within Δ",
        r.crater_depth / S);
  CHECK(hypot(r.crater_pos[0], r.crater_pos[1]) < 3.2 * S, "... at the centre (%.2fΔ, %.2fΔ)",
        r.crater_pos[0] / S, r.crater_pos[1] / S);
  /* below its own surroundings (the ring 4Δ..8Δ around it, beyond the crater's 3.2Δ):
     the same 4.4Δ on a flat wall */
  CHECK(fabs(r.crater_depth_local - 4.4 * S) <= S && fabs(r.crater_local_ref) <= 0.5 * S &&
            hypot(r.crater_local_pos[0], r.crater_local_pos[1]) < 3.2 * S,
        "local crater depth 4.4Δ: %.3fΔ within Δ, its surroundings at %.3fΔ, at (%.2fΔ, %.2fΔ)",
        r.crater_depth_local / S, r.crater_local_ref / S, r.crater_local_pos[0] / S,
        r.crater_local_pos[1] / S);
  CHECK(r.r_crater > 20 * S && r.r_crater < 23.2 * S,
        "cratered area reaches the second crater "
        "(r_crater %.2fΔ)",
        r.r_crater / S);
  CHECK(fabs(r.r_damage_particles - 19 * S) <= S, "damaged particles out to 19Δ: %.3fΔ",
        r.r_damage_particles / S);
  /* the damaged area: the disc of damage to 15.5Δ; the plastic ring at 18.2..19Δ lies
     beyond an undamaged gap of 2.7Δ and is not part of it */
  CHECK(r.r_damage >= 14.5 * S && r.r_damage <= 15.5 * S + par.ring,
        "damaged area: the disc to 15.5Δ, not the separate plastic ring: r_damage %.2fΔ "
        "(ring %.1fΔ)",
        r.r_damage / S, par.ring / S);
  CHECK(r.n_damaged > 0 && fabs(r.m_damaged - 2e-6 * (double)r.n_damaged) < 1e-9 * r.m_damaged,
        "damaged mass mirrored: %zu particles", r.n_damaged);
  par.eps_p_min = 0.5;
  CHECK(measure_backwall(&p, &g, &par, &r, &err) == 0 && fabs(r.r_damage_particles - 15.5 * S) <= S,
        "plastic strain below the threshold: damage radius 15.5Δ (%.3fΔ)",
        r.r_damage_particles / S);
  CHECK(r.r_damage >= 14.5 * S && r.r_damage <= 15.5 * S + par.ring,
        "... and the damaged area ends at 15.5Δ: r_damage %.2fΔ", r.r_damage / S);
  /* ejecta flying back out in front of the wall are not wall */
  const size_t e = add_particle(&p, x0 - 0.05, 0.0, 0.5 * S, 1e-6, 4);
  p.damage[e] = 1.0;
  p.x[1][e] = 28 * S;
  CHECK(measure_backwall(&p, &g, &par, &r, &err) == 0 && fabs(r.crater_depth - 4.4 * S) <= S &&
            r.r_damage_particles < 16.5 * S,
        "ejecta beyond margin_front are ignored");
  /* scattered damage outside the disc (through the thickness at 1 lattice site (y, z) in
     7 beyond 16Δ, as plate edges at a rigid wall give; each marks the columns within
     tol = Δ, so about 1 − (6/7)^π = 38 % of the columns): the extent of damage reaches
     the edge, the damaged area does not */
  for (size_t i = 0; i < p.n; i++) {
    const long a = lround(p.x[1][i] / S - 0.5), b = lround(p.x[2][i] / S - 0.5);
    if (hypot(p.x[1][i], p.x[2][i]) > 16 * S && ((3 * a + 5 * b) % 7 + 7) % 7 == 0)
      p.damage[i] = 1.0;
  }
  int rc = measure_backwall(&p, &g, &par, &r, &err);
  CHECK(rc == 0 && r.r_damage_particles > 29 * S && r.r_damage >= 14.5 * S &&
            r.r_damage <= 15.5 * S + par.ring,
        "scattered damage: extent %.2fΔ, damaged area still %.2fΔ", r.r_damage_particles / S,
        r.r_damage / S);
  par.area_fraction = 0.25; /* the scattered damage now counts as an area */
  rc = measure_backwall(&p, &g, &par, &r, &err);
  CHECK(rc == 0 && r.r_damage > 29 * S,
        "... unless area_fraction is lowered below its share: %.2fΔ", r.r_damage / S);
  par.area_fraction = 0.5;
  CHECK(fabs(r.wall_shift) <= 1e-12, "the wall in place: wall_shift %gΔ", r.wall_shift / S);
  particles_free(&p);

  /* the whole wall moved back by 2Δ (a free wall drifting with the momentum it took): the
     wall far from the impact moved with it, the craters are as deep as before; from the
     original face (far_reference 0) the depth grows by 2Δ */
  particles_init(&p);
  backwall(&p, 2 * S);
  meas_backwall_defaults(&par, &g);
  CHECK(measure_backwall(&p, &g, &par, &r, &err) == 0 && fabs(r.wall_shift - 2 * S) <= 1e-12 &&
            fabs(r.crater_depth - 4.4 * S) <= S,
        "moved wall: wall_shift %.3fΔ (2Δ), depth from the far wall %.3fΔ (4.4Δ within Δ)",
        r.wall_shift / S, r.crater_depth / S);
  CHECK(fabs(r.crater_depth_local - 4.4 * S) <= S && fabs(r.crater_local_ref) <= 0.5 * S,
        "... below its surroundings %.3fΔ (4.4Δ within Δ), they at %.3fΔ", r.crater_depth_local / S,
        r.crater_local_ref / S);
  /* splash joined to the moved wall (two layers 0.8Δ and 2Δ before its face, linked to
     it and to each other within the friends-of-friends link of 1.5Δ) over the whole
     ring 4Δ..8Δ: not the surface a gauge rests on, the crater still 4.4Δ below its
     surroundings (taken with the splash it reads 6.5Δ) */
  {
    const size_t n0 = p.n;
    for (int k = 0; k < 9; k++)
      for (int j = -9; j < 9; j++) {
        const double y = (j + 0.5) * S, z = (k + 0.5) * S, rho = hypot(y, z);
        if (rho >= 3.5 * S && rho <= 8.5 * S) {
          add_particle(&p, x0 + 1.2 * S, y, z, 1e-6, 4);
          add_particle(&p, x0, y, z, 1e-6, 4);
        }
      }
    CHECK(p.n > n0 + 50 && measure_backwall(&p, &g, &par, &r, &err) == 0 &&
              fabs(r.crater_depth_local - 4.4 * S) <= S && fabs(r.crater_depth - 4.4 * S) <= S,
          "splash over the ring (%zu particles): below its surroundings %.3fΔ (4.4Δ within Δ), "
          "from the far wall %.3fΔ",
          p.n - n0, r.crater_depth_local / S, r.crater_depth / S);
    p.n = n0;
    measure_backwall(&p, &g, &par, &r, &err);
  }
  CHECK(r.r_damage >= 14.5 * S && r.r_damage <= 15.5 * S + par.ring,
        "... its damaged area as before: r_damage %.2fΔ", r.r_damage / S);
  par.far_reference = 0;
  CHECK(measure_backwall(&p, &g, &par, &r, &err) == 0 && fabs(r.wall_shift) <= 1e-12 &&
            fabs(r.crater_depth - 6.4 * S) <= S,
        "... from the original face %.3fΔ (6.4Δ within Δ)", r.crater_depth / S);
  particles_free(&p);

  /* a bulge: the wall within ρ < 12Δ of the axis pushed back by 2Δ, the rest in place:
     the far wall has not moved, the bulge adds to the depth */
  particles_init(&p);
  backwall(&p, 0.0);
  for (size_t i = 0; i < p.n; i++)
    if (hypot(p.x[1][i], p.x[2][i]) < 12 * S) p.x[0][i] += 2 * S;
  meas_backwall_defaults(&par, &g);
  CHECK(measure_backwall(&p, &g, &par, &r, &err) == 0 && fabs(r.wall_shift) <= 1e-12 &&
            fabs(r.crater_depth - 6.4 * S) <= S,
        "bulged wall: wall_shift %gΔ, depth %.3fΔ (6.4Δ within Δ)", r.wall_shift / S,
        r.crater_depth / S);
  /* the crater's surroundings (4Δ..8Δ) lie on the bulge: below them it is 4.4Δ deep, and
     they are 2Δ back */
  CHECK(fabs(r.crater_depth_local - 4.4 * S) <= S && fabs(r.crater_local_ref - 2 * S) <= 0.5 * S,
        "... below its surroundings %.3fΔ (4.4Δ within Δ), they at %.3fΔ (2Δ)",
        r.crater_depth_local / S, r.crater_local_ref / S);
  /* a ring beyond the bulge (13Δ..18Δ) takes the bulge in again: 6.4Δ */
  par.local_inner = 13 * S;
  par.local_outer = 18 * S;
  CHECK(measure_backwall(&p, &g, &par, &r, &err) == 0 &&
            fabs(r.crater_depth_local - 6.4 * S) <= S && fabs(r.crater_local_ref) <= 0.5 * S,
        "... with a ring beyond the bulge %.3fΔ (6.4Δ within Δ)", r.crater_depth_local / S);
  par.local_outer = S;
  hv_error_clear(&err);
  CHECK(measure_backwall(&p, &g, &par, &r, &err) == -1 && err.code == HV_EXIT_INPUT,
        "local_outer <= local_inner: an error");
  meas_backwall_defaults(&par, &g);
  par.far_fraction = 0.0;
  hv_error_clear(&err);
  CHECK(measure_backwall(&p, &g, &par, &r, &err) == -1 && err.code == HV_EXIT_INPUT,
        "far_fraction 0: an error");
  particles_free(&p);

  /* a wall perforated by a hole of radius 5Δ, no other damage: the hole is the area */
  particles_init(&p);
  for (int k = 0; k < 20; k++)
    for (int j = -20; j < 20; j++)
      for (int i = 0; i < 4; i++) {
        const double y = (j + 0.5) * S, z = (k + 0.5) * S;
        if (hypot(y, z) < 5 * S) continue;
        add_particle(&p, x0 + (i + 0.5) * S, y, z, 1e-6, 4);
      }
  meas_backwall_defaults(&par, &g);
  rc = measure_backwall(&p, &g, &par, &r, &err);
  CHECK(rc == 0 && r.r_damage >= 4 * S - 1e-12 && r.r_damage <= 5 * S + par.ring &&
            r.crater_depth < 1e-12,
        "perforated wall: the hole is the damaged area (%.2fΔ for radius 5Δ)", r.r_damage / S);
  /* spall behind the hole: a detached cluster of 3 x 3 x 2 particles 12Δ behind the face
     on the axis is not wall (attached_only, the default): the hole stays a hole, no
     crater; taking every particle, the cluster would read as a crater 11.5Δ deep */
  for (int k = 0; k < 3; k++)
    for (int j = -1; j < 2; j++)
      for (int i = 0; i < 2; i++)
        add_particle(&p, x0 + (12 + i) * S, (j + 0.5) * S, (k + 0.5) * S, 1e-6, 4);
  rc = measure_backwall(&p, &g, &par, &r, &err);
  CHECK(rc == 0 && r.crater_depth < 1e-12 && r.r_damage >= 4 * S - 1e-12 &&
            r.r_damage <= 5 * S + par.ring,
        "spall behind the hole is not wall: depth %.3gΔ, damaged area %.2fΔ", r.crater_depth / S,
        r.r_damage / S);
  par.attached_only = 0;
  rc = measure_backwall(&p, &g, &par, &r, &err);
  CHECK(rc == 0 && fabs(r.crater_depth - 11.5 * S) < 1e-9,
        "... taking every particle, it reads as a crater %.3fΔ deep (11.5Δ)", r.crater_depth / S);
  par.attached_only = 1;
  par.ring = 0;
  CHECK(measure_backwall(&p, &g, &par, &r, &err) == -1 && err.code == HV_EXIT_INPUT,
        "ring 0: an error");
  meas_backwall_defaults(&par, &g);
  particles_free(&p);

  /* the rim: an intact half-model wall of six layers (|y| <= 15Δ, 0 <= z <= 15Δ) whose
     rear layer's edge row at y = 14.5Δ lies 0.3Δ further out (a plate's edge, where the
     layers do not move alike). The columns (cell Δ/2, from y = -15.5Δ) centred at y =
     15.75Δ lie within tol = Δ of that row (0.95Δ) and not of the other layers' (1.25Δ):
     read, their front is the rear layer's, a crater 5Δ deep at the rim. The columns
     beyond the inscribed radius of the particle centres less tol (14.5Δ − Δ) are not
     read: no crater, as the wall has none */
  particles_init(&p);
  for (int k = 0; k < 15; k++)
    for (int j = -15; j < 15; j++)
      for (int i = 0; i < 6; i++)
        add_particle(&p, x0 + (i + 0.5) * S, (j + 0.5 + (i == 5 && j == 14 ? 0.3 : 0.0)) * S,
                     (k + 0.5) * S, 1e-6, 4);
  meas_backwall_defaults(&par, &g);
  CHECK(measure_backwall(&p, &g, &par, &r, &err) == 0 && r.crater_depth < 1e-12 &&
            r.crater_depth_local < 1e-12 && r.r_crater == 0.0 && fabs(r.wall_shift) < 1e-12,
        "a wall's rim, one layer's edge 0.3Δ further out: no crater (depth %.3gΔ, below its "
        "surroundings %.3gΔ, crater radius %.3gΔ; the rim read: 5Δ at 21.6Δ)",
        r.crater_depth / S, r.crater_depth_local / S, r.r_crater / S);
  particles_free(&p);

  /* an intact wall: no crater, no damage, no solid fields needed */
  particles_init(&p);
  for (int k = 0; k < 10; k++)
    for (int j = -10; j < 10; j++)
      for (int i = 0; i < 4; i++)
        add_particle(&p, x0 + (i + 0.5) * S, (j + 0.5) * S, (k + 0.5) * S, 1e-6, 4);
  CHECK(measure_backwall(&p, &g, &par, &r, &err) == 0 && r.crater_depth < 1e-12 &&
            r.r_damage == 0 && r.n_damaged == 0 && r.n_wall == p.n,
        "intact wall without solid fields: depth %.3gΔ, no damage", r.crater_depth / S);

  /* pressure at the centre: 1 GPa in the first layer within 2Δ, 0.5 GPa below */
  for (size_t i = 0; i < p.n; i++) p.p[i] = p.x[0][i] < x0 + S ? 1e9 : 5e8;
  size_t cnt = 0;
  double pc = measure_center_pressure(&p, &g, 2 * S, 0.6 * S, NULL, &cnt);
  CHECK_CLOSE(pc, 1e9, 1e-3, "centre pressure over the first layer");
  CHECK(cnt == 6, "particles within 2Δ of the axis in the first layer: %zu", cnt);
  pc = measure_center_pressure(&p, &g, 2 * S, 1.2 * S, NULL, &cnt);
  CHECK_CLOSE(pc, 7.5e8, 1e-3, "two layers: the mean");
  pc = measure_center_pressure(&p, &g, 2 * S, 1.2 * S, NULL, NULL);
  CHECK_CLOSE(pc, 7.5e8, 1e-3, "count may be NULL");
  struct meas_geom far = g;
  far.yc = 1.0;
  CHECK(isnan(measure_center_pressure(&p, &far, 2 * S, S, NULL, &cnt)) && cnt == 0,
        "no particle near the axis: NaN");
  particles_free(&p);
}

/* The backwall's peak centre pressure through a case file: a wall 2 mm thick of four
 * layers of 0.5 mm, 1 GPa in its first layer within 1.6 mm of the axis, 0 elsewhere.
 * measure_run_step averages over the configured disc and depth: by default (2Δ = 1 mm
 * each: columns within 1 mm, the layers x_f to x_f + 2Δ inclusive, three) 1/3 GPa; pressure_depth 0.3 mm (the first
 * layer) 1 GPa; pressure_radius 4 mm with it, the share of the first layer's particles
 * within 1.6 mm among those within 4 mm, about (1.6/4)² = 0.16. Without a backwall the
 * keys are refused (exit 2). */
static double gauge_pressure(const char *keys, int *rc, char *msg, size_t nmsg)
{
  char text[1024];
  snprintf(text, sizeof text,
           "name: gauge\n"
           "domain: {min: [-2 mm, -5 mm, 0], max: [4 mm, 5 mm, 5 mm], half_model: true}\n"
           "bodies:\n"
           "  - name: wall\n"
           "    material: al-alloy\n"
           "    shape: {type: box, min: [0, -5 mm, -5 mm], max: [2 mm, 5 mm, 5 mm]}\n"
           "    spacing: 0.5 mm\n"
           "time: {end: 0}\n"
           "measure: {%s}\n",
           keys);
  struct hv_error err;
  hv_error_clear(&err);
  struct sim s;
  struct measure_run mr;
  memset(&s, 0, sizeof s);
  memset(&mr, 0, sizeof mr);
  struct cfg *c = cfg_load_string(text, "gauge.yaml", &err);
  *rc = !c || run_setup(&s, c, &err) || measure_run_read(&mr, &s, c, &err) ? err.code : 0;
  snprintf(msg, nmsg, "%s", err.msg);
  double pc = NAN;
  if (!*rc) {
    for (size_t i = 0; i < s.p.n; i++)
      s.p.p[i] = s.p.x[0][i] < 0.5e-3 && hypot(s.p.x[1][i], s.p.x[2][i]) < 1.6e-3 ? 1e9 : 0.0;
    measure_run_step(&mr, &s);
    pc = mr.peak_pressure;
  }
  measure_run_free(&mr); /* a set-up that failed half way holds memory too */
  sim_free(&s);
  if (c) cfg_free(c);
  return pc;
}

static void test_gauge(void)
{
  int rc;
  char msg[2048];
  double pc = gauge_pressure("backwall: wall", &rc, msg, sizeof msg);
  CHECK(rc == 0 && fabs(pc - 1e9 / 3) < 1e-6 * 1e9,
        "default 2Δ disc and depth: %.6g Pa, 1/3 "
        "GPa (%s)",
        pc, rc ? msg : "ok");
  pc = gauge_pressure("backwall: wall, pressure_depth: 0.3 mm", &rc, msg, sizeof msg);
  CHECK(rc == 0 && fabs(pc - 1e9) < 1e-6 * 1e9,
        "pressure_depth 0.3 mm: the first layer, "
        "%.6g Pa (1 GPa)",
        pc);
  pc = gauge_pressure("backwall: wall, pressure_depth: 0.3 mm, pressure_radius: 4 mm", &rc, msg,
                      sizeof msg);
  CHECK(rc == 0 && fabs(pc / 1e9 - 0.16) < 0.25 * 0.16,
        "pressure_radius 4 mm: %.4g GPa, the "
        "area share (1.6/4)^2 = 0.16 within 25 %%",
        pc / 1e9);
  (void)gauge_pressure("pressure_radius: 4 mm", &rc, msg, sizeof msg);
  CHECK(rc == HV_EXIT_INPUT && strstr(msg, "gauge.yaml") && strstr(msg, "pressure_radius") &&
            strstr(msg, "no measure.backwall"),
        "no backwall: refused, exit 2 (%d): %s", rc, msg);
  (void)gauge_pressure("backwall: wall, pressure_depth: -1 mm", &rc, msg, sizeof msg);
  CHECK(rc == HV_EXIT_INPUT && strstr(msg, "pressure_depth"),
        "a negative depth: refused (%d): "
        "%s",
        rc, msg);
}

int main(void)
{
  test_gauge();
  test_debris();
  test_debris_front();
  test_gas();
  test_backwall();
  return test_finish();
}
