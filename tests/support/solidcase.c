/* solidcase.c — see solidcase.h. */
#include "solidcase.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "core/error.h"
#include "io/snapshot.h"
#include "testlib.h"

int sc_threads(void)
{
  const char *s = getenv("HVSPH_TEST_THREADS");
  int n = s ? atoi(s) : 1;
  return n > 0 ? n : 1;
}

const char *sc_outdir(const char *outname)
{
  static char buf[4][4096];
  static int k = 0;
  char *b = buf[k++ % 4];
  snprintf(b, 4096, "%s/%s", test_tmpdir(), outname);
  return b;
}

int sc_run(const char *example, const char *outname, const char *extra, double *seconds)
{
  char cmd[8192];
  static char out[65536];
  const char *more = getenv("HVSPH_CASE_ARGS");
  snprintf(cmd, sizeof cmd,
           "'%s' run '%s/examples/verification/%s.yaml' -o '%s' --overwrite "
           "--quiet "
           "--threads %d %s %s",
           test_bin(), test_source_dir(), example, sc_outdir(outname), sc_threads(),
           extra ? extra : "", more ? more : "");
  printf("running: %s\n", cmd);
  fflush(stdout);
  struct timespec t0, t1;
  clock_gettime(CLOCK_MONOTONIC, &t0);
  int rc = test_run(cmd, out, sizeof out);
  clock_gettime(CLOCK_MONOTONIC, &t1);
  double s = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
  if (seconds) *seconds = s;
  printf("  exit status %d after %.1f s\n", rc, s);
  if (rc) {
    size_t len = strlen(out);
    printf("  output (last 2000 bytes):\n%s\n", len > 2000 ? out + len - 2000 : out);
  }
  fflush(stdout);
  return rc;
}

int sc_count_snapshots(const char *dir)
{
  char path[4300];
  struct stat st;
  int k = 0;
  for (;; k++) {
    snprintf(path, sizeof path, "%s/particles_%05d.csv", dir, k);
    if (stat(path, &st)) break;
  }
  return k;
}

int sc_read(const char *dir, int k, struct particles *p, double *t)
{
  char path[4300];
  struct hv_error err;
  hv_error_clear(&err);
  snprintf(path, sizeof path, "%s/particles_%05d.csv", dir, k);
  particles_init(p);
  particles_enable_solid(p);
  if (io_read_particles_csv(path, p, t, &err)) {
    printf("  cannot read %s: %s\n", path, err.msg);
    return -1;
  }
  return 0;
}

size_t *sc_slots_by_id(const struct particles *p, size_t nid)
{
  size_t *slot = malloc((nid ? nid : 1) * sizeof *slot);
  if (!slot) abort();
  for (size_t k = 0; k < nid; k++) slot[k] = SIZE_MAX;
  for (size_t i = 0; i < p->n; i++)
    if (p->id[i] >= 0 && (size_t)p->id[i] < nid) slot[p->id[i]] = i;
  return slot;
}

static int cmp_double(const void *a, const void *b)
{
  double x = *(const double *)a, y = *(const double *)b;
  return x < y ? -1 : x > y;
}

int sc_layers(const struct particles *p, const unsigned char *sel, int dim, double tol,
              int *layer_of_id, size_t nid)
{
  for (size_t k = 0; k < nid; k++) layer_of_id[k] = -1;
  size_t m = 0;
  double *c = malloc((p->n ? p->n : 1) * sizeof *c);
  if (!c) abort();
  for (size_t i = 0; i < p->n; i++)
    if (sel[i]) c[m++] = p->x[dim][i];
  qsort(c, m, sizeof *c, cmp_double);
  /* layer boundaries: gaps wider than tol between consecutive sorted coordinates */
  double *lo = malloc((m ? m : 1) * sizeof *lo);
  if (!lo) abort();
  int nl = 0;
  for (size_t k = 0; k < m; k++)
    if (k == 0 || c[k] - c[k - 1] > tol) lo[nl++] = c[k];
  for (size_t i = 0; i < p->n; i++) {
    if (!sel[i] || p->id[i] < 0 || (size_t)p->id[i] >= nid) continue;
    int a = 0, b = nl - 1; /* last layer with lo <= x */
    while (a < b) {
      int mid = (a + b + 1) / 2;
      if (lo[mid] <= p->x[dim][i])
        a = mid;
      else
        b = mid - 1;
    }
    layer_of_id[p->id[i]] = a;
  }
  free(lo);
  free(c);
  return nl;
}

void sc_layer_mean(const struct particles *p, const double *f, const int *layer_of_id, size_t nid,
                   int nlayer, double *out)
{
  long *cnt = calloc((size_t)nlayer + 1, sizeof *cnt);
  if (!cnt) abort();
  for (int l = 0; l < nlayer; l++) out[l] = 0.0;
  for (size_t i = 0; i < p->n; i++) {
    if (p->id[i] < 0 || (size_t)p->id[i] >= nid) continue;
    int l = layer_of_id[p->id[i]];
    if (l < 0 || l >= nlayer) continue;
    out[l] += f[i];
    cnt[l]++;
  }
  for (int l = 0; l < nlayer; l++) out[l] = cnt[l] ? out[l] / (double)cnt[l] : (double)NAN;
  free(cnt);
}

double sc_front(const double *X, const double *v, int n, double level, int from_end)
{
  if (n < 2) return (double)NAN;
  const int s = from_end ? -1 : 1;
  int k = from_end ? n - 1 : 0;
  const int above0 = v[k] > level;
  for (int j = k + s; j >= 0 && j < n; j += s) {
    const int above = v[j] > level;
    if (above != above0) {
      const int i = j - s; /* last layer on the first side */
      const double f = (level - v[i]) / (v[j] - v[i]);
      return X[i] + f * (X[j] - X[i]);
    }
  }
  return (double)NAN;
}

double sc_plateau(const double *X, const double *f, int n, double front, double lo, double hi,
                  int *count)
{
  double s = 0.0;
  int c = 0;
  for (int l = 0; l < n; l++) {
    const double q = X[l] / front; /* 0 at the contact, 1 at the front */
    if (q > lo && q < hi) {
      s += f[l];
      c++;
    }
  }
  if (count) *count = c;
  return c ? s / c : (double)NAN;
}

double sc_mg_pressure(double rho0, double c0, double n, double Gamma, double rho, double E)
{
  const double eta = rho / rho0;
  const double pc = rho0 * c0 * c0 / n * (pow(eta, n) - 1.0);
  const double Ec = c0 * c0 / n * ((pow(eta, n - 1.0) - 1.0) / (n - 1.0) - 1.0 + rho0 / rho);
  return pc + Gamma * rho * (E - Ec);
}

void sc_mg_hugoniot(double rho0, double c0, double n, double Gamma, double up, double *rho1,
                    double *Us, double *p1)
{
  double a = rho0 * (1.0 + 1e-9), b = 4.0 * rho0; /* residual < 0 at a, > 0 at b */
  for (int k = 0; k < 200; k++) {
    const double r = 0.5 * (a + b);
    const double p = rho0 * up * up * r / (r - rho0); /* the jump conditions' p₁(ρ₁) */
    const double E = 0.5 * p * (1.0 / rho0 - 1.0 / r);
    if (sc_mg_pressure(rho0, c0, n, Gamma, r, E) - p > 0)
      b = r;
    else
      a = r;
  }
  *rho1 = 0.5 * (a + b);
  *Us = up * *rho1 / (*rho1 - rho0);
  *p1 = rho0 * *Us * up;
}

double sc_linfit(const double *x, const double *y, int n, double *a, double *rms)
{
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int k = 0; k < n; k++) {
    sx += x[k];
    sy += y[k];
  }
  const double mx = sx / n, my = sy / n;
  for (int k = 0; k < n; k++) {
    sxx += (x[k] - mx) * (x[k] - mx);
    sxy += (x[k] - mx) * (y[k] - my);
  }
  const double b = sxx > 0 ? sxy / sxx : (double)NAN, a0 = my - b * mx;
  if (a) *a = a0;
  if (rms) {
    double r = 0;
    for (int k = 0; k < n; k++) r += (y[k] - a0 - b * x[k]) * (y[k] - a0 - b * x[k]);
    *rms = sqrt(r / n);
  }
  return b;
}

const char *sc_run_open(const char *example, const char *outname, const char *extra,
                        const char *label, int min_snap, int *nsnap)
{
  double secs;
  const int rc = sc_run(example, outname, extra, &secs);
  CHECK(rc == 0, "%s runs (exit status %d, %.1f s)", label, rc, secs);
  if (rc) return NULL;
  const char *dir = sc_outdir(outname);
  *nsnap = sc_count_snapshots(dir);
  CHECK(*nsnap >= min_snap, "%s: %d snapshots", label, *nsnap);
  return *nsnap >= min_snap ? dir : NULL;
}

int sc_two_bodies(const char *dir, struct particles *p0, int *layer[2], int nl[2])
{
  if (sc_read(dir, 0, p0, NULL)) {
    CHECK(0, "snapshot 0 of %s readable", dir);
    return -1;
  }
  const size_t nid = p0->n;
  unsigned char *sel = malloc(nid);
  for (int b = 0; b < 2; b++) {
    for (size_t i = 0; i < nid; i++) sel[i] = p0->body[i] == b;
    layer[b] = malloc(nid * sizeof(int));
    nl[b] = sc_layers(p0, sel, 0, 0.2 * p0->h[0], layer[b], nid);
  }
  free(sel);
  return 0;
}
