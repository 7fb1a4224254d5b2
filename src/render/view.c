/* view.c — where a picture lies: line of sight, mirroring, extent and page layout.
 *
 * The plot area takes nu × nv pixels at the top of the picture, right of a margin ml for
 * the left axis; under it lie the band of the bottom axis (mb) and the caption band.
 * Pixels are square: the extent (the --box, or every particle with its kernel support 2h
 * and a 4 % margin) is grown about its centre until its aspect matches the plot area's.
 * Mirroring is automatic for a half model: on when every particle lies at z >= -h/2;
 * a quarter model (render_quarter_model) is mirrored across y = 0 as well.
 * In particles mode along z no mirror is drawn, and along y not the one across y = 0:
 * the viewer looks at a symmetry plane, where the model shows its cut through the middle
 * of the body.
 */
#include <math.h>

#include "render/render.h"

void render_options_default(struct render_options *o)
{
  *o = (struct render_options){0};
  o->mode = RENDER_RADIOGRAPH;
  o->axis = 2;
  o->color = RENDER_COLOR_MATERIAL;
  o->mirror = -1;
  o->mu = RENDER_MU_AUTO;
  o->labels = 1;
}

int render_half_model(const struct particles *p)
{
  for (size_t i = 0; i < p->n; i++)
    if (p->x[2][i] < -0.5 * p->h[i]) return 0;
  return 1;
}

int render_quarter_model(const struct particles *p)
{
  int near = 0;
  for (size_t i = 0; i < p->n; i++) {
    if (p->x[1][i] < -0.5 * p->h[i]) return 0;
    near = near || p->x[1][i] < fabs(p->h[i]);
  }
  return near && render_half_model(p);
}

/* Bounding box (u, v) of the particles in the depth slab with their supports. */
static int particle_extent(const struct particles *p, const struct render_view *v, double ext[4])
{
  ext[0] = ext[2] = HUGE_VAL;
  ext[1] = ext[3] = -HUGE_VAL;
  int any = 0;
  for (size_t i = 0; i < p->n; i++)
    for (int copy = 0; copy < RENDER_COPIES; copy++) {
      double x[3];
      if (!render_copy_pos(p, i, copy, v, x)) continue;
      double d = x[v->axis], r = 2.0 * fabs(p->h[i]);
      if (!(d >= v->d0 && d <= v->d1) || !isfinite(x[v->iu]) || !isfinite(x[v->iv])) continue;
      ext[0] = fmin(ext[0], x[v->iu] - r);
      ext[1] = fmax(ext[1], x[v->iu] + r);
      ext[2] = fmin(ext[2], x[v->iv] - r);
      ext[3] = fmax(ext[3], x[v->iv] + r);
      any = 1;
    }
  return any;
}

int render_view_setup(const struct particles *p, const struct render_options *o,
                      struct render_view *view, struct hv_error *err)
{
  struct render_view v = {0};
  if (o->axis < 0 || o->axis > 2)
    return hv_error_set(err, HV_EXIT_USAGE, "the view axis must be x, y or z");
  v.axis = o->axis;
  v.iu = o->axis == 0 ? 1 : 0;
  v.iv = o->axis == 2 ? 1 : 2;
  v.mirror = o->mirror < 0 ? render_half_model(p) : o->mirror;
  v.mirror_y = v.mirror && render_quarter_model(p);
  if (o->mode == RENDER_PARTICLES && o->axis == 2) v.mirror = v.mirror_y = 0;
  if (o->mode == RENDER_PARTICLES && o->axis == 1) v.mirror_y = 0;
  v.d0 = -HUGE_VAL;
  v.d1 = HUGE_VAL;
  double ext[4];
  if (o->have_box) {
    for (int k = 0; k < 3; k++)
      if (!(o->box[2 * k] < o->box[2 * k + 1]))
        return hv_error_set(err, HV_EXIT_USAGE, "--box: the %c range is empty (min >= max)",
                            "xyz"[k]);
    v.d0 = o->box[2 * v.axis];
    v.d1 = o->box[2 * v.axis + 1];
    ext[0] = o->box[2 * v.iu];
    ext[1] = o->box[2 * v.iu + 1];
    ext[2] = o->box[2 * v.iv];
    ext[3] = o->box[2 * v.iv + 1];
  } else {
    if (p->n == 0) return hv_error_set(err, HV_EXIT_INPUT, "the snapshot holds no particles");
    if (!particle_extent(p, &v, ext))
      return hv_error_set(err, HV_EXIT_INPUT, "no particle with a finite position to show");
    double span = fmax(fmax(ext[1] - ext[0], ext[3] - ext[2]), 1e-6);
    ext[0] -= 0.04 * span;
    ext[1] += 0.04 * span;
    ext[2] -= 0.04 * span;
    ext[3] += 0.04 * span;
  }
  for (int k = 0; k < 4; k++) v.ext[k] = ext[k];
  double du = ext[1] - ext[0], dv = ext[3] - ext[2];

  if (o->width > 0 && o->height > 0) {
    v.width = o->width;
    v.height = o->height;
  } else {
    v.width = o->width > 0 ? o->width : RENDER_WIDTH_DEFAULT;
  }
  if (v.width < RENDER_MIN_WIDTH || v.width > RENDER_MAX_SIDE)
    return hv_error_set(err, HV_EXIT_USAGE, "--size: the width must be %d to %d pixels",
                        RENDER_MIN_WIDTH, RENDER_MAX_SIDE);
  v.scale = v.width >= 640 ? 2 : 1;
  v.band = 36 * v.scale;
  /* the left margin holds a label of 5 characters (30 s), the tick (3 s) and a gap, and
   * the axis name "y [mm]" (36 s); the bottom band a tick, a gap and a line of text */
  v.ml = 40 * v.scale;
  v.mb = 16 * v.scale;
  v.nu = v.width - v.ml;
  if (v.height > 0) {
    if (v.height < RENDER_MIN_HEIGHT || v.height > RENDER_MAX_SIDE)
      return hv_error_set(err, HV_EXIT_USAGE, "--size: the height must be %d to %d pixels",
                          RENDER_MIN_HEIGHT, RENDER_MAX_SIDE);
    if (v.height - v.band - v.mb < 40)
      return hv_error_set(err, HV_EXIT_USAGE,
                          "--size: a picture %d pixels wide needs a height of at least %d "
                          "(%d for the axis and the caption)",
                          v.width, v.band + v.mb + 40, v.band + v.mb);
    v.nv = v.height - v.band - v.mb;
  } else {
    double nv = round(v.nu * dv / du);
    v.nv = (int)fmin(fmax(nv, 120.0), 0.75 * v.nu); /* at most 4:3 upright */
    v.height = v.nv + v.mb + v.band;
  }
  v.pix = fmax(du / v.nu, dv / v.nv);
  if (!(v.pix > 0.0 && isfinite(0.5 * v.pix * v.nu) && isfinite(0.5 * v.pix * v.nv) &&
        isfinite(ext[0] + ext[1]) && isfinite(ext[2] + ext[3])))
    return o->have_box
               ? hv_error_set(err, HV_EXIT_USAGE,
                              "--box: %.6g..%.6g m by %.6g..%.6g m cannot be "
                              "drawn with pixels of a finite, nonzero size",
                              ext[0], ext[1], ext[2], ext[3])
               : hv_error_set(err, HV_EXIT_INPUT,
                              "the particles' extent (%.6g..%.6g m by "
                              "%.6g..%.6g m) cannot be drawn with pixels of a finite, nonzero "
                              "size",
                              ext[0], ext[1], ext[2], ext[3]);
  double cu = 0.5 * (ext[0] + ext[1]), cv = 0.5 * (ext[2] + ext[3]);
  v.u0 = cu - 0.5 * v.pix * v.nu;
  v.u1 = cu + 0.5 * v.pix * v.nu;
  v.v0 = cv - 0.5 * v.pix * v.nv;
  v.v1 = cv + 0.5 * v.pix * v.nv;
  *view = v;
  return 0;
}
