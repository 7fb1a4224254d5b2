/* ble_plot.c — ballistic_limit.png of `hvsph sweep` (ble_plot.h), drawn with the
 * render module's canvas and font.
 *
 * Layout: a plot area with a left margin for the diameter ticks and a bottom band for
 * the speed ticks; a legend in the bottom right of the plot; the case file's name at
 * the top right. Speeds span 0 to the larger of
 * 8 km/s and 1.1 × the fastest point (so both regime boundaries of a normal impact show);
 * diameters 0 to 1.15 × the largest of the brackets and the curve over that span.
 */
#include "render/ble_plot.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render/render_internal.h"

#define PLOT_W 900
#define PLOT_H 600
#define ML     70 /* [px] left margin */
#define MB     50 /* [px] bottom margin */
#define MT     30 /* [px] top margin (title) */
#define MR     20 /* [px] right margin */
#define PI_    3.14159265358979323846

static const unsigned char ink[3] = {0, 0, 0};
static const unsigned char grey[3] = {150, 150, 150};
static const unsigned char blue[3] = {30, 90, 200};
static const unsigned char red[3] = {200, 40, 40};
static const unsigned char curve_col[4][3] = {{0, 0, 0}, {0, 130, 60}, {150, 80, 0}, {120, 0, 150}};

struct frame {
  double vmax, dmax;  /* [km/s], [mm] */
  int x0, x1, y0, y1; /* plot area: x0..x1 left to right, y0 (top) .. y1 (bottom) */
};

static int px(const struct frame *f, double v)
{
  return f->x0 + (int)lround(v / f->vmax * (f->x1 - f->x0));
}
static int py(const struct frame *f, double d)
{
  return f->y1 - (int)lround(d / f->dmax * (f->y1 - f->y0));
}

/* A thick dot (2r+1 px square) clipped to the plot area. */
static void dot(struct canvas *c, const struct frame *f, int x, int y, int r,
                const unsigned char *col)
{
  for (int j = y - r; j <= y + r; j++)
    for (int i = x - r; i <= x + r; i++)
      if (i >= f->x0 && i <= f->x1 && j >= f->y0 && j <= f->y1) canvas_blend(c, i, j, col, 1.0);
}

/* A line by steps of one pixel along its longer side (width 2r+1). */
static void seg(struct canvas *c, const struct frame *f, int xa, int ya, int xb, int yb, int r,
                const unsigned char *col, int dash)
{
  const int n = abs(xb - xa) > abs(yb - ya) ? abs(xb - xa) : abs(yb - ya);
  for (int k = 0; k <= n; k++) {
    if (dash && (k / 6) % 2) continue;
    const double t = n ? (double)k / n : 0.0;
    dot(c, f, (int)lround(xa + t * (xb - xa)), (int)lround(ya + t * (yb - ya)), r, col);
  }
}

static void ticks(struct canvas *c, const struct frame *f)
{
  char lab[32];
  canvas_rect(c, f->x0 - 1, f->y0, f->x0 + 1, f->y1 + 1, ink);
  canvas_rect(c, f->x0 - 1, f->y1, f->x1 + 1, f->y1 + 2, ink);
  const double sv = render_tick_step(f->vmax, f->x1 - f->x0, 60);
  for (double v = 0; v <= f->vmax * (1 + 1e-9); v += sv) {
    const int x = px(f, v);
    canvas_rect(c, x, f->y1, x + 1, f->y1 + 6, ink);
    snprintf(lab, sizeof lab, "%g", v);
    canvas_text(c, x - canvas_text_width(2, lab) / 2, f->y1 + 10, 2, ink, lab);
  }
  const double sd = render_tick_step(f->dmax, f->y1 - f->y0, 40);
  for (double d = 0; d <= f->dmax * (1 + 1e-9); d += sd) {
    const int y = py(f, d);
    canvas_rect(c, f->x0 - 6, y, f->x0, y + 1, ink);
    snprintf(lab, sizeof lab, "%g", d);
    canvas_text(c, f->x0 - 10 - canvas_text_width(2, lab), y - 7, 2, ink, lab);
  }
  const char *xl = "impact speed [km/s]";
  canvas_text(c, (f->x0 + f->x1 - canvas_text_width(2, xl)) / 2, f->y1 + 30, 2, ink, xl);
  canvas_text(c, 4, f->y0 - 22, 2, ink, "critical diameter [mm]");
}

int ble_plot_write(const struct ble_plot *bp, const char *path, struct hv_error *err)
{
  struct frame f = {
      .vmax = 8.0, .dmax = 0.0, .x0 = ML, .x1 = PLOT_W - MR, .y0 = MT + 10, .y1 = PLOT_H - MB};
  double angles[4];
  int nang = 0;
  for (int k = 0; k < bp->npoints; k++) {
    const struct ble_plot_point *q = &bp->points[k];
    if (isfinite(q->speed)) f.vmax = fmax(f.vmax, 1.1e-3 * q->speed);
    if (isfinite(q->hi)) f.dmax = fmax(f.dmax, 1e3 * q->hi);
    int seen = 0;
    for (int a = 0; a < nang; a++) seen |= angles[a] == q->obliquity;
    if (!seen && nang < 4 && isfinite(q->obliquity)) angles[nang++] = q->obliquity;
  }
  if (nang == 0) angles[nang++] = 0.0;
  const int nsamp = 400;
  if (bp->has_ble)
    for (int a = 0; a < nang; a++)
      for (int s = 1; s <= nsamp; s++) {
        const double d = ble_whipple_dc(&bp->ble, 1e3 * f.vmax * s / nsamp, angles[a] * PI_ / 180);
        /* the ballistic branch grows without bound as v -> 0: its span above 1 km/s */
        if (isfinite(d) && f.vmax * s / nsamp >= 1.0) f.dmax = fmax(f.dmax, 1e3 * d);
      }
  if (!(f.dmax > 0)) f.dmax = 1.0;
  f.dmax *= 1.15;

  struct canvas c;
  canvas_init(&c, PLOT_W, PLOT_H);
  if (bp->has_ble)
    for (int a = 0; a < nang; a++) {
      const double th = angles[a] * PI_ / 180;
      const double vb[2] = {1e-3 * ble_whipple_v_low(th), 1e-3 * ble_whipple_v_high(th)};
      for (int b = 0; b < 2; b++)
        if (vb[b] < f.vmax) seg(&c, &f, px(&f, vb[b]), f.y0, px(&f, vb[b]), f.y1, 0, grey, 1);
      int xp = -1, yp = -1;
      for (int s = 1; s <= nsamp; s++) {
        const double v = f.vmax * s / nsamp;
        const double d = 1e3 * ble_whipple_dc(&bp->ble, 1e3 * v, th);
        if (!isfinite(d)) continue;
        const int x = px(&f, v), y = py(&f, fmin(d, 2 * f.dmax));
        if (xp >= 0) seg(&c, &f, xp, yp, x, y, 1, curve_col[a], 0);
        xp = x;
        yp = y;
      }
    }
  for (int k = 0; k < bp->npoints; k++) {
    const struct ble_plot_point *q = &bp->points[k];
    if (!isfinite(q->speed) || !isfinite(q->lo) || !isfinite(q->hi)) continue;
    const int x = px(&f, 1e-3 * q->speed);
    const int ylo = py(&f, 1e3 * q->lo), yhi = py(&f, 1e3 * q->hi);
    if (q->state == 0) {
      seg(&c, &f, x, ylo, x, yhi, 1, blue, 0);
      seg(&c, &f, x - 6, ylo, x + 6, ylo, 0, blue, 0);
      seg(&c, &f, x - 6, yhi, x + 6, yhi, 0, blue, 0);
      dot(&c, &f, x, py(&f, 0.5e3 * (q->lo + q->hi)), 4, blue);
    } else if (q->state == 1 || q->state == 2) {
      /* the limit lies below LO (yes at both ends) or above HI (no at both) */
      const int y = q->state == 1 ? ylo : yhi, dir = q->state == 1 ? 1 : -1;
      seg(&c, &f, x, y, x, y + dir * 30, 1, red, 0);
      seg(&c, &f, x - 6, y + dir * 22, x, y + dir * 30, 1, red, 0);
      seg(&c, &f, x + 6, y + dir * 22, x, y + dir * 30, 1, red, 0);
    } else {
      seg(&c, &f, x, ylo, x, yhi, 0, grey, 1);
    }
  }
  ticks(&c, &f);
  /* legend: bottom right, under the curve's shatter and hypervelocity branches, where
     no bracket of a shield's usual sweep falls (the equation's d_c there is some mm) */
  const int nleg = (bp->has_ble ? nang + 1 : 0) + 2;
  int ly = f.y1 - 10 - 22 * nleg;
  const int lx = f.x0 + (f.x1 - f.x0) / 2;
  char text[200];
  if (bp->has_ble)
    for (int a = 0; a < nang; a++) {
      canvas_rect(&c, lx, ly + 6, lx + 24, ly + 9, curve_col[a]);
      snprintf(text, sizeof text, "Christiansen Whipple BLE, %g deg", angles[a]);
      canvas_text(&c, lx + 32, ly, 2, ink, text);
      ly += 22;
    }
  if (bp->has_ble) {
    seg(&c, &f, lx, ly + 7, lx + 24, ly + 7, 0, grey, 1);
    canvas_text(&c, lx + 32, ly, 2, ink, "regime bounds 3/cos, 7/cos km/s");
    ly += 22;
  }
  canvas_rect(&c, lx + 11, ly, lx + 14, ly + 16, blue);
  canvas_text(&c, lx + 32, ly, 2, ink, "hvsph bracket (bisection)");
  ly += 22;
  canvas_rect(&c, lx + 11, ly, lx + 14, ly + 16, red);
  canvas_text(&c, lx + 32, ly, 2, ink, "limit outside the range");
  const char *slash = strrchr(bp->title, '/');
  const char *title = slash ? slash + 1 : bp->title;
  canvas_text(&c, PLOT_W - MR - canvas_text_width(2, title), 4, 2, ink, title);
  const int rc = canvas_write_png(&c, path, "hvsph sweep: ballistic-limit curve", err);
  canvas_free(&c);
  return rc;
}
