/* test_check.c — `hvsph check` and the set-up checks of a user's first hour (issue 71):
 *   - check describes a small impact (bodies, plate layers, particles per radius, first
 *     step, steps, memory, wall time) and writes nothing, not even the output folder;
 *   - a measured plate of fewer than four layers at the impact point is warned of (two
 *     of 1.26 mm gave perforation answers that flipped with the sphere's size), four
 *     are not;
 *   - wrong units: a bare radius of 1.5 (m) where the spacing is 0.25 mm, "was it 1.5
 *     mm?"; a bare time.end of 20 (s) for a solid's 4 ns step, "was it 20 us?"; the
 *     verification cases in scaled units (Sod's time.end 0.2, the rubber rings' radius
 *     4) pass;
 *   - time.dt_min not below the first stable step is refused, a large dt_init and a
 *     tiny dt_max are warned of;
 *   - a misspelt required key, duplicate body names and a body at the speed of light are
 *     refused (exit 2) with file, line and key, an earlier run's files untouched;
 *   - the progress line gives a long remaining time as h:mm:ss;
 *   - an axisymmetric set-up (a constructed struct sim of rings, p->axisym): a rod of 5
 *     rows has radius 5Δ (5 particles per radius, not the 2.5 of half its extent in y),
 *     a plate of 4 ring layers, 30 rows, is a plate along x, 4 layers at the impact
 *     point (read as 3D its z extent of one spacing would make it a plate along z).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "run/plausible.h"
#include "run/run.h"
#include "sim/sim.h"
#include "testlib.h"
#include "testparticles.h"

/* A 1 mm aluminium sphere at 5 km/s on a 2.52 mm backwall of two 1.26 mm layers, whose
 * perforation is measured: about 400 particles. */
static const char *const impact_lines[] = {
    "name: impact",                                                               /* 1 */
    "domain:",                                                                    /* 2 */
    "  min: [-3 mm, -6 mm, -6 mm]",                                               /* 3 */
    "  max: [4 mm, 6 mm, 6 mm]",                                                  /* 4 */
    "bodies:",                                                                    /* 5 */
    "  - name: projectile",                                                       /* 6 */
    "    material: al-alloy",                                                     /* 7 */
    "    shape: {type: sphere, center: [-1.5 mm, 0, 0], radius: 1 mm}",           /* 8 */
    "    spacing: 0.25 mm",                                                       /* 9 */
    "    velocity: [5 km/s, 0, 0]",                                               /* 10 */
    "  - name: backwall",                                                         /* 11 */
    "    material: al-alloy",                                                     /* 12 */
    "    shape: {type: box, min: [0, -5 mm, -5 mm], max: [2.52 mm, 5 mm, 5 mm]}", /* 13 */
    "    spacing: 1.26 mm",                                                       /* 14 */
    "time:",                                                                      /* 15 */
    "  end: 2 us",                                                                /* 16 */
    "output:",                                                                    /* 17 */
    "  every: 1 us",                                                              /* 18 */
    "measure:",                                                                   /* 19 */
    "  backwall: backwall",                                                       /* 20 */
};
#define NLINES ((int)(sizeof impact_lines / sizeof impact_lines[0]))

/* The case with line `line` (1-based) replaced by `repl`; line 0: unchanged. */
static const char *variant(int line, const char *repl)
{
  static char text[8192];
  size_t k = 0;
  for (int i = 1; i <= NLINES; i++)
    k +=
        (size_t)snprintf(text + k, sizeof text - k, "%s\n", i == line ? repl : impact_lines[i - 1]);
  return text;
}

static char out[65536];

/* hvsph ARGS run in the scratch folder; stdout and stderr together in out. */
static int hvsph(const char *args)
{
  char cmd[9000];
  snprintf(cmd, sizeof cmd, "cd '%s' && '%s' %s 2>&1", test_tmpdir(), test_bin(), args);
  return test_run(cmd, out, sizeof out);
}

static int has(const char *s) { return strstr(out, s) != NULL; }

/* The one "hvsph: error:" line holds every piece of want (NULL-terminated). */
static void check_error(const char *what, const char *const *want)
{
  int count = 0;
  const char *line = NULL;
  for (const char *p = out; (p = strstr(p, "hvsph: error: ")) != NULL; p++)
    if (p == out || p[-1] == '\n') {
      count++;
      line = p;
    }
  CHECK(count == 1, "%s: one error line (found %d): %s", what, count, out);
  if (count != 1) return;
  char buf[4096];
  snprintf(buf, sizeof buf, "%.*s", (int)strcspn(line, "\n"), line);
  for (int i = 0; want[i]; i++)
    CHECK(strstr(buf, want[i]) != NULL, "%s: message has \"%s\"\n          %s", what, want[i], buf);
}

static int exists(const char *path)
{
  struct stat st;
  return stat(path, &st) == 0;
}

static void test_describe(void)
{
  test_write_file("impact.yaml", variant(0, ""));
  char outdir[4200];
  snprintf(outdir, sizeof outdir, "%s/out", test_tmpdir());
  int rc = hvsph("check impact.yaml --threads 1");
  CHECK(rc == 0, "check of a sound case: exit %d (want 0): %s", rc, out);
  /* 280 particles in the sphere (R/Δ = 4), 8 x 8 x 2 in the backwall */
  CHECK(has("projectile") && has("280") && has("4.0 particles per radius"),
        "the projectile's particles and particles per radius: %s", out);
  CHECK(has("backwall") && has("128") && has("plate 2.52 mm thick along x: 2 particle layers"),
        "the backwall's particles and layers: %s", out);
  CHECK(has("first time step") && has("CFL h/v_sig"), "the first time step: %s", out);
  CHECK(has("steps            about ") && has("an estimate"), "the estimated steps: %s", out);
  CHECK(has("memory") && has("bytes per particle"), "the memory: %s", out);
  CHECK(has("wall time        about ") && has("timed here"), "the wall time: %s", out);
  CHECK(!exists(outdir), "check writes nothing: no %s", outdir);
  /* the measured backwall: two layers at the impact point, warned of */
  CHECK(has("perforation measured (measure.backwall): 2 particle layers") &&
            has("warning: plate 'backwall' (measure.backwall): only 2 particle layers") &&
            has("at most 0.63 mm"),
        "a measured plate of 2 layers is warned of: %s", out);
  /* four layers of 0.63 mm: no warning */
  rc = hvsph("check impact.yaml --threads 1 --set 'bodies[1].spacing=0.63 mm'");
  CHECK(rc == 0 && has("measure.backwall): 4 particle layers") && !has("only 4"),
        "four layers are not warned of (exit %d): %s", rc, out);
  /* a plate not measured is described, not warned of */
  rc = hvsph("check impact.yaml --threads 1 --set measure.backwall=projectile");
  CHECK(rc == 0 && !has("warning: plate 'backwall'"), "an unmeasured plate: no warning: %s", out);
  /* the command line and the case: 1 and 2 */
  rc = hvsph("check");
  CHECK(rc == 1 && has("missing case file"), "check without a case: exit %d (want 1)", rc);
  rc = hvsph("check impact.yaml --bogus");
  CHECK(rc == 1 && has("unexpected argument '--bogus'"), "a bad option: exit %d (want 1)", rc);
  rc = hvsph("check impact.yaml --set time.clf=0.3");
  CHECK(rc == 2 && has("unknown key 'time.clf'"), "an unknown key: exit %d (want 2)", rc);
  rc = hvsph("check impact.yaml --material al-alloy=steel-bumper");
  CHECK(rc == 0 && has("steel-bumper"), "--material: exit %d: %s", rc, out);
  rc = hvsph("check --help");
  CHECK(rc == 0 && has("hvsph check CASE.yaml"), "check --help: exit %d", rc);
  CHECK(!exists(outdir), "and still no output folder");
}

/* Wrong units in lengths and times: errors at the key, with the unit meant. */
static void test_wrong_units(void)
{
  test_write_file("radius.yaml",
                  variant(8, "    shape: {type: sphere, center: [-1.5 mm, 0, 0], radius: 1.5}"));
  int rc = hvsph("check radius.yaml");
  CHECK(rc == 2, "a bare radius of 1.5 (m) at 0.25 mm: exit %d (want 2)", rc);
  check_error("bare radius",
              (const char *const[]){
                  "radius.yaml:8: bodies[0].shape.radius: ", "the bare number 1.5 is read as 1.5 m",
                  "more than this machine's memory holds", "was it 1.5 mm?", NULL});
  /* the same through run: exit 2, the earlier run's file untouched */
  char cmd[4400];
  snprintf(cmd, sizeof cmd, "mkdir -p '%s/old' && printf 'earlier\\n' > '%s/old/summary.csv'",
           test_tmpdir(), test_tmpdir());
  test_run(cmd, NULL, 0);
  rc = hvsph("run radius.yaml -o old --quiet");
  CHECK(rc == 2 && has("was it 1.5 mm?"), "run refuses the bare radius (exit %d)", rc);
  char p[4400];
  snprintf(p, sizeof p, "%s/old/summary.csv", test_tmpdir());
  char *prev = test_slurp(p, NULL);
  CHECK(prev && !strcmp(prev, "earlier\n"), "the earlier summary.csv is untouched");
  free(prev);
  /* a bare 1.5 m that fits in memory (a 0.3 m lattice) is warned of, a solid of real
     density (it then reaches out of the domain of millimetres: refused after) */
  rc = hvsph("check radius.yaml --set 'bodies[0].spacing=0.3 m'");
  CHECK(has("warning: radius.yaml:8: bodies[0].shape.radius: body 'projectile': the bare "
            "number 1.5 is read as 1.5 m") &&
            has("was it 1.5 mm?"),
        "a bare metre-sized solid is warned of (exit %d): %s", rc, out);
  /* a bare spacing wider than the body: no particle, and the unit meant */
  rc = hvsph("check impact.yaml --set bodies[0].spacing=0.25");
  CHECK(rc == 2, "a bare spacing of 0.25 (m) for a 2 mm sphere: exit %d (want 2)", rc);
  check_error("bare spacing", (const char *const[]){"impact.yaml:6: body 'projectile': spacing "
                                                    "0.25 m gives no particle inside the shape",
                                                    "bodies[0].spacing is the bare number 0.25",
                                                    "was it 0.25 mm?", NULL});
  /* time.end: 20 (s) at a first step of about 4 ns: 5e9 steps */
  test_write_file("end.yaml", variant(16, "  end: 20"));
  rc = hvsph("check end.yaml");
  CHECK(rc == 2, "a bare time.end of 20 (s): exit %d (want 2)", rc);
  check_error("bare end",
              (const char *const[]){"end.yaml:16: time.end: ", "the bare number 20 is read as 20 s",
                                    "was it 20 us?", NULL});
  rc = hvsph("run end.yaml -o old --quiet");
  CHECK(rc == 2 && has("was it 20 us?"), "run refuses it too (exit %d)", rc);
  prev = test_slurp(p, NULL);
  CHECK(prev && !strcmp(prev, "earlier\n"), "the earlier summary.csv is still untouched");
  free(prev);
  /* written with its unit it is meant: a warning */
  rc = hvsph("check impact.yaml --set 'time.end=20 s' --set output.every=0");
  CHECK(rc == 0 && has("warning: --set: time.end = 20 s is about"),
        "20 s with its unit: warned, exit %d: %s", rc, out);
  /* bare 20 us-scale values pass */
  rc = hvsph("check impact.yaml --set time.end=2e-6");
  CHECK(rc == 0, "a bare time.end of 2e-6 (s): exit %d: %s", rc, out);
  /* the step keys against the first stable step (about 5 ns): a dt_min above it would
     fail the first step (refused), a dt_init 200 times it is an unstable first step and
     a dt_max far below it makes 2e10 steps (both warned of, not blamed on time.end) */
  rc = hvsph("check impact.yaml --set time.dt_min=1e-6");
  CHECK(rc == 2, "time.dt_min above the first step: exit %d (want 2)", rc);
  check_error("dt_min", (const char *const[]){"--set: time.dt_min: 1e-06 s is not below the "
                                              "first stable step",
                                              "would stop as failed", NULL});
  rc = hvsph("check impact.yaml --set time.dt_init=1e-6");
  CHECK(rc == 0 && has("warning: --set: time.dt_init = 1e-06 s is 2e+02 times the first "
                       "stable step"),
        "a large dt_init is warned of (exit %d): %s", rc, out);
  rc = hvsph("check impact.yaml --set time.dt_max=1e-16 --set time.end=2e-6");
  CHECK(rc == 0 && has("warning: --set: time.dt_max = 1e-16 s, below the first stable step") &&
            !has("time.end: the bare number"),
        "a tiny dt_max is warned of, time.end not blamed (exit %d): %s", rc, out);
  /* the verification cases in scaled units: Sod (time.end 0.2, lengths 0.5, gas) and
     the rubber rings (radius 4, time.end 140, a non-gas of rho0 = 1) */
  const char *scaled[] = {"examples/verification/sod.yaml", "examples/verification/rings.yaml"};
  for (int k = 0; k < 2; k++) {
    snprintf(cmd, sizeof cmd, "check '%s/%s' --threads 1", test_source_dir(), scaled[k]);
    rc = hvsph(cmd);
    CHECK(rc == 0 && !has("bare number"), "%s checks fine (exit %d): %s", scaled[k], rc, out);
  }
}

/* A misspelt required key, duplicate names, the speed of light. */
static void test_refused(void)
{
  test_write_file("ennd.yaml", variant(16, "  ennd: 2 us"));
  int rc = hvsph("check ennd.yaml");
  CHECK(rc == 2, "time.ennd: exit %d (want 2)", rc);
  check_error("ennd", (const char *const[]){"ennd.yaml:16: missing required key 'time.end'",
                                            "'ennd'", "did you mean 'end'?", NULL});
  test_write_file("dup.yaml", variant(11, "  - name: projectile"));
  rc = hvsph("check dup.yaml");
  CHECK(rc == 2, "duplicate names: exit %d (want 2)", rc);
  check_error("dup", (const char *const[]){
                         "dup.yaml:11: bodies[1].name: ", "a second body named 'projectile'",
                         "bodies[0], at dup.yaml:6", NULL});
  /* the speed of light and beyond, at set-up: an earlier run's checkpoint and summary
     are left as they were (1e300 m/s failed only at step 0, after the checkpoint had
     been removed) */
  char cmd[4400], p[4400];
  snprintf(cmd, sizeof cmd,
           "mkdir -p '%s/fast' && printf 'ckpt\\n' > '%s/fast/checkpoint.hvc'"
           " && printf 'earlier\\n' > '%s/fast/summary.csv'",
           test_tmpdir(), test_tmpdir(), test_tmpdir());
  test_run(cmd, NULL, 0);
  static const struct {
    const char *line, *key, *speed;
  } fast[] = {
      {"    velocity: [1e300, 0, 0]", "fast.yaml:10: bodies[0].velocity: ", "1e+300 m/s"},
      {"    velocity: [2.5e8, 2.5e8, 0]", "fast.yaml:10: bodies[0].velocity: ", "3.53553e+08 m/s"},
      {"    speed: 299792458", "fast.yaml:10: bodies[0].speed: ", "299792458 m/s"},
      {"    velocity: [5 km/s, 0, 0]\n    radial_velocity: 3e8",
       "fast.yaml:11: bodies[0].radial_velocity: ", "with its radial velocity"},
  };
  for (size_t k = 0; k < sizeof fast / sizeof fast[0]; k++) {
    test_write_file("fast.yaml", variant(10, fast[k].line));
    rc = hvsph("run fast.yaml -o fast --quiet");
    CHECK(rc == 2, "%s: exit %d (want 2)", fast[k].line, rc);
    check_error(fast[k].line, (const char *const[]){fast[k].key, fast[k].speed,
                                                    "not below the speed of light", NULL});
  }
  for (int k = 0; k < 2; k++) {
    snprintf(p, sizeof p, "%s/fast/%s", test_tmpdir(), k ? "summary.csv" : "checkpoint.hvc");
    char *f = test_slurp(p, NULL);
    CHECK(f && !strcmp(f, k ? "earlier\n" : "ckpt\n"), "the earlier %s is untouched",
          k ? "summary.csv" : "checkpoint.hvc");
    free(f);
  }
}

/* Durations on the progress line; a run's long remaining time as h:mm:ss. */
static void test_progress(void)
{
  static const struct {
    double s;
    const char *want;
  } cases[] = {{7.6, "7.6 s"},      {59.94, "59.9 s"},      {60.0, "0:01:00"},
               {3725.0, "1:02:05"}, {100000.0, "27:46:40"}, {3 * 86400.0 + 1, "72:00:01 (3 days)"},
               {INFINITY, "inf s"}};
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
    char buf[64];
    run_format_duration(buf, sizeof buf, cases[k].s);
    CHECK(!strcmp(buf, cases[k].want), "%g s is written '%s' (want '%s')", cases[k].s, buf,
          cases[k].want);
  }
  /* 1000 s of a gas lattice at steps of 0.4 ms: hours left after three steps */
  char cmd[4400];
  snprintf(cmd, sizeof cmd,
           "run '%s/examples/verification/tiny.yaml' -o progress --overwrite --threads 1 "
           "--set 'time.end=1000 s' --set time.max_steps=3 --set output.log_every=1 "
           "--set output.every=0",
           test_source_dir());
  const int rc = hvsph(cmd);
  const char *r = strstr(out, "remaining ");
  int h = -1, m = -1, sec = -1;
  if (r) sscanf(r, "remaining %d:%d:%d", &h, &m, &sec);
  CHECK(rc == 0 && h >= 1 && m >= 0 && m < 60 && sec >= 0 && sec < 60,
        "the progress line gives the remaining time as h:mm:ss (exit %d): %s", rc, out);
}

static void test_axisym(void)
{
  static struct sim s; /* zero: 3D defaults, no half model */
  const double D = 1e-3;
  particles_init(&s.p);
  s.nbody = 2;
  s.body[0] = (struct body_info){
      .name = "rod", .spacing = D, .lo = {-10 * D, 0, -0.5 * D}, .hi = {0, 5 * D, 0.5 * D}};
  s.body[1] = (struct body_info){
      .name = "plate", .spacing = D, .lo = {0, 0, -0.5 * D}, .hi = {4 * D, 30 * D, 0.5 * D}};
  for (int i = 0; i < 10; i++)
    for (int j = 0; j < 5; j++) tp_add(&s.p, (i - 9.5) * D, (j + 0.5) * D, 0, 1e-6, D, 7850, 0);
  for (int i = 0; i < 4; i++)
    for (int j = 0; j < 30; j++) tp_add(&s.p, (i + 0.5) * D, (j + 0.5) * D, 0, 1e-6, D, 7850, 1);
  double ext[3], t = 0.0;
  s.p.axisym = 0;
  CHECK(check_plate_axis(&s, 1, &t) == 2, "read as 3D, the plate of rings looks thin along z");
  s.p.axisym = 1;
  check_body_extent(&s, 0, ext);
  CHECK(ext[0] == 10 * D && ext[1] == 10 * D && ext[2] == 10 * D,
        "RZ: the rod's extent is its diameter across x (%g, %g, %g mm)", ext[0] * 1e3, ext[1] * 1e3,
        ext[2] * 1e3);
  CHECK(check_plate_axis(&s, 1, &t) == 0 && fabs(t - 4 * D) < 1e-15 &&
            check_plate_axis(&s, 0, &t) == -1,
        "RZ: the plate is thin along x (%g mm), the rod is no plate", t * 1e3);
  const int one = 1;
  CHECK(check_plate_layers(&s, &one, 1, 5 * D, 0.0) == 4, "RZ: 4 ring layers at the impact point");
  particles_free(&s.p);
}

int main(void)
{
  char data[4200];
  snprintf(data, sizeof data, "%s/data", test_source_dir());
  setenv("HVSPH_DATA", data, 0);
  test_describe();
  test_wrong_units();
  test_refused();
  test_progress();
  test_axisym();
  return test_finish();
}
