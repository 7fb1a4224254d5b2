/* caption.c — the caption band under the plot area.
 *
 * Row 1: a scale bar (1, 2 or 5 × 10ᵏ, about a fifth of the picture width) with its
 * length, what the picture shows, and the snapshot time at the right.
 * Row 2, the key: for a radiograph a film wedge (grey level against areal density σ from
 * 0 to where the film is nearly black, T < 5 %), for particles coloured by a quantity a
 * colour bar with ticks in display units, for materials a legend of colour swatches.
 * Everything is in the built-in font (font.c), black on the white band.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "render/render_internal.h"

static const unsigned char ink[3] = {0, 0, 0};
static const unsigned char rule[3] = {150, 150, 150};

/* The largest 1, 2 or 5 × 10ᵏ not above x (x > 0). */
static double nice_floor(double x)
{
  double e = pow(10.0, floor(log10(x))), f = x / e;
  return (f >= 5.0 ? 5.0 : f >= 2.0 ? 2.0 : 1.0) * e;
}

/* Tick step near span/n: 1, 2 or 5 × 10ᵏ. */
static double nice_step(double span, int n)
{
  double s = span / n, e = pow(10.0, floor(log10(s))), f = s / e;
  return (f < 1.5 ? 1.0 : f < 3.5 ? 2.0 : f < 7.5 ? 5.0 : 10.0) * e;
}

static void format_length(char *buf, size_t len, double L)
{
  if (L >= 1.0)
    snprintf(buf, len, "%g m", L);
  else if (L >= 1e-3)
    snprintf(buf, len, "%g mm", round(L * 1e6) / 1e3);
  else
    snprintf(buf, len, "%g µm", round(L * 1e9) / 1e3);
}

static void format_time(char *buf, size_t len, double t)
{
  double us = t * 1e6;
  if (us == 0.0)
    snprintf(buf, len, "t = 0 µs");
  else if (fabs(us) >= 100.0)
    snprintf(buf, len, "t = %.0f µs", us);
  else if (fabs(us) >= 10.0)
    snprintf(buf, len, "t = %.1f µs", us);
  else if (fabs(us) >= 0.1)
    snprintf(buf, len, "t = %.2f µs", us);
  else
    snprintf(buf, len, "t = %.3g µs", us);
}

/* Ticks and labels under a horizontal bar [x0, x0 + w) for values lo..hi (display units). */
static void bar_ticks(struct canvas *c, int x0, int w, int y, int s, double lo, double hi)
{
  double step = nice_step(hi - lo, w >= 200 * s ? 5 : 3);
  int dec = step >= 1.0 ? 0 : (int)ceil(-log10(step) - 1e-9);
  int last_right = -1000000;
  /* ticks t0 + k step, counted: a span below the rounding of lo (a --range such as
   * 1,1.0000000000000002) must not make t += step stand still */
  const double t0 = ceil(lo / step - 1e-9) * step;
  for (int k = 0; k <= 100; k++) {
    const double t = t0 + k * step;
    if (!(t <= hi + 1e-9 * step)) break;
    int x = x0 + (int)lround((t - lo) / (hi - lo) * (w - 1));
    canvas_rect(c, x, y, x + s, y + 2 * s, ink);
    char lab[32];
    snprintf(lab, sizeof lab, "%.*f", dec, fabs(t) < 0.5 * step ? 0.0 : t);
    int tw = canvas_text_width(s, lab), tx = x - tw / 2;
    if (tx < 2 * s) tx = 2 * s; /* the end labels stay on the picture */
    if (tx + tw > c->w) tx = c->w - tw;
    if (tx < last_right + 4 * s) continue;
    canvas_text(c, tx, y + 3 * s, s, ink, lab);
    last_right = tx + tw;
  }
}

static void key_wedge(struct canvas *c, const struct caption_key *k, int x0, int y, int w, int s)
{
  double smax = k->hi;
  for (int i = 0; i < w; i++) {
    double T = exp(-k->mu * smax * i / (w - 1));
    unsigned char g[3];
    g[0] = g[1] = g[2] = (unsigned char)lround(255.0 * T);
    canvas_rect(c, x0 + i, y, x0 + i + 1, y + 6 * s, g);
  }
}

static void key_colorbar(struct canvas *c, int x0, int y, int w, int s)
{
  for (int i = 0; i < w; i++) {
    unsigned char rgb[3];
    render_colormap((double)i / (w - 1), rgb);
    canvas_rect(c, x0 + i, y, x0 + i + 1, y + 6 * s, rgb);
  }
}

static void key_legend(struct canvas *c, const struct caption_key *k,
                       const struct render_info *info, int x, int y, int s)
{
  for (int slot = 0; slot < k->nmat; slot++) { /* in palette order */
    int m = 0;
    while (m < k->nmat && k->slot[m] != slot) m++;
    if (m == k->nmat || !k->present[m]) continue;
    char name[96];
    if (info && info->material_names && m < info->nmat && info->material_names[m])
      snprintf(name, sizeof name, "%s", info->material_names[m]);
    else
      snprintf(name, sizeof name, "material %d", m);
    int need = 10 * s + canvas_text_width(s, name);
    if (x + need > c->w - 8 * s) {
      canvas_text(c, x, y, s, ink, "...");
      return;
    }
    unsigned char rgb[3];
    render_palette(slot, rgb);
    canvas_rect(c, x, y, x + 7 * s, y + 7 * s, rgb);
    canvas_text(c, x + 10 * s, y, s, ink, name);
    x += need + 12 * s;
  }
}

void render_caption(struct canvas *c, const struct render_view *v, const struct render_info *info,
                    const char *const what[2], const struct caption_key *key)
{
  int s = v->scale, y0 = v->nv + v->mb;
  canvas_rect(c, 0, y0, c->w, y0 + s, rule);

  /* row 1: scale bar, what is shown, time */
  double L = nice_floor(0.2 * v->pix * v->nu);
  int lpx = (int)lround(L / v->pix), x = 8 * s, ya = y0 + 5 * s;
  canvas_rect(c, x, ya + 3 * s, x + lpx, ya + 5 * s, ink);
  canvas_rect(c, x, ya, x + s, ya + 8 * s, ink);
  canvas_rect(c, x + lpx - s, ya, x + lpx, ya + 8 * s, ink);
  char buf[256];
  format_length(buf, sizeof buf, L);
  x += lpx + 5 * s;
  x += canvas_text(c, x, ya, s, ink, buf) + 16 * s;
  int right = c->w - 8 * s;
  if (info && isfinite(info->time)) {
    format_time(buf, sizeof buf, info->time);
    right -= canvas_text_width(s, buf);
    canvas_text(c, right, ya, s, ink, buf);
    right -= 16 * s;
  }
  for (int k = 0; k < 2; k++) /* the long description where it fits, else the short one */
    if (what[k] && x + canvas_text_width(s, what[k]) <= right) {
      canvas_text(c, x, ya, s, ink, what[k]);
      break;
    }

  /* row 2: the key */
  int yb = y0 + 18 * s;
  if (key->kind == 2) {
    key_legend(c, key, info, 8 * s, yb, s);
    return;
  }
  /* the bar takes half the width, or less down to a third to make room for the label */
  const char *label = key->label[0];
  int lw = canvas_text_width(s, label), room = c->w - 28 * s;
  if (room - lw < c->w / 3 && key->label[1]) {
    label = key->label[1];
    lw = canvas_text_width(s, label);
  }
  int bw = room - lw;
  if (bw > c->w / 2) bw = c->w / 2;
  if (bw < c->w / 3) {
    bw = c->w - 16 * s; /* no room for the label beside the bar */
    label = NULL;
  }
  if (key->kind == 0)
    key_wedge(c, key, 8 * s, yb, bw, s);
  else
    key_colorbar(c, 8 * s, yb, bw, s);
  bar_ticks(c, 8 * s, bw, yb + 6 * s, s, key->lo / key->unit, key->hi / key->unit);
  if (label) canvas_text(c, 8 * s + bw + 12 * s, yb - s, s, ink, label);
}
