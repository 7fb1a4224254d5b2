/* test_fof.c — friends-of-friends fragments on constructed particle sets:
 * two separated clusters of known mass and velocity (two fragments with exact sums; a
 * linking length longer than the gap merges them), the order and labels, masks and
 * material masses, the mirror rule of half models, the grid against an O(N²) brute
 * force on random points (uniform and per-particle linking lengths), invariance under
 * a permutation of the particles, the CSV writer and bad input.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diag/fof.h"
#include "particles/particles.h"
#include "testlib.h"
#include "testparticles.h"

static size_t add_particle(struct particles *p, double x, double y, double z, double m,
                           const double v[3], int mat, int body)
{
  const size_t i = tp_add(p, x, y, z, m, 1.0, 1.0, body);
  for (int d = 0; d < 3; d++) p->v[d][i] = v[d];
  p->mat[i] = mat;
  p->id[i] = (int64_t)i + 1000;
  return i;
}

/* A cubic block of nx × ny × nz particles, spacing s, first particle at lo. */
static void add_block(struct particles *p, const double lo[3], int nx, int ny, int nz, double s,
                      double m, const double v[3], int mat_even, int mat_odd, int body)
{
  for (int k = 0; k < nz; k++)
    for (int j = 0; j < ny; j++)
      for (int i = 0; i < nx; i++)
        add_particle(p, lo[0] + i * s, lo[1] + j * s, lo[2] + k * s, m, v,
                     (i + j + k) % 2 ? mat_odd : mat_even, body);
}

static const double S = 1e-3; /* [m] lattice spacing */

static void two_clusters(struct particles *p, double gap)
{
  const double va[3] = {100.0, 0.0, -3.0}, vb[3] = {-50.0, 20.0, 7.0};
  const double loa[3] = {0, 0, 0}, lob[3] = {4 * S + gap, 0.0, 1.0 * S};
  add_block(p, loa, 5, 5, 5, S, 2e-3, va, 0, 0, 0); /* 125 × 2 g */
  add_block(p, lob, 4, 4, 4, S, 1e-3, vb, 0, 1, 1); /* 64 × 1 g, materials 0/1 */
}

static void test_two_clusters(void)
{
  struct particles p;
  particles_init(&p);
  const double gap = 3.0 * S; /* nearest distance between the clusters */
  two_clusters(&p, gap);
  struct fof_params par = {.b = FOF_B_FACTOR * S, .nmat = 2};
  struct fof_result r;
  struct hv_error err;
  hv_error_clear(&err);
  CHECK(fof_find(&p, &par, &r, &err) == 0, "fof runs: %s", err.msg);
  CHECK(r.nfrag == 2 && r.n_full == 2, "two clusters, b = 1.5 Δ: %zu fragments", r.nfrag);
  if (r.nfrag == 2) {
    CHECK_CLOSE(r.frag[0].m, 0.25, 1e-15, "heavier cluster's mass (exact)");
    CHECK_CLOSE(r.frag[1].m, 0.064, 1e-15, "lighter cluster's mass (exact)");
    CHECK(r.frag[0].count == 125 && r.frag[1].count == 64, "particle counts %zu, %zu",
          r.frag[0].count, r.frag[1].count);
    CHECK(r.frag[0].root == 0 && r.frag[1].root == 125, "roots are the smallest slots");
    CHECK(r.frag[0].root_id == 1000 && r.frag[1].root_id == 1125, "root ids");
    CHECK_CLOSE(r.frag[0].x[0], 2 * S, 1e-15, "centre of the first cluster, x");
    CHECK_CLOSE(r.frag[0].x[2], 2 * S, 1e-15, "centre of the first cluster, z");
    CHECK_CLOSE(r.frag[1].x[0], 4 * S + gap + 1.5 * S, 1e-15, "centre of the second, x");
    CHECK_CLOSE(r.frag[1].x[1], 1.5 * S, 1e-15, "centre of the second, y");
    CHECK_CLOSE(r.frag[0].v[0], 100.0, 1e-12, "velocity of the first, vx");
    CHECK_CLOSE(r.frag[0].v[2], -3.0, 1e-12, "velocity of the first, vz");
    CHECK_CLOSE(r.frag[1].v[0], -50.0, 1e-12, "velocity of the second, vx");
    CHECK_CLOSE(r.frag[1].v[1], 20.0, 1e-12, "velocity of the second, vy");
    CHECK_CLOSE(r.mat_mass[0 * 2 + 0], 0.25, 1e-15, "first: all material 0");
    CHECK_CLOSE(r.mat_mass[0 * 2 + 1], 0.0, 0.0, "first: no material 1");
    CHECK_CLOSE(r.mat_mass[1 * 2 + 0], 0.032, 1e-15, "second: 32 g of material 0");
    CHECK_CLOSE(r.mat_mass[1 * 2 + 1], 0.032, 1e-15, "second: 32 g of material 1");
    CHECK_CLOSE(r.m_total, 0.314, 1e-15, "total mass");
    int ok = 1;
    for (size_t i = 0; i < p.n; i++) ok &= r.group[i] == (i < 125 ? 0 : 1);
    CHECK(ok, "every particle labelled with its cluster");
  }
  fof_result_free(&r);

  par.b = 1.01 * gap; /* longer than the gap: one fragment */
  CHECK(fof_find(&p, &par, &r, &err) == 0, "fof runs");
  CHECK(r.nfrag == 1, "b = 1.01 × gap merges the clusters: %zu fragments", r.nfrag);
  if (r.nfrag == 1) {
    CHECK_CLOSE(r.frag[0].m, 0.314, 1e-15, "merged mass");
    CHECK_CLOSE(r.frag[0].v[0], (0.25 * 100 - 0.064 * 50) / 0.314, 1e-12, "merged momentum / mass");
  }
  fof_result_free(&r);
  par.b = 0.99 * gap;
  CHECK(fof_find(&p, &par, &r, &err) == 0 && r.nfrag == 2, "b = 0.99 × gap keeps two");
  fof_result_free(&r);
  par.b = 0.9 * S; /* shorter than the lattice spacing: every particle alone */
  CHECK(fof_find(&p, &par, &r, &err) == 0 && r.nfrag == p.n, "b < Δ: %zu single particles",
        r.nfrag);
  CHECK(r.nfrag == p.n && r.frag[0].m == 2e-3 && r.frag[0].root == 0 && r.frag[124].root == 124 &&
            r.frag[125].root == 125,
        "equal masses sorted by smallest slot");
  CHECK(fof_count_min(&r, 2) == 0, "no fragment of two or more particles");
  fof_result_free(&r);

  /* a mask leaves out the second cluster */
  if (p.n != 125 + 64) { /* two_clusters' particles; the mask below is one per slot */
    CHECK(0, "two clusters of 125 + 64 particles: %zu", p.n);
    particles_free(&p);
    return;
  }
  unsigned char *mask = calloc(p.n, 1);
  for (size_t i = 0; i < 125; i++) mask[i] = 1;
  par.b = 1.01 * gap;
  par.mask = mask;
  CHECK(fof_find(&p, &par, &r, &err) == 0 && r.nfrag == 1 && fabs(r.frag[0].m - 0.25) < 1e-15,
        "mask: only the first cluster");
  CHECK(r.group[125] == -1 && r.group[0] == 0, "masked particles have no fragment");
  fof_result_free(&r);
  free(mask);
  particles_free(&p);
}

static void test_half_model(void)
{
  struct particles p;
  particles_init(&p);
  const double v[3] = {10, 0, 5};
  const double on[3] = {0, 0, 0.5 * S}, off[3] = {20 * S, 0, 10 * S};
  add_block(&p, on, 3, 3, 3, S, 1e-3, v, 0, 0, 0);  /* touches z = 0: its own mirror */
  add_block(&p, off, 2, 2, 2, S, 1e-3, v, 0, 0, 0); /* has a mirror twin */
  struct fof_params par = {.b = 1.5 * S, .nmat = 1, .half_model = 1};
  struct fof_result r;
  struct hv_error err;
  CHECK(fof_find(&p, &par, &r, &err) == 0 && r.nfrag == 2, "half model: two fragments");
  if (r.nfrag == 2) {
    CHECK_CLOSE(r.frag[0].m, 2 * 27e-3, 1e-15, "on the plane: mass doubled");
    CHECK(r.frag[0].multiplicity == 1, "on the plane: multiplicity 1");
    CHECK(r.frag[0].x[2] == 0.0 && r.frag[0].v[2] == 0.0, "on the plane: z = 0, vz = 0");
    CHECK_CLOSE(r.mat_mass[0], 2 * 27e-3, 1e-15, "material mass doubled too");
    CHECK_CLOSE(r.frag[1].m, 8e-3, 1e-15, "off the plane: one twin's mass");
    CHECK(r.frag[1].multiplicity == 2, "off the plane: multiplicity 2");
    CHECK_CLOSE(r.frag[1].x[2], 10.5 * S, 1e-15, "off the plane: its own centre");
    CHECK(r.n_full == 3, "full picture: 3 fragments (%zu)", r.n_full);
    CHECK_CLOSE(r.m_total, 2 * 27e-3 + 2 * 8e-3, 1e-15, "full mass");
  }
  fof_result_free(&r);
  particles_free(&p);
}

/* A quarter model (planes y = 0 and z = 0): a fragment on both planes is one piece with
 * its three images (mass x 4, multiplicity 1), one on the plane y = 0 only is one with
 * its image there and has a twin across z = 0 (mass x 2, multiplicity 2), one clear of
 * both stands for four (multiplicity 4). */
static void test_quarter_model(void)
{
  struct particles p;
  particles_init(&p);
  const double v[3] = {10, 3, 5};
  const double both[3] = {0, 0.5 * S, 0.5 * S}, ony[3] = {20 * S, 0.5 * S, 10 * S},
               clear[3] = {40 * S, 10 * S, 10 * S};
  add_block(&p, both, 3, 3, 3, S, 1e-3, v, 0, 0, 0);
  add_block(&p, ony, 3, 3, 3, S, 1e-3, v, 0, 0, 0);
  add_block(&p, clear, 2, 2, 2, S, 1e-3, v, 0, 0, 0);
  struct fof_params par = {.b = 1.5 * S, .nmat = 1, .half_model = 1, .quarter_model = 1};
  struct fof_result r;
  struct hv_error err;
  CHECK(fof_find(&p, &par, &r, &err) == 0 && r.nfrag == 3, "quarter model: three fragments");
  if (r.nfrag == 3) {
    CHECK_CLOSE(r.frag[0].m, 4 * 27e-3, 1e-15, "on both planes: mass x 4");
    CHECK(r.frag[0].multiplicity == 1, "on both planes: multiplicity 1");
    CHECK(r.frag[0].x[1] == 0.0 && r.frag[0].x[2] == 0.0 && r.frag[0].v[1] == 0.0 &&
              r.frag[0].v[2] == 0.0,
          "on both planes: on the axis, moving along it");
    CHECK_CLOSE(r.frag[1].m, 2 * 27e-3, 1e-15, "on y = 0 only: mass x 2");
    CHECK(r.frag[1].multiplicity == 2 && r.frag[1].count == 54,
          "on y = 0 only: multiplicity 2, the half model's 54 particles (%zu)", r.frag[1].count);
    CHECK(r.frag[0].count == 54 && r.frag[2].count == 8,
          "counts: the half model's particles (%zu, %zu)", r.frag[0].count, r.frag[2].count);
    CHECK(r.frag[1].x[1] == 0.0 && r.frag[1].v[1] == 0.0 && fabs(r.frag[1].v[2] - 5.0) < 1e-12,
          "on y = 0 only: y = 0, vy = 0, its own vz");
    CHECK_CLOSE(r.frag[2].m, 8e-3, 1e-15, "clear of both: one image's mass");
    CHECK(r.frag[2].multiplicity == 4, "clear of both: multiplicity 4");
    CHECK(r.n_full == 7, "full picture: 7 fragments (%zu)", r.n_full);
    CHECK_CLOSE(r.m_total, 4 * (27e-3 + 27e-3 + 8e-3), 1e-15, "full mass");
    CHECK_CLOSE(r.mat_mass[0], 4 * 27e-3, 1e-15, "material mass of the first x 4 too");
  }
  fof_result_free(&r);
  particles_free(&p);
}

/* O(N²) reference labels: the smallest index of each particle's set. */
static void brute(const struct particles *p, const double *b, uint32_t *root)
{
  const size_t n = p->n;
  for (size_t i = 0; i < n; i++) root[i] = (uint32_t)i;
  for (size_t i = 0; i < n; i++)
    for (size_t j = i + 1; j < n; j++) {
      double r2 = 0;
      for (int d = 0; d < 3; d++) r2 += (p->x[d][i] - p->x[d][j]) * (p->x[d][i] - p->x[d][j]);
      const double l = 0.5 * (b[i] + b[j]);
      if (r2 < l * l) {
        uint32_t a = (uint32_t)i, c = (uint32_t)j;
        while (root[a] != a) a = root[a];
        while (root[c] != c) c = root[c];
        if (a < c)
          root[c] = a;
        else if (c < a)
          root[a] = c;
      }
    }
  for (size_t i = 0; i < n; i++) {
    uint32_t a = (uint32_t)i;
    while (root[a] != a) a = root[a];
    root[i] = a;
  }
}

static uint64_t rng = 88172645463325252ULL;
static double urand(void)
{
  rng ^= rng << 13;
  rng ^= rng >> 7;
  rng ^= rng << 17;
  return (double)(rng >> 11) / 9007199254740992.0;
}

static int pair_cmp(const void *pa, const void *pb)
{
  const double *a = pa, *b = pb;
  if (a[0] != b[0]) return a[0] < b[0] ? -1 : 1;
  return a[1] < b[1] ? -1 : a[1] > b[1];
}

static void test_brute_force(int per_particle)
{
  struct particles p;
  particles_init(&p);
  const size_t n = 3000;
  const double v0[3] = {0, 0, 0};
  for (size_t i = 0; i < n; i++) /* clumpy: points around 40 centres */
    add_particle(&p, 0, 0, 0, 1.0 + (double)(i % 7), v0, 0, 0);
  double cx[40][3];
  for (int c = 0; c < 40; c++)
    for (int d = 0; d < 3; d++) cx[c][d] = urand() * 0.1;
  double *b = malloc(n * sizeof *b);
  for (size_t i = 0; i < n; i++) {
    const int c = (int)(urand() * 40) % 40;
    for (int d = 0; d < 3; d++) p.x[d][i] = cx[c][d] + (urand() - 0.5) * 0.012;
    b[i] = per_particle ? 1e-3 * (0.5 + 1.5 * urand()) : 1.2e-3;
  }
  struct fof_params par = {.b = 1.2e-3, .b_particle = per_particle ? b : NULL, .nmat = 1};
  struct fof_result r;
  struct hv_error err;
  CHECK(fof_find(&p, &par, &r, &err) == 0, "random points: fof runs");
  uint32_t *root = malloc(n * sizeof *root);
  brute(&p, b, root);
  int same = 1;
  size_t nroots = 0;
  for (size_t i = 0; i < n; i++) {
    nroots += root[i] == i;
    same &= r.group[i] >= 0 && r.frag[r.group[i]].root == root[i];
  }
  CHECK(same && nroots == r.nfrag,
        "%s linking: grid agrees with the O(N²) search (%zu vs %zu "
        "fragments)",
        per_particle ? "per-particle" : "uniform", r.nfrag, nroots);
  int sorted = 1;
  double msum = 0;
  for (size_t f = 0; f < r.nfrag; f++) {
    msum += r.frag[f].m;
    if (f)
      sorted &= r.frag[f].m < r.frag[f - 1].m ||
                (r.frag[f].m == r.frag[f - 1].m && r.frag[f].root > r.frag[f - 1].root);
  }
  CHECK(sorted, "fragments sorted by mass, then root");
  CHECK(r.nfrag > 40 && r.nfrag < n, "a mixture of clusters and loners (%zu)", r.nfrag);
  CHECK_CLOSE(msum, r.m_total, 1e-9, "fragment masses add up");

  /* the same particles in reverse order give the same fragments (masses, counts) */
  struct particles q;
  particles_init(&q);
  double *bq = malloc(n * sizeof *bq);
  for (size_t k = 0; k < n; k++) {
    const size_t i = n - 1 - k;
    const double vv[3] = {p.v[0][i], p.v[1][i], p.v[2][i]};
    add_particle(&q, p.x[0][i], p.x[1][i], p.x[2][i], p.m[i], vv, 0, 0);
    bq[k] = b[i];
  }
  struct fof_params parq = par;
  parq.b_particle = per_particle ? bq : NULL;
  struct fof_result rq;
  CHECK(fof_find(&q, &parq, &rq, &err) == 0 && rq.nfrag == r.nfrag, "reversed order: same count");
  int eq = rq.nfrag == r.nfrag;
  if (eq) { /* equal masses may be ordered differently: compare sorted (mass, count) lists */
    double *a = malloc(2 * r.nfrag * sizeof *a), *c = malloc(2 * r.nfrag * sizeof *c);
    for (size_t f = 0; f < r.nfrag; f++) {
      a[2 * f] = r.frag[f].m;
      a[2 * f + 1] = (double)r.frag[f].count;
      c[2 * f] = rq.frag[f].m;
      c[2 * f + 1] = (double)rq.frag[f].count;
    }
    qsort(a, r.nfrag, 2 * sizeof *a, pair_cmp);
    qsort(c, r.nfrag, 2 * sizeof *c, pair_cmp);
    for (size_t f = 0; f < 2 * r.nfrag; f++) eq &= fabs(a[f] - c[f]) <= 1e-9 * fabs(a[f]);
    free(a);
    free(c);
  }
  CHECK(eq, "reversed order: same masses and counts, fragment by fragment");
  fof_result_free(&rq);
  free(bq);
  particles_free(&q);
  free(root);
  free(b);
  fof_result_free(&r);
  particles_free(&p);
}

static void test_csv(void)
{
  struct particles p;
  particles_init(&p);
  two_clusters(&p, 3 * S);
  struct fof_params par = {.b = 1.5 * S, .nmat = 2};
  struct fof_result r;
  struct hv_error err;
  hv_error_clear(&err);
  CHECK(fof_find(&p, &par, &r, &err) == 0, "fof runs");
  char path[4200];
  snprintf(path, sizeof path, "%s/fragments_00003.csv", test_tmpdir());
  const char *names[2] = {"tungsten", "steel"};
  CHECK(fof_write_csv(path, &r, 1.5e-5, names, "hvsph test", &err) == 0, "writes %s: %s", path,
        err.msg);
  FILE *f = fopen(path, "r");
  char line[3][1024] = {{0}};
  int nl = 0;
  char buf[1024];
  while (f && fgets(buf, sizeof buf, f))
    if (buf[0] != '#' && nl < 3) snprintf(line[nl++], sizeof line[0], "%s", buf);
  if (f) fclose(f);
  CHECK(strcmp(line[0], "rank,mass,multiplicity,count,x,y,z,vx,vy,vz,root_id,m_tungsten,"
                        "m_steel\n") == 0,
        "header: %s", line[0]);
  double m1 = 0, cnt1 = 0, x1 = 0;
  CHECK(sscanf(line[1], "0,%lf,1,%lf,%lf,", &m1, &cnt1, &x1) == 3 && m1 == r.frag[0].m &&
            cnt1 == 125 && x1 == r.frag[0].x[0],
        "first row (values round-trip): %s", line[1]);
  double m2 = 0, cnt2 = 0;
  CHECK(sscanf(line[2], "1,%lf,1,%lf,", &m2, &cnt2) == 2 && m2 == r.frag[1].m && cnt2 == 64,
        "second row: %s", line[2]);
  fof_result_free(&r);
  particles_free(&p);
}

static void test_bad_input(void)
{
  struct particles p;
  particles_init(&p);
  two_clusters(&p, 3 * S);
  struct fof_params par = {.b = 0.0, .nmat = 1};
  struct fof_result r;
  struct hv_error err;
  hv_error_clear(&err);
  CHECK(fof_find(&p, &par, &r, &err) == -1 && err.code == HV_EXIT_INPUT, "b = 0 is an error");
  CHECK(strstr(err.msg, "linking length") != NULL, "message names the linking length: %s", err.msg);
  par.b = 1e-30; /* far too many cells across the particles */
  hv_error_clear(&err);
  CHECK(fof_find(&p, &par, &r, &err) == -1 && err.code == HV_EXIT_RUN,
        "tiny b: an error, not "
        "a crash (%s)",
        err.msg);
  p.x[0][3] = NAN;
  par.b = 1.5 * S;
  CHECK(fof_find(&p, &par, &r, &err) == 0 && r.n_skipped == 1 && r.group[3] == -1,
        "a non-finite position is skipped and counted");
  fof_result_free(&r);
  particles_free(&p);
}

int main(void)
{
  test_two_clusters();
  test_half_model();
  test_quarter_model();
  test_brute_force(0);
  test_brute_force(1);
  test_csv();
  test_bad_input();
  return test_finish();
}
