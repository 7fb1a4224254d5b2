/* measure.c — thick-target cavity, debris cloud, backwall and gas shock front; the
 * plate's hole is in measure_plate.c. Definitions in measure.h and
 * docs/measurements.md. Every loop is serial and runs in slot order, so results do
 * not depend on the number of threads.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "diag/measure.h"

#include "diag/fof.h"
#include "diag/measure_rz.h"

#define MEAS_MAX_CELLS    4096 /* per side of the backwall's column grid */
#define CAVITY_MAX_SLICES 100000000

/* Particle i belongs to the body (body < 0: any), passes the mask and has a finite position. */
static int taken(const struct particles *p, size_t i, int body, const unsigned char *mask)
{
  if (body >= 0 && p->body[i] != body) return 0;
  if (mask && !mask[i]) return 0;
  return isfinite(p->x[0][i]) && isfinite(p->x[1][i]) && isfinite(p->x[2][i]);
}

/* Distance from the axis y = yc, z = 0. */
static double radial(const struct particles *p, size_t i, double yc)
{
  return hypot(p->x[1][i] - yc, p->x[2][i]);
}

static int geom_ok(const struct meas_geom *g, const char *what, struct hv_error *err)
{
  if (!(g->spacing > 0 && isfinite(g->spacing) && isfinite(g->x0) && isfinite(g->yc) &&
        g->thickness >= 0 && isfinite(g->thickness)))
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: the geometry needs a positive spacing (%g m), "
                        "a thickness >= 0 (%g m) and finite x0, yc",
                        what, g->spacing, g->thickness);
  return 0;
}

/* ---- thick target ---------------------------------------------------------------- */

void meas_cavity_defaults(struct meas_cavity_params *par, const struct meas_geom *g)
{
  memset(par, 0, sizeof *par);
  par->slice = 0.5 * g->spacing;
  par->footprint = 0.5 * g->spacing;
  par->r_open = g->spacing;
  par->v_max = INFINITY;
  par->min_count = 1;
  par->wall_slab = 4.0 * g->spacing;
  par->wall_dr = 0.25 * g->spacing;
  par->wall_fill = 0.5;
  par->mask = NULL;
}

void meas_cavity_free(struct meas_cavity *c)
{
  free(c->r_profile);
  c->r_profile = NULL;
  c->nslice = 0;
}

static int cavity_taken(const struct particles *p, size_t i, const struct meas_geom *g,
                        const struct meas_cavity_params *par)
{
  if (!taken(p, i, g->body, par->mask) || p->x[0][i] < g->x0) return 0;
  if (isfinite(par->v_max)) {
    const double v2 = p->v[0][i] * p->v[0][i] + p->v[1][i] * p->v[1][i] + p->v[2][i] * p->v[2][i];
    if (!(v2 <= par->v_max * par->v_max)) return 0;
  }
  return 1;
}

#define CAVITY_MAX_WALL_BINS 50000000
#define CAVITY_WALL_ANNULI   4000.0

/* Adds w × (the share of [lo, hi] that falls in bin j, bins of width d from 0) to
 * acc[j] for j < n. */
static void spread(double *acc, size_t n, double d, double lo, double hi, double w)
{
  if (!(hi > lo)) return;
  const double per = w / (hi - lo);
  const double jlo = floor(lo / d), jhi = floor(hi / d);
  for (double jd = fmax(0.0, jlo); jd <= jhi && jd < (double)n; jd += 1.0) {
    const double a = fmax(lo, jd * d), b = fmin(hi, (jd + 1.0) * d);
    if (b > a) acc[(size_t)jd] += per * (b - a);
  }
}

/* The wall by filled volume over the slabs wholly within x0 .. x0 + out->L (measure.h):
 * sets out->D_wall, D_wall_mean and nwall. Each particle fills a cube of its own volume
 * m/ρ: its volume is spread evenly over its edge w = (m/ρ)^(1/3) in depth and in radius
 * (clipped at the axis), so that a lattice fills the annuli evenly whatever its spacing
 * and orientation, and a sharp wall of centres at r_c reads as material from r_c − w/2. */
static int cavity_wall(const struct particles *p, const struct meas_geom *g,
                       const struct meas_cavity_params *par, struct meas_cavity *out,
                       struct hv_error *err)
{
  const double ds = par->wall_slab, dr = par->wall_dr;
  const double nsd = floor(out->L / ds);
  if (!(nsd >= 1.0)) return 0;
  double rmax = 0.0;
  for (size_t i = 0; i < p->n; i++)
    if (cavity_taken(p, i, g, par) && p->x[0][i] < g->x0 + nsd * ds + g->spacing)
      rmax = fmax(rmax, radial(p, i, g->yc));
  /* annuli out to the farthest target particle, at most CAVITY_WALL_ANNULI of them: a
     fragment flung far out is not wall, and the wall lies within the first few hundred */
  const double nbd = fmin(floor((rmax + g->spacing) / dr) + 2.0, CAVITY_WALL_ANNULI);
  if (!(nsd * nbd <= CAVITY_MAX_WALL_BINS))
    return hv_error_set(err, HV_EXIT_INPUT,
                        "cavity measurement: %g × %g wall bins; use wider "
                        "wall_slab or wall_dr",
                        nsd, nbd);
  const size_t ns = (size_t)nsd, nb = (size_t)nbd;
  double *vol = hv_calloc(ns * nb, sizeof *vol, "cavity wall bins");
  for (size_t i = 0; i < p->n; i++) {
    if (!cavity_taken(p, i, g, par) || !(p->rho[i] > 0) || !(p->m[i] > 0)) continue;
    /* the cell's edge: a cube's, or for a ring (volume 2π r A) its section's √A */
    const double v = p->m[i] / p->rho[i], r = radial(p, i, g->yc), x = p->x[0][i] - g->x0;
    const double w = p->axisym ? sqrt(v / (2.0 * HV_MEAS_PI * r)) : cbrt(v);
    if (!(isfinite(w) && w > 0.0)) continue;
    const double x0 = x - 0.5 * w, x1 = x + 0.5 * w;
    for (double kd = fmax(0.0, floor(x0 / ds)); kd <= floor(x1 / ds) && kd < nsd; kd += 1.0) {
      const double in = fmin(x1, (kd + 1.0) * ds) - fmax(x0, kd * ds);
      if (in > 0)
        spread(vol + (size_t)kd * nb, nb, dr, fmax(0.0, r - 0.5 * w), r + 0.5 * w, v * in / w);
    }
  }
  const double share = 1.0 / meas_images(g->half_model, g->quarter_model);
  double sum = 0.0;
  for (size_t k = 0; k < ns; k++) {
    double *f = vol + k * nb;
    for (size_t b = 0; b < nb; b++) {
      const double r0 = (double)b * dr, r1 = r0 + dr;
      f[b] /= share * HV_MEAS_PI * (r1 * r1 - r0 * r0) * ds;
    }
    double rw = (double)nb * dr; /* no crossing: the wall is beyond the material */
    for (size_t b = 0; b < nb; b++) {
      if (f[b] < par->wall_fill || (b + 1 < nb && f[b + 1] < par->wall_fill)) continue;
      if (b == 0) {
        rw = 0.0;
      } else { /* between the centres of annuli b − 1 (below the fill) and b */
        const double f0 = f[b - 1], f1 = f[b];
        const double t = f1 > f0 ? (par->wall_fill - f0) / (f1 - f0) : 1.0;
        rw = ((double)b - 0.5 + fmin(1.0, fmax(0.0, t))) * dr;
      }
      break;
    }
    out->D_wall = fmax(out->D_wall, 2.0 * rw);
    sum += 2.0 * rw;
  }
  free(vol);
  out->nwall = ns;
  out->D_wall_mean = sum / (double)ns;
  return 0;
}

int measure_cavity(const struct particles *p, const struct meas_geom *g,
                   const struct meas_cavity_params *par, struct meas_cavity *out,
                   struct hv_error *err)
{
  memset(out, 0, sizeof *out);
  if (geom_ok(g, "cavity measurement", err)) return -1;
  if (!(par->slice > 0 && isfinite(par->slice) && par->footprint >= 0 && isfinite(par->footprint) &&
        par->r_open >= 0 && isfinite(par->r_open) && par->v_max > 0 && par->min_count >= 1 &&
        par->min_count <= MEAS_CAVITY_MAX_COUNT && par->wall_slab > 0 && isfinite(par->wall_slab) &&
        par->wall_dr > 0 && isfinite(par->wall_dr) && par->wall_fill > 0 && par->wall_fill < 1))
    return hv_error_set(err, HV_EXIT_INPUT,
                        "cavity measurement: slice (> 0), footprint, r_open "
                        "(>= 0), v_max (> 0), min_count (1..%d), wall_slab and wall_dr (> 0) "
                        "and wall_fill (0..1) out of range",
                        MEAS_CAVITY_MAX_COUNT);
  const int K = par->min_count;
  const double dx = par->slice, fp = par->footprint;
  out->slice = dx;
  /* material more than 2Δ behind the block's original rear face (spall, a plug or
     fragments thrown through it) is not the cavity's: the slices end there, so a
     fragment flung far along the axis neither asks for ~10⁸ slices nor moves L */
  const double xcap = g->thickness > 0 ? g->x0 + g->thickness + 2.0 * g->spacing : (double)INFINITY;
  double xmax = -INFINITY;
  for (size_t i = 0; i < p->n; i++)
    if (cavity_taken(p, i, g, par) && p->x[0][i] > xmax && p->x[0][i] <= xcap) xmax = p->x[0][i];
  if (!isfinite(xmax)) return 0; /* no target material below the surface */
  const double ns = floor((xmax - g->x0) / dx) + 1.0;
  if (!(ns <= CAVITY_MAX_SLICES))
    return hv_error_set(err, HV_EXIT_INPUT,
                        "cavity measurement: %g slices of %g m; use thicker "
                        "slices",
                        ns, dx);
  const size_t nslice = (size_t)ns;
  double *best = hv_malloc(nslice * (size_t)K * sizeof *best, "cavity slices");
  for (size_t k = 0; k < nslice * (size_t)K; k++) best[k] = INFINITY;
  for (size_t i = 0; i < p->n; i++) {
    if (!cavity_taken(p, i, g, par) || p->x[0][i] > xcap) continue;
    size_t k = (size_t)((p->x[0][i] - g->x0) / dx);
    if (k >= nslice) k = nslice - 1;
    double r = radial(p, i, g->yc), *b = best + k * (size_t)K;
    for (int j = 0; j < K; j++) /* keep the K smallest, ascending */
      if (r < b[j]) {
        const double t = b[j];
        b[j] = r;
        r = t;
      }
  }
  out->nslice = nslice;
  out->r_profile = hv_malloc(nslice * sizeof *out->r_profile, "cavity profile");
  size_t kc = nslice; /* first closed slice */
  for (size_t k = 0; k < nslice; k++) {
    const double r = best[k * (size_t)K + (size_t)K - 1];
    out->r_profile[k] = isfinite(r) ? r - fp : (double)INFINITY;
    if (kc == nslice && out->r_profile[k] <= par->r_open) kc = k;
  }
  free(best);
  out->nopen = kc;
  if (kc == 0) return 0; /* no cavity at the surface */
  if (kc == nslice) {
    out->perforated = 1;
    out->L = xmax - g->x0 + fp;
  } else {
    double xb = INFINITY;
    for (size_t i = 0; i < p->n; i++) {
      if (!cavity_taken(p, i, g, par) || p->x[0][i] > xcap) continue;
      size_t k = (size_t)((p->x[0][i] - g->x0) / dx);
      if (k >= nslice) k = nslice - 1;
      if (k == kc && radial(p, i, g->yc) - fp <= par->r_open && p->x[0][i] < xb) xb = p->x[0][i];
    }
    out->L = fmax(0.0, xb - fp - g->x0);
  }
  double sum = 0.0;
  size_t cnt = 0;
  for (size_t k = 0; k < kc; k++) {
    const double r = out->r_profile[k];
    if (!isfinite(r)) continue;
    if (2.0 * r > out->D) {
      out->D = 2.0 * r;
      out->depth_at_D = ((double)k + 0.5) * dx;
    }
    sum += 2.0 * r;
    cnt++;
  }
  out->D_mean = cnt ? sum / (double)cnt : 0.0;
  return cavity_wall(p, g, par, out, err);
}

/* ---- debris cloud ---------------------------------------------------------------- */

void meas_debris_defaults(struct meas_debris_params *par, const struct meas_geom *g)
{
  memset(par, 0, sizeof *par);
  par->body = -1;
  par->x_rear = g->x0 + g->thickness;
  par->yc = g->yc;
  par->margin = 2.0 * g->spacing;
  par->x_limit = INFINITY;
  par->q_lead = 0.99;
  par->q_angle = 0.90;
  par->front_fraction = 0.5;
  par->half_model = g->half_model;
  par->quarter_model = g->quarter_model;
  par->mask = NULL;
}

struct wval {
  double v, w;
};

static int wval_cmp(const void *pa, const void *pb)
{
  const struct wval *a = pa, *b = pb;
  return a->v < b->v ? -1 : a->v > b->v;
}

/* The q mass quantile: the smallest value v such that the values <= v carry at least a
 * fraction q of the weight. Sorts a. */
static double wquantile(struct wval *a, size_t n, double q)
{
  qsort(a, n, sizeof *a, wval_cmp);
  double W = 0.0, cum = 0.0;
  for (size_t k = 0; k < n; k++) W += a[k].w;
  const double target = q * W * (1.0 - 1e-12);
  for (size_t k = 0; k < n; k++) {
    cum += a[k].w;
    if (cum >= target) return a[k].v;
  }
  return a[n - 1].v;
}

int measure_debris(const struct particles *p, const struct meas_debris_params *par,
                   struct meas_debris *out, struct hv_error *err)
{
  memset(out, 0, sizeof *out);
  if (!(isfinite(par->x_rear) && isfinite(par->yc) && par->margin >= 0 && isfinite(par->margin) &&
        !isnan(par->x_limit) && par->q_lead > 0 && par->q_lead <= 1 && par->q_angle > 0 &&
        par->q_angle <= 1 && par->front_fraction >= 0 && par->front_fraction < 1))
    return hv_error_set(err, HV_EXIT_INPUT,
                        "debris cloud measurement: x_rear, yc, margin "
                        "(>= 0) must be finite, the quantiles in (0, 1] and the front "
                        "fraction in [0, 1)");
  const double xlo = par->x_rear + par->margin;
  size_t n = 0;
  for (size_t i = 0; i < p->n; i++)
    if (taken(p, i, par->body, par->mask) && p->x[0][i] > xlo && p->x[0][i] < par->x_limit) n++;
  out->v_mean = out->v_lead = out->v_max = out->x_lead = out->half_angle = NAN;
  out->half_angle_front = NAN;
  out->gap = par->x_limit - par->x_rear;
  if (!n) return 0;
  struct wval *vx = hv_malloc(n * sizeof *vx, "cloud"), *xs = hv_malloc(n * sizeof *xs, "cloud");
  struct wval *th = hv_malloc(n * sizeof *th, "cloud");
  double *dx = hv_malloc(n * sizeof *dx, "cloud"); /* x − x_rear, in particle order */
  double m = 0.0, mv = 0.0, vmax = -INFINITY;
  size_t k = 0;
  for (size_t i = 0; i < p->n; i++) {
    if (!(taken(p, i, par->body, par->mask) && p->x[0][i] > xlo && p->x[0][i] < par->x_limit))
      continue;
    const double mi = p->m[i], v = p->v[0][i], dxr = p->x[0][i] - par->x_rear;
    m += mi;
    mv += mi * v;
    if (v > vmax) vmax = v;
    vx[k] = (struct wval){v, mi};
    xs[k] = (struct wval){dxr, mi};
    th[k] = (struct wval){atan2(radial(p, i, par->yc), dxr), mi};
    dx[k] = dxr;
    k++;
  }
  out->count = n;
  out->m = meas_images(par->half_model, par->quarter_model) * m;
  out->v_mean = m > 0 ? mv / m : (double)NAN;
  out->v_max = vmax;
  out->v_lead = wquantile(vx, n, par->q_lead);
  out->x_lead = wquantile(xs, n, par->q_lead);
  /* the front, before th is sorted (it is still in particle order, as dx): vx, done
     with, takes the front's angles */
  size_t nf = 0;
  for (k = 0; k < n; k++)
    if (dx[k] >= par->front_fraction * out->x_lead) vx[nf++] = th[k];
  out->half_angle_front = nf ? wquantile(vx, nf, par->q_angle) : (double)NAN;
  out->half_angle = wquantile(th, n, par->q_angle);
  free(vx);
  free(xs);
  free(th);
  free(dx);
  return 0;
}

/* ---- backwall -------------------------------------------------------------------- */

void meas_backwall_defaults(struct meas_backwall_params *par, const struct meas_geom *g)
{
  const double s = g->spacing;
  memset(par, 0, sizeof *par);
  par->tol = s;
  par->footprint = 0.5 * s;
  par->cell = 0.5 * s;
  par->margin_front = fmax(g->thickness, 2.0 * s);
  par->damage_min = 1.0;
  par->eps_p_min = 0.1;
  par->crater_min = s;
  par->ring = 2.0 * s;
  par->area_fraction = 0.5;
  par->mask = NULL;
  par->scale = NULL;
  par->attached_only = 1;
  par->far_reference = 1;
  par->far_fraction = 0.8;
  par->local_inner = fmax(0.5 * g->thickness, 2.0 * s);
  par->local_outer = fmax(g->thickness, 4.0 * s);
}

int meas_keep_largest_piece(const struct particles *p, const struct meas_geom *g,
                            const double *scale, unsigned char *sel, struct hv_error *err)
{
  double *b = NULL;
  if (scale) {
    b = hv_malloc((p->n + 1) * sizeof *b, "linking lengths");
    for (size_t i = 0; i < p->n; i++) b[i] = FOF_B_FACTOR * g->spacing * scale[i];
  }
  struct fof_params fp = {.b = FOF_B_FACTOR * g->spacing,
                          .b_particle = b,
                          .mask = sel,
                          .nmat = 0,
                          .half_model = g->half_model,
                          .quarter_model = g->quarter_model};
  struct fof_result fr;
  fof_result_init(&fr);
  const int rc = fof_find(p, &fp, &fr, err);
  free(b);
  if (rc == 0)
    for (size_t i = 0; i < p->n; i++)
      if (sel[i] && fr.group[i] != 0) sel[i] = 0; /* sorted by mass: 0 is the largest */
  fof_result_free(&fr);
  return rc;
}

/* The backwall's columns: xf[k] the smallest x − footprint of the wall particles (col, or
 * those of the body/mask at x >= xlo) within tol of column k's axis, among those whose
 * x − footprint >= xmin; hit[k] (when not NULL) set where a damaged one lies.
 * In a half model a column with centre w >= 0 is never nearer a mirrored particle
 * (u, −z) than the particle itself, so the mirror images add nothing. A quarter model's
 * columns span −u as well, as the half model's do (measure_backwall), and each particle
 * is taken with its image (−u, w) across the plane y = 0: the half model's columns. */
static void fill_columns(const struct particles *p, const struct meas_geom *g,
                         const struct meas_backwall_params *par, const unsigned char *col,
                         double xlo, double xmin, const double lo[2], double c, int nu, int nw,
                         double *xf, unsigned char *hit)
{
  const double fp = par->footprint, tol = par->tol;
  const size_t nimg = g->quarter_model ? 2 : 1; /* the image (−u, w) second */
  for (size_t q = 0; q < nimg * p->n; q++) {
    const size_t i = q / nimg;
    if (col ? !col[i] : (!taken(p, i, g->body, par->mask) || p->x[0][i] < xlo)) continue;
    const double si = par->scale ? par->scale[i] : 1.0, ti = si * tol;
    const double u = (q % nimg ? -1.0 : 1.0) * (p->x[1][i] - g->yc), w = p->x[2][i],
                 x = p->x[0][i] - si * fp;
    if (x < xmin) continue;
    const int dmg = p->solid && (p->damage[i] >= par->damage_min || p->eps_p[i] >= par->eps_p_min);
    int a0 = (int)ceil((u - ti - lo[0]) / c - 0.5), a1 = (int)floor((u + ti - lo[0]) / c - 0.5);
    int b0 = (int)ceil((w - ti - lo[1]) / c - 0.5), b1 = (int)floor((w + ti - lo[1]) / c - 0.5);
    if (a0 < 0) a0 = 0;
    if (b0 < 0) b0 = 0;
    if (a1 > nu - 1) a1 = nu - 1;
    if (b1 > nw - 1) b1 = nw - 1;
    for (int b = b0; b <= b1; b++) {
      const double dw = lo[1] + ((double)b + 0.5) * c - w;
      for (int a = a0; a <= a1; a++) {
        const double du = lo[0] + ((double)a + 0.5) * c - u;
        const size_t k = (size_t)b * (size_t)nu + (size_t)a;
        if (du * du + dw * dw > ti * ti) continue;
        if (x < xf[k]) xf[k] = x;
        if (dmg && hit) hit[k] = 1;
      }
    }
  }
}

/* crater_depth_local (measure.h): each column within r_read of the axis cratered below
 * the far wall against the lower median front of the columns local_inner to local_outer
 * from it. The ring is
 * sampled on every st-th column (st about local_inner / 4 cells, the lattice symmetric
 * about the column), mirrored at z = 0 in a half model (there lo[1] = 0); a column whose ring holds less
 * than a quarter of its samples (the wall's edge, a hole) is skipped. */
static void crater_local(const struct meas_backwall_params *par, const struct meas_geom *g,
                         const double lo[2], double c, int nu, int nw, const double *xf,
                         double shift, double r_read, struct meas_backwall *out)
{
  out->crater_depth_local = 0.0;
  const int st = par->local_inner / (4.0 * c) > 1.0 ? (int)(par->local_inner / (4.0 * c)) : 1;
  const int m = (int)ceil(par->local_outer / c) / st * st;
  const size_t side = (size_t)(2 * (m / st) + 1); /* the sampled square holds the ring */
  int *off = hv_malloc(2 * side * side * sizeof *off, "crater ring");
  struct wval *ring = hv_malloc(side * side * sizeof *ring, "crater ring");
  size_t noff = 0;
  for (int db = -m; db <= m; db += st)
    for (int da = -m; da <= m; da += st) {
      const double r = c * hypot(da, db);
      if (r < par->local_inner || r > par->local_outer) continue;
      off[2 * noff] = da;
      off[2 * noff + 1] = db;
      noff++;
    }
  double best = -INFINITY; /* stays so (no reading) when the ring holds no sample */
  for (int b = 0; noff && b < nw; b++)
    for (int a = 0; a < nu; a++) {
      const double x = xf[(size_t)b * (size_t)nu + (size_t)a];
      if (!isfinite(x) || !(x - g->x0 - shift > 0.0)) continue;
      if (hypot(lo[0] + ((double)a + 0.5) * c, lo[1] + ((double)b + 0.5) * c) > r_read) continue;
      size_t n = 0;
      for (size_t k = 0; k < noff; k++) {
        const int aa = a + off[2 * k];
        int bb = b + off[2 * k + 1];
        if (bb < 0 && g->half_model) bb = -bb - 1;
        if (aa < 0 || aa >= nu || bb < 0 || bb >= nw) continue;
        const double v = xf[(size_t)bb * (size_t)nu + (size_t)aa];
        if (isfinite(v)) ring[n++] = (struct wval){v, 1.0};
      }
      if (4 * n < noff) continue;
      const double ref = wquantile(ring, n, 0.5);
      if (x - ref > best) {
        best = x - ref;
        out->crater_local_pos[0] = lo[0] + ((double)a + 0.5) * c + g->yc;
        out->crater_local_pos[1] = lo[1] + ((double)b + 0.5) * c;
        out->crater_local_ref = ref - g->x0 - shift;
      }
    }
  free(off);
  free(ring);
  out->crater_depth_local = fmax(best, 0.0);
}

/* The backwall parameters are in range (measure_backwall's message says which). */
static int backwall_params_ok(const struct meas_backwall_params *par)
{
  return (par->tol > 0 && isfinite(par->tol) && par->cell > 0 && isfinite(par->cell) &&
          par->footprint >= 0 && isfinite(par->footprint) && par->margin_front >= 0 &&
          isfinite(par->margin_front) && par->crater_min >= 0 && isfinite(par->crater_min) &&
          par->ring > 0 && isfinite(par->ring) && par->area_fraction > 0 &&
          par->area_fraction <= 1 && par->far_fraction > 0 && par->far_fraction <= 1 &&
          par->local_inner >= 0 && par->local_outer > par->local_inner &&
          isfinite(par->local_outer));
}

/* The wall's particles at or behind xlo: counted, their (u, w) extent (each widened by
 * its tolerance) and the damaged ones' count, mass and farthest radius. */
static void scan_wall(const struct particles *p, const struct meas_geom *g,
                      const struct meas_backwall_params *par, double xlo, double lo[2],
                      double hi[2], struct meas_backwall *out)
{
  const double tol = par->tol;
  for (size_t i = 0; i < p->n; i++) {
    if (!taken(p, i, g->body, par->mask) || p->x[0][i] < xlo) continue;
    out->n_wall++;
    const double uw[2] = {p->x[1][i] - g->yc, p->x[2][i]};
    const double ti = par->scale ? par->scale[i] * tol : tol;
    for (int d = 0; d < 2; d++) {
      lo[d] = fmin(lo[d], uw[d] - ti);
      hi[d] = fmax(hi[d], uw[d] + ti);
    }
    const double dmg = p->solid ? p->damage[i] : 0.0, ep = p->solid ? p->eps_p[i] : 0.0;
    if (p->solid && (dmg >= par->damage_min || ep >= par->eps_p_min)) {
      out->n_damaged++;
      out->m_damaged += p->m[i];
      out->r_damage_particles = fmax(out->r_damage_particles, radial(p, i, g->yc));
    }
  }
}

/* The radius about the axis within which craters are read: the inscribed radius of the
 * centres of the particles the columns see (col, or those of the body/mask at x >= xlo),
 * a half or quarter model's planes mirrored, less tol (the coarsest particle's, scale).
 * At the wall's rim a column lies
 * within tol of some layers' outermost particles and not of others (a layer's edge a
 * fraction of Δ further out than the next), and its front is the first layer that
 * reaches it: the rear layer alone reads as a crater all but the wall's thickness deep
 * (the RZ Whipple shield's 2.50 mm in a 3 mm wall of six 0.5 mm layers, 60.2 mm from
 * the axis at its disc's rim; sweep of 2026-12-07 at 5e03719). Below 0 when the wall
 * does not surround the axis by more than tol: no crater is read. */
static double crater_read_radius(const struct particles *p, const struct meas_geom *g,
                                 const struct meas_backwall_params *par, const unsigned char *col,
                                 double xlo)
{
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY}, smax = 1.0;
  for (size_t i = 0; i < p->n; i++) {
    if (col ? !col[i] : (!taken(p, i, g->body, par->mask) || p->x[0][i] < xlo)) continue;
    if (par->scale) smax = fmax(smax, par->scale[i]);
    const double uw[2] = {p->x[1][i] - g->yc, p->x[2][i]};
    for (int d = 0; d < 2; d++) {
      lo[d] = fmin(lo[d], uw[d]);
      hi[d] = fmax(hi[d], uw[d]);
    }
  }
  double r = fmin(fmin(hi[0], g->quarter_model ? hi[0] : -lo[0]), hi[1]);
  if (!g->half_model && !g->quarter_model) r = fmin(r, -lo[1]);
  return r - smax * par->tol;
}

/* The far wall's front: the median of the column fronts xf at ρ >= far_fraction R_in
 * (0 when no column is that far). */
static double far_wall_front(const struct meas_geom *g, const struct meas_backwall_params *par,
                             const double lo[2], const double hi[2], double c, int nu, int nw,
                             const double *xf)
{
  double shift = 0.0;
  double r_in = fmin(fmin(-lo[0], hi[0]), hi[1]);
  if (!g->half_model) r_in = fmin(r_in, -lo[1]);
  struct wval *far = NULL;
  size_t nfar = 0;
  for (int pass = 0; pass < 2 && r_in > 0; pass++) { /* count, then collect */
    if (pass == 1) {
      if (!nfar) break;
      far = hv_malloc(nfar * sizeof *far, "backwall far wall");
      nfar = 0;
    }
    for (int b = 0; b < nw; b++)
      for (int a = 0; a < nu; a++) {
        const size_t k = (size_t)b * (size_t)nu + (size_t)a;
        const double u = lo[0] + ((double)a + 0.5) * c, w = lo[1] + ((double)b + 0.5) * c;
        if (!isfinite(xf[k]) || hypot(u, w) < par->far_fraction * r_in) continue;
        if (far) far[nfar] = (struct wval){xf[k] - g->x0, 1.0};
        nfar++;
      }
  }
  if (far) shift = wquantile(far, nfar, 0.5); /* the median (the lower one of two) */
  free(far);
  return shift;
}

/* Rings around the axis: columns counted, and damaged ones (a hole, damaged material or
 * a crater deeper than crater_min) among them; r_damage the outer edge of the rings,
 * from the axis out, of which at least area_fraction is damaged. Sets the crater's
 * position and radius; returns the deepest column's depth below the far wall. Craters
 * are read within r_read of the axis only (crater_read_radius: the wall's rim). */
static double ring_damage(const struct meas_geom *g, const struct meas_backwall_params *par,
                          const double lo[2], const double hi[2], double c, int nu, int nw,
                          const double *xf, const unsigned char *hit, double shift, double r_read,
                          struct meas_backwall *out)
{
  const double rmax = hypot(fmax(fabs(lo[0]), fabs(hi[0])), fmax(fabs(lo[1]), fabs(hi[1])));
  const size_t nring = (size_t)(rmax / par->ring) + 2;
  size_t *ring_n = hv_calloc(2 * nring, sizeof *ring_n, "backwall rings");
  double dmax = -INFINITY;
  for (int b = 0; b < nw; b++)
    for (int a = 0; a < nu; a++) {
      const size_t k = (size_t)b * (size_t)nu + (size_t)a;
      const double x = xf[k];
      const double u = lo[0] + ((double)a + 0.5) * c, w = lo[1] + ((double)b + 0.5) * c;
      const double r = hypot(u, w);
      const size_t q = (size_t)(r / par->ring);
      int damaged = !isfinite(x) || hit[k]; /* a hole, or damaged material */
      if (isfinite(x) && r <= r_read) {
        const double d = x - g->x0 - shift; /* xf: the particles' front, x − footprint */
        if (d > dmax) {
          dmax = d;
          out->crater_pos[0] = u + g->yc;
          out->crater_pos[1] = w;
        }
        if (d > par->crater_min) {
          out->r_crater = fmax(out->r_crater, r);
          damaged = 1;
        }
      }
      if (q < nring) {
        ring_n[2 * q]++;
        ring_n[2 * q + 1] += (size_t)damaged;
      }
    }
  out->r_damage = 0.0;
  for (size_t q = 0; q < nring; q++) {
    if (!ring_n[2 * q] || (double)ring_n[2 * q + 1] < par->area_fraction * (double)ring_n[2 * q])
      break;
    out->r_damage = (double)(q + 1) * par->ring;
  }
  free(ring_n);
  return dmax;
}

int measure_backwall(const struct particles *p, const struct meas_geom *g,
                     const struct meas_backwall_params *par, struct meas_backwall *out,
                     struct hv_error *err)
{
  memset(out, 0, sizeof *out);
  if (geom_ok(g, "backwall measurement", err)) return -1;
  if (!backwall_params_ok(par))
    return hv_error_set(err, HV_EXIT_INPUT,
                        "backwall measurement: tol, cell, ring (> 0), "
                        "footprint, margin_front and crater_min (>= 0) must be finite, "
                        "area_fraction and far_fraction in (0, 1] and 0 <= local_inner < "
                        "local_outer finite");
  if (p->axisym) { /* rings: revolved into points round their circles (measure_rz.c) */
    if (g->yc != 0.0 || g->half_model)
      return hv_error_set(err, HV_EXIT_INPUT,
                          "backwall measurement: the rings' axis is r = 0 (yc %g, half model "
                          "%d)",
                          g->yc, g->half_model);
    return measure_backwall_rz(p, g, par, out, err);
  }
  const double xlo = g->x0 - par->margin_front, tol = par->tol;
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  scan_wall(p, g, par, xlo, lo, hi, out);
  out->m_damaged *= meas_images(g->half_model, g->quarter_model);
  if (!out->n_wall) return 0;
  /* the columns see the wall's particles, or with attached_only its largest piece */
  unsigned char *col = NULL;
  if (par->attached_only) {
    col = hv_calloc(p->n + 1, 1, "backwall selection");
    for (size_t i = 0; i < p->n; i++) col[i] = taken(p, i, g->body, par->mask) && p->x[0][i] >= xlo;
    if (meas_keep_largest_piece(p, g, par->scale, col, err)) {
      free(col);
      return -1;
    }
  }
  if (g->half_model) lo[1] = 0.0;       /* columns on the simulated side suffice: see below */
  if (g->quarter_model) lo[0] = -hi[0]; /* the half model's columns: see fill_columns */
  double c = par->cell;
  const double span = fmax(hi[0] - lo[0], hi[1] - lo[1]);
  if (span / c > MEAS_MAX_CELLS) c = span / MEAS_MAX_CELLS;
  const int nu = (int)ceil((hi[0] - lo[0]) / c) > 0 ? (int)ceil((hi[0] - lo[0]) / c) : 1;
  const int nw = (int)ceil((hi[1] - lo[1]) / c) > 0 ? (int)ceil((hi[1] - lo[1]) / c) : 1;
  double *xf = hv_malloc((size_t)nu * (size_t)nw * sizeof *xf, "backwall columns");
  unsigned char *hit = hv_malloc((size_t)nu * (size_t)nw, "backwall columns");
  for (size_t k = 0; k < (size_t)nu * (size_t)nw; k++) {
    xf[k] = INFINITY;
    hit[k] = 0;
  }
  fill_columns(p, g, par, col, xlo, -INFINITY, lo, c, nu, nw, xf, hit);
  /* the far wall: the median front of the columns at ρ >= far_fraction R_in */
  double shift = 0.0;
  if (par->far_reference) shift = far_wall_front(g, par, lo, hi, c, nu, nw, xf);
  out->wall_shift = shift;
  const double r_read = crater_read_radius(p, g, par, col, xlo);
  {
    /* the surface a gauge rests on: wall particles at most tol ahead of the far wall's
       face (splash still joined to the wall is not its surface) */
    const size_t ncol = (size_t)nu * (size_t)nw;
    double *xs = hv_malloc(ncol * sizeof *xs, "backwall surface");
    for (size_t k = 0; k < ncol; k++) xs[k] = INFINITY;
    fill_columns(p, g, par, col, xlo, g->x0 + shift - tol, lo, c, nu, nw, xs, NULL);
    crater_local(par, g, lo, c, nu, nw, xs, shift, r_read, out);
    free(xs);
  }
  const double dmax = ring_damage(g, par, lo, hi, c, nu, nw, xf, hit, shift, r_read, out);
  free(xf);
  free(hit);
  free(col);
  out->crater_depth = fmax(dmax, 0.0);
  return 0;
}

double measure_center_pressure(const struct particles *p, const struct meas_geom *g, double r0,
                               double depth, const unsigned char *mask, size_t *count)
{
  double xf = INFINITY;
  for (size_t i = 0; i < p->n; i++)
    if (taken(p, i, g->body, mask) && radial(p, i, g->yc) < r0 && p->x[0][i] >= g->x0 - depth &&
        p->x[0][i] < xf)
      xf = p->x[0][i];
  double m = 0.0, mp = 0.0;
  size_t cnt = 0;
  if (isfinite(xf))
    for (size_t i = 0; i < p->n; i++)
      if (taken(p, i, g->body, mask) && radial(p, i, g->yc) < r0 && p->x[0][i] >= xf &&
          p->x[0][i] <= xf + depth) {
        m += p->m[i];
        mp += p->m[i] * p->p[i];
        cnt++;
      }
  if (count) *count = cnt;
  return cnt && m > 0 ? mp / m : (double)NAN;
}

/* ---- gas shock front ------------------------------------------------------------- */

void meas_gas_defaults(struct meas_gas_params *par, int body, double rho_ref,
                       const double origin[3], double spacing)
{
  memset(par, 0, sizeof *par);
  par->body = body;
  par->rho_ref = rho_ref;
  par->factor = 1.1;
  for (int d = 0; d < 3; d++) par->origin[d] = origin[d];
  par->r_axis = 2.0 * spacing;
  par->mask = NULL;
}

int measure_gas_front(const struct particles *p, const struct meas_gas_params *par,
                      struct meas_gas_front *out, struct hv_error *err)
{
  memset(out, 0, sizeof *out);
  if (!(par->rho_ref > 0 && isfinite(par->rho_ref) && par->factor > 0 && isfinite(par->factor) &&
        par->r_axis >= 0 && isfinite(par->origin[0]) && isfinite(par->origin[1]) &&
        isfinite(par->origin[2])))
    return hv_error_set(err, HV_EXIT_INPUT,
                        "gas front measurement: rho_ref and factor must be "
                        "positive, r_axis >= 0 and the origin finite");
  const double rho_s = par->factor * par->rho_ref;
  size_t on_axis = 0;
  for (size_t i = 0; i < p->n; i++) {
    if (!taken(p, i, par->body, par->mask) || !(p->rho[i] > rho_s)) continue;
    const double dx = p->x[0][i] - par->origin[0];
    const double ra = hypot(p->x[1][i] - par->origin[1], p->x[2][i] - par->origin[2]);
    out->n_shocked++;
    if (ra <= par->r_axis) {
      on_axis++;
      if (dx > out->x_axial) out->x_axial = dx;
    }
    out->r_radial = fmax(out->r_radial, ra);
    out->r_max = fmax(out->r_max, hypot(dx, ra));
  }
  /* shocked gas, but none on the axis (debris has pushed the gas off it): the front on
     the axis is not at the origin, it is not there to be read */
  if (out->n_shocked && !on_axis) out->x_axial = NAN;
  return 0;
}
