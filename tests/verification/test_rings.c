/* test_rings.c — colliding rubber rings (Gray, Monaghan & Swift 2001, CMAME 190:6641;
 * issue 3, item 6; examples/verification/rings.yaml).
 *
 * Two elastic rings (inner radius 3, outer radius 4, ρ₀ = c₀ = 1, G = 0.22) approach
 * each other at 0.059 c₀ each, collide, and bounce apart. The test runs the case three times:
 *
 * 1. As given (Monaghan–Gray artificial stress on, ε = 0.3): at every output time each
 *    ring is one friends-of-friends group (linking length b = FOF_FACTOR × the initial
 *    spacing, periodic in z like the case, in the full picture: the simulated half and
 *    its mirror image) — no particle has left its ring; and at the end the
 *    centre-of-mass velocities are reversed: the left ring moves left and the right ring
 *    right, each faster than VREV_MIN × the impact speed, and the rings' centres are
 *    moving apart. Measured at the time of writing: one group per ring at every output;
 *    the centres turn round at t ≈ 92; at t = 140 the rings separate at ∓0.0070 (12% of
 *    the impact speed; the rings are still touching and still accelerating apart).
 *    Reported but not asserted: whether each ring is still a closed loop (ring_analysis
 *    below). It is not: from t ≈ 70 each ring has a crack through its far side (at
 *    y = 0, where the hoop tension of the flattened ring is largest), and at twice the
 *    resolution it cracks in several places. The friends-of-friends criterion of the
 *    brief (no particle leaves its ring) does not see a crack that leaves the ring in
 *    one piece; this is recorded as a problem of the artificial stress at ε = 0.3 in
 *    docs/verification-solids.md.
 * 2. With sph.artificial_stress.epsilon = 0 (until t = 100): the tensile instability
 *    opens gaps wider than b in the rings — at some output a ring falls apart into more
 *    than one group. Measured at the time of writing (full picture): 3 groups at t = 60,
 *    up to 6 (largest 606 of 2184 particles) at t = 90; the gaps open and close again
 *    (the rings are not torn to pieces, but they are no longer continuous solids).
 * 3. With sph.artificial_stress.epsilon = 0.6: the rings stay closed loops at every
 *    output (no crack) and bounce back nearly elastically: at t = 140 the centres move
 *    apart at more than VREV_STRONG × the impact speed. Measured at the time of writing:
 *    no crack; turn-round at t ≈ 82; ∓0.0419 at t = 140 (71% of the impact speed, against
 *    12% with the cracked rings of run 1, whose cracks take up the elastic energy).
 * What the checks catch: rings that stick together (no reversal of the centre-of-mass
 * velocities), particles torn off a ring (more than one group), and — run 2 — the
 * tensile instability that the artificial stress exists to suppress.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "solidcase.h"
#include "testlib.h"

#define V_IMPACT 0.059 /* [c0] each ring's speed towards the other (the case) */
#define LZ       1.5   /* [length unit] the case's periodic domain height in z */
#define FOF_FACTOR                                                                                 \
  1.5 /* linking length in initial spacings (the brief; fof.h's
                              documented default FOF_B_FACTOR) */
#define VREV_MIN                                                                                   \
  0.05                    /* reversed speed at the end > 5% of the impact speed
                              (measured 12% at t = 140: a clear bounce, with margin) */
#define EPS0_END    "100" /* run 2: end time (the gaps open from t = 60) */
#define EPS_STRONG  "0.6" /* run 3: a stronger artificial stress (see the header) */
#define VREV_STRONG 0.5   /* run 3: rebound > 50% of the impact speed (measured 71%) */
#define HV_PI       3.14159265358979323846

/* Union-find root with path halving. */
static size_t root(size_t *par, size_t a)
{
  while (par[a] != a) a = par[a] = par[par[a]];
  return a;
}

/* Friends-of-friends analysis of ring b in the full picture: the simulated half y > 0
 * and its mirror image (the case's y_min symmetry plane), periodic in z.
 *   *groups:  groups among all its particles (1: nothing has left the ring);
 *   *largest: particles in the largest group (of the full picture);
 *   returns the number of "cuts": of NWIN angular windows (half-width WIN_DEG about
 *   the ring's centre of mass) whose removal leaves the rest of the ring in more than
 *   one group of at least MIN_PIECE of its particles (smaller islands left at the
 *   window's edges are not counted). An intact ring is a closed loop: taking out any
 *   one window leaves one C-shaped group; a ring with a crack somewhere falls apart
 *   when a window elsewhere is taken out (a single crack does not split a loop, so
 *   counting groups alone would not see it). */
#define NWIN      8    /* windows every 45 degrees */
#define WIN_DEG   12.0 /* removed arc 24 deg: 1.26 at the inner radius 3, > b = 0.375 */
#define MIN_PIECE 0.05 /* a piece counts when it holds 5% of the ring's particles */
static int ring_analysis(const struct particles *p, int b, double link, int *groups,
                         size_t *largest)
{
  size_t m = 0;
  for (size_t i = 0; i < p->n; i++) m += p->body[i] == b;
  const size_t n2 = 2 * m;
  double *x = malloc(n2 * sizeof *x), *y = malloc(n2 * sizeof *y), *z = malloc(n2 * sizeof *z);
  double *ang = malloc(n2 * sizeof *ang), xc = 0;
  size_t k = 0;
  for (size_t i = 0; i < p->n; i++)
    if (p->body[i] == b) {
      for (int s = 0; s < 2; s++) { /* the particle and its mirror image */
        x[k + s * m] = p->x[0][i];
        y[k + s * m] = s ? -p->x[1][i] : p->x[1][i];
        z[k + s * m] = p->x[2][i];
      }
      xc += p->x[0][i];
      k++;
    }
  xc /= (double)m; /* centre of the full ring: (xc, 0) */
  for (size_t a = 0; a < n2; a++) ang[a] = atan2(y[a], x[a] - xc) * 180.0 / HV_PI;
  /* pairs closer than the linking length (nearest image in z), from a grid of cells
     of side b in x and y (counting sort by cell) */
  double xlo = HUGE_VAL, ylo = HUGE_VAL, xhi = -HUGE_VAL, yhi = -HUGE_VAL;
  for (size_t a = 0; a < n2; a++) {
    xlo = fmin(xlo, x[a]);
    xhi = fmax(xhi, x[a]);
    ylo = fmin(ylo, y[a]);
    yhi = fmax(yhi, y[a]);
  }
  const long nx = (long)((xhi - xlo) / link) + 1, ny = (long)((yhi - ylo) / link) + 1;
  size_t *start = calloc((size_t)(nx * ny) + 1, sizeof *start), *order = malloc(n2 * sizeof *order);
  long *cell = malloc(n2 * sizeof *cell);
  for (size_t a = 0; a < n2; a++) {
    cell[a] = (long)((x[a] - xlo) / link) * ny + (long)((y[a] - ylo) / link);
    start[cell[a] + 1]++;
  }
  for (long c = 0; c < nx * ny; c++) start[c + 1] += start[c];
  {
    size_t *fill = malloc((size_t)(nx * ny) * sizeof *fill);
    for (long c = 0; c < nx * ny; c++) fill[c] = start[c];
    for (size_t a = 0; a < n2; a++) order[fill[cell[a]]++] = a;
    free(fill);
  }
  size_t npair = 0, cap = 16 * n2;
  size_t *pa = malloc(cap * sizeof *pa), *pb = malloc(cap * sizeof *pb);
  const double b2 = link * link;
  for (size_t a = 0; a < n2; a++) {
    const long cx = cell[a] / ny, cy = cell[a] % ny;
    for (long ix = cx - 1; ix <= cx + 1; ix++)
      for (long iy = cy - 1; iy <= cy + 1; iy++) {
        if (ix < 0 || ix >= nx || iy < 0 || iy >= ny) continue;
        const long cc = ix * ny + iy;
        for (size_t q = start[cc]; q < start[cc + 1]; q++) {
          const size_t c = order[q];
          if (c <= a) continue;
          const double dx = x[a] - x[c], dy = y[a] - y[c];
          double dz = fabs(z[a] - z[c]);
          if (dz > 0.5 * LZ) dz = LZ - dz;
          if (dx * dx + dy * dy + dz * dz >= b2) continue;
          if (npair == cap) {
            cap *= 2;
            pa = realloc(pa, cap * sizeof *pa);
            pb = realloc(pb, cap * sizeof *pb);
          }
          pa[npair] = a;
          pb[npair++] = c;
        }
      }
  }
  free(start);
  free(order);
  free(cell);
  size_t *par = malloc(n2 * sizeof *par), *cnt = malloc(n2 * sizeof *cnt);
  unsigned char *out = malloc(n2);
  int cuts = 0;
  for (int w = -1; w < NWIN; w++) { /* w = -1: the whole ring */
    const double centre = -180.0 + 360.0 * w / NWIN;
    for (size_t a = 0; a < n2; a++) {
      double d = fabs(ang[a] - centre);
      if (d > 180.0) d = 360.0 - d;
      out[a] = w >= 0 && d < WIN_DEG;
      par[a] = a;
      cnt[a] = 0;
    }
    for (size_t q = 0; q < npair; q++) {
      if (out[pa[q]] || out[pb[q]]) continue;
      size_t ra = root(par, pa[q]), rc = root(par, pb[q]);
      if (ra != rc) par[ra > rc ? ra : rc] = ra < rc ? ra : rc;
    }
    int g = 0, pieces = 0;
    size_t big = 0;
    for (size_t a = 0; a < n2; a++) {
      if (out[a]) continue;
      size_t r = root(par, a);
      if (cnt[r]++ == 0) g++;
      if (cnt[r] == (size_t)(MIN_PIECE * (double)n2) + 1) pieces++;
      if (cnt[r] > big) big = cnt[r];
    }
    if (w < 0) {
      *groups = g;
      *largest = big;
    } else if (pieces > 1) {
      cuts++;
    }
  }
  free(x);
  free(y);
  free(z);
  free(ang);
  free(pa);
  free(pb);
  free(par);
  free(cnt);
  free(out);
  return cuts;
}

/* Centre-of-mass x and x-velocity of body b. */
static void com(const struct particles *p, int b, double *x, double *v)
{
  double m = 0, mx = 0, mv = 0;
  for (size_t i = 0; i < p->n; i++)
    if (p->body[i] == b) {
      m += p->m[i];
      mx += p->m[i] * p->x[0][i];
      mv += p->m[i] * p->v[0][i];
    }
  *x = mx / m;
  *v = mv / m;
}

/* Runs one variant; *worst_groups and *worst_cuts get the largest numbers of groups and
 * cuts (ring_analysis) seen in a ring at any output, *first_cut the first output time
 * with a cut (or -1); the last output's centre-of-mass positions and velocities go to
 * xc, vc (and the one before to xc_prev). Returns 0, or -1 when the run fails. */
static int run_variant(const char *out, const char *extra, int *worst_groups, int *worst_cuts,
                       double *first_cut, double xc[2], double vc[2], double xc_prev[2],
                       double *t_end, int *nsnap_out)
{
  double secs, v;
  int rc = sc_run("rings", out, extra, &secs);
  CHECK(rc == 0, "rings.yaml %s runs (exit status %d, %.1f s)", extra ? extra : "", rc, secs);
  if (rc) return -1;
  const char *dir = sc_outdir(out);
  const int nsnap = sc_count_snapshots(dir);
  *nsnap_out = nsnap;
  *worst_groups = *worst_cuts = 0;
  *first_cut = -1;
  *t_end = NAN; /* with fewer than two outputs the checks on these fail, as they should */
  for (int b = 0; b < 2; b++) xc[b] = vc[b] = xc_prev[b] = NAN;
  double link = 0;
  for (int k = 0; k < nsnap; k++) {
    struct particles p;
    double t;
    if (sc_read(dir, k, &p, &t)) return -1;
    if (k == 0) {
      link = FOF_FACTOR * cbrt(p.m[0] / p.rho[0]); /* m = rho0 x spacing^3 (cubic) */
      printf("  %zu particles (half of each ring), linking length %.4f\n", p.n, link);
    }
    printf("  t = %5.1f", t);
    for (int b = 0; b < 2; b++) {
      size_t largest = 0;
      int g = 0;
      const int cuts = ring_analysis(&p, b, link, &g, &largest);
      if (g > *worst_groups) *worst_groups = g;
      if (cuts > *worst_cuts) *worst_cuts = cuts;
      if (cuts > 0 && *first_cut < 0) *first_cut = t;
      if (k == nsnap - 2) com(&p, b, &xc_prev[b], &v);
      com(&p, b, &xc[b], &vc[b]);
      printf(" | %s: x_cm %+.3f v_cm %+.5f, %d group(s) (largest %zu), %d of %d windows cut",
             b ? "right" : "left", xc[b], vc[b], g, largest, cuts, NWIN);
    }
    printf("\n");
    *t_end = t;
    particles_free(&p);
  }
  return 0;
}

int main(void)
{
  double xc[2], vc[2], xp[2], t_end, first_cut;
  int nsnap, groups, cuts;
  printf("run 1: artificial stress on (the case as given)\n");
  if (run_variant("rings", NULL, &groups, &cuts, &first_cut, xc, vc, xp, &t_end, &nsnap))
    return test_finish();
  CHECK(nsnap >= 10, "%d snapshots", nsnap);
  CHECK(groups == 1,
        "no particle leaves its ring: every ring is one friends-of-friends group "
        "at every output (largest count of groups: %d)",
        groups);
  /* Reported, not asserted (see the header): whether the rings stay closed loops. */
  if (cuts == 0)
    printf("note: the rings stay closed loops (no crack) at every output\n");
  else
    printf("note: KNOWN PROBLEM: the rings crack (they stay single groups, but are no longer "
           "closed loops): up to %d of %d windows cut, first at t = %.0f "
           "(docs/verification-solids.md)\n",
           cuts, NWIN, first_cut);
  CHECK(vc[0] < -VREV_MIN * V_IMPACT && vc[1] > VREV_MIN * V_IMPACT,
        "the rings bounce: at t = %.0f the centre-of-mass velocities are %+.5f (left) and "
        "%+.5f (right), reversed and faster than %.0f%% of the impact speed %.3f",
        t_end, vc[0], vc[1], 100 * VREV_MIN, V_IMPACT);
  CHECK(xc[1] - xc[0] > xp[1] - xp[0],
        "the rings move apart: centre distance %.4f at the "
        "end > %.4f one output earlier",
        xc[1] - xc[0], xp[1] - xp[0]);

  printf("run 2: sph.artificial_stress.epsilon = 0\n");
  if (run_variant("rings_eps0", "--set sph.artificial_stress.epsilon=0 --set time.end=" EPS0_END,
                  &groups, &cuts, &first_cut, xc, vc, xp, &t_end, &nsnap))
    return test_finish();
  CHECK(groups > 1,
        "without artificial stress the tensile instability opens the rings: up to "
        "%d friends-of-friends groups in a ring",
        groups);

  printf("run 3: sph.artificial_stress.epsilon = " EPS_STRONG "\n");
  if (run_variant("rings_eps06", "--set sph.artificial_stress.epsilon=" EPS_STRONG, &groups, &cuts,
                  &first_cut, xc, vc, xp, &t_end, &nsnap))
    return test_finish();
  CHECK(groups == 1 && cuts == 0,
        "with epsilon = " EPS_STRONG " the rings stay closed loops "
        "(largest count of groups %d, of cut windows %d)",
        groups, cuts);
  CHECK(vc[0] < -VREV_STRONG * V_IMPACT && vc[1] > VREV_STRONG * V_IMPACT,
        "with epsilon = " EPS_STRONG " the rings bounce back elastically: at t = %.0f the "
        "centre-of-mass velocities are %+.5f and %+.5f, more than %.0f%% of the impact speed",
        t_end, vc[0], vc[1], 100 * VREV_STRONG);
  return test_finish();
}
