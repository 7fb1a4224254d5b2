/* profile.c — see profile.h. */
#include "profile.h"

#include <dirent.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/error.h"
#include "io/snapshot.h"
#include "testlib.h"

static double now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Appends s to buf in single quotes (shell-safe). */
static void append_quoted(char *buf, size_t len, const char *s)
{
  size_t k = strlen(buf);
  if (k + 3 >= len) return;
  buf[k++] = ' ';
  buf[k++] = '\'';
  for (; *s && k + 6 < len; s++) {
    if (*s == '\'') {
      memcpy(buf + k, "'\\''", 4);
      k += 4;
    } else {
      buf[k++] = *s;
    }
  }
  buf[k++] = '\'';
  buf[k] = 0;
}

int verif_threads(void)
{
  const char *s = getenv("HVSPH_TEST_THREADS");
  int n = s ? atoi(s) : 1;
  return n > 0 ? n : 1;
}

int verif_run(const char *name, int argc, char **argv, double *wall)
{
  return verif_run_as(name, name, argc, argv, wall);
}

int verif_run_as(const char *name, const char *dirname, int argc, char **argv, double *wall)
{
  static char cmd[16384], out[65536];
  const char *more = getenv("HVSPH_CASE_ARGS");
  snprintf(cmd, sizeof cmd,
           "'%s' run '%s/examples/verification/%s.yaml' -o '%s/%s' --overwrite "
           "--quiet "
           "--threads %d",
           test_bin(), test_source_dir(), name, test_tmpdir(), dirname, verif_threads());
  for (int i = 1; i < argc; i++) append_quoted(cmd, sizeof cmd, argv[i]);
  if (more && *more) {
    size_t k = strlen(cmd);
    snprintf(cmd + k, sizeof cmd - k, " %s", more);
  }
  printf("  running: %s\n", cmd);
  fflush(stdout);
  double t0 = now();
  int rc = test_run(cmd, out, sizeof out);
  *wall = now() - t0;
  if (out[0]) printf("  hvsph says:\n%s\n", out);
  printf("  wall-clock time of the run: %.1f s (%d thread%s)\n", *wall, verif_threads(),
         verif_threads() > 1 ? "s" : "");
  return rc;
}

int verif_read_last(const char *name, struct particles *p, double *t)
{
  char dir[4200], path[4500], best[300] = "";
  snprintf(dir, sizeof dir, "%s/%s", test_tmpdir(), name);
  DIR *d = opendir(dir);
  if (!d) {
    printf("  cannot open %s\n", dir);
    return -1;
  }
  struct dirent *e;
  while ((e = readdir(d))) {
    size_t l = strlen(e->d_name);
    if (strncmp(e->d_name, "particles_", 10) || l < 15 || strcmp(e->d_name + l - 4, ".csv"))
      continue;
    if (strlen(e->d_name) < sizeof best && strcmp(e->d_name, best) > 0)
      snprintf(best, sizeof best, "%s", e->d_name);
  }
  closedir(d);
  if (!best[0]) {
    printf("  no particles_*.csv in %s\n", dir);
    return -1;
  }
  snprintf(path, sizeof path, "%s/%s", dir, best);
  struct hv_error err;
  hv_error_clear(&err);
  if (io_read_particles_csv(path, p, t, &err)) {
    printf("  cannot read %s: %s\n", path, err.msg);
    return -1;
  }
  printf("  read %s: %zu particles at t = %.9g s\n", path, p->n, *t);
  return 0;
}

FILE *profile_open(const char *file, const char *comment, const char *header)
{
  char path[4500];
  snprintf(path, sizeof path, "%s/%s", test_tmpdir(), file);
  FILE *f = fopen(path, "w");
  if (!f) {
    printf("  cannot write %s\n", path);
    exit(1);
  }
  fprintf(f, "# %s\n%s\n", comment, header);
  printf("  profile: %s\n", path);
  return f;
}

void profile_close(FILE *f)
{
  if (fclose(f)) {
    printf("  error closing a profile file\n");
    exit(1);
  }
}

double *profile_radii(const struct particles *p)
{
  double *r = malloc((p->n + 1) * sizeof *r);
  if (!r) exit(1);
  for (size_t i = 0; i < p->n; i++)
    r[i] = sqrt(p->x[0][i] * p->x[0][i] + p->x[1][i] * p->x[1][i] + p->x[2][i] * p->x[2][i]);
  return r;
}

void profile_bin(const double *r, const double *m, const double *q, size_t n, double dr, int nb,
                 double *mean, long *count)
{
  double *msum = calloc((size_t)nb, sizeof *msum);
  if (!msum) exit(1);
  for (int b = 0; b < nb; b++) {
    mean[b] = 0.0;
    count[b] = 0;
  }
  for (size_t i = 0; i < n; i++) {
    double k = floor(r[i] / dr);
    if (k < 0 || k >= nb) continue;
    int b = (int)k;
    mean[b] += m[i] * q[i];
    msum[b] += m[i];
    count[b]++;
  }
  for (int b = 0; b < nb; b++) mean[b] = count[b] ? mean[b] / msum[b] : (double)NAN;
  free(msum);
}
