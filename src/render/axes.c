/* axes.c — the axes of a picture: lines along the left and bottom edges of the plot area,
 * ticks in mm pointing out of it, their labels, and the axis names ("x [mm]") in the
 * left margin, the upward one at its top, the rightward one at its foot (the corner
 * left of the bottom axis, where no tick label goes).
 *
 * Tick steps are 1, 2 or 5 × 10ᵏ mm (render_tick_step), the smallest of them whose
 * ticks lie far enough apart for their labels: 42 s pixels along the bottom (a label of
 * five characters, 30 s, and two characters' gap) and 24 s up the left side (three text
 * heights), s the font scale. Ticks sit at whole multiples of the step, so 0 is a tick
 * whenever the axis crosses it (the impact point, the symmetry plane). A label that would
 * leave the picture, overlap the one before or the axis name is left out; its tick stays.
 */
#include <math.h>
#include <stdio.h>

#include "render/render_internal.h"

static const unsigned char ink[3] = {0, 0, 0};
static const unsigned char line[3] = {110, 110, 110};

double render_tick_step(double span, double npx, double min_px)
{
  if (!(span > 0.0 && npx > 0.0 && min_px > 0.0) || !isfinite(span)) return 0.0;
  const double want = span * min_px / npx; /* the least step, in the units of span */
  double e = pow(10.0, floor(log10(want)));
  for (;; e *= 10.0) {
    static const double m[3] = {1.0, 2.0, 5.0};
    for (int k = 0; k < 3; k++) /* a hair of tolerance: 2 · 10ᵏ asked is 2 · 10ᵏ given */
      if (m[k] * e >= want * (1.0 - 1e-9)) return m[k] * e;
  }
}

/* The label of tick t [mm] for a step: as many decimals as the step needs; -0 as 0. */
static void tick_label(char *buf, size_t len, double t, double step)
{
  const int dec = step >= 1.0 ? 0 : (int)ceil(-log10(step) - 1e-9);
  snprintf(buf, len, "%.*f", dec, fabs(t) < 0.5 * step ? 0.0 : t);
}

void render_axes(struct canvas *c, const struct render_view *v)
{
  const int s = v->scale, ml = v->ml, nu = v->nu, nv = v->nv;
  const double pmm = v->pix * 1e3; /* pixel edge [mm] */
  char name[32], lab[48];

  /* the axis lines, just outside the plot area */
  canvas_rect(c, ml - s, 0, ml, nv + s, line);
  canvas_rect(c, ml - s, nv, ml + nu, nv + s, line);

  /* bottom: u */
  snprintf(name, sizeof name, "%c [mm]", "xyz"[v->iu]);
  const int name_w = canvas_text_width(s, name), text_y = nv + 5 * s;
  canvas_text(c, 0, text_y, s, ink, name);
  const double u0 = v->u0 * 1e3, u1 = v->u1 * 1e3;
  double step = render_tick_step(u1 - u0, nu, 42.0 * s);
  if (step > 0.0) {
    int last_right = -1000000;
    const double t0 = ceil(u0 / step - 1e-9) * step;
    for (int k = 0; k <= 1000; k++) {
      const double t = t0 + k * step;
      const int x = ml + (int)floor((t - u0) / pmm);
      if (!(t <= u1) || x >= ml + nu) break;
      canvas_rect(c, x, nv + s, x + s, nv + 4 * s, ink);
      tick_label(lab, sizeof lab, t, step);
      const int tw = canvas_text_width(s, lab), tx = x - tw / 2;
      if (tx < name_w + FONT_ADVANCE * s || tx + tw > c->w || tx < last_right + 2 * s) continue;
      canvas_text(c, tx, text_y, s, ink, lab);
      last_right = tx + tw;
    }
  }

  /* left: v, labels right-aligned against the ticks; the axis name at the top */
  snprintf(name, sizeof name, "%c [mm]", "xyz"[v->iv]);
  canvas_text(c, 0, s, s, ink, name);
  const double v0 = v->v0 * 1e3, v1 = v->v1 * 1e3;
  step = render_tick_step(v1 - v0, nv, 24.0 * s);
  if (step > 0.0) {
    int last_top = 1000000;
    const double t0 = ceil(v0 / step - 1e-9) * step;
    for (int k = 0; k <= 1000; k++) {
      const double t = t0 + k * step;
      const int y = (int)floor((v1 - t) / pmm);
      if (!(t <= v1) || y < 0) break;
      if (y >= nv) continue;
      canvas_rect(c, ml - 4 * s, y, ml - s, y + s, ink);
      tick_label(lab, sizeof lab, t, step);
      const int tw = canvas_text_width(s, lab), ty = y - 3 * s;
      int tx = ml - 5 * s - tw;
      if (tx < 0) tx = 0;
      /* below the axis name, above the bottom axis' labels, apart from the one below */
      if (ty < 11 * s || ty + 7 * s > nv + s || ty + 9 * s > last_top) continue;
      canvas_text(c, tx, ty, s, ink, lab);
      last_top = ty;
    }
  }
}
