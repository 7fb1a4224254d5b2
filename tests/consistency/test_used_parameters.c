/* test_used_parameters.c — used_parameters.yaml is a case file that reproduces its run.
 *
 * Its header says "This file can be run as a case file". examples/verification/
 * tiny.yaml is run, then the used_parameters.yaml it wrote is run as a case; the
 * second run must succeed and write bitwise the same particle files, run.pvd and
 * summary.csv (same version, same case name). Its own used_parameters.yaml must hold
 * the same keys with the same values (only the header lines and the "default"
 * markers may differ, since every value is now given explicitly).
 *
 * A restart's --set output.every (recorded in its used_parameters.yaml) takes effect
 * at the multiples of the new interval after the checkpoint's time (docs/cli.md,
 * "hvsph restart"): tiny.yaml run to 0.01 s (outputs every 0.005 s), then continued to
 * 0.04 s with output.every = 0.01 s, must have written outputs at 0, 0.005, 0.01, 0.02,
 * 0.03 and 0.04 s (a longer interval once skipped 0.02 s: the output count of the old
 * interval was kept), and with 0.0025 s outputs from 0.0125 s on.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testlib.h"

static const char *join(char *buf, size_t len, const char *a, const char *b)
{
  if ((size_t)snprintf(buf, len, "%s/%s", a, b) >= len) {
    fprintf(stderr, "path too long: %s/%s\n", a, b);
    exit(1);
  }
  return buf;
}

/* used_parameters.yaml without comment lines and without the "default" markers. */
static char *normalised(const char *path)
{
  char *s = test_slurp(path, NULL);
  if (!s) return NULL;
  char *out = malloc(strlen(s) + 1), *o = out;
  for (char *line = strtok(s, "\n"); line; line = strtok(NULL, "\n")) {
    if (line[0] == '#') continue;
    char *mark = strstr(line, "  # ");
    size_t n = strlen(line);
    if (mark) {
      char *d = strstr(mark, "default");
      if (d && d[7] == '\0') { /* "  # m, default" -> "  # m", "  # default" -> "" */
        n = (size_t)(d - line);
        while (n > 0 && (line[n - 1] == ' ' || line[n - 1] == ',' || line[n - 1] == '#')) n--;
      }
    }
    memcpy(o, line, n);
    o += n;
    *o++ = '\n';
  }
  *o = '\0';
  free(s);
  return out;
}

static int run(const char *casefile, const char *dir, char *out, size_t len)
{
  char cmd[9000];
  if ((size_t)snprintf(cmd, sizeof cmd, "rm -rf '%s' && '%s' run '%s' -o '%s' --quiet", dir,
                       test_bin(), casefile, dir) >= sizeof cmd)
    return -1;
  return test_run(cmd, out, len);
}

/* The time column of summary.csv; returns the number of rows (at most max) or -1. */
static int summary_times(const char *dir, double *t, int max)
{
  char path[4400];
  char *s = test_slurp(join(path, sizeof path, dir, "summary.csv"), NULL);
  if (!s) return -1;
  int n = 0, header = 0;
  for (char *line = strtok(s, "\n"); line; line = strtok(NULL, "\n")) {
    if (line[0] == '#') continue;
    if (!header) {
      header = 1;
      continue;
    }
    const char *c = strchr(line, ',');
    if (c && n < max) t[n++] = strtod(c + 1, NULL);
  }
  free(s);
  return n;
}

/* Runs tiny.yaml to 0.01 s, restarts it to 0.04 s with output.every = every; checks
   the summary's times are the nwant times of want. */
static void restart_every(const char *casefile, const char *dir, const char *every,
                          const double *want, int nwant)
{
  char cmd[9000], out[8192];
  int rc = -1;
  if ((size_t)snprintf(cmd, sizeof cmd,
                       "(rm -rf '%s' && '%s' run '%s' -o '%s' --quiet --set "
                       "time.end=0.01 && '%s' restart '%s' --quiet --set time.end=0.04 --set "
                       "output.every=%s)",
                       dir, test_bin(), casefile, dir, test_bin(), dir, every) < sizeof cmd)
    rc = test_run(cmd, out, sizeof out);
  CHECK(rc == 0, "run to 0.01 s, restart to 0.04 s with output.every = %s s (exit %d)%s%s", every,
        rc, rc ? ": " : "", rc ? out : "");
  double t[64];
  const int n = summary_times(dir, t, 64);
  int same = n == nwant;
  for (int k = 0; k < n && same; k++) same = fabs(t[k] - want[k]) < 1e-12;
  printf("  output.every = %s s at the restart: outputs at", every);
  for (int k = 0; k < n; k++) printf(" %g", t[k]);
  printf(" s\n");
  CHECK(same,
        "output.every = %s s at the restart: %d outputs, at the multiples of the "
        "interval in force (want %d)",
        every, n, nwant);
}

/* The same for measure.every: measurements (the gas shock in 'right') every 0.002 s to
   0.01 s, then every 0.004 s to 0.03 s; besides, at the output times (every 0.005 s). */
static void restart_measure_every(const char *casefile, const char *dir)
{
  char cmd[9000], out[8192], path[4400];
  int rc = -1;
  if ((size_t)snprintf(cmd, sizeof cmd,
                       "(rm -rf '%s' && '%s' run '%s' -o '%s' --quiet --set "
                       "time.end=0.01 --set measure.gas=right --set measure.every=0.002 && '%s' "
                       "restart '%s' --quiet --set time.end=0.03 --set measure.every=0.004)",
                       dir, test_bin(), casefile, dir, test_bin(), dir) < sizeof cmd)
    rc = test_run(cmd, out, sizeof out);
  CHECK(rc == 0,
        "run to 0.01 s with measure.every = 0.002 s, restart to 0.03 s with 0.004 s "
        "(exit %d)%s%s",
        rc, rc ? ": " : "", rc ? out : "");
  static const double want[] = {0,     0.002, 0.004, 0.005, 0.006, 0.008, 0.01, 0.012,
                                0.015, 0.016, 0.02,  0.024, 0.025, 0.028, 0.03};
  const int nwant = (int)(sizeof want / sizeof want[0]);
  double t[64];
  int n = 0;
  char *s = test_slurp(join(path, sizeof path, dir, "measurements.csv"), NULL);
  for (char *line = s ? strtok(s, "\n") : NULL; line; line = strtok(NULL, "\n")) {
    const char *c = strchr(line, ',');
    if (line[0] != '#' && c && !strncmp(c + 1, "shocked_particles,", 18) && n < 64)
      t[n++] = strtod(line, NULL);
  }
  free(s);
  int same = n == nwant;
  for (int k = 0; k < n && same; k++) same = fabs(t[k] - want[k]) < 1e-12;
  printf("  measure.every = 0.004 s at the restart: measurements at");
  for (int k = 0; k < n; k++) printf(" %g", t[k]);
  printf(" s\n");
  CHECK(same,
        "measure.every = 0.004 s at the restart: %d measurement times, the multiples of "
        "the interval in force and the output times (want %d)",
        n, nwant);
}

int main(void)
{
  char casefile[4200], d1[4200], d2[4200], used1[4400], used2[4400], out[8192];
  join(casefile, sizeof casefile, test_source_dir(), "examples/verification/tiny.yaml");
  join(d1, sizeof d1, test_tmpdir(), "first");
  join(d2, sizeof d2, test_tmpdir(), "again");
  join(used1, sizeof used1, d1, "used_parameters.yaml");
  join(used2, sizeof used2, d2, "used_parameters.yaml");

  int rc = run(casefile, d1, out, sizeof out);
  CHECK(rc == 0, "tiny.yaml runs (exit %d)%s%s", rc, rc ? ": " : "", rc ? out : "");
  if (rc) return test_finish();
  rc = run(used1, d2, out, sizeof out);
  CHECK(rc == 0, "its used_parameters.yaml runs as a case file (exit %d)%s%s", rc, rc ? ": " : "",
        rc ? out : "");
  if (rc) return test_finish();

  static const char *const files[] = {"summary.csv",         "run.pvd",
                                      "particles_00000.vtu", "particles_00000.csv",
                                      "particles_00004.vtu", "particles_00004.csv"};
  for (size_t k = 0; k < sizeof files / sizeof files[0]; k++) {
    char p1[4400], p2[4400];
    size_t n1 = 0, n2 = 0;
    char *a = test_slurp(join(p1, sizeof p1, d1, files[k]), &n1);
    char *b = test_slurp(join(p2, sizeof p2, d2, files[k]), &n2);
    CHECK(a && b && n1 == n2 && !memcmp(a, b, n1),
          "%s: the rerun wrote the same %zu bytes "
          "(%zu)",
          files[k], n1, n2);
    free(a);
    free(b);
  }
  char *u1 = normalised(used1), *u2 = normalised(used2);
  int same = u1 && u2 && !strcmp(u1, u2);
  CHECK(same, "the rerun's used_parameters.yaml holds the same keys and values");
  if (!same && u1 && u2) {
    char *l1 = u1, *l2 = u2;
    while (*l1 && *l1 == *l2) l1++, l2++;
    while (l1 > u1 && l1[-1] != '\n') l1--;
    while (l2 > u2 && l2[-1] != '\n') l2--;
    printf("  first difference:\n    %.*s\n    %.*s\n", (int)strcspn(l1, "\n"), l1,
           (int)strcspn(l2, "\n"), l2);
  }
  free(u1);
  free(u2);

  char d3[4200];
  static const double longer[] = {0, 0.005, 0.01, 0.02, 0.03, 0.04};
  restart_every(casefile, join(d3, sizeof d3, test_tmpdir(), "restart-longer"), "0.01", longer, 6);
  static const double shorter[] = {0,     0.005,  0.01, 0.0125, 0.015, 0.0175, 0.02, 0.0225,
                                   0.025, 0.0275, 0.03, 0.0325, 0.035, 0.0375, 0.04};
  restart_every(casefile, join(d3, sizeof d3, test_tmpdir(), "restart-shorter"), "0.0025", shorter,
                15);
  restart_measure_every(casefile, join(d3, sizeof d3, test_tmpdir(), "restart-measure"));
  return test_finish();
}
