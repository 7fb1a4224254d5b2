/* test_measure_rz.c — the measurements on an axisymmetric run's rings (p->axisym;
 * src/diag/measure_rz.c and the RZ branches of measure.c), on constructed ring sets with
 * known answers. Spacing Δ = 1 mm; rings on the lattice x = (i + 1/2) Δ, r = (j + 1/2) Δ
 * (never on the axis), each of mass 2π r ρ Δ² (its true 3D mass), h = 1.3 Δ.
 *  - a thick target with a cylindrical cavity of radius 5Δ, 12Δ deep: L = 12 Δ and
 *    D = 10 Δ exactly (the first rings beyond it sit Δ/2 inside the material); the wall
 *    by filled volume within Δ/4 (its annuli) of 10 Δ, which needs a ring's cell edge
 *    to be its section's √(m / 2π r ρ) = Δ (a cube of the ring's volume, 3D's rule,
 *    would be 3.3 Δ at r = 5.5 Δ and smear the wall);
 *  - a plate with a hole of three rows (rings from r = 3.5 Δ): perforated, d_circle =
 *    d_equiv = 6 Δ exactly, area π (2.5 Δ)²; a loose ring left in the hole is not plate
 *    (attached_only), but is with attached_only off (not perforated then); an intact
 *    plate is not perforated;
 *  - a debris cloud of rings at two radii and two speeds: its mass and mass-mean axial
 *    velocity with ring masses exactly (a mean over rings would be 2385 m/s, not 1277);
 *  - fragments: friends-of-friends in the (x, r) plane, each fragment a set of rings
 *    with the sum of their masses, largest mass first (4 rings far out outweigh 9 on
 *    the axis), multiplicity 1;
 *  - through-wall: detached spall rings behind a wall, with the mass and velocity of
 *    the rings; the wall's own rings not;
 *  - a backwall with a crater 2Δ deep within 3Δ of the axis: the crater depth 2Δ
 *    (revolved rings), n_wall counting rings; the same crater in a wall of six layers to
 *    r = 29.5Δ whose rear layer's outermost ring lies 0.1Δ further out: still 2Δ within
 *    3Δ of the axis, not the rim's 5Δ at 30.5Δ (the RZ Whipple shield's 2.50 mm);
 *  - the run's shadow of a wall of rings 30Δ in radius (what went through is counted
 *    within it): 28Δ, not the one spacing that the 3D rule (the nearer edge across y,
 *    here the axis itself) would leave; and measure.axis_y off the axis refused in an RZ
 *    case (its file, line and key named), accepted in 3D;
 *  - `hvsph measure` of a 3D run one of whose snapshots says it is axisymmetric: refused
 *    (exit 2) naming the snapshot and the case's geometry, measurements.csv untouched.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "config/config.h"
#include "diag/fof.h"
#include "diag/measure.h"
#include "diag/through.h"
#include "particles/particles.h"
#include "run/measure_run.h"
#include "sim/sim.h"
#include "testlib.h"
#include "testparticles.h"

static const double D = 1e-3, RHO = 7850.0;

static size_t ring(struct particles *p, double x, double r, int body, double vx)
{
  const size_t i = tp_add(p, x, r, 0.0, 2.0 * HV_MEAS_PI * r * RHO * D * D, 1.3 * D, RHO, body);
  p->v[0][i] = vx;
  p->axisym = 1;
  return i;
}

static double ring_mass(double r) { return 2.0 * HV_MEAS_PI * r * RHO * D * D; }

static void test_cavity(void)
{
  struct particles p;
  particles_init(&p);
  for (int i = 0; i < 40; i++)
    for (int j = 0; j < 30; j++)
      if (i >= 12 || j >= 5) ring(&p, (i + 0.5) * D, (j + 0.5) * D, 0, 0.0);
  struct meas_geom g = {.body = 0, .x0 = 0.0, .thickness = 40 * D, .yc = 0.0, .spacing = D};
  struct meas_cavity_params cp;
  meas_cavity_defaults(&cp, &g);
  struct meas_cavity c;
  struct hv_error err;
  hv_error_clear(&err);
  CHECK(measure_cavity(&p, &g, &cp, &c, &err) == 0, "cavity of rings measured: %s", err.msg);
  CHECK(fabs(c.L - 12 * D) < 1e-12 && fabs(c.D - 10 * D) < 1e-12 && !c.perforated,
        "rings: L = %.4g mm (12), D = %.4g mm (10)", c.L * 1e3, c.D * 1e3);
  CHECK(c.nwall > 0 && fabs(c.D_wall - 10 * D) < 0.25 * D &&
            fabs(c.D_wall_mean - 10 * D) < 0.25 * D,
        "rings: the wall by filled volume %.4g mm (mean %.4g) within Δ/4 of 10 mm", c.D_wall * 1e3,
        c.D_wall_mean * 1e3);
  meas_cavity_free(&c);
  particles_free(&p);
}

static void plate(struct particles *p, int rows_out)
{
  for (int i = 0; i < 4; i++)
    for (int j = rows_out; j < 25; j++) ring(p, (i + 0.5) * D, (j + 0.5) * D, 1, 0.0);
}

static void test_plate(void)
{
  struct meas_geom g = {.body = 1, .x0 = 0.0, .thickness = 4 * D, .yc = 0.0, .spacing = D};
  struct meas_plate_params pp;
  meas_plate_defaults(&pp, &g);
  struct meas_plate h;
  struct hv_error err;
  hv_error_clear(&err);
  struct particles p;
  particles_init(&p);
  plate(&p, 0);
  CHECK(measure_plate(&p, &g, &pp, &h, &err) == 0 && !h.perforated && h.d_circle == 0.0 &&
            h.n_plate == 100,
        "an intact plate of rings: not perforated (%zu rings): %s", h.n_plate, err.msg);
  particles_free(&p);
  particles_init(&p);
  plate(&p, 3);
  CHECK(measure_plate(&p, &g, &pp, &h, &err) == 0 && h.perforated && !h.hole_open,
        "a plate of rings without its first three rows: perforated: %s", err.msg);
  CHECK(fabs(h.d_circle - 6 * D) < 1e-12 && fabs(h.d_equiv - 6 * D) < 1e-12 &&
            fabs(h.d_circle_impact - 6 * D) < 1e-12 &&
            fabs(h.area - HV_MEAS_PI * 6.25 * D * D) < 1e-15,
        "hole: d_circle %.4g mm, d_equiv %.4g mm (6), area %.4g mm2", h.d_circle * 1e3,
        h.d_equiv * 1e3, h.area * 1e6);
  ring(&p, 2.5 * D, 0.5 * D, 1, 0.0); /* a loose ring in the hole: 3 Δ from the plate */
  CHECK(measure_plate(&p, &g, &pp, &h, &err) == 0 && h.perforated &&
            fabs(h.d_circle - 6 * D) < 1e-12 && h.n_detached == 1,
        "a loose ring in the hole is not plate (%zu detached)", h.n_detached);
  pp.attached_only = 0;
  CHECK(measure_plate(&p, &g, &pp, &h, &err) == 0 && !h.perforated,
        "with attached_only off the loose ring closes the hole");
  g.yc = 1e-3;
  CHECK(measure_plate(&p, &g, &pp, &h, &err) != 0 && strstr(err.msg, "r = 0"),
        "an axis off r = 0 refused: %s", err.msg);
  particles_free(&p);
}

static void test_cloud_fragments(void)
{
  struct particles p;
  particles_init(&p);
  plate(&p, 3);
  /* behind the plate (rear face 4Δ; margin 2Δ): 9 rings near the axis at 3 km/s, 4 far
     out at 20.5-21.5 Δ at 1 km/s */
  double m = 0.0, mv = 0.0, mnear = 0.0, mfar = 0.0;
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) {
      ring(&p, (10.5 + i) * D, (j + 0.5) * D, 0, 3000.0);
      m += ring_mass((j + 0.5) * D);
      mv += 3000.0 * ring_mass((j + 0.5) * D);
      mnear += ring_mass((j + 0.5) * D);
    }
  for (int i = 0; i < 2; i++)
    for (int j = 0; j < 2; j++) {
      ring(&p, (10.5 + i) * D, (20.5 + j) * D, 0, 1000.0);
      m += ring_mass((20.5 + j) * D);
      mv += 1000.0 * ring_mass((20.5 + j) * D);
      mfar += ring_mass((20.5 + j) * D);
    }
  struct meas_geom g = {.body = 1, .x0 = 0.0, .thickness = 4 * D, .yc = 0.0, .spacing = D};
  struct meas_debris_params dp;
  meas_debris_defaults(&dp, &g);
  struct meas_debris c;
  struct hv_error err;
  hv_error_clear(&err);
  CHECK(measure_debris(&p, &dp, &c, &err) == 0 && c.count == 13, "cloud of 13 rings: %s", err.msg);
  CHECK(fabs(c.m / m - 1) < 1e-12 && fabs(c.v_mean - mv / m) < 1e-9 &&
            fabs(c.v_mean - 1000.0 - 2000.0 * mnear / m) < 1e-9,
        "cloud: mass %.6g kg, mean axial velocity %.6g m/s with ring masses", c.m, c.v_mean);

  unsigned char *mask = calloc(p.n, 1);
  for (size_t i = 0; i < p.n; i++) mask[i] = p.body[i] == 0;
  struct fof_params fp = {.b = FOF_B_FACTOR * D, .mask = mask, .nmat = 1};
  struct fof_result fr;
  fof_result_init(&fr);
  CHECK(fof_find(&p, &fp, &fr, &err) == 0 && fr.nfrag == 2, "fragments of rings: %zu", fr.nfrag);
  CHECK(fr.nfrag == 2 && fr.frag[0].count == 4 && fabs(fr.frag[0].m / mfar - 1) < 1e-12 &&
            fr.frag[1].count == 9 && fabs(fr.frag[1].m / mnear - 1) < 1e-12 &&
            fr.frag[0].multiplicity == 1 && fr.frag[1].multiplicity == 1 && fr.n_full == 2,
        "each fragment a set of rings with their summed mass, the heavier first "
        "(%.4g g of 4 rings, %.4g g of 9)",
        fr.nfrag ? fr.frag[0].m * 1e3 : 0.0, fr.nfrag > 1 ? fr.frag[1].m * 1e3 : 0.0);
  CHECK(fr.nfrag == 2 && fabs(fr.frag[0].v[0] - 1000.0) < 1e-9 &&
            fabs(fr.frag[0].x[1] - (20.5 * 20.5 + 21.5 * 21.5) / 42.0 * D) < 1e-12,
        "a ring fragment's y is its mass-mean radius (%.6g mm), v_x its axial velocity",
        fr.nfrag ? fr.frag[0].x[1] * 1e3 : 0.0);
  fof_result_free(&fr);
  free(mask);

  /* through the plate, taken as a wall: the rings behind it that move away */
  struct meas_through_params tp;
  meas_through_defaults(&tp, &g);
  struct meas_through t;
  CHECK(measure_through(&p, &g, &tp, &t, &err) == 0 && t.through && t.n == 13 &&
            fabs(t.mass / m - 1) < 1e-12 && fabs(t.velocity - mv / m) < 1e-9 && t.wall_mass == 0.0,
        "through: %zu rings, %.6g kg at %.6g m/s", t.n, t.mass, t.velocity);
  /* spall: two wall rings detached behind it */
  const size_t s0 = ring(&p, 8.5 * D, 10.5 * D, 1, 300.0),
               s1 = ring(&p, 8.5 * D, 11.5 * D, 1, 300.0);
  const double ms = p.m[s0] + p.m[s1];
  CHECK(measure_through(&p, &g, &tp, &t, &err) == 0 && t.n == 15 &&
            fabs(t.wall_mass / ms - 1) < 1e-12,
        "through: detached spall rings counted as wall mass (%.6g kg)", t.wall_mass);
  particles_free(&p);
}

static void test_backwall(void)
{
  struct particles p;
  particles_init(&p);
  size_t n = 0;
  for (int i = 0; i < 4; i++)
    for (int j = 0; j < 15; j++)
      if (i >= 2 || j >= 3) {
        ring(&p, (i + 0.5) * D, (j + 0.5) * D, 2, 0.0);
        n++;
      }
  struct meas_geom g = {.body = 2, .x0 = 0.0, .thickness = 4 * D, .yc = 0.0, .spacing = D};
  struct meas_backwall_params bp;
  meas_backwall_defaults(&bp, &g);
  struct meas_backwall b;
  struct hv_error err;
  hv_error_clear(&err);
  CHECK(measure_backwall(&p, &g, &bp, &b, &err) == 0, "backwall of rings measured: %s", err.msg);
  CHECK(fabs(b.crater_depth - 2 * D) < 1e-9 && b.n_wall == n && b.wall_shift == 0.0,
        "backwall of rings: crater depth %.4g mm (2), %zu rings of %zu", b.crater_depth * 1e3,
        b.n_wall, n);
  particles_free(&p);

  /* the disc's rim (the RZ Whipple sweep of 2026-12-07 at 5e03719 read 2.50 mm, the rear
     layer of six 0.5 mm ones, at 60.2 mm from the axis, its wall's rim, for a wall
     barely touched): six layers to r = 29.5Δ with the same crater, the rear layer's
     outermost ring 0.1Δ further out. Revolved, the columns just beyond 30.5Δ lie within
     tol = Δ of that ring's points and not of the other layers': read, a crater 5Δ deep
     there. Not read (beyond the inscribed radius less tol): the crater is the 2Δ one */
  particles_init(&p);
  for (int i = 0; i < 6; i++)
    for (int j = 0; j < 30; j++)
      if (i >= 2 || j >= 3)
        ring(&p, (i + 0.5) * D, (j + 0.5 + (i == 5 && j == 29 ? 0.1 : 0.0)) * D, 2, 0.0);
  g.thickness = 6 * D;
  meas_backwall_defaults(&bp, &g);
  CHECK(measure_backwall(&p, &g, &bp, &b, &err) == 0 && fabs(b.crater_depth - 2 * D) < 1e-9 &&
            b.r_crater < 3 * D && hypot(b.crater_pos[0], b.crater_pos[1]) < 3 * D,
        "a disc's rim, the rear layer's edge 0.1Δ further out: crater depth %.4g mm (2) at "
        "%.3g mm from the axis, crater radius %.3g mm (< 3)",
        b.crater_depth * 1e3, hypot(b.crater_pos[0], b.crater_pos[1]) * 1e3, b.r_crater * 1e3);
  particles_free(&p);
}

static void test_shadow(void)
{
  static struct sim s;
  particles_init(&s.p);
  s.nbody = 1;
  s.body[0] =
      (struct body_info){.spacing = D, .lo = {0, 0, -0.5 * D}, .hi = {4 * D, 30 * D, 0.5 * D}};
  const int b = 0;
  CHECK(fabs(measure_run_shadow(&s, &b, 1, 0.0, D) - D) < 1e-15, "3D reading: one spacing");
  /* 3D, a wall narrower across z than across y: the shadow is the nearer edge of both,
     less two spacings (across y alone, 28Δ: debris passing over the z edge counted as
     through) */
  s.body[0] =
      (struct body_info){.spacing = D, .lo = {0, -30 * D, 0}, .hi = {4 * D, 30 * D, 20 * D}};
  s.bnd.half_model = 1;
  CHECK(fabs(measure_run_shadow(&s, &b, 1, 0.0, D) - 18 * D) < 1e-15,
        "3D half model, wall to 30Δ across y and 20Δ across z: shadow %gΔ (18)",
        measure_run_shadow(&s, &b, 1, 0.0, D) / D);
  s.bnd.half_model = 0;
  s.body[0].lo[2] = -10 * D;
  CHECK(fabs(measure_run_shadow(&s, &b, 1, 0.0, D) - 8 * D) < 1e-15,
        "3D whole model, the wall from -10Δ to 20Δ across z: shadow %gΔ (8)",
        measure_run_shadow(&s, &b, 1, 0.0, D) / D);
  s.body[0] =
      (struct body_info){.spacing = D, .lo = {0, 0, -0.5 * D}, .hi = {4 * D, 30 * D, 0.5 * D}};
  s.p.axisym = 1;
  CHECK(fabs(measure_run_shadow(&s, &b, 1, 0.0, D) - 28 * D) < 1e-15,
        "RZ: the wall's shadow is its radius less two spacings (%g mm)",
        measure_run_shadow(&s, &b, 1, 0.0, D) * 1e3);
  struct hv_error err;
  hv_error_clear(&err);
  struct cfg *c = cfg_load_string("measure:\n  axis_y: 2 mm\n", "rz.yaml", &err);
  struct measure_run mr;
  CHECK(c && measure_run_read(&mr, &s, c, &err) != 0 && err.code == HV_EXIT_INPUT &&
            strstr(err.msg, "rz.yaml:2") && strstr(err.msg, "measure.axis_y"),
        "RZ: measure.axis_y off the axis refused: %s", err.msg);
  measure_run_free(&mr);
  s.p.axisym = 0;
  CHECK(measure_run_read(&mr, &s, c, &err) == 0 && mr.axis_y == 2e-3, "3D: measure.axis_y taken");
  measure_run_free(&mr);
  cfg_free(c);
}

static void test_measure_command(void)
{
  char dir[4200], casefile[4200], cmd[20000], out[8192], snap[4400], mcsv[4400];
  snprintf(dir, sizeof dir, "%s/run3d", test_tmpdir());
  snprintf(casefile, sizeof casefile, "%s/impact.yaml", test_tmpdir());
  const char *yaml = "name: impact\n"
                     "domain: {min: [-3 mm, -6 mm, -6 mm], max: [4 mm, 6 mm, 6 mm]}\n"
                     "bodies:\n"
                     "  - name: projectile\n"
                     "    material: al-alloy\n"
                     "    shape: {type: sphere, center: [-1.5 mm, 0, 0], radius: 1 mm}\n"
                     "    spacing: 0.25 mm\n"
                     "    velocity: [5 km/s, 0, 0]\n"
                     "  - name: backwall\n"
                     "    material: al-alloy\n"
                     "    shape: {type: box, min: [0, -5 mm, -5 mm], max: [2.52 mm, 5 mm, 5 mm]}\n"
                     "    spacing: 0.63 mm\n"
                     "time: {end: 0.2 us}\n"
                     "output: {every: 0.1 us, csv: true}\n"
                     "measure: {backwall: backwall}\n";
  FILE *f = fopen(casefile, "w");
  CHECK(f && fputs(yaml, f) >= 0 && fclose(f) == 0, "case written");
  snprintf(cmd, sizeof cmd, "rm -rf '%s' && '%s' run '%s' -o '%s' --quiet 2>&1", dir, test_bin(),
           casefile, dir);
  int rc = test_run(cmd, out, sizeof out);
  CHECK(rc == 0, "a small 3D run (exit %d): %s", rc, out);
  snprintf(snap, sizeof snap, "%s/particles_00001.csv", dir);
  snprintf(mcsv, sizeof mcsv, "%s/measurements.csv", dir);
  char *before = test_slurp(mcsv, NULL);
  /* marked axisymmetric, its points moved into the half-plane (|y|, z = 0), which the
     reader asks of rings: the case's geometry is then what refuses it */
  snprintf(cmd, sizeof cmd,
           "awk -F, -v OFS=, 'NR == 1 {print; print \"# geometry: axisymmetric\"; next} "
           "/^#/ || /^id/ {print; next} {if ($3 < 0) $3 = -$3; $4 = 0; print}' '%s' > '%s.tmp' "
           "&& mv '%s.tmp' '%s'",
           snap, snap, snap, snap);
  CHECK(test_run(cmd, NULL, 0) == 0, "snapshot 1 marked axisymmetric");
  snprintf(cmd, sizeof cmd, "'%s' measure '%s' 2>&1", test_bin(), dir);
  rc = test_run(cmd, out, sizeof out);
  CHECK(rc == 2 && strstr(out, "particles_00001.csv is axisymmetric") &&
            strstr(out, "domain.geometry"),
        "hvsph measure refuses an axisymmetric snapshot of a 3D case (exit %d): %s", rc, out);
  char *after = test_slurp(mcsv, NULL);
  CHECK(before && after && !strcmp(before, after), "measurements.csv left as it was");
  free(before);
  free(after);
}

int main(void)
{
  test_cavity();
  test_plate();
  test_cloud_fragments();
  test_backwall();
  test_shadow();
  char data[4200];
  snprintf(data, sizeof data, "%s/data", test_source_dir());
  setenv("HVSPH_DATA", data, 0);
  test_measure_command();
  return test_finish();
}
