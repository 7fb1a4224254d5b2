/* test_config.c — the case-file reader: getters with units, defaults, messages with
 * file and line, unknown and duplicate keys, --set, used_parameters.yaml round trip. */
#include "config/config.h"
#include "testlib.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Checks that err holds exactly `expect` with code HV_EXIT_INPUT. */
static void check_msg(int rc, const struct hv_error *err, const char *expect)
{
  CHECK(rc == -1 && err->code == HV_EXIT_INPUT, "fails with HV_EXIT_INPUT (rc %d, code %d)", rc,
        err->code);
  int same = !strcmp(err->msg, expect);
  CHECK(same, "message '%s'%s%s", err->msg, same ? "" : "\n        wanted:  ", same ? "" : expect);
}

static const char *case_text = "time:\n"                               /* 1 */
                               "  end: 35 us\n"                        /* 2 */
                               "  cfl: 0.3\n"                          /* 3 */
                               "bodies:\n"                             /* 4 */
                               "  - name: projectile\n"                /* 5 */
                               "    density: \"2.78 g/cm3\"\n"         /* 6 */
                               "    velocity: [6.2 km/s, 0, 10 m/s]\n" /* 7 */
                               "    centre: [0, 1.5 mm, 0]\n"          /* 8 */
                               "  - name: plate\n"                     /* 9 */
                               "    density: -5 kg/m3\n"               /* 10 */
                               "sph:\n"                                /* 11 */
                               "  kernel: wendland\n"                  /* 12 */
                               "  neighbours: 1e2\n"                   /* 13 */
                               "  symmetric: yes\n"                    /* 14 */
                               "  radii: [1 mm, 2 mm, 3 cm, 4]\n";     /* 15 */

static struct cfg *load_case(struct hv_error *err)
{
  struct cfg *c = cfg_load_string(case_text, "case.yaml", err);
  CHECK(c != NULL, "case loads (%s)", c ? "ok" : err->msg);
  return c;
}

static void test_getters(void)
{
  struct hv_error err = {0};
  struct cfg *c = load_case(&err);
  if (!c) return;
  double v = 0.0, vec[3] = {0.0, 0.0, 0.0};
  int rc = cfg_get_quantity(c, "time.end", UNIT_TIME, NULL, 0.0, HUGE_VAL, &v, &err);
  CHECK(rc == 0 && v == 3.5e-5, "time.end = 35 us -> %.17g", v);
  rc = cfg_get_quantity(c, "bodies[0].density", UNIT_DENSITY, NULL, DBL_MIN, HUGE_VAL, &v, &err);
  CHECK(rc == 0 && v == 2780.0, "bodies[0].density = 2.78 g/cm3 -> %.17g", v);
  rc = cfg_get_vec3(c, "bodies[0].velocity", UNIT_VELOCITY, NULL, vec, &err);
  CHECK(rc == 0 && vec[0] == 6200.0 && vec[1] == 0.0 && vec[2] == 10.0,
        "velocity with mixed units -> %g %g %g", vec[0], vec[1], vec[2]);
  CHECK(cfg_get_vec3(c, "bodies[0].centre", UNIT_LENGTH, NULL, vec, &err) == 0 && vec[0] == 0.0 &&
            vec[1] == 1.5e-3 && vec[2] == 0.0,
        "centre [0, 1.5 mm, 0]");
  const char *s = NULL;
  CHECK(cfg_get_string(c, "bodies[1].name", NULL, &s, &err) == 0 && !strcmp(s, "plate"),
        "name 'plate'");
  static const char *const kernels[] = {"cubic", "wendland", NULL};
  int k = -1;
  CHECK(cfg_get_choice(c, "sph.kernel", NULL, kernels, &k, &err) == 0 && k == 1, "kernel choice 1");
  long n = 0;
  CHECK(cfg_get_int(c, "sph.neighbours", NULL, 1, 1000, &n, &err) == 0 && n == 100,
        "1e2 as int 100");
  int b = 0;
  CHECK(cfg_get_bool(c, "sph.symmetric", NULL, &b, &err) == 0 && b == 1, "yes -> true");
  double *list = NULL;
  int len = 0;
  CHECK(cfg_get_list(c, "sph.radii", UNIT_LENGTH, &list, &len, &err) == 0 && len == 4 &&
            list[0] == 1e-3 && list[1] == 2e-3 && list[2] == 0.03 && list[3] == 4.0,
        "list with units");
  free(list);
  CHECK(cfg_has(c, "bodies[1].density") && !cfg_has(c, "bodies[2]") && !cfg_has(c, "time.start"),
        "cfg_has");
  CHECK(cfg_len(c, "bodies") == 2 && cfg_len(c, "time") == -1, "cfg_len");
  CHECK(cfg_is_map(c, "time") && !cfg_is_map(c, "bodies"), "cfg_is_map");
  const char *const *keys = NULL;
  int nk = cfg_keys(c, "", &keys);
  CHECK(nk == 3 && !strcmp(keys[0], "time") && !strcmp(keys[1], "bodies") &&
            !strcmp(keys[2], "sph"),
        "top-level keys in document order");
  nk = cfg_keys(c, "bodies[0]", &keys);
  CHECK(nk == 4 && !strcmp(keys[3], "centre"), "keys of bodies[0]");
  char where[256];
  CHECK(!strcmp(cfg_where(c, "bodies[1].density", where, sizeof where), "case.yaml:10"),
        "cfg_where %s", where);
  CHECK(!strcmp(cfg_where(c, "nothing", where, sizeof where), "case.yaml"), "cfg_where absent");
  cfg_free(c);
}

static void test_defaults_and_errors(void)
{
  struct hv_error err = {0};
  struct cfg *c = load_case(&err);
  if (!c) return;
  double v = 0.0, def = 1e-6, vec[3], dv[3] = {1, 2, 3};
  CHECK(cfg_get_quantity(c, "time.dt_max", UNIT_TIME, &def, 0.0, HUGE_VAL, &v, &err) == 0 &&
            v == 1e-6,
        "absent key takes the default");
  CHECK(cfg_get_vec3(c, "bodies[1].velocity", UNIT_VELOCITY, dv, vec, &err) == 0 && vec[2] == 3.0,
        "absent vec3 takes the default");
  int rc = cfg_get_quantity(c, "time.start", UNIT_TIME, NULL, 0.0, HUGE_VAL, &v, &err);
  check_msg(rc, &err, "case.yaml:1: missing required key 'time.start'");
  rc = cfg_get_quantity(c, "output.every", UNIT_TIME, NULL, 0.0, HUGE_VAL, &v, &err);
  check_msg(rc, &err, "case.yaml: missing required key 'output.every'");
  rc = cfg_get_quantity(c, "bodies[1].density", UNIT_DENSITY, NULL, DBL_MIN, HUGE_VAL, &v, &err);
  check_msg(rc, &err, "case.yaml:10: bodies[1].density: -5 kg/m3 is out of range (must be > 0)");
  rc = cfg_get_quantity(c, "time.cfl", UNIT_NONE, NULL, 0.5, 1.0, &v, &err);
  check_msg(rc, &err, "case.yaml:3: time.cfl: 0.3 is out of range (must be in [0.5, 1])");
  rc = cfg_get_quantity(c, "time.end", UNIT_TIME, NULL, 1.0, HUGE_VAL, &v, &err);
  check_msg(rc, &err,
            "case.yaml:2: time.end: '35 us' (3.5e-05 s) is out of range (must be >= 1 s)");
  rc = cfg_get_quantity(c, "bodies[0].density", UNIT_VELOCITY, NULL, -HUGE_VAL, HUGE_VAL, &v, &err);
  check_msg(rc, &err,
            "case.yaml:6: bodies[0].density: unit 'g/cm3' is a density, expected a velocity "
            "(e.g. m/s)");
  rc = cfg_get_vec3(c, "bodies[0].centre", UNIT_TIME, NULL, vec, &err);
  check_msg(rc, &err,
            "case.yaml:8: bodies[0].centre[1]: unit 'mm' is a length, expected a time (e.g. s)");
  rc = cfg_get_vec3(c, "sph.radii", UNIT_LENGTH, NULL, vec, &err);
  CHECK(rc == -1 && strstr(err.msg, "case.yaml:15: sph.radii: expected a list of 3"),
        "vec3 length: %s", err.msg);
  rc = cfg_get_quantity(c, "time", UNIT_TIME, NULL, 0.0, HUGE_VAL, &v, &err);
  check_msg(rc, &err, "case.yaml:2: time: expected a single value, found a mapping");
  static const char *const kernels[] = {"cubic", "m4", NULL};
  int k;
  rc = cfg_get_choice(c, "sph.kernel", NULL, kernels, &k, &err);
  check_msg(rc, &err, "case.yaml:12: sph.kernel: 'wendland' is not one of 'cubic', 'm4'");
  long n;
  rc = cfg_get_int(c, "time.cfl", NULL, 0, 10, &n, &err);
  check_msg(rc, &err, "case.yaml:3: time.cfl: '0.3' is not an integer");
  rc = cfg_get_int(c, "sph.neighbours", NULL, 0, 10, &n, &err);
  check_msg(rc, &err, "case.yaml:13: sph.neighbours: 100 is out of range (must be in [0, 10])");
  int b;
  rc = cfg_get_bool(c, "sph.kernel", NULL, &b, &err);
  check_msg(rc, &err,
            "case.yaml:12: sph.kernel: 'wendland' is not a yes/no value (use true or false)");
  cfg_free(c);
}

static void test_scalar_forms(void)
{
  struct hv_error err = {0};
  struct cfg *c = cfg_load_string("b: [on, Off, TRUE, no, 'yes', maybe]\n"
                                  "i: [1e6, -42, 1.5, 9e99, 12 m, \"7\"]\nnull_key:\n",
                                  "forms.yaml", &err);
  CHECK(c != NULL, "loads");
  if (!c) return;
  static const int want_b[] = {1, 0, 1, 0, 1, -1};
  for (int i = 0; i < 6; i++) {
    char path[32];
    int b = -1;
    snprintf(path, sizeof path, "b[%d]", i);
    int rc = cfg_get_bool(c, path, NULL, &b, &err);
    CHECK(want_b[i] < 0 ? rc == -1 : rc == 0 && b == want_b[i], "bool %s", path);
  }
  static const long want_i[] = {1000000, -42, 0, 0, 0, 7};
  static const int ok_i[] = {1, 1, 0, 0, 0, 1};
  for (int i = 0; i < 6; i++) {
    char path[32];
    long v = -1;
    snprintf(path, sizeof path, "i[%d]", i);
    int rc = cfg_get_int(c, path, NULL, LONG_MIN, LONG_MAX, &v, &err);
    CHECK(ok_i[i] ? rc == 0 && v == want_i[i] : rc == -1, "int %s", path);
  }
  double q;
  {
    /* a fraction too small for a double is not the integer 0 */
    struct cfg *t = cfg_load_string("n: 1e-400\n", "forms.yaml", &err);
    long v = -1;
    int r = t ? cfg_get_int(t, "n", NULL, LONG_MIN, LONG_MAX, &v, &err) : 0;
    check_msg(r, &err, "forms.yaml:1: n: '1e-400' is not an integer");
    cfg_free(t);
  }
  int rc = cfg_get_quantity(c, "null_key", UNIT_LENGTH, NULL, -HUGE_VAL, HUGE_VAL, &q, &err);
  check_msg(rc, &err, "forms.yaml:3: null_key: the key has no value");
  rc = cfg_get_quantity(c, "b[9]", UNIT_LENGTH, NULL, -HUGE_VAL, HUGE_VAL, &q, &err);
  check_msg(rc, &err, "forms.yaml:1: missing required key 'b[9]'");
  rc = cfg_get_quantity(c, "b..x", UNIT_LENGTH, NULL, -HUGE_VAL, HUGE_VAL, &q, &err);
  check_msg(rc, &err, "forms.yaml: bad key path 'b..x'");
  cfg_free(c);
}

static void test_unknown_keys(void)
{
  struct hv_error err = {0};
  const char *text = "material:\n"        /* 1 */
                     "  density: 2700\n"  /* 2 */
                     "  yeild: 300 MPa\n" /* 3 */
                     "  shear: 26 GPa\n"  /* 4 */
                     "extra:\n"           /* 5 */
                     "  deep:\n"          /* 6 */
                     "    a: 1\n"         /* 7 */
                     "sph:\n"             /* 8 */
                     "  etta: 0.1\n"      /* 9 */
                     "  eta: 1.2\n"       /* 10 */
                     "time:\n"            /* 11: asked into, every key defaulted */
                     "  ned: 1\n";        /* 12 */
  struct cfg *c = cfg_load_string(text, "case.yaml", &err);
  CHECK(c != NULL, "loads");
  if (!c) return;
  double v, def = 1e8;
  cfg_get_quantity(c, "material.density", UNIT_DENSITY, NULL, 0.0, HUGE_VAL, &v, &err);
  cfg_get_quantity(c, "material.yield", UNIT_PRESSURE, &def, 0.0, HUGE_VAL, &v, &err);
  cfg_get_quantity(c, "sph.eta", UNIT_NONE, NULL, 0.0, HUGE_VAL, &v, &err);
  cfg_get_quantity(c, "time.end", UNIT_TIME, &def, 0.0, HUGE_VAL, &v, &err);
  const char *const *keys;
  CHECK(cfg_keys(c, "extra", &keys) == 1, "cfg_keys does not mark used");
  int rc = cfg_check_unused(c, &err);
  check_msg(rc, &err,
            "case.yaml:3: unknown key 'material.yeild' (did you mean 'yield'?)\n"
            "case.yaml:4: unknown key 'material.shear'\n"
            "case.yaml:5: unknown key 'extra'\n"
            "case.yaml:9: unknown key 'sph.etta' (did you mean 'eta'?)\n"
            "case.yaml:12: unknown key 'time.ned' (did you mean 'end'?)");
  cfg_mark_used(c, "extra");
  cfg_mark_used(c, "time.ned");
  cfg_mark_used(c, "material");
  cfg_mark_used(c, "sph.etta");
  hv_error_clear(&err);
  CHECK(cfg_check_unused(c, &err) == 0 && err.code == 0, "no unknown keys after cfg_mark_used");
  cfg_free(c);

  /* a known key with a scalar, or nothing, where the program reads keys below it is
     not an "unknown key 'output' (did you mean 'output'?)" */
  c = cfg_load_string("sph:\n  viscosity: 1 kg\noutput:\ntime: {end: 1 us}\n", "case.yaml", &err);
  CHECK(c != NULL, "loads");
  if (!c) return;
  cfg_get_quantity(c, "sph.viscosity.alpha", UNIT_NONE, &def, 0.0, HUGE_VAL, &v, &err);
  cfg_get_quantity(c, "output.every", UNIT_TIME, &def, 0.0, HUGE_VAL, &v, &err);
  cfg_get_quantity(c, "time.end", UNIT_TIME, NULL, 0.0, HUGE_VAL, &v, &err);
  hv_error_clear(&err);
  rc = cfg_check_unused(c, &err);
  check_msg(rc, &err,
            "case.yaml:2: sph.viscosity: expected a mapping of keys below it, found '1 kg'\n"
            "case.yaml:3: output: the key has no value (its keys must be indented below it)");
  cfg_free(c);
}

/* A required key that is missing because it is misspelt (`time: {ennd: 0.02}`): the
 * message names the misspelt key's line and the key meant. Only a key of the same mapping
 * that nothing read, one or two edits away: an unrelated key gets the plain message. */
static void test_missing_near_miss(void)
{
  struct hv_error err = {0};
  struct cfg *c = cfg_load_string("name: x\ntime:\n  cfl: 0.3\n  ennd: 0.02\n", "case.yaml", &err);
  CHECK(c != NULL, "loads");
  if (!c) return;
  double v;
  int rc = cfg_get_quantity(c, "time.end", UNIT_TIME, NULL, 0.0, HUGE_VAL, &v, &err);
  check_msg(rc, &err,
            "case.yaml:4: missing required key 'time.end': this line has 'ennd' "
            "instead; did you mean 'end'?");
  cfg_free(c);
  c = cfg_load_string("time: {ennd: 0.02}\n", "case.yaml", &err);
  CHECK(c != NULL, "loads");
  if (!c) return;
  rc = cfg_get_quantity(c, "time.end", UNIT_TIME, NULL, 0.0, HUGE_VAL, &v, &err);
  check_msg(rc, &err,
            "case.yaml:1: missing required key 'time.end': this line has 'ennd' "
            "instead; did you mean 'end'?");
  cfg_free(c);
  /* far from it (three edits): the plain message at the mapping's line */
  c = cfg_load_string("name: x\ntime:\n  stop: 0.02\n", "case.yaml", &err);
  CHECK(c != NULL, "loads");
  if (!c) return;
  rc = cfg_get_quantity(c, "time.end", UNIT_TIME, NULL, 0.0, HUGE_VAL, &v, &err);
  check_msg(rc, &err, "case.yaml:2: missing required key 'time.end'");
  /* a near key in another mapping is not taken for it */
  rc = cfg_get_quantity(c, "name.x", UNIT_TIME, NULL, 0.0, HUGE_VAL, &v, &err);
  CHECK(rc == -1 && !strstr(err.msg, "did you mean"), "no hint across mappings: %s", err.msg);
  cfg_free(c);
  /* a key already read is not offered (bodies[0].spacing read, particles missing) */
  c = cfg_load_string("b: {particle: 5, particles2: 1}\n", "case.yaml", &err);
  CHECK(c != NULL, "loads");
  if (!c) return;
  long n;
  cfg_get_int(c, "b.particle", NULL, 0, 10, &n, &err);
  rc = cfg_get_int(c, "b.particles", NULL, 0, 10, &n, &err);
  check_msg(rc, &err,
            "case.yaml:1: missing required key 'b.particles': this line has "
            "'particles2' instead; did you mean 'particles'?");
  cfg_free(c);
}

static void test_yaml_errors(void)
{
  struct hv_error err = {0};
  struct cfg *c = cfg_load_string("a: 1\nb:\n  c: 2\na: 3\n", "case.yaml", &err);
  CHECK(c == NULL, "duplicate key rejected");
  check_msg(-1, &err, "case.yaml:4: duplicate key 'a' (first at line 1)");
  c = cfg_load_string("a: 1\nb: [1, 2\nc: 3\n", "case.yaml", &err);
  CHECK(c == NULL && !strncmp(err.msg, "case.yaml:4:1: YAML syntax error: ", 34),
        "syntax error has file:line:col: %s", err.msg);
  c = cfg_load_string("a: 1\n  b: 2\n", "bad.yaml", &err);
  CHECK(c == NULL && !strncmp(err.msg, "bad.yaml:1:4: YAML syntax error: ", 33), "syntax error: %s",
        err.msg);
  c = cfg_load_string("- 1\n- 2\n", "case.yaml", &err);
  check_msg(c ? 0 : -1, &err,
            "case.yaml:1: the document must be a mapping of keys, not a sequence");
  c = cfg_load_string("a: 1\n---\nb: 2\n", "case.yaml", &err);
  CHECK(c == NULL && strstr(err.msg, "only one YAML document"), "two documents: %s", err.msg);
  c = cfg_load("/nonexistent/case.yaml", &err);
  CHECK(c == NULL && err.code == HV_EXIT_INPUT && strstr(err.msg, "/nonexistent/case.yaml") &&
            strstr(err.msg, "No such file"),
        "missing file: %s", err.msg);
  c = cfg_load_string("# only a comment\n", "empty.yaml", &err);
  CHECK(c && cfg_keys(c, "", &(const char *const *){NULL}) == 0,
        "empty document is an empty mapping");
  cfg_free(c);
  c = cfg_load_string("base: &b {rho: 1000, c: 1500}\ncopy: *b\n", "case.yaml", &err);
  double v = 0;
  CHECK(c && cfg_get_quantity(c, "copy.c", UNIT_VELOCITY, NULL, 0, HUGE_VAL, &v, &err) == 0 &&
            v == 1500,
        "aliases are expanded");
  cfg_free(c);
}

/* Bytes that are not UTF-8 (a Latin-1 degree sign in a comment, say) stop the reading
 * with the file, line and column of the first one: libfyaml dropped the rest of the
 * document silently after such a byte in a comment, or named the wrong line. */
static void test_not_utf8(void)
{
  struct hv_error err = {0};
  struct cfg *c = cfg_load_string("time: {end: 1}  # 60\xb0\na: 2\n", "case.yaml", &err);
  check_msg(c ? 0 : -1, &err,
            "case.yaml:1:21: not valid UTF-8 (byte 0xb0); save the file as UTF-8");
  cfg_free(c);
  c = cfg_load_string("# caf\xe9\ntime: {end: 1}\n", "case.yaml", &err);
  check_msg(c ? 0 : -1, &err, "case.yaml:1:6: not valid UTF-8 (byte 0xe9); save the file as UTF-8");
  cfg_free(c);
  c = cfg_load_string("x: 1\n\xff: 1\ny: 2\n", "case.yaml", &err);
  check_msg(c ? 0 : -1, &err, "case.yaml:2:1: not valid UTF-8 (byte 0xff); save the file as UTF-8");
  cfg_free(c);
  c = cfg_load_string("a: 1\nb: \xc3\n", "case.yaml", &err); /* cut sequence */
  check_msg(c ? 0 : -1, &err, "case.yaml:2:4: not valid UTF-8 (byte 0xc3); save the file as UTF-8");
  cfg_free(c);
  c = cfg_load_string("a: \xed\xa0\x80\n", "case.yaml", &err); /* a UTF-16 surrogate */
  CHECK(c == NULL && strstr(err.msg, "case.yaml:1:4: not valid UTF-8"), "surrogate: %s", err.msg);
  cfg_free(c);
  c = cfg_load_string("a: \xc0\xaf\n", "case.yaml", &err); /* overlong '/' */
  CHECK(c == NULL && strstr(err.msg, "case.yaml:1:4: not valid UTF-8"), "overlong: %s", err.msg);
  cfg_free(c);
  /* UTF-8 itself is read: a BOM, a micro sign, a degree sign in a comment */
  c = cfg_load_string("\xef\xbb\xbf"
                      "a: 3 \xc2\xb5s  # 60\xc2\xb0\nb: \"\xe2\x82\xac\"\n",
                      "case.yaml", &err);
  double v = 0;
  CHECK(c && cfg_get_quantity(c, "a", UNIT_TIME, NULL, 0, HUGE_VAL, &v, &err) == 0 && v == 3e-6,
        "UTF-8 with a BOM loads (%s)", err.msg);
  cfg_free(c);
  /* --set values are checked too */
  c = cfg_new_empty("case.yaml");
  int rc = cfg_apply_set(c, "name=caf\xe9", &err);
  check_msg(rc, &err, "--set name: not valid UTF-8 (byte 0xe9)");
  cfg_free(c);
}

/* Aliases: one inside the value it names is refused (it was read as a cut copy), and
 * so is a document whose aliases expand beyond reason (nested aliases of aliases grow
 * tenfold a line: ran out of memory). */
static void test_alias_limits(void)
{
  struct hv_error err = {0};
  struct cfg *c = cfg_load_string("a:\n  b: &x\n    c: 1\n    d: *x\n", "case.yaml", &err);
  check_msg(c ? 0 : -1, &err,
            "case.yaml:4: alias '*x' inside the value it names (a recursive alias)");
  cfg_free(c);
  c = cfg_load_string("a: &s [1, *s]\n", "case.yaml", &err);
  check_msg(c ? 0 : -1, &err,
            "case.yaml:1: alias '*s' inside the value it names (a recursive alias)");
  cfg_free(c);
  char y[4096];
  int k = snprintf(y, sizeof y, "a0: &a0 [x, x, x, x, x, x, x, x, x, x]\n");
  for (int i = 1; i <= 9; i++)
    k += snprintf(y + k, sizeof y - (size_t)k,
                  "a%d: &a%d [*a%d, *a%d, *a%d, *a%d, *a%d, *a%d, *a%d, *a%d, *a%d, *a%d]\n", i, i,
                  i - 1, i - 1, i - 1, i - 1, i - 1, i - 1, i - 1, i - 1, i - 1, i - 1);
  c = cfg_load_string(y, "case.yaml", &err);
  CHECK(c == NULL && err.code == HV_EXIT_INPUT &&
            !strncmp(err.msg, "case.yaml:6: alias '*a4'", 24) && strstr(err.msg, "aliases"),
        "alias bomb refused: %s", c ? "(loaded)" : err.msg);
  cfg_free(c);
  /* an anchor used after its value is complete still works, also nested */
  c = cfg_load_string("m: &m {rho: 1, e: &e {k: 2}}\nn: *m\no: *e\n", "case.yaml", &err);
  double v = 0;
  CHECK(c && cfg_get_quantity(c, "n.e.k", UNIT_NONE, NULL, 0, HUGE_VAL, &v, &err) == 0 && v == 2 &&
            cfg_get_quantity(c, "o.k", UNIT_NONE, NULL, 0, HUGE_VAL, &v, &err) == 0 && v == 2,
        "aliases of complete values (%s)", err.msg);
  cfg_free(c);
}

/* Deep nesting: refused with a message (the reader recursed once a level, and a line of
 * 100000 '[' overflowed the stack); as deep as a key path can reach is read. */
static void test_deep_nesting(void)
{
  struct hv_error err = {0};
  size_t d = 100000;
  char *y = malloc(2 * d + 16);
  if (!y) return;
  size_t k = (size_t)sprintf(y, "x: 1\na: ");
  for (size_t i = 0; i < d; i++) y[k++] = '[';
  for (size_t i = 0; i < d; i++) y[k++] = ']';
  y[k] = '\0';
  struct cfg *c = cfg_load_string(y, "case.yaml", &err);
  check_msg(c ? 0 : -1, &err, "case.yaml:2: values nested more than 64 deep");
  cfg_free(c);
  /* 63 lists in the root mapping: a[0][0]...[0] has 64 components */
  k = (size_t)sprintf(y, "a: ");
  for (size_t i = 0; i < 63; i++) y[k++] = '[';
  y[k++] = '7';
  for (size_t i = 0; i < 63; i++) y[k++] = ']';
  y[k] = '\0';
  c = cfg_load_string(y, "case.yaml", &err);
  char path[256] = "a";
  for (int i = 0; i < 62; i++) strcat(path, "[0]");
  double v = 0, *list = NULL;
  int n = 0;
  CHECK(c && cfg_get_list(c, path, UNIT_NONE, &list, &n, &err) == 0 && n == 1,
        "64 levels load and read (%s)", err.msg);
  free(list);
  strcat(path, "[0]");
  CHECK(c && cfg_get_quantity(c, path, UNIT_NONE, NULL, 0, HUGE_VAL, &v, &err) == 0 && v == 7,
        "the deepest value (%s)", err.msg);
  cfg_free(c);
  free(y);
}

static void test_set(void)
{
  struct hv_error err = {0};
  struct cfg *c = load_case(&err);
  if (!c) return;
  int lvl = hv_log_level;
  hv_log_level = 0; /* keep the "override:" lines out of the test output */
  CHECK(cfg_apply_set(c, "time.end=50 us", &err) == 0, "replace time.end");
  CHECK(cfg_apply_set(c, "output.every = 5 us", &err) == 0, "create output.every");
  CHECK(cfg_apply_set(c, "bodies[1].velocity=[0, 0, -1 km/s]", &err) == 0, "set a list");
  CHECK(cfg_apply_set(c, "bodies[2].name=witness", &err) == 0, "append a sequence entry");
  double v = 0, vec[3] = {0, 0, 0};
  int rc = cfg_get_quantity(c, "time.end", UNIT_TIME, NULL, 0, HUGE_VAL, &v, &err);
  CHECK(rc == 0 && v == 5e-5, "time.end replaced: %g", v);
  rc = cfg_get_quantity(c, "output.every", UNIT_TIME, NULL, 0, HUGE_VAL, &v, &err);
  CHECK(rc == 0 && v == 5e-6, "output.every created: %g", v);
  rc = cfg_get_vec3(c, "bodies[1].velocity", UNIT_VELOCITY, NULL, vec, &err);
  CHECK(rc == 0 && vec[2] == -1000.0, "list set: %g", vec[2]);
  const char *s;
  CHECK(cfg_get_string(c, "bodies[2].name", NULL, &s, &err) == 0 && !strcmp(s, "witness"),
        "appended");
  rc = cfg_get_quantity(c, "time.end", UNIT_TIME, NULL, 1.0, HUGE_VAL, &v, &err);
  check_msg(rc, &err, "--set: time.end: '50 us' (5e-05 s) is out of range (must be >= 1 s)");
  cfg_apply_set(c, "time.end=5 kg", &err);
  rc = cfg_get_quantity(c, "time.end", UNIT_TIME, NULL, 0, HUGE_VAL, &v, &err);
  check_msg(rc, &err, "--set: time.end: unit 'kg' is a mass, expected a time (e.g. s)");
  rc = cfg_apply_set(c, "time.end", &err);
  check_msg(rc, &err, "--set 'time.end': expected key=value");
  rc = cfg_apply_set(c, " =3", &err);
  check_msg(rc, &err, "--set ' =3': empty key");
  rc = cfg_apply_set(c, "bodies[5].name=x", &err);
  CHECK(rc == -1 && strstr(err.msg, "'bodies'") && strstr(err.msg, "fewer entries"),
        "index gap: %s", err.msg);
  rc = cfg_apply_set(c, "time.end.x=1", &err);
  check_msg(rc, &err, "--set time.end.x: 'time.end' is not a mapping");
  cfg_free(c);
  /* a --set below a key the file gives a value: the message names where it is written
     (tools/fuzz-input.py, 2026-12-07 at 6f0da84: a case file cut short after 'time:\n  e') */
  c = cfg_load_string("output: {every: 1 us}\ntime:\n  e\n", "case.yaml", &err);
  rc = c ? cfg_apply_set(c, "time.end=1 us", &err) : 0;
  check_msg(rc, &err, "case.yaml:2: --set time.end: 'time' is not a mapping");
  cfg_free(c);
  c = cfg_load_string("time: {end: 1 us}\n", "case.yaml", &err);
  rc = c ? cfg_apply_set(c, "[0].x=1", &err) : 0;
  check_msg(rc, &err, "case.yaml: --set [0].x: the top level is not a sequence");
  cfg_free(c);
  /* a key written with no value takes --set's keys as an empty mapping would */
  c = cfg_load_string("time:\noutput: ~\n", "case.yaml", &err);
  CHECK(c && cfg_apply_set(c, "time.end=2 us", &err) == 0 &&
            cfg_apply_set(c, "output.every=1 us", &err) == 0 &&
            cfg_get_quantity(c, "time.end", UNIT_TIME, NULL, 0, HUGE_VAL, &v, &err) == 0 &&
            v == 2e-6,
        "--set into an empty 'time:' and 'output: ~' (%s)", err.msg);
  rc = cfg_apply_set(c, "a=[1, 2", &err);
  check_msg(rc, &err, "--set a: YAML syntax error: flow sequence without a closing bracket");
  /* the reader's other messages about a --set value name no line either: its lines
     are not the case file's ("--set a:1:" read as a key 'a:1') */
  rc = cfg_apply_set(c, "a={x: 1, x: 2}", &err);
  check_msg(rc, &err, "--set a: duplicate key 'x'");
  rc = cfg_apply_set(c, "a=*q", &err);
  check_msg(rc, &err, "--set a: unknown alias '*q'");
  rc = cfg_apply_set(c, "a=1\n---\n2", &err);
  check_msg(rc, &err, "--set a: only one YAML document is allowed");
  hv_log_level = lvl;
  cfg_free(c);
}

static void test_write_used(void)
{
  struct hv_error err = {0};
  struct cfg *c = load_case(&err);
  if (!c) return;
  double end, dens, vel[3], dt, def_dt = 2.5e-9, dv[3] = {1.5, -2, 0.1};
  const char *name, *mode;
  long n, dn = 7;
  int sym, di = 0;
  double *radii;
  int nr;
  int ok =
      cfg_get_quantity(c, "time.end", UNIT_TIME, NULL, 0, HUGE_VAL, &end, &err) == 0 &&
      cfg_get_quantity(c, "time.dt", UNIT_TIME, &def_dt, 0, HUGE_VAL, &dt, &err) == 0 &&
      cfg_get_quantity(c, "bodies[0].density", UNIT_DENSITY, NULL, 0, HUGE_VAL, &dens, &err) == 0 &&
      cfg_get_vec3(c, "bodies[0].velocity", UNIT_VELOCITY, NULL, vel, &err) == 0 &&
      cfg_get_vec3(c, "bodies[1].spin", UNIT_RATE, dv, vel, &err) == 0 &&
      cfg_get_string(c, "bodies[1].name", NULL, &name, &err) == 0 &&
      cfg_get_string(c, "output.mode", "a \"quoted\": value", &mode, &err) == 0 &&
      cfg_get_int(c, "sph.neighbours", NULL, 0, 1000, &n, &err) == 0 &&
      cfg_get_int(c, "sph.max_iter", &dn, 0, 1000, &n, &err) == 0 &&
      cfg_get_bool(c, "sph.symmetric", NULL, &sym, &err) == 0 &&
      cfg_get_bool(c, "sph.verbose", &di, &sym, &err) == 0 &&
      cfg_get_list(c, "sph.radii", UNIT_LENGTH, &radii, &nr, &err) == 0;
  CHECK(ok, "getters before writing (%s)", ok ? "ok" : err.msg);
  if (!ok) {
    cfg_free(c);
    return;
  }
  free(radii);
  char path[4096];
  snprintf(path, sizeof path, "%s/used_parameters.yaml", test_tmpdir());
  CHECK(cfg_write_used(c, path, "1.2.3-test", &err) == 0, "write_used (%s)", err.msg);
  FILE *f = fopen(path, "r");
  char text[8192] = "";
  size_t len = f ? fread(text, 1, sizeof text - 1, f) : 0;
  text[len] = '\0';
  if (f) fclose(f);
  CHECK(strstr(text, "# Parameters used by hvsph 1.2.3-test\n# case file: case.yaml\n") != NULL,
        "header names version and case");
  CHECK(strstr(text, "time:\n  end: 3.5e-05  # s\n  dt: 2.5e-09  # s, default\n") != NULL,
        "nested keys with SI values, unit and default comments");
  CHECK(strstr(text, "bodies:\n  - density: 2780  # kg/m3\n    velocity: [6200, 0, 10]  # m/s\n"
                     "  - spin: [1.5, -2, 0.1]  # 1/s, default\n    name: \"plate\"\n") != NULL,
        "sequence of mappings");
  CHECK(strstr(text, "  max_iter: 7  # default\n") && strstr(text, "  verbose: false  # default\n"),
        "int and bool defaults");
  CHECK(strstr(text, "radii: [0.001, 0.002, 0.03, 4]  # m\n") != NULL, "list in SI");
  if (test_failed) printf("written file:\n%s", text);
  cfg_free(c);

  /* Read back: the same values. */
  c = cfg_load(path, &err);
  CHECK(c != NULL, "used_parameters.yaml loads (%s)", c ? "ok" : err.msg);
  if (!c) return;
  double v, w[3];
  CHECK(cfg_get_quantity(c, "time.end", UNIT_TIME, NULL, 0, HUGE_VAL, &v, &err) == 0 && v == 3.5e-5,
        "end");
  CHECK(cfg_get_quantity(c, "time.dt", UNIT_TIME, NULL, 0, HUGE_VAL, &v, &err) == 0 && v == 2.5e-9,
        "dt");
  CHECK(cfg_get_quantity(c, "bodies[0].density", UNIT_DENSITY, NULL, 0, HUGE_VAL, &v, &err) == 0 &&
            v == 2780.0,
        "density");
  CHECK(cfg_get_vec3(c, "bodies[0].velocity", UNIT_VELOCITY, NULL, w, &err) == 0 &&
            w[0] == 6200.0 && w[2] == 10.0,
        "velocity");
  CHECK(cfg_get_vec3(c, "bodies[1].spin", UNIT_RATE, NULL, w, &err) == 0 && w[0] == 1.5 &&
            w[1] == -2.0 && w[2] == 0.1,
        "spin");
  CHECK(cfg_get_string(c, "bodies[1].name", NULL, &name, &err) == 0 && !strcmp(name, "plate"),
        "name");
  CHECK(cfg_get_string(c, "output.mode", NULL, &mode, &err) == 0 &&
            !strcmp(mode, "a \"quoted\": value"),
        "quoted string round trip");
  CHECK(cfg_get_int(c, "sph.neighbours", NULL, 0, 1000, &n, &err) == 0 && n == 100, "int");
  CHECK(cfg_get_bool(c, "sph.symmetric", NULL, &sym, &err) == 0 && sym == 1, "bool");
  CHECK(cfg_get_list(c, "sph.radii", UNIT_LENGTH, &radii, &nr, &err) == 0 && nr == 4 &&
            radii[2] == 0.03,
        "list");
  free(radii);
  cfg_mark_used(c, "sph");
  cfg_mark_used(c, "time");
  cfg_mark_used(c, "output");
  CHECK(cfg_check_unused(c, &err) == 0, "nothing unknown in the written file (%s)", err.msg);
  cfg_free(c);

  /* The header names the case file in a comment: a name with a line break or bytes that
     are not UTF-8 (a Latin-1 file name) must not break the file or add keys to it. */
  c = cfg_new_empty("caf\xe9\nb: 1.yaml");
  CHECK(cfg_write_used(c, path, "1.2.3-test", &err) == 0, "write_used (%s)", err.msg);
  cfg_free(c);
  c = cfg_load(path, &err);
  CHECK(c != NULL && cfg_keys(c, "", &(const char *const *){NULL}) == 0,
        "odd case-file name: the file reads back with no keys (%s)", c ? "ok" : err.msg);
  cfg_free(c);

  /* An unwritable folder: an error naming the path, no temp file left. */
  c = cfg_new_empty("bench");
  int rc = cfg_write_used(c, "/nonexistent-dir/used.yaml", "x", &err);
  CHECK(rc == -1 && err.code == HV_EXIT_INPUT && strstr(err.msg, "/nonexistent-dir/used.yaml"),
        "unwritable: %s", err.msg);
  cfg_free(c);
}

/* cfg_check_typical: a bare number outside the range is an error naming the file, line
 * and key, with the likely unit; with a unit, 0 or in the range it passes; in a run's
 * used_parameters.yaml (its header) the numbers are SI as written, except a --set's. */
static void test_typical(void)
{
  struct hv_error err = {0};
  struct cfg *c =
      cfg_load_string("a: 2.78\nb: 2.78 kg/m3\nc: 0\nd: 2780\ne: 1e9\n", "case.yaml", &err);
  CHECK(c != NULL, "typical: the document loads");
  if (!c) return;
  const char *w = "densities of condensed materials";
  int rc = cfg_check_typical(c, "a", UNIT_DENSITY, 50.0, 1e5, w, &err);
  CHECK(rc == -1 && err.code == HV_EXIT_INPUT &&
            strstr(err.msg, "case.yaml:1: a: the bare number 2.78 is read as 2.78 kg/m3") &&
            strstr(err.msg, "was it 2.78 g/cm3?"),
        "typical: a bare 2.78 is refused: %s", err.msg);
  rc = cfg_check_typical(c, "e", UNIT_DENSITY, 50.0, 1e5, w, &err); /* no unit fits */
  CHECK(rc == -1 && strstr(err.msg, "case.yaml:5: e:") && !strstr(err.msg, "was it"),
        "typical: a bare 1e9 is refused without a guess: %s", err.msg);
  CHECK(!cfg_check_typical(c, "b", UNIT_DENSITY, 50.0, 1e5, w, &err) &&
            !cfg_check_typical(c, "c", UNIT_DENSITY, 50.0, 1e5, w, &err) &&
            !cfg_check_typical(c, "d", UNIT_DENSITY, 50.0, 1e5, w, &err) &&
            !cfg_check_typical(c, "nokey", UNIT_DENSITY, 50.0, 1e5, w, &err),
        "typical: with a unit, 0, in range or absent it passes");
  cfg_free(c);
  c = cfg_load_string("# Parameters used by hvsph test\na: 2.78  # kg/m3\n", "used.yaml", &err);
  CHECK(c && !cfg_check_typical(c, "a", UNIT_DENSITY, 50.0, 1e5, w, &err),
        "typical: a used_parameters.yaml's SI numbers pass");
  rc = c ? cfg_apply_set(c, "a=2.78", &err) : -1;
  CHECK(rc == 0 && cfg_check_typical(c, "a", UNIT_DENSITY, 50.0, 1e5, w, &err) == -1 &&
            strstr(err.msg, "--set: a: the bare number 2.78"),
        "typical: ... but not a --set on it: %s", err.msg);
  cfg_free(c);
}

int main(void)
{
  test_getters();
  test_defaults_and_errors();
  test_scalar_forms();
  test_unknown_keys();
  test_missing_near_miss();
  test_yaml_errors();
  test_not_utf8();
  test_alias_limits();
  test_deep_nesting();
  test_set();
  test_write_used();
  test_typical();
  return test_finish();
}
