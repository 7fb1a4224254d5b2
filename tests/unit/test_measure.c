/* test_measure.c — plate holes and thick-target cavities on constructed lattices with
 * known answers.
 *
 * Plates (half and full models, cubic and hcp lattices): a cylindrical hole of known
 * diameter D punched through (particles with centres inside removed) must be found
 * perforated, with the largest-circle and equivalent-area diameters within one spacing Δ
 * of D; the circle must be at least as large as the one centred on the hole's axis that
 * the definition gives for the remaining particles. A blind crater is not a perforation;
 * debris behind the slab does not count as plate, a plug still in the slab blocks the
 * view; an elliptical (oblique) hole gives its minor axis and its area; a plate gone
 * across the window is an open hole.
 * Blocks: a cylindrical cavity of known depth and diameter gives L and D within Δ; a
 * wider entrance crater sets D (the largest) but not D_mean; a stray particle in the
 * cavity stops it unless min_count or v_max leave it out. The wall by filled volume
 * (D_wall) reads a punched cylinder within Δ/2 on cubic and hcp lattices and does not
 * move for strays that narrow D_mean.
 * A target of two bodies (`measure.thick_target: [block, core]`, a block refined near its
 * axis, run through `hvsph run` to t = 0): a cavity 8 mm deep and 6 mm across cut into
 * the fine core gives L and D within the core's spacing, in rows named after the first
 * body; the outer block alone would read the core's 10 mm channel as a perforation; an
 * empty list and an unknown body are refused (exit 2). `measure.cavity_min_count: 2`
 * passes over a stray particle on the axis that closes the cavity halfway by default.
 * A plate of two bodies (`measure.plates: [[ring, disc]]`) and a backwall of two
 * (`measure.backwall: [ring, disc]`: a crater 1 mm deep and 6 mm across in the fine
 * disc gives its depth, radius and damaged radius within the disc's spacing, the coarse
 * ring no crater) likewise.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diag/measure.h"
#include "diag/measure_table.h"
#include "particles/particles.h"
#include "testlib.h"
#include "testparticles.h"

static const double S = 1e-3; /* [m] lattice spacing Δ */

static size_t add_particle(struct particles *p, const double x[3], int body)
{
  return tp_add(p, x[0], x[1], x[2], 7.8e3 * S * S * S, 1.2 * S, 7.8e3, body);
}

/* What to cut out of a lattice. */
struct cut {
  double yc;        /* hole axis y (z = 0) */
  double R;         /* cylinder radius (0: none) */
  double xcut;      /* the cylinder removes x < xcut */
  double a, b, ey;  /* ellipse semi-axes along y and z, centre y (a = 0: none) */
  double R2, xcut2; /* a second, wider cylinder over x < xcut2 (entrance crater) */
};

static int kept(const struct cut *c, const double x[3])
{
  const double u = x[1] - c->yc, w = x[2];
  if (c->R > 0 && u * u + w * w < c->R * c->R && x[0] < c->xcut) return 0;
  if (c->R2 > 0 && u * u + w * w < c->R2 * c->R2 && x[0] < c->xcut2) return 0;
  if (c->a > 0) {
    const double eu = (x[1] - c->ey) / c->a, ew = x[2] / c->b;
    if (eu * eu + ew * ew < 1.0) return 0;
  }
  return 1;
}

/* Fills the box lo..hi with a lattice of spacing S (cubic: (i + ½) Δ from lo; hcp as the
 * setup builds it: ABAB layers along z, nearest neighbours at Δ), keeping the points
 * that the cut leaves. Returns the smallest radial distance (from y = cut->yc, z = 0) of
 * a kept point with x < xmax_r. */
static double add_lattice(struct particles *p, const double lo[3], const double hi[3], int hcp,
                          const struct cut *c, int body, double xmax_r)
{
  const double step[3] = {S, hcp ? S * sqrt(3.0) / 2 : S, hcp ? S * sqrt(2.0 / 3.0) : S};
  double rmin = INFINITY;
  for (long k = 0;; k++) {
    const double z = lo[2] + ((double)k + 0.5) * step[2];
    if (z > hi[2]) break;
    for (long j = 0;; j++) {
      const long kk = k % 2, jj = j % 2;
      const double y = lo[1] + ((double)j + (hcp ? (double)kk / 3.0 : 0.0) + 0.5) * step[1];
      if (y > hi[1]) break;
      for (long i = 0;; i++) {
        const double x = lo[0] + ((double)i + (hcp ? 0.5 * (double)(jj + kk) + 0.25 : 0.5)) * S;
        if (x > hi[0]) break;
        const double q[3] = {x, y, z};
        if (!kept(c, q)) continue;
        add_particle(p, q, body);
        if (x < xmax_r) rmin = fmin(rmin, hypot(y - c->yc, z));
      }
    }
  }
  return rmin;
}

/* A plate 3Δ thick at x0 = 10 mm, |y| <= 30Δ, 0 <= z <= 30Δ (half) or |z| <= 30Δ (full). */
static const double X0 = 0.01, TH = 3 * S, W = 30 * S;

static void plate_geom(struct meas_geom *g, double yc, int half)
{
  *g = (struct meas_geom){
      .body = 1, .x0 = X0, .thickness = TH, .yc = yc, .spacing = S, .half_model = half};
}

/* The half-model plate on the axis yc = 0 with default measurement parameters. */
static void half_plate(struct meas_geom *g, struct meas_plate_params *par)
{
  plate_geom(g, 0.0, 1);
  meas_plate_defaults(par, g);
}

static void check_hole(double D, double yc, int half, int hcp)
{
  struct particles p;
  particles_init(&p);
  const double lo[3] = {X0, -W, half ? 0.0 : -W}, hi[3] = {X0 + TH, W, W};
  const struct cut c = {.yc = yc, .R = 0.5 * D, .xcut = 1.0};
  const double rmin = add_lattice(&p, lo, hi, hcp, &c, 1, 1.0);
  const double other[3] = {X0 - 0.05, 0, 0}; /* a particle of another body, in the hole's way */
  add_particle(&p, other, 0);
  struct meas_geom g;
  plate_geom(&g, yc, half);
  struct meas_plate_params par;
  meas_plate_defaults(&par, &g);
  par.slab_front = 0.1; /* reaches the other body's particle: only body 1 counts */
  struct meas_plate r;
  struct hv_error err;
  hv_error_clear(&err);
  const char *what = hcp ? "hcp" : "cubic";
  const char *model = half ? "half" : "full";
  CHECK(measure_plate(&p, &g, &par, &r, &err) == 0, "plate measurement runs: %s", err.msg);
  CHECK(r.perforated && !r.hole_open,
        "%s %s plate, D = %.2fΔ, yc = %.2fΔ: perforated, closed "
        "hole",
        what, model, D / S, yc / S);
  CHECK(fabs(r.d_circle - D) <= S, "%s %s D = %.2fΔ: largest circle %.3fΔ within Δ", what, model,
        D / S, r.d_circle / S);
  CHECK(fabs(r.d_equiv - D) <= S, "%s %s D = %.2fΔ: equivalent-area diameter %.3fΔ within Δ", what,
        model, D / S, r.d_equiv / S);
  CHECK(fabs(r.d_circle_impact - D) <= S,
        "%s %s D = %.2fΔ: circle at the impact point %.3fΔ "
        "within Δ",
        what, model, D / S, r.d_circle_impact / S);
  /* the definition at the hole's axis, from the kept particles: the search can only do better */
  const double d_axis = 2 * (rmin - 0.5 * S);
  CHECK(r.d_circle >= d_axis - 1e-12 && r.d_circle <= d_axis + 0.5 * S,
        "%s %s D = %.2fΔ: circle %.4fΔ >= the one on the axis %.4fΔ (and close to it)", what, model,
        D / S, r.d_circle / S, d_axis / S);
  CHECK_CLOSE(r.d_circle_impact, d_axis, 1e-12, "circle centred at the impact point = definition");
  CHECK(hypot(r.circle_center[0] - yc, r.circle_center[1]) <= 0.5 * S,
        "%s %s: circle centred on the hole (%.3fΔ, %.3fΔ)", what, model,
        (r.circle_center[0] - yc) / S, r.circle_center[1] / S);
  CHECK(r.n_plate == p.n - 1, "every plate particle taken (%zu of %zu)", r.n_plate, p.n - 1);
  particles_free(&p);
}

static void test_holes(void)
{
  const double D[3] = {8.6 * S, 12.3 * S, 17.0 * S};
  for (int k = 0; k < 3; k++) {
    check_hole(D[k], 0.0, 1, 0);
    check_hole(D[k], 0.37 * S, 1, 0);
    check_hole(D[k], 0.21 * S, 0, 0);
    check_hole(D[k], 0.0, 1, 1);
  }
}

static void test_blind_and_slab(void)
{
  struct particles p;
  particles_init(&p);
  const double lo[3] = {X0, -W, 0}, hi[3] = {X0 + TH, W, W};
  const struct cut c = {.yc = 0, .R = 6 * S, .xcut = X0 + 2 * S}; /* leaves the last layer */
  add_lattice(&p, lo, hi, 0, &c, 1, 1.0);
  struct meas_geom g;
  struct meas_plate_params par;
  half_plate(&g, &par);
  struct meas_plate r;
  struct hv_error err;
  CHECK(measure_plate(&p, &g, &par, &r, &err) == 0 && !r.perforated, "blind crater: not "
                                                                     "perforated");
  CHECK(r.d_circle == 0 && r.d_equiv == 0 && r.area == 0, "blind crater: no hole diameter");
  particles_free(&p);

  /* a hole, then plate debris far behind it (outside the slab) and a plug inside the slab */
  particles_init(&p);
  const struct cut h = {.yc = 0, .R = 6 * S, .xcut = 1.0};
  add_lattice(&p, lo, hi, 0, &h, 1, 1.0);
  const double dlo[3] = {X0 + TH + 20 * S, -3 * S, 0}, dhi[3] = {X0 + TH + 23 * S, 3 * S, 3 * S};
  const struct cut none = {0};
  add_lattice(&p, dlo, dhi, 0, &none, 1, 1.0);
  CHECK(measure_plate(&p, &g, &par, &r, &err) == 0 && r.perforated &&
            fabs(r.d_circle - 12 * S) <= S,
        "debris of the plate beyond the slab is not plate (D %.3fΔ)", r.d_circle / S);
  const double plo[3] = {X0 + TH + 0.5 * S, -2 * S, 0}, phi[3] = {X0 + TH + 1.5 * S, 2 * S, 2 * S};
  const size_t before_plug = p.n;
  add_lattice(&p, plo, phi, 0, &none, 1, 1.0);
  const size_t nplug = p.n - before_plug;
  /* the plug's first layer is 1.5Δ behind the plate's last one: not linked to it */
  CHECK(measure_plate(&p, &g, &par, &r, &err) == 0 && r.perforated &&
            fabs(r.d_circle - 12 * S) <= S && r.n_detached == nplug && nplug > 0,
        "a plug broken loose, still inside the slab, is debris: D %.3fΔ, %zu particles left "
        "out (its %zu)",
        r.d_circle / S, r.n_detached, nplug);
  par.attached_only = 0;
  CHECK(measure_plate(&p, &g, &par, &r, &err) == 0 && !r.perforated,
        "with attached_only 0 the plug blocks the line of sight");
  par.slab_rear = 0.2 * S;
  CHECK(measure_plate(&p, &g, &par, &r, &err) == 0 && r.perforated,
        "... and is left out with a thinner slab");
  particles_free(&p);
}

/* A hole of 12Δ with loose fragments drifting in its plane, and with a petal still
 * joined to the rim. */
static void test_detached(void)
{
  struct particles p;
  particles_init(&p);
  const double lo[3] = {X0, -W, 0}, hi[3] = {X0 + TH, W, W};
  const struct cut h = {.yc = 0, .R = 6 * S, .xcut = 1.0};
  add_lattice(&p, lo, hi, 0, &h, 1, 1.0);
  const size_t nplate = p.n;
  /* three single particles in the hole, 2Δ and more from each other and from the rim */
  const double loose[3][3] = {{X0 + 1.5 * S, 0.0, 0.5 * S},
                              {X0 + 1.5 * S, 2.2 * S, 1.0 * S},
                              {X0 + 0.5 * S, -1.5 * S, 2.5 * S}};
  for (int k = 0; k < 3; k++) add_particle(&p, loose[k], 1);
  struct meas_geom g;
  struct meas_plate_params par;
  half_plate(&g, &par);
  struct meas_plate r;
  struct hv_error err;
  CHECK(measure_plate(&p, &g, &par, &r, &err) == 0 && r.perforated &&
            fabs(r.d_circle - 12 * S) <= S && r.n_detached == 3 && r.n_plate == nplate,
        "three loose particles in the hole are not plate: D %.3fΔ (12Δ punched), %zu left out",
        r.d_circle / S, r.n_detached);
  par.attached_only = 0;
  CHECK(measure_plate(&p, &g, &par, &r, &err) == 0 && r.d_circle < 8 * S,
        "counted as plate they shrink the circle to %.3fΔ", r.d_circle / S);
  particles_free(&p);

  /* a petal: a chain at Δ spacing from the rim (radius 6Δ) in to radius 3Δ */
  particles_init(&p);
  add_lattice(&p, lo, hi, 0, &h, 1, 1.0);
  for (int k = 0; k < 3; k++) {
    const double q[3] = {X0 + 1.5 * S, 0.0, (5.5 - k) * S};
    add_particle(&p, q, 1);
  }
  par.attached_only = 1;
  CHECK(measure_plate(&p, &g, &par, &r, &err) == 0 && r.n_detached == 0 && r.d_circle < 10.5 * S,
        "a petal joined to the rim is plate: D %.3fΔ, %zu left out", r.d_circle / S, r.n_detached);
  particles_free(&p);

  /* rubble: a ring of split particles joined to the rim (radius 6Δ) filling the hole to
     radius 4Δ. As plate it shrinks the hole to about 8Δ; masked out as measure_run does
     for hole_diameter_intact (damage < 1 only), the punched 12Δ comes back */
  particles_init(&p);
  add_lattice(&p, lo, hi, 0, &h, 1, 1.0);
  const size_t nintact = p.n;
  for (double y = -5.5 * S; y <= 5.5 * S + 1e-12; y += S)
    for (double z = 0.5 * S; z <= 5.5 * S + 1e-12; z += S) {
      const double rr = hypot(y, z);
      if (rr < 4.0 * S || rr > 6.0 * S) continue;
      for (int l = 0; l < 3; l++) {
        const double q[3] = {X0 + (0.5 + l) * S, y, z};
        add_particle(&p, q, 1);
      }
    }
  unsigned char *intact = malloc(p.n);
  for (size_t i = 0; i < p.n; i++) intact[i] = i < nintact;
  CHECK(measure_plate(&p, &g, &par, &r, &err) == 0 && r.d_circle < 9 * S,
        "rubble joined to the rim is plate: D %.3fΔ", r.d_circle / S);
  par.mask = intact;
  CHECK(measure_plate(&p, &g, &par, &r, &err) == 0 && fabs(r.d_circle - 12 * S) <= S,
        "without the rubble (the intact mask): D %.3fΔ (12Δ punched)", r.d_circle / S);
  par.mask = NULL;
  free(intact);
  particles_free(&p);
}

static void test_ellipse_and_open(void)
{
  struct particles p;
  particles_init(&p);
  const double lo[3] = {X0, -W, 0}, hi[3] = {X0 + TH, W, W};
  const struct cut c = {.a = 10 * S, .b = 5 * S, .ey = 2 * S};
  add_lattice(&p, lo, hi, 0, &c, 1, 1.0);
  struct meas_geom g;
  struct meas_plate_params par;
  half_plate(&g, &par);
  struct meas_plate r;
  struct hv_error err;
  CHECK(measure_plate(&p, &g, &par, &r, &err) == 0 && r.perforated, "elliptical hole found");
  CHECK(fabs(r.d_circle - 10 * S) <= S, "ellipse 20Δ × 10Δ: largest circle = minor axis (%.3fΔ)",
        r.d_circle / S);
  CHECK(fabs(r.d_equiv - 2 * sqrt(50.0) * S) <= S,
        "ellipse: equivalent diameter 2√(ab) = %.3fΔ "
        "(%.3fΔ)",
        2 * sqrt(50.0), r.d_equiv / S);
  CHECK(fabs(r.circle_center[0] - 2 * S) <= S && fabs(r.circle_center[1]) <= S,
        "ellipse: circle at its centre (%.2fΔ, %.2fΔ)", r.circle_center[0] / S,
        r.circle_center[1] / S);
  CHECK(fabs(r.area - HV_MEAS_PI * 50 * S * S) <= 0.25 * HV_MEAS_PI * 50 * S * S,
        "ellipse: hole area %.1f Δ² (the area inside tol, smaller than πab = %.1f Δ²)",
        r.area / (S * S), HV_MEAS_PI * 50);
  particles_free(&p);

  particles_init(&p);
  const struct cut gone = {.yc = 0, .R = 25 * S, .xcut = 1.0};
  add_lattice(&p, lo, hi, 0, &gone, 1, 1.0);
  par.r_max = 20 * S;
  CHECK(measure_plate(&p, &g, &par, &r, &err) == 0 && r.perforated && r.hole_open,
        "a hole wider than the window is open");
  CHECK(isfinite(r.d_circle) && r.d_circle <= 51 * S && isfinite(r.d_equiv),
        "open hole: the circle stays inside it (%.2fΔ, a lower bound)", r.d_circle / S);
  par.r_max = 0;
  CHECK(measure_plate(&p, &g, &par, &r, &err) == 0 && r.perforated && !r.hole_open &&
            fabs(r.d_circle - 50 * S) <= S,
        "the whole plate's window sees it closed (%.2fΔ)", r.d_circle / S);
  struct particles empty;
  particles_init(&empty);
  CHECK(measure_plate(&empty, &g, &par, &r, &err) == 0 && r.n_plate == 0,
        "no plate particles: "
        "no crash (perforated %d)",
        r.perforated);
  particles_free(&empty);
  par.tol = -1;
  hv_error_clear(&err);
  CHECK(measure_plate(&p, &g, &par, &r, &err) == -1 && err.code == HV_EXIT_INPUT,
        "negative tolerance: an error (%s)", err.msg);
  par.tol = S;
  par.footprint = INFINITY; /* refused like the cavity's and the backwall's */
  hv_error_clear(&err);
  CHECK(measure_plate(&p, &g, &par, &r, &err) == -1 && err.code == HV_EXIT_INPUT,
        "infinite footprint: an error, not d_equiv = %g (%s)", r.d_equiv, err.msg);
  particles_free(&p);
}

/* A block 50Δ deep at x0 = 0, |y| <= 15Δ, 0 <= z <= 15Δ (a half model), with a cavity. */
static const struct meas_geom BLOCK_G = {
    .body = 2, .x0 = 0.0, .thickness = 50 * S, .yc = 0.0, .spacing = S, .half_model = 1};

/* The cavity of the block's particles with the default parameters. */
static struct meas_cavity measure_block(const struct particles *p)
{
  struct meas_cavity_params par;
  meas_cavity_defaults(&par, &BLOCK_G);
  struct meas_cavity r;
  struct hv_error err;
  hv_error_clear(&err);
  CHECK(measure_cavity(p, &BLOCK_G, &par, &r, &err) == 0, "cavity measurement runs: %s", err.msg);
  return r;
}

static void block(struct particles *p, const struct cut *c)
{
  const double lo[3] = {0, -15 * S, 0}, hi[3] = {50 * S, 15 * S, 15 * S};
  add_lattice(p, lo, hi, 0, c, 2, 1.0);
}

static void test_cavity(void)
{
  struct particles p;
  particles_init(&p);
  const double Rc = 4.6 * S, Lc = 23.4 * S;
  const struct cut c = {.R = Rc, .xcut = Lc};
  block(&p, &c);
  struct meas_geom g = BLOCK_G;
  struct meas_cavity_params par;
  meas_cavity_defaults(&par, &g);
  struct meas_cavity r = measure_block(&p);
  struct hv_error err;
  hv_error_clear(&err);
  CHECK(fabs(r.L - Lc) <= S, "cavity depth %.2fΔ: L = %.3fΔ within Δ", Lc / S, r.L / S);
  CHECK(fabs(r.D - 2 * Rc) <= S, "cavity diameter %.2fΔ: D = %.3fΔ within Δ", 2 * Rc / S, r.D / S);
  CHECK(fabs(r.D_mean - 2 * Rc) <= S, "D_mean = %.3fΔ within Δ", r.D_mean / S);
  /* the definition from the kept lattice: the nearest wall particle minus the footprint */
  const double rmin_wall = hypot(1.5, 4.5) * S; /* nearest lattice (y, z) outside 4.6Δ */
  CHECK_CLOSE(r.D, 2 * (rmin_wall - 0.5 * S), 1e-12, "D = 2 (ρ_min − Δ/2)");
  CHECK(!r.perforated && r.nopen > 0 && r.nslice >= 99, "not perforated; %zu slices, %zu open",
        r.nslice, r.nopen);
  /* the wall by filled volume: five slabs of 4Δ lie within L = 23.4Δ; the removed
     centres take π Rc² of the cross-section, so the wall reads 2 Rc within Δ/2 */
  const double Dw = r.D_wall, Dwm = r.D_wall_mean;
  CHECK(r.nwall == 5, "five wall slabs within L (%zu)", r.nwall);
  CHECK(fabs(Dw - 2 * Rc) <= 0.5 * S && fabs(Dwm - 2 * Rc) <= 0.5 * S,
        "wall by filled volume: D_wall = %.3fΔ, D_wall_mean = %.3fΔ, 2 Rc = %.2fΔ within Δ/2",
        Dw / S, Dwm / S, 2 * Rc / S);
  meas_cavity_free(&r);

  /* a stray target particle inside the cavity at depth 10.2Δ */
  const double stray[3] = {10.2 * S, 0.3 * S, 0.4 * S};
  const size_t is = add_particle(&p, stray, 2);
  CHECK(measure_cavity(&p, &g, &par, &r, &err) == 0 && r.L < 11 * S,
        "a stray particle on the axis closes the cavity (L = %.2fΔ)", r.L / S);
  meas_cavity_free(&r);
  par.min_count = 2;
  CHECK(measure_cavity(&p, &g, &par, &r, &err) == 0 && fabs(r.L - Lc) <= S,
        "min_count 2 ignores one stray particle (L = %.2fΔ)", r.L / S);
  meas_cavity_free(&r);
  par.min_count = 1;
  p.v[0][is] = -800.0;
  par.v_max = 100.0;
  CHECK(measure_cavity(&p, &g, &par, &r, &err) == 0 && fabs(r.L - Lc) <= S,
        "v_max leaves out a particle flying back out (L = %.2fΔ)", r.L / S);
  meas_cavity_free(&r);
  unsigned char *mask = malloc(p.n);
  memset(mask, 1, p.n);
  mask[is] = 0;
  par.v_max = INFINITY;
  par.mask = mask;
  CHECK(measure_cavity(&p, &g, &par, &r, &err) == 0 && fabs(r.L - Lc) <= S,
        "a mask leaves it out too (L = %.2fΔ)", r.L / S);
  meas_cavity_free(&r);
  free(mask);
  particles_free(&p);

  /* wider entrance crater: radius 7.6Δ over the first 3Δ */
  particles_init(&p);
  const struct cut e = {.R = Rc, .xcut = Lc, .R2 = 7.6 * S, .xcut2 = 3 * S};
  block(&p, &e);
  meas_cavity_defaults(&par, &g);
  CHECK(measure_cavity(&p, &g, &par, &r, &err) == 0, "entrance crater: runs");
  CHECK(fabs(r.D - 15.2 * S) <= S && r.depth_at_D < 3 * S,
        "D is the largest diameter, at the entrance (%.2fΔ at depth %.2fΔ)", r.D / S,
        r.depth_at_D / S);
  CHECK(r.D_mean < 0.5 * (r.D + 2 * Rc) && fabs(r.L - Lc) <= S,
        "D_mean follows the channel "
        "(%.2fΔ); L unchanged (%.2fΔ)",
        r.D_mean / S, r.L / S);
  meas_cavity_free(&r);
  particles_free(&p);

  /* through the whole block: perforated; an intact block: no cavity */
  particles_init(&p);
  const struct cut t = {.R = Rc, .xcut = 1.0};
  block(&p, &t);
  CHECK(measure_cavity(&p, &g, &par, &r, &err) == 0 && r.perforated && fabs(r.L - 50 * S) <= S,
        "a channel through the block: perforated, L = %.2fΔ", r.L / S);
  meas_cavity_free(&r);
  particles_free(&p);
  particles_init(&p);
  const struct cut n0 = {0};
  block(&p, &n0);
  CHECK(measure_cavity(&p, &g, &par, &r, &err) == 0 && r.L == 0 && r.D == 0 && !r.perforated,
        "intact block: L = D = 0 (L %.3gΔ)", r.L / S);
  meas_cavity_free(&r);
  par.min_count = 9;
  hv_error_clear(&err);
  CHECK(measure_cavity(&p, &g, &par, &r, &err) == -1 && err.code == HV_EXIT_INPUT,
        "min_count 9: an error (%s)", err.msg);
  particles_free(&p);
}

/* A block with a cavity of radius R (in Δ) and depth 23.4Δ on a cubic or hcp lattice,
 * with nstray single particles inside it at radius 3Δ: returns the measurement. */
static struct meas_cavity wall_case(double R, int hcp, int nstray)
{
  struct particles p;
  particles_init(&p);
  const double lo[3] = {0, -15 * S, 0}, hi[3] = {50 * S, 15 * S, 15 * S};
  const struct cut c = {.R = R * S, .xcut = 23.4 * S};
  add_lattice(&p, lo, hi, hcp, &c, 2, 23.4 * S);
  if (hcp) /* an hcp site holds Δ³/√2 */
    for (size_t i = 0; i < p.n; i++) p.m[i] /= sqrt(2.0);
  for (int k = 0; k < nstray; k++) { /* at depths 1.2, 3.2, 5.2 … Δ, angle 0.3 + 0.13k */
    const double a = 0.3 + 0.13 * k, q[3] = {(1.2 + 2.0 * k) * S, 3 * S * cos(a), 3 * S * sin(a)};
    add_particle(&p, q, 2);
  }
  struct meas_cavity r = measure_block(&p);
  particles_free(&p);
  return r;
}

/* The wall by filled volume (D_wall, D_wall_mean): a cut cavity reads its radius within
 * Δ/2 on cubic and hcp lattices (the removed centres take π R² of the cross-section);
 * eleven stray particles inside the channel (one every 2Δ of depth) narrow D_mean by
 * more than Δ/2 and D_wall by less than Δ/10; bad parameters are refused. */
static void test_cavity_wall(void)
{
  const double radii[2] = {4.6, 9.3};
  for (int hcp = 0; hcp < 2; hcp++)
    for (int k = 0; k < 2; k++) {
      struct meas_cavity r = wall_case(radii[k], hcp, 0);
      CHECK(r.nwall == 5, "%s, R = %.1fΔ: five wall slabs of 4Δ within L = %.2fΔ (%zu)",
            hcp ? "hcp" : "cubic", radii[k], r.L / S, r.nwall);
      CHECK(fabs(r.D_wall - 2 * radii[k] * S) <= 0.5 * S &&
                fabs(r.D_wall_mean - 2 * radii[k] * S) <= 0.5 * S,
            "%s, R = %.1fΔ: D_wall = %.3fΔ, D_wall_mean = %.3fΔ, 2R within Δ/2 (nearest "
            "particle: D = %.3fΔ)",
            hcp ? "hcp" : "cubic", radii[k], r.D_wall / S, r.D_wall_mean / S, r.D / S);
      meas_cavity_free(&r);
    }
  struct meas_cavity a = wall_case(4.6, 0, 0), b = wall_case(4.6, 0, 11);
  CHECK(fabs(b.L - a.L) <= 1e-12, "the strays leave L as it is (%.3fΔ)", b.L / S);
  CHECK(a.D_mean - b.D_mean > 0.5 * S,
        "eleven strays narrow D_mean by more than Δ/2: %.3fΔ → %.3fΔ", a.D_mean / S, b.D_mean / S);
  CHECK(fabs(a.D_wall_mean - b.D_wall_mean) < 0.1 * S && fabs(a.D_wall - b.D_wall) < 0.1 * S,
        "… and the wall by filled volume by less than Δ/10: D_wall_mean %.3fΔ → %.3fΔ, "
        "D_wall %.3fΔ → %.3fΔ",
        a.D_wall_mean / S, b.D_wall_mean / S, a.D_wall / S, b.D_wall / S);
  meas_cavity_free(&b);
  /* a fragment flung 10 km out (in the slabs' depth) leaves the wall as it is (without
     the cap on the annuli it asked for 2·10⁸ bins and the measurement failed) */
  struct particles q;
  particles_init(&q);
  block(&q, &(struct cut){.R = 4.6 * S, .xcut = 23.4 * S});
  add_particle(&q, (const double[3]){10.2 * S, 1e4, 0.0}, 2);
  b = measure_block(&q);
  CHECK(fabs(a.D_wall - b.D_wall) < 1e-12 && fabs(a.D_wall_mean - b.D_wall_mean) < 1e-12,
        "a particle 10 km from the axis: D_wall %.3fΔ → %.3fΔ (annuli capped)", a.D_wall / S,
        b.D_wall / S);
  meas_cavity_free(&b);
  particles_free(&q);
  /* target fragments flung 100 km and 2.1Δ behind the block's rear face (50Δ), on the
     axis: left out of the slices, so L, D and the slices stay as they are (before, the
     100 km one asked for 4·10⁸ slices and the measurement failed) */
  const double far[2] = {1e5, 52.1 * S};
  for (int k = 0; k < 2; k++) {
    particles_init(&q);
    block(&q, &(struct cut){.R = 4.6 * S, .xcut = 23.4 * S});
    add_particle(&q, (const double[3]){far[k], 0.0, 0.0}, 2);
    b = measure_block(&q);
    CHECK(b.L == a.L && b.D == a.D && b.nslice == a.nslice,
          "a fragment on the axis at x = %g m: L %.3fΔ → %.3fΔ, D %.3fΔ → %.3fΔ, %zu → %zu "
          "slices",
          far[k], a.L / S, b.L / S, a.D / S, b.D / S, a.nslice, b.nslice);
    meas_cavity_free(&b);
    particles_free(&q);
  }
  meas_cavity_free(&a);

  struct particles p;
  particles_init(&p);
  block(&p, &(struct cut){.R = 4.6 * S, .xcut = 23.4 * S});
  struct meas_geom g = BLOCK_G;
  struct meas_cavity_params par;
  struct hv_error err;
  const double bad[3][3] = {{0, 0.25, 0.5}, {4, -1, 0.5}, {4, 0.25, 1.0}};
  for (int k = 0; k < 3; k++) {
    meas_cavity_defaults(&par, &g);
    par.wall_slab = bad[k][0] * S;
    par.wall_dr = bad[k][1] * S;
    par.wall_fill = bad[k][2];
    hv_error_clear(&err);
    CHECK(measure_cavity(&p, &g, &par, &a, &err) == -1 && err.code == HV_EXIT_INPUT &&
              strstr(err.msg, "wall"),
          "wall_slab %gΔ, wall_dr %gΔ, wall_fill %g: refused (%s)", bad[k][0], bad[k][1], bad[k][2],
          err.msg);
  }
  particles_free(&p);
}

/* the last value of (quantity, object) in a measurements.csv; NAN if none */
static double csv_value(const char *path, const char *quantity, const char *object)
{
  struct meas_table t;
  struct hv_error err = {0};
  double v = NAN;
  meas_table_init(&t);
  if (meas_table_read(&t, path, &err) == 0)
    for (size_t k = 0; k < t.n; k++)
      if (!strcmp(t.rows[k].quantity, quantity) && !strcmp(t.rows[k].object, object))
        v = t.rows[k].value;
  meas_table_free(&t);
  return v;
}

/* Writes case text k of a family as STEM_k.yaml and runs it into TMP/STEM_k. refuse: it
 * must end with exit 2 and a message naming key; else it must run (exit 0). Returns 1
 * when it ran, with its measurements.csv path in csv. `what` names the variant. */
static int run_variant(const char *text, const char *stem, int k, int refuse, const char *key,
                       const char *what, char *csv, size_t ncsv)
{
  char name[96], cmd[8192], out[4096];
  const char *tmp = test_tmpdir();
  snprintf(name, sizeof name, "%s_%d.yaml", stem, k);
  const char *file = test_write_file(name, text);
  snprintf(cmd, sizeof cmd, "'%s' run '%s' -o '%s/%s_%d' --overwrite --quiet", test_bin(), file,
           tmp, stem, k);
  snprintf(csv, ncsv, "%s/%s_%d/measurements.csv", tmp, stem, k);
  const int st = test_run(cmd, out, sizeof out);
  if (refuse) {
    CHECK(st == 2 && strstr(out, key), "%s is refused, exit 2 naming %s (exit %d): %s", what, key,
          st, out);
    return 0;
  }
  CHECK(st == 0, "%s runs (exit %d): %s", what, st, out);
  return st == 0;
}

static void test_cavity_two_bodies(void)
{
  static const char *const fmt =
      "name: two-body-target\n"
      "domain: {min: [-5 mm, -15 mm, 0], max: [25 mm, 15 mm, 15 mm], half_model: true}\n"
      "bodies:\n"
      "  - name: block\n"
      "    material: steel-target\n"
      "    shape: {type: box, min: [0, -15 mm, -15 mm], max: [20 mm, 15 mm, 15 mm],\n"
      "            minus: [{type: box, min: [0, -5 mm, -5 mm], max: [20 mm, 5 mm, 5 mm]}]}\n"
      "    spacing: 1 mm\n"
      "  - name: core\n"
      "    material: steel-target\n"
      "    shape: {type: box, min: [0, -5 mm, -5 mm], max: [20 mm, 5 mm, 5 mm],\n"
      "            minus: [{type: cylinder, center: [4 mm, 0, 0], axis: [1, 0, 0],\n"
      "                     radius: 3 mm, length: 8 mm}]}\n"
      "    spacing: 0.5 mm\n"
      "time: {end: 0}\n"
      "measure: {thick_target: %s}\n";
  char text[2048], what[128], path[4400];
  const char *targets[] = {"[block, core]", "block", "[]", "[block, cores]"};
  double L[2] = {NAN, NAN}, D[2] = {NAN, NAN}, Dw[2] = {NAN, NAN}, perf[2] = {NAN, NAN};
  for (int k = 0; k < 4; k++) {
    snprintf(text, sizeof text, fmt, targets[k]);
    snprintf(what, sizeof what, "thick_target: %s", targets[k]);
    if (!run_variant(text, "two_body", k, k >= 2, "thick_target", what, path, sizeof path))
      continue;
    L[k] = csv_value(path, "penetration_depth", "block");
    D[k] = csv_value(path, "cavity_diameter", "block");
    Dw[k] = csv_value(path, "cavity_diameter_wall", "block");
    perf[k] = csv_value(path, "perforated", "block");
  }
  const double dc = 0.5e-3; /* the core's spacing */
  CHECK(fabs(L[0] - 8e-3) <= dc, "two bodies: L = %.3f mm, 8 mm within the core's 0.5 mm",
        1e3 * L[0]);
  CHECK(fabs(D[0] - 6e-3) <= dc, "two bodies: D = %.3f mm, 6 mm within 0.5 mm", 1e3 * D[0]);
  CHECK(fabs(Dw[0] - 6e-3) <= 0.5 * dc, "two bodies: D_wall = %.3f mm, 6 mm within 0.25 mm",
        1e3 * Dw[0]);
  CHECK(L[1] > 19e-3 && perf[1] == 1.0,
        "the outer block alone sees the core's channel as a "
        "perforation: L = %.2f mm",
        1e3 * L[1]);
}

/* measure.cavity_min_count through a case file: the block of test_cavity_two_bodies
 * without its coarse ring (0.5 mm lattice), its 8 mm deep, 6 mm wide cavity holding one
 * stray target particle on the axis 4 mm down (a body `stray` of one particle, measured
 * with the block: thick_target: [block, stray]). The stray closes the cavity at 4 mm
 * by default; cavity_min_count: 2 passes over it and reads the whole 8 mm. 0, 9 and a
 * count without a thick target are refused, exit 2 naming the key. */
static void test_cavity_min_count_case(void)
{
  static const char *const fmt =
      "name: stray-target\n"
      "domain: {min: [-5 mm, -5 mm, 0], max: [25 mm, 5 mm, 5 mm], half_model: true}\n"
      "bodies:\n"
      "  - name: block\n"
      "    material: steel-target\n"
      "    shape: {type: box, min: [0, -5 mm, -5 mm], max: [20 mm, 5 mm, 5 mm],\n"
      "            minus: [{type: cylinder, center: [4 mm, 0, 0], axis: [1, 0, 0],\n"
      "                     radius: 3 mm, length: 8 mm}]}\n"
      "    spacing: 0.5 mm\n"
      "  - name: stray\n"
      "    material: steel-target\n"
      "    shape: {type: box, min: [3.75 mm, -0.25 mm, 0], max: [4.25 mm, 0.25 mm, 0.5 mm]}\n"
      "    spacing: 0.5 mm\n"
      "time: {end: 0}\n"
      "measure: {%s}\n";
  const char *meas[] = {"thick_target: [block, stray]",
                        "thick_target: [block, stray], cavity_min_count: 2",
                        "thick_target: [block, stray], cavity_min_count: 0",
                        "thick_target: [block, stray], cavity_min_count: 9", "cavity_min_count: 2"};
  char text[2048], path[4400];
  double L[2] = {NAN, NAN};
  for (int k = 0; k < 5; k++) {
    snprintf(text, sizeof text, fmt, meas[k]);
    if (!run_variant(text, "stray", k, k >= 2, "cavity_min_count", meas[k], path, sizeof path))
      continue;
    L[k] = csv_value(path, "penetration_depth", "block");
  }
  const double d = 0.5e-3;
  CHECK(fabs(L[0] - 4e-3) <= d,
        "a stray on the axis 4 mm down closes the cavity there by "
        "default: L = %.3f mm, 4 mm within 0.5 mm",
        1e3 * L[0]);
  CHECK(fabs(L[1] - 8e-3) <= d,
        "cavity_min_count: 2 passes over it: L = %.3f mm, 8 mm within "
        "0.5 mm",
        1e3 * L[1]);
}

/* A plate (or backwall) of two bodies through a case file, variant k of a family: `ring`,
 * a box 0 <= x <= t mm, |y|, |z| <= 20 mm on a 1 mm lattice, with the disc cut out;
 * `disc`, the cylinder of radius r mm through the plate around (t/2, yd, 0) on a 0.25 mm
 * lattice; a cylinder of radius 3 mm at the axis, 0 <= x <= 1 mm, cut from both (a hole
 * through a 1 mm plate, a crater 1 mm deep in a thicker one); run to t = 0 with
 * measure: {meas}. refuse/key as run_variant; returns 1 when it ran (csv: its
 * measurements.csv). */
static int ring_disc_variant(const char *stem, int k, int refuse, const char *key, const char *meas,
                             const char *mat, double t, double yd, double r, char *csv, size_t ncsv)
{
  static const char *const cut =
      "{type: cylinder, center: [0.5 mm, 0, 0], axis: [1, 0, 0], radius: 3 mm, length: 1 mm}";
  char text[2048], disc[256];
  snprintf(disc, sizeof disc,
           "{type: cylinder, center: [%g mm, %g mm, 0], axis: [1, 0, 0], "
           "radius: %g mm, length: %g mm}",
           0.5 * t, yd, r, t);
  snprintf(text, sizeof text,
           "name: two-body-plate\n"
           "domain: {min: [-5 mm, -20 mm, 0], max: [5 mm, 20 mm, 20 mm], half_model: true}\n"
           "bodies:\n"
           "  - name: ring\n"
           "    material: %s\n"
           "    shape: {type: box, min: [0, -20 mm, -20 mm], max: [%g mm, 20 mm, 20 mm],\n"
           "            minus: [%s, %s]}\n"
           "    spacing: 1 mm\n"
           "  - name: disc\n"
           "    material: %s\n"
           "    shape: {type: cylinder, center: [%g mm, %g mm, 0], axis: [1, 0, 0],\n"
           "            radius: %g mm, length: %g mm, minus: [%s]}\n"
           "    spacing: 0.25 mm\n"
           "time: {end: 0}\n"
           "measure: {%s}\n",
           mat, t, disc, cut, mat, 0.5 * t, yd, r, t, cut, meas);
  return run_variant(text, stem, k, refuse, key, meas, csv, ncsv);
}

/* A plate refined near the impact point, measured as one plate through a case file
 * (measure.plates: [[ring, disc]]): a coarse ring (1 mm lattice, one layer) and a fine
 * disc (0.25 mm, four layers, off the axis at y = 6 mm, radius 4 mm), with a 6 mm hole at
 * the impact point cut from both, so that the hole's rim is half coarse, half fine. Each
 * particle covers the plane at its own body's spacing: at the fine spacing everywhere
 * the ring's 1 mm lattice would read as a sieve, and the hole would leak through it to
 * the window's edge. */
static void test_plate_two_bodies(void)
{
  char what[128], path[4400];
  const char *plates[] = {"[[ring, disc]]", "[ring]", "[[]]", "[[ring, ring]]", "[[ring, discs]]"};
  for (int k = 0; k < 5; k++) {
    snprintf(what, sizeof what, "plates: %s", plates[k]);
    if (!ring_disc_variant("two_body_plate", k, k >= 2, "measure.plates[0]", what, "steel-bumper",
                           1.0, 6.0, 4.0, path, sizeof path))
      continue;
    const double perf = csv_value(path, "perforated", "ring");
    const double open = csv_value(path, "hole_open", "ring");
    const double d = csv_value(path, "hole_diameter", "ring");
    const double de = csv_value(path, "hole_diameter_equiv", "ring");
    if (k == 0) {
      const double dc = 1e-3; /* the ring's spacing: half the rim is the ring's */
      CHECK(perf == 1.0 && open == 0.0, "ring + disc: perforated (%g), the hole closed (%g)", perf,
            open);
      CHECK(fabs(d - 6e-3) <= dc, "ring + disc: hole %.3f mm, 6 mm within the ring's 1 mm",
            1e3 * d);
      CHECK(fabs(de - 6e-3) <= dc,
            "ring + disc: equivalent-area diameter %.3f mm, 6 mm within "
            "1 mm",
            1e3 * de);
    } else {
      /* the hole and the disc's place are one opening: 3 mm + 4 mm from the axis at y = 6 mm
         (14 mm long); the largest circle is the disc's 8 mm */
      CHECK(perf == 1.0 && fabs(d - 8e-3) <= 1e-3,
            "the ring alone: the disc's place is part "
            "of its hole, largest circle %.2f mm (8 mm within its 1 mm spacing)",
            1e3 * d);
    }
  }
}

/* A backwall refined near the axis, measured as one through a case file
 * (measure.backwall: [ring, disc]): a coarse ring (1 mm lattice, two layers of a 2 mm
 * wall) around a fine disc (0.25 mm, eight layers, radius 8 mm) with a crater 1 mm deep
 * and 6 mm across cut into the disc's front. The crater's depth is 1 mm exactly (the
 * fine layer at 1.125 mm, less its footprint), its radius and the damaged area's 3 mm
 * within the ring width 2 x 0.25 mm. Each particle covers its columns at its own body's
 * spacing: at the fine spacing everywhere the ring's first layer (0.5 mm behind the face)
 * would read as a crater 0.375 mm deep out to the wall's edge. */
static void test_backwall_two_bodies(void)
{
  char what[128], path[4400];
  const char *walls[] = {"[ring, disc]", "ring", "[]", "[ring, ring]", "[ring, discs]"};
  for (int k = 0; k < 5; k++) {
    snprintf(what, sizeof what, "backwall: %s", walls[k]);
    if (!ring_disc_variant("two_body_backwall", k, k >= 2, "measure.backwall", what, "al-alloy",
                           2.0, 0.0, 8.0, path, sizeof path))
      continue;
    const double depth = csv_value(path, "crater_depth", "ring");
    const double rc = csv_value(path, "crater_radius", "ring");
    const double rd = csv_value(path, "damage_radius", "ring");
    const double perf = csv_value(path, "perforated", "ring");
    const double hd = csv_value(path, "hole_diameter", "ring");
    if (k == 0) {
      const double dc = 0.25e-3; /* the disc's spacing */
      CHECK(fabs(depth - 1e-3) <= 1e-9, "ring + disc: crater depth %.4f mm, 1 mm exactly",
            1e3 * depth);
      CHECK(fabs(rc - 3e-3) <= 2 * dc, "ring + disc: crater radius %.3f mm, 3 mm within 0.5 mm",
            1e3 * rc);
      CHECK(fabs(rd - 3e-3) <= 2 * dc, "ring + disc: damaged radius %.3f mm, 3 mm within 0.5 mm",
            1e3 * rd);
      CHECK(perf == 0.0, "ring + disc: not perforated (%g)", perf);
      CHECK(hd == 0.0, "ring + disc: hole diameter 0 (%g)", hd);
    } else {
      CHECK(perf == 1.0 && fabs(hd - 16e-3) <= 1e-3,
            "the ring alone: the disc's place is a "
            "hole through it (%g), largest circle %.2f mm (16 mm within its 1 mm spacing)",
            perf, 1e3 * hd);
    }
  }
}

/* A backwall that has moved back as a whole, 5 mm behind its 1 mm thickness (a free
 * plate at 1 km/s for 5 us, intact): its material still blocks the line of sight, so
 * it is not perforated (a slab ending 2t behind the original face would hold none of
 * it and read one open hole). The wall far from the impact has moved 5 mm with it
 * (wall_shift), so it has no crater; measured from the original face
 * (`measure.crater_reference: original-face`) its depth is the 5 mm it has moved
 * (docs/measurements.md). */
static void test_backwall_moved(void)
{
  static const char *const fmt =
      "name: moved-backwall\n"
      "domain: {min: [-5 mm, -10 mm, 0], max: [15 mm, 10 mm, 10 mm], half_model: true}\n"
      "bodies:\n"
      "  - name: wall\n"
      "    material: al-alloy\n"
      "    shape: {type: box, min: [0, -10 mm, -10 mm], max: [1 mm, 10 mm, 10 mm]}\n"
      "    spacing: 0.5 mm\n"
      "    velocity: [1 km/s, 0, 0]\n"
      "time: {end: 5 us}\n"
      "output: {every: 5 us}\n"
      "measure: {backwall: wall%s}\n";
  char text[1024], path[4400];
  snprintf(text, sizeof text, fmt, "");
  if (!run_variant(text, "moved_backwall", 0, 0, "measure.backwall", "a backwall moved 5 mm", path,
                   sizeof path))
    return;
  const double perf = csv_value(path, "perforated", "wall");
  const double depth = csv_value(path, "crater_depth", "wall");
  const double shift = csv_value(path, "wall_shift", "wall");
  CHECK(perf == 0.0, "a wall moved 5 mm back is not perforated (%g)", perf);
  CHECK(fabs(shift - 5e-3) <= 1e-6, "... the wall far from the impact moved %.4f mm (5 mm)",
        1e3 * shift);
  CHECK(fabs(depth) <= 1e-6, "... and it has no crater: depth %.4f mm from the far wall",
        1e3 * depth);
  snprintf(text, sizeof text, fmt, ", crater_reference: original-face");
  if (!run_variant(text, "moved_backwall", 1, 0, "measure.backwall",
                   "the moved backwall from its "
                   "original face",
                   path, sizeof path))
    return;
  const double depth0 = csv_value(path, "crater_depth", "wall");
  CHECK(fabs(depth0 - 5e-3) <= 0.25e-3,
        "... its depth from the original face %.3f mm (5 mm "
        "within half its 0.5 mm spacing)",
        1e3 * depth0);
  CHECK(csv_value(path, "wall_shift", "wall") == 0.0, "... and no wall_shift then");
  snprintf(text, sizeof text, fmt, ", crater_reference: far");
  run_variant(text, "moved_backwall", 2, 1, "measure.crater_reference",
              "an unknown crater_reference", path, sizeof path);
}

int main(void)
{
  test_holes();
  test_blind_and_slab();
  test_detached();
  test_ellipse_and_open();
  test_cavity();
  test_cavity_wall();
  test_cavity_two_bodies();
  test_cavity_min_count_case();
  test_plate_two_bodies();
  test_backwall_two_bodies();
  test_backwall_moved();
  return test_finish();
}
