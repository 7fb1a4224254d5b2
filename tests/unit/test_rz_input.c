/* test_rz_input.c — bad input of axisymmetric (RZ) cases (issue 74, item 7): each is
 * refused with exit status 2 and one message naming the file, the line and the key,
 * and nothing is written (the output folder is not even made).
 *
 * The base case is a small valid RZ impact (a copper cylinder on a copper plate, both
 * on the axis); each variant changes one thing:
 *   a sphere centred off the axis (it reaches r < 0)     shape, "off the axis"
 *   a cylinder off the axis                              shape, "off the axis"
 *   a cylinder not along x                               shape, "not the x axis"
 *   a box                                                shape, "use a cylinder"
 *   a velocity with a radial component                   velocity, "not along the axis"
 *   speed with an impact angle of 60 deg                 impact_angle
 *   speed with an obliquity of 30 deg                    obliquity
 *   half_model                                           domain.half_model
 *   a face across the axis (y_min, r_min)                domain.boundary.y_min / r_min
 *   a z face                                             domain.boundary.z_max
 *   domain.min with three components                     domain.min, "two components"
 *   domain.min with r ≠ 0                                domain.min, "r = 0"
 *   3D-only sph options (gradient correction, the viscosity switch, the artificial
 *   stress) and an hcp lattice                            each its key
 *   an energy deposit off the axis                       energy_deposit.center
 * The base case itself must run (to 1 us) and write its snapshots, so that each
 * refusal is the variant's.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "testlib.h"

static const char *const base =
    "name: rzbad\n"               /* 1 */
    "domain:\n"                   /* 2 */
    "  geometry: axisymmetric\n"  /* 3 */
    "  min: [-10 mm, 0]\n"        /* 4 */
    "  max: [10 mm, 10 mm]\n"     /* 5 */
    "  boundary: {x_max: wall}\n" /* 6 */
    "bodies:\n"                   /* 7 */
    "  - name: rod\n"             /* 8 */
    "    material: copper\n"      /* 9 */
    "    shape: {type: cylinder, center: [-2.1 mm, 0, 0], axis: [1, 0, 0], "
    "radius: 1 mm, length: 4 mm}\n"   /* 10 */
    "    spacing: 0.25 mm\n"          /* 11 */
    "    velocity: [500 m/s, 0, 0]\n" /* 12 */
    "  - name: plate\n"               /* 13 */
    "    material: copper\n"          /* 14 */
    "    shape: {type: cylinder, center: [1 mm, 0, 0], axis: [1, 0, 0], "
    "radius: 5 mm, length: 2 mm}\n"         /* 15 */
    "    spacing: 0.25 mm\n"                /* 16 */
    "time: {end: 1 us}\n"                   /* 17 */
    "output: {every: 0.5 us, csv: true}\n"; /* 18 */

/* base with `from` replaced by `to` (first occurrence), plus `extra` appended */
static const char *variant(const char *from, const char *to, const char *extra)
{
  static char buf[8192];
  const char *at = from ? strstr(base, from) : NULL;
  if (from && !at) {
    fprintf(stderr, "variant: '%s' not in the base case\n", from);
    exit(1);
  }
  if (at)
    snprintf(buf, sizeof buf, "%.*s%s%s%s", (int)(at - base), base, to, at + strlen(from),
             extra ? extra : "");
  else
    snprintf(buf, sizeof buf, "%s%s", base, extra ? extra : "");
  return buf;
}

static int exists(const char *path)
{
  struct stat st;
  return stat(path, &st) == 0;
}

int main(void)
{
  char out[8192], cmd[16384], dir[4200];
  const char *file = test_write_file("good.yaml", base);
  snprintf(dir, sizeof dir, "%s/out_good", test_tmpdir());
  snprintf(cmd, sizeof cmd, "'%s' run '%s' -o '%s' --overwrite --quiet --threads 1", test_bin(),
           file, dir);
  int rc = test_run(cmd, out, sizeof out);
  char snap[4400];
  snprintf(snap, sizeof snap, "%s/particles_00002.csv", dir);
  CHECK(rc == 0 && exists(snap), "the base RZ case runs (exit %d) and writes its snapshots\n%s", rc,
        out);

  test_refused_case(
      "sphere off the axis",
      variant("shape: {type: cylinder, center: [-2.1 mm, 0, 0], axis: [1, 0, 0], radius: 1 "
              "mm, length: 4 mm}",
              "shape: {type: sphere, center: [-2.1 mm, 0.5 mm, 0], radius: 1 mm}", NULL),
      10, "bodies[0].shape", "off the axis");
  test_refused_case("cylinder off the axis",
                    variant("center: [-2.1 mm, 0, 0]", "center: [-2.1 mm, 0, 1 mm]", NULL), 10,
                    "bodies[0].shape", "off the axis");
  test_refused_case("cylinder not along x",
                    variant("axis: [1, 0, 0], radius: 1", "axis: [0, 1, 0], radius: 1", NULL), 10,
                    "bodies[0].shape", "not the x axis");
  test_refused_case(
      "box",
      variant("{type: cylinder, center: [1 mm, 0, 0], axis: [1, 0, 0], radius: 5 mm, length: "
              "2 mm}",
              "{type: box, min: [0, 0, -5 mm], max: [2 mm, 5 mm, 5 mm]}", NULL),
      15, "bodies[1].shape", "cylinder");
  test_refused_case("radial velocity", variant("[500 m/s, 0, 0]", "[500 m/s, 10 m/s, 0]", NULL), 12,
                    "bodies[0].velocity", "not along the axis");
  test_refused_case(
      "impact angle",
      variant("velocity: [500 m/s, 0, 0]", "speed: 500 m/s\n    impact_angle: 60 deg", NULL), 13,
      "bodies[0].impact_angle", "not along the axis");
  test_refused_case(
      "obliquity",
      variant("velocity: [500 m/s, 0, 0]", "speed: 500 m/s\n    obliquity: 30 deg", NULL), 13,
      "bodies[0].obliquity", "not along the axis");
  test_refused_case(
      "half model",
      variant("  geometry: axisymmetric\n", "  geometry: axisymmetric\n  half_model: true\n", NULL),
      4, "domain.half_model", "3D option");
  test_refused_case("y_min face", variant("{x_max: wall}", "{x_max: wall, y_min: wall}", NULL), 6,
                    "domain.boundary.y_min", "across the axis");
  test_refused_case("r_min face", variant("{x_max: wall}", "{x_max: wall, r_min: wall}", NULL), 6,
                    "domain.boundary.r_min", "across the axis");
  test_refused_case("z face", variant("{x_max: wall}", "{x_max: wall, z_max: wall}", NULL), 6,
                    "domain.boundary.z_max", NULL);
  test_refused_case("3 components", variant("min: [-10 mm, 0]", "min: [-10 mm, 0, 0]", NULL), 4,
                    "domain.min", "two components");
  test_refused_case("r_min not 0", variant("min: [-10 mm, 0]", "min: [-10 mm, 1 mm]", NULL), 4,
                    "domain.min", "r = 0");
  test_refused_case("gradient correction",
                    variant(NULL, NULL, "sph: {gradient_correction: true}\n"), 19,
                    "sph.gradient_correction", "3D-only");
  test_refused_case("viscosity switch",
                    variant(NULL, NULL, "sph: {viscosity: {switch: cullen-dehnen}}\n"), 19,
                    "sph.viscosity.switch", "3D-only");
  test_refused_case("artificial stress",
                    variant(NULL, NULL, "sph: {artificial_stress: {epsilon: 0.3}}\n"), 19,
                    "sph.artificial_stress.epsilon", "3D-only");
  test_refused_case("hcp lattice",
                    variant("    spacing: 0.25 mm\n    velocity",
                            "    lattice: hcp\n    spacing: 0.25 mm\n    velocity", NULL),
                    11, "bodies[0].lattice", "3D lattice");
  test_refused_case(
      "energy deposit off the axis",
      variant(NULL, NULL, "energy_deposit: {energy: 1 J, center: [0, 1 mm, 0], radius: 1 mm}\n"),
      19, "energy_deposit.center", "off the axis");
  test_refused_case("stretch cap below 1", variant(NULL, NULL, "sph: {rz_stretch_max: 0.5}\n"), 19,
                    "sph.rz_stretch_max", "below 1");
  test_refused_case(
      "stretch cap in 3D",
      variant("  geometry: axisymmetric\n  min: [-10 mm, 0]\n  max: [10 mm, 10 mm]\n",
              "  geometry: 3d\n  min: [-10 mm, -10 mm, -10 mm]\n  max: [10 mm, 10 mm, 10 mm]\n",
              "sph: {rz_stretch_max: 2}\n"),
      19, "sph.rz_stretch_max", "axisymmetric runs");
  return test_finish();
}
