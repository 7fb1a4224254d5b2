/* measure_run.c — see measure_run.h. */
#include "run/measure_run.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diag/fof.h"
#include "diag/measure.h"
#include "diag/through.h"
#include "run/plausible.h"
#include "version.h"

static int body_by_name(const struct sim *s, struct cfg *c, const char *path, int *out,
                        struct hv_error *err)
{
  const char *name;
  char where[256];
  if (cfg_get_string(c, path, NULL, &name, err)) return -1;
  for (int b = 0; b < s->nbody; b++)
    if (!strcmp(s->body[b].name, name)) {
      *out = b;
      return 0;
    }
  return hv_error_set(err, HV_EXIT_INPUT, "%s: %s: no body named '%s'",
                      cfg_where(c, path, where, sizeof where), path, name);
}

static int body_list(const struct sim *s, struct cfg *c, const char *path, int *out, int *n,
                     struct hv_error *err)
{
  char key[128], where[256];
  *n = 0;
  if (!cfg_has(c, path)) return 0;
  int len = cfg_len(c, path);
  if (len < 0 || len > MR_MAX)
    return hv_error_set(err, HV_EXIT_INPUT, "%s: %s must be a list of at most %d body names",
                        cfg_where(c, path, where, sizeof where), path, MR_MAX);
  for (int k = 0; k < len; k++) {
    snprintf(key, sizeof key, "%s[%d]", path, k);
    if (body_by_name(s, c, key, &out[k], err)) return -1;
  }
  *n = len;
  return 0;
}

/* A key naming one body, or a list of the bodies that make one object (a target or
 * backwall refined near the impact axis: [target, target-core]); absent: *n = 0. */
static int body_or_list(const struct sim *s, struct cfg *c, const char *path, const char *whose,
                        int *out, int *n, struct hv_error *err)
{
  char where[256];
  *n = 0;
  if (cfg_len(c, path) >= 0) {
    if (body_list(s, c, path, out, n, err)) return -1;
    if (*n == 0)
      return hv_error_set(err, HV_EXIT_INPUT,
                          "%s: %s: an empty list (name %s body, or its "
                          "bodies)",
                          cfg_where(c, path, where, sizeof where), path, whose);
    for (int a = 0; a < *n; a++)
      for (int b = a + 1; b < *n; b++)
        if (out[a] == out[b])
          return hv_error_set(err, HV_EXIT_INPUT, "%s: %s names body '%s' twice",
                              cfg_where(c, path, where, sizeof where), path, s->body[out[a]].name);
  } else if (cfg_has(c, path)) {
    if (body_by_name(s, c, path, &out[0], err)) return -1;
    *n = 1;
  }
  return 0;
}

/* measure.plates: a list whose entries are a body's name or a list of bodies (one plate
 * made of several bodies, e.g. a fine disc around the impact point inside a coarse plate). */
static int plate_list(const struct sim *s, struct cfg *c, struct measure_run *mr,
                      struct hv_error *err)
{
  const char *path = "measure.plates";
  char key[128], where[256];
  mr->nplate = 0;
  if (!cfg_has(c, path)) return 0;
  const int len = cfg_len(c, path);
  if (len < 0 || len > MR_MAX)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: %s must be a list of at most %d plates (a "
                        "body's name, or a list of the bodies that make one plate)",
                        cfg_where(c, path, where, sizeof where), path, MR_MAX);
  for (int k = 0; k < len; k++) {
    snprintf(key, sizeof key, "%s[%d]", path, k);
    if (cfg_len(c, key) >= 0) {
      if (body_list(s, c, key, mr->plate[k], &mr->nplate_body[k], err)) return -1;
      if (mr->nplate_body[k] == 0)
        return hv_error_set(err, HV_EXIT_INPUT,
                            "%s: %s: an empty list (name the plate's "
                            "body, or its bodies)",
                            cfg_where(c, key, where, sizeof where), key);
      for (int a = 0; a < mr->nplate_body[k]; a++)
        for (int b = a + 1; b < mr->nplate_body[k]; b++)
          if (mr->plate[k][a] == mr->plate[k][b])
            return hv_error_set(err, HV_EXIT_INPUT, "%s: %s names body '%s' twice",
                                cfg_where(c, key, where, sizeof where), key,
                                s->body[mr->plate[k][a]].name);
    } else {
      if (body_by_name(s, c, key, &mr->plate[k][0], err)) return -1;
      mr->nplate_body[k] = 1;
    }
  }
  mr->nplate = len;
  return 0;
}

int measure_run_read(struct measure_run *mr, struct sim *s, struct cfg *c, struct hv_error *err)
{
  memset(mr, 0, sizeof *mr);
  mr->gas = -1;
  meas_table_init(&mr->table);
  if (!cfg_has(c, "measure")) return 0;
  mr->any = 1;
  double zero = 0.0;
  int no = 0;
  if (cfg_get_quantity(c, "measure.axis_y", UNIT_LENGTH, &zero, -HUGE_VAL, HUGE_VAL, &mr->axis_y,
                       err) ||
      cfg_get_bool(c, "measure.fragments", &no, &mr->fragments, err) || plate_list(s, c, mr, err) ||
      body_list(s, c, "measure.debris", mr->debris, &mr->ndebris, err))
    return -1;
  if (s->bnd.quarter_model && mr->axis_y != 0.0) {
    char where[256];
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: measure.axis_y: a quarter model's impact axis is its planes' "
                        "line y = 0, z = 0, not y = %g m",
                        cfg_where(c, "measure.axis_y", where, sizeof where), mr->axis_y);
  }
  if (s->p.axisym && mr->axis_y != 0.0) { /* the rings' axis is r = 0 (measure_rz.h) */
    char where[256];
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: measure.axis_y: %g m, but an axisymmetric case's impact axis is "
                        "its axis of symmetry, r = 0: leave it out",
                        cfg_where(c, "measure.axis_y", where, sizeof where), mr->axis_y);
  }
  if (body_or_list(s, c, "measure.thick_target", "the target's", mr->target, &mr->ntarget, err) ||
      body_or_list(s, c, "measure.backwall", "the backwall's", mr->backwall, &mr->nbackwall, err))
    return -1;
  if (cfg_has(c, "measure.gas") && body_by_name(s, c, "measure.gas", &mr->gas, err)) return -1;
  const long one = 1;
  long mc = 1;
  if (cfg_get_int(c, "measure.cavity_min_count", &one, 1, MEAS_CAVITY_MAX_COUNT, &mc, err))
    return -1;
  mr->cavity_min_count = (int)mc;
  if (mc > 1 && mr->ntarget == 0) {
    char where[256];
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: measure.cavity_min_count is the thick target's, "
                        "but there is no measure.thick_target",
                        cfg_where(c, "measure.cavity_min_count", where, sizeof where));
  }
  mr->peak_pressure = -HUGE_VAL;
  if (cfg_get_quantity(c, "measure.pressure_radius", UNIT_LENGTH, &zero, 0.0, HUGE_VAL,
                       &mr->p_radius, err) ||
      cfg_get_quantity(c, "measure.pressure_depth", UNIT_LENGTH, &zero, 0.0, HUGE_VAL, &mr->p_depth,
                       err))
    return -1;
  if ((mr->p_radius > 0 || mr->p_depth > 0) && mr->nbackwall == 0) {
    char where[256];
    const char *key = mr->p_radius > 0 ? "measure.pressure_radius" : "measure.pressure_depth";
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: %s is the backwall's centre pressure, but there is "
                        "no measure.backwall",
                        cfg_where(c, key, where, sizeof where), key);
  }
  static const char *const crater_refs[] = {"far-wall", "original-face", NULL};
  if (cfg_get_choice(c, "measure.crater_reference", crater_refs[0], crater_refs,
                     &mr->crater_original, err))
    return -1;
  if (mr->crater_original && mr->nbackwall == 0) {
    char where[256];
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: measure.crater_reference is the backwall's, but "
                        "there is no measure.backwall",
                        cfg_where(c, "measure.crater_reference", where, sizeof where));
  }
  return cfg_get_quantity(c, "measure.every", UNIT_TIME, &zero, 0.0, HUGE_VAL, &mr->every, err);
}

void measure_run_free(struct measure_run *mr) { meas_table_free(&mr->table); }

static struct meas_geom geom(const struct measure_run *mr, const struct sim *s, int b)
{
  const struct body_info *bi = &s->body[b];
  return (struct meas_geom){.body = b,
                            .x0 = bi->lo[0],
                            .thickness = bi->hi[0] - bi->lo[0],
                            .yc = mr->axis_y,
                            .spacing = bi->spacing,
                            .half_model = s->bnd.half_model,
                            .quarter_model = s->bnd.quarter_model};
}

/* The geometry of n bodies taken as one (a target or plate refined near the impact
 * axis): the front face the foremost of theirs, the thickness to the rearmost face, the
 * spacing the finest; body -1 (the caller's mask selects them). One body: its own. */
static struct meas_geom union_geom(const struct measure_run *mr, const struct sim *s,
                                   const int *bodies, int n)
{
  struct meas_geom g = geom(mr, s, bodies[0]);
  if (n < 2) return g;
  double hi = s->body[bodies[0]].hi[0];
  for (int k = 1; k < n; k++) {
    const struct body_info *bi = &s->body[bodies[k]];
    g.x0 = fmin(g.x0, bi->lo[0]);
    hi = fmax(hi, bi->hi[0]);
    g.spacing = fmin(g.spacing, bi->spacing);
  }
  g.thickness = hi - g.x0;
  g.body = -1;
  return g;
}

/* mask[i] = particle i belongs to one of the n bodies */
static void bodies_mask(const struct sim *s, const int *bodies, int n, unsigned char *mask)
{
  for (size_t i = 0; i < s->p.n; i++) {
    mask[i] = 0;
    for (int k = 0; k < n; k++) mask[i] |= s->p.body[i] == bodies[k];
  }
}

/* The backwall's bodies as one (union_geom) and, for several, their mask (free it). */
static struct meas_geom backwall_geom(const struct measure_run *mr, const struct sim *s,
                                      unsigned char **mask)
{
  *mask = NULL;
  if (mr->nbackwall > 1) {
    *mask = hv_malloc(s->p.n + 1, "backwall mask");
    bodies_mask(s, mr->backwall, mr->nbackwall, *mask);
  }
  return union_geom(mr, s, mr->backwall, mr->nbackwall);
}

void measure_run_step(struct measure_run *mr, const struct sim *s)
{
  if (mr->nbackwall == 0) return;
  unsigned char *mask;
  struct meas_geom g = backwall_geom(mr, s, &mask);
  const double r0 = mr->p_radius > 0 ? mr->p_radius : 2 * g.spacing;
  const double depth = mr->p_depth > 0 ? mr->p_depth : 2 * g.spacing;
  double pc = measure_center_pressure(&s->p, &g, r0, depth, mask, NULL);
  free(mask);
  if (pc > mr->peak_pressure) mr->peak_pressure = pc;
}

/* The front face of the next plate (or backwall) behind body b, for a cloud's end. */
static double next_face(const struct measure_run *mr, const struct sim *s, int b)
{
  double x = INFINITY, rear = s->body[b].hi[0];
  for (int k = 0; k < mr->nplate; k++)
    for (int j = 0; j < mr->nplate_body[k]; j++) {
      const double f = s->body[mr->plate[k][j]].lo[0];
      if (f > rear && f < x) x = f;
    }
  for (int j = 0; j < mr->nbackwall; j++) {
    const double f = s->body[mr->backwall[j]].lo[0];
    if (f > rear && f < x) x = f;
  }
  return x;
}

/* The thick target's cavity. A target of several bodies (a block refined near its
 * axis) is measured as one: its particles are those of every listed body, its front face
 * the foremost of theirs, its spacing the finest (where the cavity runs: footprint and
 * r_open Δ/2 and Δ of it, slices Δ thick). */
static int measure_target(struct measure_run *mr, const struct sim *s, double t,
                          struct hv_error *err)
{
  struct meas_geom g = union_geom(mr, s, mr->target, mr->ntarget);
  unsigned char *mask = NULL;
  if (mr->ntarget > 1) {
    mask = hv_malloc(s->p.n + 1, "thick-target mask");
    bodies_mask(s, mr->target, mr->ntarget, mask);
  }
  struct meas_cavity_params cp;
  struct meas_cavity cav;
  meas_cavity_defaults(&cp, &g);
  cp.mask = mask;
  cp.min_count = mr->cavity_min_count;
  /* slices one fine spacing thick: each holds a layer of the fine body, so that no slice
     sees only the coarse body's particles further out */
  if (mask) cp.slice = g.spacing;
  const int rc = measure_cavity(&s->p, &g, &cp, &cav, err);
  free(mask);
  if (rc) {
    meas_cavity_free(&cav); /* the profile, when the wall's step failed */
    return -1;
  }
  meas_table_add_cavity(&mr->table, t, s->body[mr->target[0]].name, &cav);
  meas_cavity_free(&cav);
  return 0;
}

/* Each measured plate's hole (with fracture also the hole in its unsplit material). */
static int measure_plates(struct measure_run *mr, const struct sim *s, double t,
                          struct hv_error *err)
{
  /* the holes in unsplit material: split particles still joined to a plate carry no
     tension, rubble that a recovered plate would not keep (one mask for every plate) */
  unsigned char *intact = NULL;
  if (s->p.solid && mr->nplate > 0) {
    intact = hv_malloc(s->p.n + 1, "intact mask");
    for (size_t i = 0; i < s->p.n; i++) intact[i] = s->p.damage[i] < 1.0;
  }
  unsigned char *group = NULL, *both = NULL;
  double *scale = NULL;
  int rc = 0;
  for (int k = 0; k < mr->nplate && !rc; k++) {
    const char *name = s->body[mr->plate[k][0]].name;
    /* a plate of several bodies is their union, each particle at its own body's spacing
       relative to the finest (measure.h) */
    struct meas_geom g = union_geom(mr, s, mr->plate[k], mr->nplate_body[k]);
    struct meas_plate_params pp;
    struct meas_plate hole;
    if (mr->nplate_body[k] > 1) {
      if (!group) {
        group = hv_malloc(s->p.n + 1, "plate mask");
        scale = hv_malloc((s->p.n + 1) * sizeof *scale, "plate spacings");
        if (intact) both = hv_malloc(s->p.n + 1, "plate mask");
      }
      bodies_mask(s, mr->plate[k], mr->nplate_body[k], group);
      for (size_t i = 0; i < s->p.n; i++) {
        scale[i] = s->body[s->p.body[i]].spacing / g.spacing;
        if (both) both[i] = group[i] && intact[i];
      }
    }
    meas_plate_defaults(&pp, &g);
    if (mr->nplate_body[k] > 1) {
      pp.mask = group;
      pp.scale = scale;
    }
    if ((rc = measure_plate(&s->p, &g, &pp, &hole, err))) break;
    meas_table_add_plate(&mr->table, t, name, &hole);
    if (intact) {
      pp.mask = mr->nplate_body[k] > 1 ? both : intact;
      if ((rc = measure_plate(&s->p, &g, &pp, &hole, err))) break;
      meas_table_add(&mr->table, t, "hole_diameter_intact", hole.d_circle, "m", name);
      meas_table_add(&mr->table, t, "hole_diameter_intact_equiv", hole.d_equiv, "m", name);
      meas_table_add(&mr->table, t, "hole_intact_open", hole.hole_open, "", name);
    }
  }
  free(intact);
  free(group);
  free(both);
  free(scale);
  return rc ? -1 : 0;
}

/* Each debris cloud behind a plate: solid material from it and what lay in front. */
static int measure_clouds(struct measure_run *mr, const struct sim *s, double t,
                          struct hv_error *err)
{
  for (int k = 0; k < mr->ndebris; k++) {
    struct meas_geom g = geom(mr, s, mr->debris[k]);
    struct meas_debris_params dp;
    struct meas_debris cloud;
    meas_debris_defaults(&dp, &g);
    dp.x_limit = next_face(mr, s, mr->debris[k]);
    /* the cloud is solid material from this plate and what lay in front of it (the
       projectile): spall thrown back from the plates behind is not, nor a gas */
    unsigned char *mask = hv_malloc(s->p.n + 1, "cloud mask");
    for (size_t i = 0; i < s->p.n; i++) {
      const struct material *m = &s->mat[s->p.mat[i]];
      mask[i] = s->body[s->p.body[i]].lo[0] < dp.x_limit &&
                (m->str.enabled || m->frac.kind != FRACTURE_NONE); /* not a gas */
    }
    dp.mask = mask;
    const int drc = measure_debris(&s->p, &dp, &cloud, err);
    free(mask);
    if (drc) return -1;
    char obj[96];
    snprintf(obj, sizeof obj, "cloud:%s", s->body[mr->debris[k]].name);
    meas_table_add_debris(&mr->table, t, obj, &cloud);
  }
  return 0;
}

double measure_run_shadow(const struct sim *s, const int *bodies, int nb, double axis_y,
                          double spacing)
{
  double rw = HUGE_VAL;
  for (int j = 0; j < nb; j++) {
    const struct body_info *bi = &s->body[bodies[j]];
    /* rings fill r <= hi[1] about the axis r = 0; 3D: the nearest edge across y and z
       (a quarter model's wall starts at the plane y = 0, its mirror beyond it; a half
       model's at z = 0). Across z too: a wall narrower in z than in y (one made long
       in −y for an oblique impact, 2026-12-08) let debris passing over its z edge, at
       z 58–63 mm beside a wall to 55 mm, count as through a 73.5 mm shadow */
    const double below = s->bnd.quarter_model ? HUGE_VAL : axis_y - bi->lo[1];
    if (s->p.axisym) {
      rw = fmin(rw, bi->hi[1]);
      continue;
    }
    rw = fmin(rw, fmin(below, bi->hi[1] - axis_y));
    rw = fmin(rw, bi->hi[2]);
    if (!s->bnd.half_model) rw = fmin(rw, -bi->lo[2]);
  }
  return fmax(rw - 2.0 * spacing, spacing);
}

/* What went through the backwall (diag/through.h): solid material behind its far face,
 * moving away, not the attached wall, within the wall's shadow (its extent across, less
 * two spacings). */
static int measure_wall_through(struct measure_run *mr, const struct sim *s,
                                const struct meas_geom *g, const unsigned char *mask,
                                const double *bscale, struct meas_through *thr,
                                struct hv_error *err)
{
  struct meas_through_params tp;
  meas_through_defaults(&tp, g);
  unsigned char *solid = hv_malloc(s->p.n + 1, "through mask");
  for (size_t i = 0; i < s->p.n; i++) {
    const struct material *m = &s->mat[s->p.mat[i]];
    solid[i] = m->str.enabled || m->frac.kind != FRACTURE_NONE;
  }
  tp.solid = solid;
  tp.wall = mask;
  tp.scale = bscale;
  tp.r_max = measure_run_shadow(s, mr->backwall, mr->nbackwall, mr->axis_y, g->spacing);
  const int rc = measure_through(&s->p, g, &tp, thr, err);
  free(solid);
  return rc;
}

/* The backwall's layers at the start (t = 0: a run's first output, or hvsph measure's
 * first snapshot, whose step is not kept): with fewer than 4 the answers follow the
 * lattice. */
static void measure_wall_layers(struct measure_run *mr, const struct sim *s, double t,
                                const char *name)
{
  const int layers = check_plate_layers(s, mr->backwall, mr->nbackwall, 0.0, mr->axis_y);
  meas_table_add(&mr->table, t, "wall_layers", layers, "", name);
  if (layers < CHECK_LAYERS_MIN)
    hv_warn("backwall '%s': only %d particle layer%s through it at the impact point: its "
            "perforation (and wall_failed) follows the lattice more than the physics "
            "below %d layers (docs/measurements.md)",
            name, layers, layers == 1 ? "" : "s", CHECK_LAYERS_MIN);
}

/* The backwall: its crater, damage, perforation and what went through, and the peak
 * pressure at its centre. */
static int measure_rear_wall(struct measure_run *mr, const struct sim *s, double t,
                             struct hv_error *err)
{
  unsigned char *mask;
  struct meas_geom g = backwall_geom(mr, s, &mask);
  const char *name = s->body[mr->backwall[0]].name;
  /* several bodies: each particle at its own body's spacing relative to the finest */
  double *bscale = NULL;
  if (mask) {
    bscale = hv_malloc((s->p.n + 1) * sizeof *bscale, "backwall spacings");
    for (size_t i = 0; i < s->p.n; i++) bscale[i] = s->body[s->p.body[i]].spacing / g.spacing;
  }
  struct meas_backwall_params bp;
  struct meas_backwall bw;
  meas_backwall_defaults(&bp, &g);
  bp.mask = mask;
  bp.scale = bscale;
  bp.far_reference = !mr->crater_original;
  struct meas_plate_params pp;
  struct meas_plate hole;
  meas_plate_defaults(&pp, &g);
  pp.mask = mask;
  pp.scale = bscale;
  /* perforation of the backwall: any of its material in the flight path blocks it,
     joined or not (a cracked bulge whose particles have drifted apart still stops
     the debris; a bumper's hole is measured on its joined piece), however far behind
     its rear face it has bulged (a slab ending 2t behind would read a bulge beyond
     it as a hole): the slab reaches the rearmost backwall particle */
  pp.attached_only = 0;
  for (size_t i = 0; i < s->p.n; i++)
    if ((mask ? mask[i] : s->p.body[i] == g.body) && isfinite(s->p.x[0][i]))
      pp.slab_rear = fmax(pp.slab_rear, s->p.x[0][i] - (g.x0 + g.thickness) + g.spacing);
  struct meas_through thr;
  const int brc = measure_backwall(&s->p, &g, &bp, &bw, err) ||
                  measure_plate(&s->p, &g, &pp, &hole, err) ||
                  measure_wall_through(mr, s, &g, mask, bscale, &thr, err);
  free(mask);
  free(bscale);
  if (brc) return -1;
  meas_table_add_backwall(&mr->table, t, name, &bw);
  meas_table_add_plate(&mr->table, t, name, &hole); /* perforated, and the hole if any */
  meas_table_add(&mr->table, t, "through", thr.through, "", name);
  meas_table_add(&mr->table, t, "through_mass", thr.mass, "kg", name);
  meas_table_add(&mr->table, t, "through_velocity", thr.velocity, "m/s", name);
  meas_table_add(&mr->table, t, "through_wall_mass", thr.wall_mass, "kg", name);
  meas_table_add(&mr->table, t, "wall_failed", hole.perforated || thr.through, "", name);
  if (s->t == 0.0) measure_wall_layers(mr, s, t, name);
  meas_table_add(&mr->table, t, "peak_pressure_center",
                 mr->peak_pressure > -HUGE_VAL ? mr->peak_pressure : (double)NAN, "Pa", name);
  return 0;
}

static int measure_all(struct measure_run *mr, const struct sim *s, struct hv_error *err)
{
  const double t = s->t;
  if (mr->ntarget > 0 && measure_target(mr, s, t, err)) return -1;
  if (measure_plates(mr, s, t, err) || measure_clouds(mr, s, t, err) ||
      (mr->nbackwall > 0 && measure_rear_wall(mr, s, t, err)))
    return -1;
  if (mr->gas >= 0) {
    const struct body_info *bi = &s->body[mr->gas];
    const double origin[3] = {bi->lo[0], mr->axis_y, 0.0};
    struct meas_gas_params gp;
    struct meas_gas_front gf;
    meas_gas_defaults(&gp, mr->gas, bi->rho, origin, bi->spacing);
    if (measure_gas_front(&s->p, &gp, &gf, err)) return -1;
    meas_table_add_gas(&mr->table, t, bi->name, &gf);
  }
  return 0;
}

int measure_run_output(struct measure_run *mr, const struct sim *s, int k, const char *outdir,
                       const char *const *matnames, struct hv_error *err)
{
  if (!mr->any) return 0;
  char path[4200], comment[512];
  snprintf(comment, sizeof comment, "hvsph %s case %s: measurements (docs/measurements.md)",
           HVSPH_VERSION, s->case_name);
  if (measure_all(mr, s, err)) {
    hv_error_prefix(err, "measurements at t = %g s: ", s->t);
    return MEASURE_FAILED_DATA;
  }
  if (mr->fragments) {
    /* solid material only (gases are not fragments); linking length 1.5 × the
       particle's own body spacing */
    const size_t n = s->p.n;
    unsigned char *mask = hv_malloc(n + 1, "fragment mask");
    double *b = hv_malloc((n + 1) * sizeof *b, "linking lengths");
    for (size_t i = 0; i < n; i++) {
      const struct material *m = &s->mat[s->p.mat[i]];
      mask[i] = m->str.enabled || m->frac.kind != FRACTURE_NONE;
      b[i] = FOF_B_FACTOR * s->body[s->p.body[i]].spacing;
    }
    struct fof_params fp = {.b = b[0],
                            .b_particle = b,
                            .mask = mask,
                            .nmat = s->nmat,
                            .half_model = s->bnd.half_model,
                            .quarter_model = s->bnd.quarter_model};
    struct fof_result fr;
    fof_result_init(&fr);
    int frc = fof_find(&s->p, &fp, &fr, err);
    free(mask);
    free(b);
    if (frc) {
      fof_result_free(&fr);
      hv_error_prefix(err, "fragments: ");
      return MEASURE_FAILED_DATA;
    }
    meas_table_add_fragments(&mr->table, s->t, "all", &fr);
    int rc = 0;
    if (k >= 0) { /* an output time: the fragments' own file too */
      snprintf(path, sizeof path, "%s/fragments_%05d.csv", outdir, k);
      rc = fof_write_csv(path, &fr, s->t, matnames, comment, err);
    }
    fof_result_free(&fr);
    if (rc) return -1;
  }
  snprintf(path, sizeof path, "%s/measurements.csv", outdir);
  return meas_table_write(&mr->table, path, comment, err);
}
