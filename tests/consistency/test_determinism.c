/* test_determinism.c — results do not depend on the number of threads.
 *
 * examples/verification/tiny.yaml (two colliding gas slabs with radial velocities,
 * walls and periodic faces, two spacings; 45 steps with particle reordering every
 * 10) is run through the hvsph binary with --threads 1, 2 and 3. Every output file
 * (particles_NNNNN.vtu and .csv at all five output times, run.pvd, summary.csv, the
 * final checkpoint.hvc) must be byte for byte the same (run_segments.csv, which records
 * the thread count and wall time, is not compared); used_parameters.yaml too, except its
 * "# written:" date line. The test also checks that the case really moves (so that
 * equal files mean something): particles travel and change velocity between the
 * first and the last snapshot, and the run takes many steps.
 * Arguments are passed on to `hvsph run` (ctest consistency.test_determinism_switch runs
 * it with --set sph.viscosity.switch=cullen-dehnen: each particle's α, written to the
 * snapshots and the checkpoint, must not depend on the threads either).
 */
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/snapshot.h"
#include "particles/particles.h"
#include "testlib.h"

#define NSNAP 5 /* tiny.yaml: end 0.02 s, every 0.005 s -> t = 0, 0.005, ..., 0.02 */

/* "a/b" into buf; a path that does not fit ends the test. */
static const char *join(char *buf, size_t len, const char *a, const char *b)
{
  if ((size_t)snprintf(buf, len, "%s/%s", a, b) >= len) {
    fprintf(stderr, "path too long: %s/%s\n", a, b);
    exit(1);
  }
  return buf;
}

static int cmpstr(const void *a, const void *b)
{
  return strcmp(*(char *const *)a, *(char *const *)b);
}

/* Sorted names of the plain entries of a folder (no "." entries); returns the count. */
static int list_dir(const char *dir, char ***names)
{
  DIR *d = opendir(dir);
  int n = 0, cap = 64;
  *names = malloc((size_t)cap * sizeof **names);
  if (!d) return -1;
  struct dirent *e;
  while ((e = readdir(d))) {
    if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..")) continue;
    if (n == cap) *names = realloc(*names, (size_t)(cap *= 2) * sizeof **names);
    (*names)[n++] = strdup(e->d_name);
  }
  closedir(d);
  qsort(*names, (size_t)n, sizeof **names, cmpstr);
  return n;
}

/* Removes the line starting with `prefix` (in place); used for the date line. */
static void drop_line(char *text, size_t *len, const char *prefix)
{
  char *p = strstr(text, prefix);
  if (!p) return;
  char *q = strchr(p, '\n');
  q = q ? q + 1 : text + *len;
  memmove(p, q, (size_t)(text + *len - q) + 1);
  *len -= (size_t)(q - p);
}

/* Compares one file of two runs byte for byte; returns the bytes compared or -1. */
static long compare(const char *d1, const char *d2, const char *name, int threads)
{
  char p1[4200], p2[4200];
  join(p1, sizeof p1, d1, name);
  join(p2, sizeof p2, d2, name);
  size_t n1 = 0, n2 = 0;
  if (!strcmp(name, "run_segments.csv")) return 0; /* threads and wall time: provenance */
  char *a = test_slurp(p1, &n1), *b = test_slurp(p2, &n2);
  long result = -1;
  if (a && b) {
    if (!strcmp(name, "used_parameters.yaml")) {
      drop_line(a, &n1, "# written:");
      drop_line(b, &n2, "# written:");
    }
    size_t k = 0;
    while (k < n1 && k < n2 && a[k] == b[k]) k++;
    int same = n1 == n2 && k == n1;
    if (same)
      result = (long)n1;
    else
      CHECK(0, "%s: 1 thread and %d threads differ at byte %zu (sizes %zu and %zu)", name, threads,
            k, n1, n2);
  } else {
    CHECK(0, "%s: missing in %s", name, a ? d2 : d1);
  }
  free(a);
  free(b);
  return result;
}

static int run_case(const char *casefile, const char *dir, int threads, int argc, char **argv)
{
  char cmd[9000], out[8192];
  size_t len =
      (size_t)snprintf(cmd, sizeof cmd, "rm -rf '%s' && '%s' run '%s' -o '%s' --threads %d --quiet",
                       dir, test_bin(), casefile, dir, threads);
  for (int a = 1; a < argc && len < sizeof cmd; a++)
    len += (size_t)snprintf(cmd + len, sizeof cmd - len, " '%s'", argv[a]);
  if (len >= sizeof cmd) return -1;
  int rc = test_run(cmd, out, sizeof out);
  CHECK(rc == 0, "run with --threads %d exits 0 (got %d)%s%s", threads, rc, rc ? ": " : "",
        rc ? out : "");
  return rc;
}

/* Index of each id (ids are 0..n-1 for a freshly set-up case). */
static size_t *by_id(const struct particles *p)
{
  size_t *ix = malloc(p->n * sizeof *ix);
  for (size_t i = 0; i < p->n; i++) ix[i] = (size_t)-1;
  for (size_t i = 0; i < p->n; i++)
    if (p->id[i] >= 0 && (size_t)p->id[i] < p->n) ix[p->id[i]] = i;
  return ix;
}

/* The case must move: displacement and velocity change between two snapshots. */
static void check_motion(const char *dir)
{
  char f0[4200], f1[4200], n1[64];
  snprintf(n1, sizeof n1, "particles_%05d.csv", NSNAP - 1);
  join(f0, sizeof f0, dir, "particles_00000.csv");
  join(f1, sizeof f1, dir, n1);
  struct particles a, b;
  struct hv_error err;
  particles_init(&a);
  particles_init(&b);
  double ta = 0, tb = 0;
  int ok = !io_read_particles_csv(f0, &a, &ta, &err) && !io_read_particles_csv(f1, &b, &tb, &err);
  CHECK(ok && a.n == b.n && a.n > 0, "first and last snapshots read back (%zu and %zu particles)",
        a.n, b.n);
  if (ok && a.n == b.n && a.n > 0) {
    size_t *ia = by_id(&a), *ib = by_id(&b);
    double dxmax = 0.0, dvmax = 0.0;
    size_t missing = 0;
    for (size_t k = 0; k < a.n; k++) {
      if (ia[k] == (size_t)-1 || ib[k] == (size_t)-1) {
        missing++;
        continue;
      }
      double dx2 = 0.0, dv2 = 0.0;
      for (int c = 0; c < 3; c++) {
        double dx = b.x[c][ib[k]] - a.x[c][ia[k]], dv = b.v[c][ib[k]] - a.v[c][ia[k]];
        if (c > 0) dx -= 0.05 * round(dx / 0.05); /* periodic in y and z (period 0.05 m) */
        dx2 += dx * dx;
        dv2 += dv * dv;
      }
      if (sqrt(dx2) > dxmax) dxmax = sqrt(dx2);
      if (sqrt(dv2) > dvmax) dvmax = sqrt(dv2);
    }
    printf("  snapshots at t = %g s and %g s: largest displacement %.4g m, largest velocity "
           "change %.4g m/s\n",
           ta, tb, dxmax, dvmax);
    CHECK(missing == 0, "every id 0..%zu is in both snapshots (%zu missing)", a.n - 1, missing);
    CHECK(ta == 0.0 && fabs(tb - 0.02) < 1e-12, "snapshot times 0 and 0.02 s (%g, %g)", ta, tb);
    CHECK(dxmax > 2e-3, "particles moved: largest displacement %.4g m > 2 mm (0.4 spacing)", dxmax);
    CHECK(dvmax > 0.1, "velocities changed: largest change %.4g m/s > 0.1 m/s", dvmax);
    free(ia);
    free(ib);
  }
  particles_free(&a);
  particles_free(&b);
}

int main(int argc, char **argv)
{
  char casefile[4200], dir[4][4200];
  join(casefile, sizeof casefile, test_source_dir(), "examples/verification/tiny.yaml");
  const int threads[] = {1, 2, 3};
  const int nt = (int)(sizeof threads / sizeof threads[0]);
  for (int k = 0; k < nt; k++) {
    char sub[32];
    snprintf(sub, sizeof sub, "threads%d", threads[k]);
    join(dir[k], sizeof dir[k], test_tmpdir(), sub);
    if (run_case(casefile, dir[k], threads[k], argc, argv)) return test_finish();
  }

  char **names = NULL;
  int n = list_dir(dir[0], &names);
  int nvtu = 0, ncsv = 0, ntmp = 0, pvd = 0, summary = 0, used = 0, ckpt = 0, seg = 0;
  for (int i = 0; i < n; i++) {
    int k;
    char ext[8];
    if (sscanf(names[i], "particles_%5d.%3s", &k, ext) == 2 && k >= 0 && k < NSNAP)
      nvtu += !strcmp(ext, "vtu"), ncsv += !strcmp(ext, "csv");
    ntmp += strstr(names[i], ".tmp.") != NULL;
    pvd += !strcmp(names[i], "run.pvd");
    summary += !strcmp(names[i], "summary.csv");
    used += !strcmp(names[i], "used_parameters.yaml");
    ckpt += !strcmp(names[i], "checkpoint.hvc");
    seg += !strcmp(names[i], "run_segments.csv");
  }
  CHECK(n == 2 * NSNAP + 5 && nvtu == NSNAP && ncsv == NSNAP && pvd && summary && used && ckpt &&
            seg && !ntmp,
        "1-thread run wrote %d files: %d .vtu, %d particle .csv (want %d each), "
        "run.pvd, summary.csv, used_parameters.yaml, checkpoint.hvc, run_segments.csv, %d "
        "temporary",
        n, nvtu, ncsv, NSNAP, ntmp);

  for (int k = 1; k < nt; k++) {
    char **other = NULL;
    int m = list_dir(dir[k], &other);
    int same_list = m == n;
    for (int i = 0; same_list && i < n; i++) same_list = !strcmp(names[i], other[i]);
    CHECK(same_list, "--threads %d wrote the same %d file names as --threads 1 (%d files)",
          threads[k], n, m);
    long total = 0;
    int files = 0, bad = 0;
    for (int i = 0; i < n; i++) {
      long b = compare(dir[0], dir[k], names[i], threads[k]);
      if (b < 0)
        bad++;
      else
        total += b, files++;
    }
    CHECK(bad == 0,
          "--threads %d: %d files (%ld bytes) bitwise identical to --threads 1, "
          "%d differ",
          threads[k], files, total, bad);
    for (int i = 0; i < m; i++) free(other[i]);
    free(other);
  }

  /* the run took many steps (the last summary row) */
  char sp[4200];
  join(sp, sizeof sp, dir[0], "summary.csv");
  size_t len;
  char *sum = test_slurp(sp, &len);
  long last_step = -1;
  if (sum) {
    char *line = strtok(sum, "\n");
    while (line) {
      long st;
      if (line[0] != '#' && sscanf(line, "%ld,", &st) == 1) last_step = st;
      line = strtok(NULL, "\n");
    }
  }
  free(sum);
  printf("  steps: %ld\n", last_step);
  /* reordering every K steps (10, or the arguments' sph.reorder_every) ran: at least 2K
     steps (individual time steps take fewer, longer steps: their test sets K = 4) */
  long every = 10;
  for (int a = 1; a < argc; a++)
    if (!strncmp(argv[a], "sph.reorder_every=", 18)) every = strtol(argv[a] + 18, NULL, 10);
  CHECK(last_step >= 2 * every,
        "the run took %ld steps (>= %ld, so reordering every %ld steps ran)", last_step, 2 * every,
        every);
  check_motion(dir[0]);

  for (int i = 0; i < n; i++) free(names[i]);
  free(names);
  return test_finish();
}
