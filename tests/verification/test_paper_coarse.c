/* test_paper_coarse.c — a coarse paper case end to end: examples/paper/bumper-1.yaml
 * (steel sphere at 3.08 km/s through a 2 mm steel plate, half model, absorbing faces)
 * at resolution 0.1 to t = 6 us; then `hvsph render` of the last snapshot and
 * `hvsph validate --no-run` over it. Checks: exit statuses; the plate is perforated
 * and its hole is larger than the projectile's diameter (13.5 mm: at 3 km/s a steel
 * sphere punches a hole wider than itself, the paper's Fig. 1) but smaller than 3
 * diameters; the radiograph PNG and validation.md exist; `hvsph measure` on the run's
 * folder rewrites measurements.csv with the same rows (the snapshots are written
 * round-trip exact), skipping a stale snapshot of an earlier run left in the folder,
 * and refuses a folder without snapshots or a case (exit 2). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testlib.h"

/* the last value of a quantity in measurements.csv */
static double measured(const char *path, const char *quantity)
{
  char *text = test_slurp(path, NULL);
  double v = -1;
  for (char *line = text ? strtok(text, "\n") : NULL; line; line = strtok(NULL, "\n")) {
    char q[64];
    double t, val;
    if (sscanf(line, "%lf,%63[^,],%lf", &t, q, &val) == 3 && !strcmp(q, quantity)) v = val;
  }
  free(text);
  return v;
}

int main(void)
{
  char cmd[8192], out[4096], path[4400];
  const char *tmp = test_tmpdir();
  snprintf(cmd, sizeof cmd, "%s run %s/examples/paper/bumper-1.yaml -o %s/validation/bumper-1 "
           "--set resolution=0.1 --set time.end=\"6 us\" --set output.every=\"3 us\" "
           "--set output.csv=true --quiet", test_bin(), test_source_dir(), tmp);
  int st = test_run(cmd, out, sizeof out);
  CHECK(st == 0, "bumper-1 at resolution 0.1 runs (exit %d): %s", st, out);
  snprintf(path, sizeof path, "%s/validation/bumper-1/measurements.csv", tmp);
  double perf = measured(path, "perforated"), d = measured(path, "hole_diameter");
  CHECK(perf == 1.0, "the plate is perforated");
  CHECK(d > 13.5e-3 && d < 3 * 13.5e-3, "hole diameter %.2f mm between 13.5 and 40.5 mm", 1e3 * d);
  /* measurements taken again from the snapshots: the same file, row for row */
  char *before = test_slurp(path, NULL);
  /* ... with a stale snapshot of an earlier, longer run left in the folder */
  snprintf(cmd, sizeof cmd, "cp %s/validation/bumper-1/particles_00002.csv "
           "%s/validation/bumper-1/particles_00007.csv && %s measure %s/validation/bumper-1 "
           "--quiet", tmp, tmp, test_bin(), tmp);
  st = test_run(cmd, out, sizeof out);
  char *after = test_slurp(path, NULL);
  const char *b1 = before ? strchr(before, '\n') : NULL, *a1 = after ? strchr(after, '\n') : NULL;
  CHECK(st == 0 && b1 && a1 && !strcmp(b1, a1),   /* the first line names the version */
        "hvsph measure reproduces the run's measurements.csv (exit %d): %s", st, out);
  CHECK(strstr(out, "particles_00007.csv") && strstr(out, "skipped"),
        "... skipping the stale particles_00007.csv: %s", out);
  free(before);
  free(after);
  snprintf(cmd, sizeof cmd, "rm -rf %s/empty && mkdir %s/empty && %s measure %s/empty --quiet",
           tmp, tmp, test_bin(), tmp);
  st = test_run(cmd, out, sizeof out);
  CHECK(st == 2 && strstr(out, "used_parameters.yaml"), "measure: a folder without a case: exit %d: %s",
        st, out);
  snprintf(cmd, sizeof cmd, "%s measure %s/empty --case %s/examples/paper/bumper-1.yaml --quiet",
           test_bin(), tmp, test_source_dir());
  st = test_run(cmd, out, sizeof out);
  CHECK(st == 2 && strstr(out, "no particles_NNNNN.csv"), "measure: a folder without snapshots: "
        "exit %d: %s", st, out);
  snprintf(cmd, sizeof cmd, "%s render %s/validation/bumper-1/particles_00002.csv -o %s/r.png "
           "--mode radiograph --axis z", test_bin(), tmp, tmp);
  st = test_run(cmd, out, sizeof out);
  CHECK(st == 0, "render (exit %d): %s", st, out);
  snprintf(cmd, sizeof cmd, "cd %s && %s validate --no-run --only bumper-1 -o %s/validation",
           test_source_dir(), test_bin(), tmp);
  st = test_run(cmd, out, sizeof out);
  snprintf(path, sizeof path, "%s/validation/validation.md", tmp);
  char *md = test_slurp(path, NULL);
  CHECK(st == 0 && md && strstr(md, "| bumper-1 | hole_diameter (bumper) |"),
        "validate --no-run writes validation.md with the case (exit %d)", st);
  free(md);
  return test_finish();
}
