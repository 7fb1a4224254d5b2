/* render.c — one picture from a particle set: view, plot (radiograph or discs), caption,
 * PNG. See render.h for the geometry and docs/rendering.md for what the pictures mean.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render/render_internal.h"

/* Display unit of a colour quantity from the largest magnitude shown. */
static void color_unit(enum render_color c, double lo, double hi, double *unit, const char **label)
{
  double big = fmax(fabs(lo), fabs(hi));
  switch (c) {
  case RENDER_COLOR_VELOCITY:
    *unit = big >= 1e3 ? 1e3 : 1.0;
    *label = big >= 1e3 ? "|v| [km/s]" : "|v| [m/s]";
    return;
  case RENDER_COLOR_PRESSURE:
    *unit = big >= 1e8 ? 1e9 : big >= 1e5 ? 1e6 : 1e3;
    *label = big >= 1e8 ? "p [GPa]" : big >= 1e5 ? "p [MPa]" : "p [kPa]";
    return;
  case RENDER_COLOR_DENSITY:
    *unit = big >= 100.0 ? 1e3 : 1.0;
    *label = big >= 100.0 ? "ρ [g/cm³]" : "ρ [kg/m³]";
    return;
  case RENDER_COLOR_ALPHA:
    *unit = 1.0;
    *label = "viscosity alpha";
    return;
  case RENDER_COLOR_DT:
    *unit = 1.0;
    *label = "log10 of the time step the particle allows [s]";
    return;
  case RENDER_COLOR_DAMAGE:
  case RENDER_COLOR_MATERIAL: break;
  }
  *unit = 1.0;
  *label = "damage";
}

static const char *color_name(enum render_color c)
{
  static const char *n[] = {"material", "damage", "velocity", "pressure", "density", "alpha", "dt"};
  return n[c];
}

/* Radiograph into the plot canvas; fills the key and the description; returns μ. */
/* The mirroring in words, for a picture's description. */
static const char *mirror_text(const struct render_view *v)
{
  return v->mirror && v->mirror_y ? ", mirrored at y = 0 and z = 0"
         : v->mirror              ? ", mirrored at z = 0"
         : v->mirror_y            ? ", mirrored at y = 0"
                                  : "";
}

static double draw_radiograph(struct canvas *c, const struct particles *p,
                              const struct particles *rings, const struct render_view *v,
                              const struct render_options *o, struct caption_key *key, char *desc,
                              size_t dlen)
{
  size_t npix = (size_t)v->nu * (size_t)v->nv;
  double *sigma = hv_malloc(npix * sizeof *sigma, "areal density picture");
  double left_out = 0.0; /* rings: p holds their halves, rings the rings themselves */
  if (rings)
    left_out = render_areal_density_rz(rings, v, sigma);
  else
    render_areal_density(p, v, sigma);
  double quartile = 0.0, mu = o->mu;
  const int automatic = !(o->mu > 0.0);
  if (automatic) {
    unsigned char *occ = hv_malloc(npix, "occupied pixels");
    render_occupied(p, v, occ);
    mu = render_auto_mu(sigma, occ, npix, &quartile);
    free(occ);
  }
  render_film(c, v, sigma, mu);
  double mass = 0.0, smax = 0.0;
  for (size_t k = 0; k < npix; k++) {
    mass += sigma[k];
    smax = fmax(smax, sigma[k]);
  }
  mass *= v->pix * v->pix;
  free(sigma);
  key->kind = 0;
  key->lo = 0.0;
  key->hi = 3.0 / mu; /* the film transmits 5 % there */
  key->unit = 1.0;
  key->mu = mu;
  char how[160] = "";
  if (automatic)
    snprintf(how, sizeof how,
             " (automatic: the lower quartile of the areal densities of the "
             "pixels holding a particle, %.6g kg/m2, at T = 1/2)",
             quartile);
  char lost[128] = "";
  if (left_out > 0.0)
    snprintf(lost, sizeof lost, " (%.6g kg of rings beyond the picture's reach left out)",
             left_out);
  snprintf(desc, dlen,
           "simulated flash radiograph along %c%s: areal density, film T = "
           "exp(-mu*sigma), mu = %.6g m2/kg%s; mass in picture %.6g kg%s, peak areal density "
           "%.6g kg/m2",
           "xyz"[v->axis], rings ? ", the axisymmetric rings revolved about the x axis" : mirror_text(v),
           mu, how, mass, lost, smax);
  return mu;
}

/* The snapshot has the column the picture is coloured by, and the options are in
 * range. Returns 0 or -1 with err set. */
static int check_input(const struct particles *p, const struct render_options *o,
                       struct hv_error *err)
{
  if (o->mode == RENDER_PARTICLES && o->color == RENDER_COLOR_DAMAGE && !p->damage)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "the snapshot has no damage column (no material "
                        "with strength or fracture): colour by another quantity");
  if (o->mode == RENDER_PARTICLES && o->color == RENDER_COLOR_ALPHA && !p->alpha)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "the snapshot has no alpha column (a run without "
                        "sph.viscosity.switch): colour by another quantity");
  if (o->mode == RENDER_PARTICLES && o->color == RENDER_COLOR_DT) {
    size_t k = 0;
    while (k < p->n && !(p->dt[k] > 0.0)) k++;
    if (k == p->n) /* the field reads 0 where a snapshot has no such column */
      return hv_error_set(err, HV_EXIT_INPUT,
                          "the snapshot has no dt column (written by an "
                          "hvsph before it kept each particle's time step): colour by another "
                          "quantity");
  }
  if (o->mode == RENDER_RADIOGRAPH && !(o->mu >= 0.0 && isfinite(o->mu)))
    return hv_error_set(err, HV_EXIT_USAGE, "--mu must be a positive number [m2/kg] or auto");
  if (o->have_range && !(o->range[0] < o->range[1]))
    return hv_error_set(err, HV_EXIT_USAGE, "--range: the low end must be below the high end");
  return 0;
}

/* render_png for the points p; rings: NULL, or the axisymmetric snapshot whose rings p
 * shows in the plane of its axis (render_rz_halves). */
static int render_picture(const char *path, const struct particles *p,
                          const struct particles *rings, const struct render_options *o,
                          const struct render_info *info, struct hv_error *err)
{
  struct render_view v;
  if (render_view_setup(p, o, &v, err)) return -1;

  struct canvas c, plot;
  canvas_init(&c, v.width, v.height);
  canvas_init(&plot, v.nu, v.nv); /* the plot area, drawn alone, then put in place */
  struct caption_key key = {0};
  char what[2][128], desc[1024], mu_label[96];
  char axis = "xyz"[v.axis], right = "xyz"[v.iu], up = "xyz"[v.iv];
  unsigned char *present = NULL;
  int *slot = NULL;
  if (o->mode == RENDER_RADIOGRAPH) {
    const double mu = draw_radiograph(&plot, p, rings, &v, o, &key, desc, sizeof desc);
    snprintf(mu_label, sizeof mu_label, "σ [kg/m²]  film T = exp(−μσ), μ = %.3g m²/kg%s", mu,
             o->mu > 0.0 ? "" : " (auto)");
    key.label[0] = mu_label;
    key.label[1] = "σ [kg/m²]";
    const char *how = rings ? ", revolved" : v.mirror ? ", mirrored" : "";
    snprintf(what[0], sizeof what[0], "x-ray along %c (%c→ %c↑)%s", axis, rings ? 'x' : right,
             rings ? 'r' : up, how);
    snprintf(what[1], sizeof what[1], "x-ray along %c%s", axis, how);
  } else {
    int nmat = 1;
    for (size_t i = 0; i < p->n; i++)
      if (p->mat[i] >= nmat && p->mat[i] < RENDER_MATERIAL_CAP) nmat = p->mat[i] + 1;
    const int given = info && info->material_slot && info->nslot >= nmat;
    if (given) nmat = info->nslot; /* a series' ranking, over all its pictures */
    present = hv_calloc((size_t)nmat, 1, "material flags");
    slot = hv_malloc((size_t)nmat * sizeof *slot, "material slots");
    if (given)
      memcpy(slot, info->material_slot, (size_t)nmat * sizeof *slot);
    else
      render_material_slots(p, nmat, slot);
    double lo, hi;
    size_t nd = render_discs(&plot, p, &v, o, &lo, &hi, present, slot, nmat);
    key.kind = o->color == RENDER_COLOR_MATERIAL ? 2 : 1;
    key.lo = lo;
    key.hi = hi;
    key.present = present;
    key.slot = slot;
    key.nmat = nmat;
    color_unit(o->color, lo, hi, &key.unit, &key.label[0]);
    const char *how = rings         ? ", rings, cut through the axis"
                      : v.mirror    ? ", mirrored"
                      : v.axis == 2 ? ", cut at z = 0"
                                    : "";
    snprintf(what[0], sizeof what[0], "seen along +%c (%c→ %c↑)%s", axis, rings ? 'x' : right,
             rings ? 'r' : up, how);
    snprintf(what[1], sizeof what[1], "along +%c%s", axis, how);
    snprintf(desc, sizeof desc,
             "particles seen along +%c%s, coloured by %s (%.6g to %.6g "
             "SI), %zu discs",
             axis,
             rings && p->n == 2 * rings->n ? ", axisymmetric rings at (x, r) and mirrored at (x, -r)"
             : rings                       ? ", axisymmetric rings at (x, r)"
                                           : mirror_text(&v),
             color_name(o->color), lo, hi, nd);
  }
  if (o->labels && info && !info->body_names && info->source) {
    /* names not given: the run's, next to the snapshot (validate's pictures, say) */
    static char names[RENDER_MAX_BODIES][64];
    const char *ptr[RENDER_MAX_BODIES];
    char dir[4096];
    snprintf(dir, sizeof dir, "%s", info->source);
    char *slash = strrchr(dir, '/');
    if (slash)
      slash[slash == dir] = '\0'; /* "/snap.csv": the root */
    else
      snprintf(dir, sizeof dir, ".");
    struct render_info named = *info;
    named.nbody = render_read_body_names(dir, names, RENDER_MAX_BODIES);
    for (int k = 0; k < named.nbody; k++) ptr[k] = names[k];
    named.body_names = ptr;
    render_body_labels(&plot, p, &v, &named);
  } else if (o->labels) {
    render_body_labels(&plot, p, &v, info);
  }
  for (int j = 0; j < v.nv; j++)
    memcpy(c.rgb + 3 * ((size_t)j * (size_t)c.w + (size_t)v.ml),
           plot.rgb + 3 * (size_t)j * (size_t)v.nu, 3 * (size_t)v.nu);
  canvas_free(&plot);
  render_axes(&c, &v);
  const char *whatp[2] = {what[0], what[1]};
  render_caption(&c, &v, info, whatp, &key);
  free(present);
  free(slot);

  char full[2048];
  snprintf(full, sizeof full,
           "%s; %s%s%st = %.9g s; picture %c right %.6g..%.6g m, %c up "
           "%.6g..%.6g m, pixel %.6g m",
           desc, info && info->source ? "snapshot " : "", info && info->source ? info->source : "",
           info && info->source ? ", " : "", info ? info->time : (double)NAN, "xyz"[v.iu], v.u0,
           v.u1, "xyz"[v.iv], v.v0, v.v1, v.pix);
  int rc = canvas_write_png(&c, path, full, err);
  canvas_free(&c);
  return rc;
}

int render_png(const char *path, const struct particles *p, const struct render_options *o,
               const struct render_info *info, struct hv_error *err)
{
  if (check_input(p, o, err)) return -1;
  if (!p->axisym) return render_picture(path, p, NULL, o, info, err);
  /* axisymmetric: the rings shown in the plane of the axis, both halves unless
     --no-mirror; the radiograph from the rings themselves (radiograph_rz.c) */
  struct render_options orz;
  if (render_rz_options(o, &orz, err)) return -1;
  struct particles halves;
  render_rz_halves(p, o->mirror != 0, &halves);
  const int rc = render_picture(path, &halves, p, &orz, info, err);
  particles_free(&halves);
  return rc;
}
