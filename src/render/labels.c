/* labels.c — each body's name on the picture, where it fits.
 *
 * A body's label is centred at the mass-weighted centre of its particles in view
 * (mirror copies included, so a mirrored half model's centre lies on the symmetry
 * plane), in the built-in font on a white box three quarters opaque, so it reads on a
 * dark radiograph as on coloured discs. A label is drawn only where it lies wholly in
 * the plot area (moved inwards when it sticks out past an edge) and overlaps no label
 * placed before; bodies are placed in index order, the case file's, so the projectile
 * comes first and a body inside another (a plate's refined disc, its centre the plate's)
 * gives way to it.
 *
 * The names come from the run's used_parameters.yaml (bodies[i].name), in the snapshot's
 * folder; without one a body is called "body N", N its index in the snapshot's body
 * column.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "config/config.h"
#include "render/render_internal.h"

static const unsigned char ink[3] = {0, 0, 0};
static const unsigned char paper[3] = {255, 255, 255};

int render_read_body_names(const char *dir, char names[][64], int max)
{
  char path[4200];
  snprintf(path, sizeof path, "%s/used_parameters.yaml", dir && dir[0] ? dir : ".");
  struct stat st;
  if (stat(path, &st) != 0 || !S_ISREG(st.st_mode)) return 0;
  struct hv_error err;
  hv_error_clear(&err);
  struct cfg *c = cfg_load(path, &err);
  if (!c) {
    hv_warn("%s: %s; the bodies are labelled \"body N\"", path, err.msg);
    return 0;
  }
  int n = cfg_len(c, "bodies");
  if (n > max) n = max;
  for (int i = 0; i < n; i++) {
    char key[64];
    const char *s = NULL;
    snprintf(key, sizeof key, "bodies[%d].name", i);
    names[i][0] = '\0';
    if (cfg_get_string(c, key, "", &s, &err) == 0 && s) snprintf(names[i], 64, "%s", s);
  }
  cfg_free(c);
  return n < 0 ? 0 : n;
}

struct box {
  int x0, y0, x1, y1; /* [x0, x1) × [y0, y1) */
};

static int overlap(const struct box *a, const struct box *b)
{
  return a->x0 < b->x1 && b->x0 < a->x1 && a->y0 < b->y1 && b->y0 < a->y1;
}

int render_body_labels(struct canvas *plot, const struct particles *p, const struct render_view *v,
                       const struct render_info *info)
{
  int nb = 0;
  for (size_t i = 0; i < p->n; i++)
    if (p->body[i] >= nb && p->body[i] < RENDER_MAX_BODIES) nb = p->body[i] + 1;
  double *sum = hv_calloc((size_t)nb * 3 + 1, sizeof *sum, "body centres");
  for (size_t i = 0; i < p->n; i++) {
    const int b = p->body[i];
    if (b < 0 || b >= nb || !(p->m[i] > 0.0)) continue;
    for (int copy = 0; copy < RENDER_COPIES; copy++) {
      double x[3];
      if (!render_copy_pos(p, i, copy, v, x)) continue;
      if (!(x[v->axis] >= v->d0 && x[v->axis] <= v->d1)) continue;
      const double u = x[v->iu], w = x[v->iv];
      if (!(u >= v->u0 && u <= v->u1 && w >= v->v0 && w <= v->v1)) continue;
      sum[3 * b] += p->m[i] * u;
      sum[3 * b + 1] += p->m[i] * w;
      sum[3 * b + 2] += p->m[i];
    }
  }
  const int s = v->scale, pad = 2 * s;
  struct box *placed = hv_malloc(((size_t)nb + 1) * sizeof *placed, "labels");
  int np = 0;
  for (int b = 0; b < nb; b++) {
    if (!(sum[3 * b + 2] > 0.0)) continue;
    const double u = sum[3 * b] / sum[3 * b + 2], w = sum[3 * b + 1] / sum[3 * b + 2];
    char name[96];
    if (info && info->body_names && b < info->nbody && info->body_names[b] &&
        info->body_names[b][0])
      snprintf(name, sizeof name, "%s", info->body_names[b]);
    else
      snprintf(name, sizeof name, "body %d", b);
    const int bw = canvas_text_width(s, name) + 2 * pad, bh = FONT_H * s + 2 * pad;
    if (bw > v->nu || bh > v->nv) continue;
    struct box r;
    r.x0 = (int)((u - v->u0) / v->pix) - bw / 2;
    r.y0 = (int)((v->v1 - w) / v->pix) - bh / 2;
    if (r.x0 < 0) r.x0 = 0;
    if (r.y0 < 0) r.y0 = 0;
    if (r.x0 + bw > v->nu) r.x0 = v->nu - bw;
    if (r.y0 + bh > v->nv) r.y0 = v->nv - bh;
    r.x1 = r.x0 + bw;
    r.y1 = r.y0 + bh;
    int free_spot = 1;
    for (int k = 0; k < np && free_spot; k++) free_spot = !overlap(&r, &placed[k]);
    if (!free_spot) continue;
    for (int y = r.y0; y < r.y1; y++)
      for (int x = r.x0; x < r.x1; x++) canvas_blend(plot, x, y, paper, 0.75);
    canvas_text(plot, r.x0 + pad, r.y0 + pad, s, ink, name);
    placed[np++] = r;
  }
  free(placed);
  free(sum);
  return np;
}
