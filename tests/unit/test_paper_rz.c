/* test_paper_rz.c — examples/paper/rz/ (issue 74): the paper's normal impacts in RZ are
 * the 3D cases of examples/paper/ in axisymmetric form, as tools/gen_paper_cases.py
 * writes them. Read as case files (YAML with units, not set up: that needs the RZ
 * solver), each one against its 3D case:
 *   - exactly the 13 normal impacts are there (six rods, bumper-1 and -3, whipple-steel,
 *     wp1-3, vessel; the oblique bumper-17 and -20 are 3D only);
 *   - domain.geometry is axisymmetric, min and max are (x, r) with r_min = 0, the x range
 *     is the 3D case's and r_max the 3D case's half-width (y max);
 *   - the same bodies (less the 3D plates' refined "-core" discs and the RZ rod targets'
 *     coarser "-mid" and "-outer" rings), in order, of the same materials; the projectile of the same
 *     shape and size at the same velocity (a 3D speed at impact_angle 90 deg is along x);
 *     every body a cylinder about the x axis or a sphere centred on it, given by its
 *     spacing (not a count);
 *   - resolution 1 is ten particles per projectile radius: radius / spacing = 10;
 *   - every plate (a cylinder no longer than its radius) has at least five layers;
 *   - the 3D case's kernel, eta and viscosity alpha and beta, without the viscosity's
 *     reconstruction (3D only: the RZ solver refuses it);
 *   - the same end time, output interval and measure: section (the 3D plate lists
 *     [bumper, bumper-core] and a backwall [backwall, backwall-core] read as bumper, backwall);
 *   - the header says how resolution maps to particles per radius, and each rod's names
 *     the sourced material set's two --material options (whose names the library has:
 *     test_materials checks the entries; hvsph validate --rz --list --material in
 *     test_cli checks that the swaps take). */
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "config/config.h"
#include "testlib.h"

static const char *const cases[] = {"rod-1929", "rod-5835", "rod-5839", "rod-5841",      "rod-5842",
                                    "rod-5844", "bumper-1", "bumper-3", "whipple-steel", "wp1",
                                    "wp2",      "wp3",      "vessel"};
#define NCASES ((int)(sizeof cases / sizeof cases[0]))

static int ends_with(const char *s, const char *tail)
{
  const size_t n = strlen(s), m = strlen(tail);
  return n >= m && !strcmp(s + n - m, tail);
}

/* The first name at path: the string there, or the first of a list (of lists). */
static const char *first_name(struct cfg *c, const char *path, char *buf, size_t len)
{
  char p[512];
  snprintf(p, sizeof p, "%s", path);
  while (cfg_len(c, p) >= 0 && strlen(p) + 4 <= sizeof p) strcat(p, "[0]");
  struct hv_error err;
  const char *s = NULL;
  snprintf(buf, len, "%s", cfg_get_string(c, p, NULL, &s, &err) ? "?" : s);
  return buf;
}

/* The measure: sections agree: the same keys, lists of the same length whose entries
 * name the same first body, and the same scalars; a body in parts ([backwall,
 * backwall-core]) against the same body in one piece (backwall) is the same. */
static int same_measure(struct cfg *rz, struct cfg *d3, char *why, size_t len)
{
  const char *const *k3, *const *kr;
  const int n3 = cfg_keys(d3, "measure", &k3), nr = cfg_keys(rz, "measure", &kr);
  if (n3 != nr || n3 <= 0) return snprintf(why, len, "%d keys against %d", nr, n3), 0;
  for (int k = 0; k < n3; k++) {
    char p[256], a[128], b[128];
    snprintf(p, sizeof p, "measure.%s", k3[k]);
    if (!cfg_has(rz, p)) return snprintf(why, len, "no %.100s", p), 0;
    int l3 = cfg_len(d3, p), lr = cfg_len(rz, p);
    if ((l3 < 0) != (lr < 0)) l3 = lr = -1; /* [backwall, backwall-core] as backwall */
    if (l3 != lr) return snprintf(why, len, "%.100s: %d entries against %d", p, lr, l3), 0;
    for (int j = 0; j < (l3 < 0 ? 1 : l3); j++) {
      char q[300];
      if (l3 < 0)
        snprintf(q, sizeof q, "%s", p);
      else
        snprintf(q, sizeof q, "%s[%d]", p, j);
      if (strcmp(first_name(rz, q, a, sizeof a), first_name(d3, q, b, sizeof b)))
        return snprintf(why, len, "%.100s: %.60s against %.60s", q, a, b), 0;
    }
  }
  return 1;
}

static double qty(struct cfg *c, const char *path, enum unit_dim d)
{
  struct hv_error err;
  double v;
  return cfg_get_quantity(c, path, d, NULL, -HUGE_VAL, HUGE_VAL, &v, &err) ? (double)NAN : v;
}

/* The bodies other than the refinements: 3D "-core" discs and "-shell"s, RZ "-mid" and
 * "-outer" rings. */
static int main_bodies(struct cfg *c, int *idx, int max)
{
  int n = 0;
  const int nb = cfg_len(c, "bodies");
  for (int b = 0; b < nb && n < max; b++) {
    char p[64], buf[128];
    snprintf(p, sizeof p, "bodies[%d].name", b);
    first_name(c, p, buf, sizeof buf);
    if (!ends_with(buf, "-core") && !ends_with(buf, "-shell") && !ends_with(buf, "-mid") &&
        !ends_with(buf, "-outer"))
      idx[n++] = b;
  }
  return n;
}

static void check_shapes(struct cfg *rz, const char *name)
{
  const int nb = cfg_len(rz, "bodies");
  struct hv_error err;
  for (int b = 0; b < nb; b++) {
    char p[128], type[64];
    snprintf(p, sizeof p, "bodies[%d].shape.type", b);
    first_name(rz, p, type, sizeof type);
    double c[3] = {NAN, NAN, NAN}, ax[3] = {0, 0, 0};
    snprintf(p, sizeof p, "bodies[%d].shape.center", b);
    cfg_get_vec3(rz, p, UNIT_LENGTH, NULL, c, &err);
    int ok = (!strcmp(type, "sphere") || !strcmp(type, "cylinder")) && c[1] == 0 && c[2] == 0;
    if (!strcmp(type, "cylinder")) {
      snprintf(p, sizeof p, "bodies[%d].shape.axis", b);
      ok = ok && !cfg_get_vec3(rz, p, UNIT_NONE, NULL, ax, &err) && ax[0] == 1 && ax[1] == 0 &&
           ax[2] == 0;
      /* a plate: a disc no longer than its radius, at least five layers through it */
      snprintf(p, sizeof p, "bodies[%d].shape.length", b);
      const double l = qty(rz, p, UNIT_LENGTH);
      snprintf(p, sizeof p, "bodies[%d].shape.radius", b);
      const double r = qty(rz, p, UNIT_LENGTH);
      snprintf(p, sizeof p, "bodies[%d].spacing", b);
      const double dx = qty(rz, p, UNIT_LENGTH);
      if (l <= r) CHECK(l / dx > 5 - 1e-9, "%s: bodies[%d], a plate: %.4g layers", name, b, l / dx);
    }
    snprintf(p, sizeof p, "bodies[%d].particles", b);
    char sp[128];
    snprintf(sp, sizeof sp, "bodies[%d].spacing", b);
    CHECK(ok && !cfg_has(rz, p) && qty(rz, sp, UNIT_LENGTH) > 0,
          "%s: bodies[%d] a %s about the x axis, given by its spacing", name, b, type);
  }
}

static void check_case(const char *name)
{
  char prz[4400], p3[4400];
  snprintf(prz, sizeof prz, "%s/examples/paper/rz/%s.yaml", test_source_dir(), name);
  snprintf(p3, sizeof p3, "%s/examples/paper/%s.yaml", test_source_dir(), name);
  struct hv_error err;
  struct cfg *rz = cfg_load(prz, &err);
  CHECK(rz != NULL, "%s: examples/paper/rz/%s.yaml reads (%s)", name, name, rz ? "ok" : err.msg);
  struct cfg *d3 = cfg_load(p3, &err);
  CHECK(d3 != NULL, "%s: the 3D case reads", name);
  if (!rz || !d3) {
    cfg_free(rz);
    cfg_free(d3);
    return;
  }
  char geo[64];
  double *mn = NULL, *mx = NULL, *mn3 = NULL, *mx3 = NULL;
  int nmn = 0, nmx = 0, n3;
  cfg_get_list(rz, "domain.min", UNIT_LENGTH, &mn, &nmn, &err);
  cfg_get_list(rz, "domain.max", UNIT_LENGTH, &mx, &nmx, &err);
  cfg_get_list(d3, "domain.min", UNIT_LENGTH, &mn3, &n3, &err);
  cfg_get_list(d3, "domain.max", UNIT_LENGTH, &mx3, &n3, &err);
  CHECK(!strcmp(first_name(rz, "domain.geometry", geo, sizeof geo), "axisymmetric") && nmn == 2 &&
            nmx == 2 && mn3 && mx3 && mn[1] == 0 && mn[0] == mn3[0] && mx[0] == mx3[0] &&
            mx[1] == mx3[1],
        "%s: axisymmetric, (x, r) from (%g, %g) to (%g, %g) m: the 3D x range, r_max its "
        "half-width",
        name, nmn ? mn[0] : -1.0, nmn > 1 ? mn[1] : -1.0, nmx ? mx[0] : -1.0,
        nmx > 1 ? mx[1] : -1.0);
  free(mn);
  free(mx);
  free(mn3);
  free(mx3);
  CHECK(qty(rz, "resolution", UNIT_NONE) == 1.0 &&
            qty(rz, "time.end", UNIT_TIME) == qty(d3, "time.end", UNIT_TIME) &&
            qty(rz, "output.every", UNIT_TIME) == qty(d3, "output.every", UNIT_TIME),
        "%s: resolution 1, the 3D case's end time and output interval", name);

  int br[16], b3[16];
  const int nr = main_bodies(rz, br, 16), nd = main_bodies(d3, b3, 16);
  int same = nr == nd && nr > 1;
  for (int k = 0; same && k < nr; k++) {
    char p[128], a[128], b[128];
    snprintf(p, sizeof p, "bodies[%d].name", br[k]);
    first_name(rz, p, a, sizeof a);
    snprintf(p, sizeof p, "bodies[%d].name", b3[k]);
    same = !strcmp(a, first_name(d3, p, b, sizeof b));
    snprintf(p, sizeof p, "bodies[%d].material", br[k]);
    first_name(rz, p, a, sizeof a);
    snprintf(p, sizeof p, "bodies[%d].material", b3[k]);
    same = same && !strcmp(a, first_name(d3, p, b, sizeof b));
  }
  CHECK(same, "%s: the 3D case's bodies (%d) and materials, in order", name, nr);

  /* the projectile: the same shape and size, at the same velocity, ten per radius */
  char t3[64], tr[64];
  first_name(rz, "bodies[0].shape.type", tr, sizeof tr);
  first_name(d3, "bodies[0].shape.type", t3, sizeof t3);
  const double r = qty(rz, "bodies[0].shape.radius", UNIT_LENGTH);
  const double dx = qty(rz, "bodies[0].spacing", UNIT_LENGTH);
  double v[3] = {NAN, NAN, NAN}, v3[3] = {NAN, NAN, NAN};
  cfg_get_vec3(rz, "bodies[0].velocity", UNIT_VELOCITY, NULL, v, &err);
  if (cfg_has(d3, "bodies[0].speed")) {
    v3[0] = qty(d3, "bodies[0].speed", UNIT_VELOCITY);
    v3[1] = v3[2] = 0;
    if (fabs(qty(d3, "bodies[0].impact_angle", UNIT_ANGLE) - 0.5 * 3.14159265358979) > 1e-9)
      v3[0] = NAN; /* oblique: no RZ case */
  } else {
    cfg_get_vec3(d3, "bodies[0].velocity", UNIT_VELOCITY, NULL, v3, &err);
  }
  CHECK(!strcmp(tr, t3) && r == qty(d3, "bodies[0].shape.radius", UNIT_LENGTH) &&
            fabs(r / dx - 10) < 1e-6 && v[0] == v3[0] && v[1] == 0 && v[2] == 0,
        "%s: the projectile, a %s of radius %g mm at %g m/s along x (3D: %g), %.6g spacings "
        "per radius",
        name, tr, r * 1e3, v[0], v3[0], r / dx);
  check_shapes(rz, name);

  /* the same SPH model but the viscosity's reconstruction, which the RZ solver refuses
     (a 3x3 correction matrix: 3D only) */
  char k3[64], kr[64];
  CHECK(!strcmp(first_name(rz, "sph.kernel", kr, sizeof kr),
                first_name(d3, "sph.kernel", k3, sizeof k3)) &&
            qty(rz, "sph.eta", UNIT_NONE) == qty(d3, "sph.eta", UNIT_NONE) &&
            qty(rz, "sph.viscosity.alpha", UNIT_NONE) ==
                qty(d3, "sph.viscosity.alpha", UNIT_NONE) &&
            qty(rz, "sph.viscosity.beta", UNIT_NONE) == qty(d3, "sph.viscosity.beta", UNIT_NONE) &&
            !cfg_has(rz, "sph.viscosity.reconstruct"),
        "%s: the 3D case's kernel, eta, alpha and beta, without the reconstruction", name);

  char why[256] = "";
  CHECK(same_measure(rz, d3, why, sizeof why), "%s: the 3D case's measure: section %s", name, why);

  char *text = test_slurp(prz, NULL);
  CHECK(text && strstr(text, "resolution: 1 = 10 particles per") &&
            strstr(text, "resolution^(-1/2)"),
        "%s: the header maps resolution to particles per radius", name);
  if (!strncmp(name, "rod-", 4))
    CHECK(text && strstr(text, "--material steel-target=steel-4340 "
                               "--material tungsten-alloy=tungsten-wha-rod"),
          "%s: the header gives the sourced set's --material options", name);
  free(text);
  cfg_free(rz);
  cfg_free(d3);
}

int main(void)
{
  char dir[4200];
  snprintf(dir, sizeof dir, "%s/examples/paper/rz", test_source_dir());
  DIR *d = opendir(dir);
  int n = 0, known = 0;
  if (d) {
    struct dirent *e;
    while ((e = readdir(d))) {
      if (!ends_with(e->d_name, ".yaml")) continue;
      n++;
      for (int k = 0; k < NCASES; k++)
        known += !strncmp(e->d_name, cases[k], strlen(cases[k])) &&
                 strlen(e->d_name) == strlen(cases[k]) + 5;
    }
    closedir(d);
  }
  CHECK(n == NCASES && known == NCASES, "examples/paper/rz holds the %d normal impacts (%d files)",
        NCASES, n);
  for (int k = 0; k < NCASES; k++) check_case(cases[k]);
  return test_finish();
}
