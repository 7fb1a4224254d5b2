/* sweep.c — `hvsph sweep`: one case over a grid of values, with an optional bisection
 * at each grid point (sweep.h; docs/cli.md, docs/ballistic-limit.md).
 *
 * Points. Every point is one `hvsph run CASE -o DIR/points/<name> --set KEY=VALUE ...`
 * in a process of its own (fork and exec of this very binary), so that a point that
 * fails (exit 3), or crashes, takes nothing else with it, and --jobs N points run side
 * by side with --threads split between them. A point's name is made of its values
 * ("speed=5km_s,radius=1.25mm"), so the same sweep asked again finds the same folders:
 * DIR/points/<name>.done (exit status and wall time) marks a point finished and is
 * reused; a folder with a checkpoint and no .done is a stopped run, continued with
 * `hvsph restart`; anything else is (re)run with --overwrite. The point's output goes
 * to DIR/points/<name>.log.
 *
 * Bisection. The key's critical value between LO and HI, where the yes/no measurement
 * (`perforated` of the case's measure.backwall by default; yes when any output of the
 * run read yes) changes, to the tolerance:
 * LO and HI are run first; if they agree, the limit lies outside the range and the sweep
 * says so; else the midpoint of the bracket is run and replaces the end it agrees with,
 * until the bracket is no wider than the tolerance. The limit is the bracket's midpoint
 * ± half its width. The sequence depends only on the answers, so a resumed sweep walks
 * the same points.
 *
 * Reproducible input. DIR/sweep_args.txt holds the command line (the case as an absolute
 * path), so that `hvsph sweep --collect DIR` can gather the points of a job array
 * (`--emit slurm`: task I runs `hvsph sweep ... --only I`, the grid point I with its
 * whole bisection).
 *
 * Bad input, found before any run (exit 2): a key the case does not have, an empty value
 * list or range, a bare number where the case writes the key with a unit, a unit of
 * another dimension than the case's, a tolerance that is not positive.
 */
#include "cli/cli.h"
#include "cli/options.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <omp.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "config/config.h"
#include "core/error.h"
#include "core/units.h"
#include "diag/ble.h"
#include "diag/measure_table.h"
#include "io/atomic_file.h"
#include "render/ble_plot.h"
#include "version.h"

#define SWEEP_MAX_KEYS  8
#define SWEEP_MAX_SETS  256
#define SWEEP_MAX_STEPS 64 /* bisection steps per grid point (2^-64 of the range) */

/* A value as the user wrote it, and what it means. */
struct sval {
  char text[128]; /* as written ("5 km/s") */
  double si;      /* SI value (NAN for text) */
};

struct vary {
  char key[256];
  int n;
  struct sval *v;
};

struct bisect {
  char key[256];
  struct sval lo, hi;
  char unit[64];  /* the unit of LO ("mm"; "" bare), used to write the midpoints */
  double unit_si; /* SI value of 1 unit */
  double tol;     /* [SI] */
  int tol_given;
};

/* One run of the sweep. */
struct point {
  char name[512];
  double bval; /* the bisected value [SI] (NAN: none) */
  char btext[128];
  int state;   /* 0 not started, 1 running, 2 done */
  int status;  /* exit status when done (-1 crashed) */
  double wall; /* [s] */
  int answer;  /* yes/no of the measurement; -1 unknown */
  double crater, through_v, through_m, layers;
  char holes[512];
};

/* A grid point, with its bisection. */
struct combo {
  int *idx;          /* value index per vary key */
  struct point *pts; /* runs, in the order asked */
  int npts, cap;
  double lo, hi; /* bracket [SI] */
  int alo, ahi;  /* answers at lo and hi (-1 unknown) */
  int done, failed, outside;
};

struct sweep {
  const char *case_abs;
  char case_path[4096];
  char dir[4096];
  const char *sets[SWEEP_MAX_SETS];
  int nsets;
  struct vary vary[SWEEP_MAX_KEYS];
  int nvary;
  int has_bisect;
  struct bisect b;
  char measure[64]; /* quantity */
  char object[128]; /* its object ("" the backwall) */
  int jobs, threads, quiet, only, collect, emit_slurm;
  struct ble_whipple ble;
  int has_ble;
  struct combo *combos;
  int ncombos;
  char tol_text[128]; /* the case's sweep.bisect.tolerance */
};

/* ---- values and keys ---------------------------------------------------------- */

static void trim(char *s)
{
  size_t n = strlen(s);
  while (n > 0 && isspace((unsigned char)s[n - 1])) s[--n] = '\0';
  size_t k = 0;
  while (s[k] && isspace((unsigned char)s[k])) k++;
  memmove(s, s + k, strlen(s + k) + 1);
}

/* The unit part of "5 km/s" ("km/s"), "" for a bare number, NULL when the text does
 * not start with a number. */
static const char *unit_part(const char *text)
{
  char *end;
  errno = 0;
  (void)strtod(text, &end);
  if (end == text) return NULL;
  while (isspace((unsigned char)*end)) end++;
  return end;
}

/* The dimension of a quantity written with a unit; -1 when no dimension takes it. */
static int text_dim(const char *text)
{
  char msg[256];
  double si;
  for (int d = 1; d < UNIT_DIM_COUNT; d++)
    if (!units_parse(text, (enum unit_dim)d, &si, msg, sizeof msg)) return d;
  return -1;
}

/* Checks a value against the case's value of the key and fills v->si: a bare number
 * where the case writes a unit, or a unit of another dimension, is bad input. */
static int check_value(struct cfg *c, const char *key, const char *what, struct sval *v,
                       struct hv_error *err)
{
  char where[256];
  const char *base;
  if (!v->text[0])
    return hv_error_set(err, HV_EXIT_INPUT, "hvsph sweep: %s: an empty value for '%s'", what, key);
  if (cfg_get_string(c, key, NULL, &base, err)) {
    err->code = 0;
    return hv_error_set(err, HV_EXIT_INPUT,
                        "hvsph sweep: %s: '%s' is not a value of the case "
                        "(%s holds a list or a mapping there)",
                        what, key, cfg_where(c, key, where, sizeof where));
  }
  const char *bu = unit_part(base), *vu = unit_part(v->text);
  v->si = NAN;
  if (!bu) return 0; /* a name or a word: passed on as written */
  if (!vu)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "hvsph sweep: %s: '%s' for %s is not a number "
                        "(the case has %s = %s at %s)",
                        what, v->text, key, key, base, cfg_where(c, key, where, sizeof where));
  if (*bu && !*vu)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "hvsph sweep: %s: %s = %s has no unit, where the "
                        "case writes %s (%s): give the value with its unit (a bare number "
                        "would be SI)",
                        what, key, v->text, base, cfg_where(c, key, where, sizeof where));
  char msg[256];
  if (*bu) {
    const int d = text_dim(base);
    if (d > 0 && units_parse(v->text, (enum unit_dim)d, &v->si, msg, sizeof msg))
      return hv_error_set(err, HV_EXIT_INPUT,
                          "hvsph sweep: %s: %s = %s: %s (the case writes "
                          "%s at %s)",
                          what, key, v->text, msg, base, cfg_where(c, key, where, sizeof where));
    if (d > 0) return 0;
  }
  if (*vu) {
    const int d = text_dim(v->text);
    if (d < 0 || units_parse(v->text, (enum unit_dim)d, &v->si, msg, sizeof msg))
      return hv_error_set(err, HV_EXIT_INPUT, "hvsph sweep: %s: %s = %s: unknown unit", what, key,
                          v->text);
  } else {
    v->si = strtod(v->text, NULL);
  }
  return 0;
}

static int case_has(struct cfg *c, const char *key, const char *what, struct hv_error *err)
{
  if (cfg_has(c, key)) return 0;
  return hv_error_set(err, HV_EXIT_INPUT,
                      "hvsph sweep: %s: the case %s has no key '%s' (a "
                      "sweep varies keys the case gives; write it in the case first)",
                      what, cfg_file(c), key);
}

/* "KEY=V1,V2,..." */
static int parse_vary(struct sweep *w, const char *arg, struct hv_error *err)
{
  const char *eq = strchr(arg, '=');
  if (w->nvary >= SWEEP_MAX_KEYS)
    return hv_error_set(err, HV_EXIT_INPUT, "hvsph sweep: at most %d --vary keys", SWEEP_MAX_KEYS);
  if (!eq || eq == arg || (size_t)(eq - arg) >= sizeof w->vary[0].key)
    return hv_error_set(err, HV_EXIT_INPUT, "hvsph sweep: --vary '%s': expected KEY=V1,V2,...",
                        arg);
  struct vary *v = &w->vary[w->nvary];
  memset(v, 0, sizeof *v);
  memcpy(v->key, arg, (size_t)(eq - arg));
  trim(v->key);
  for (int k = 0; k < w->nvary; k++)
    if (!strcmp(w->vary[k].key, v->key))
      return hv_error_set(err, HV_EXIT_INPUT, "hvsph sweep: --vary %s given twice", v->key);
  const char *s = eq + 1;
  while (*s) {
    const char *comma = strchr(s, ',');
    const size_t len = comma ? (size_t)(comma - s) : strlen(s);
    v->v = hv_realloc(v->v, (size_t)(v->n + 1) * sizeof *v->v, "sweep values");
    memset(&v->v[v->n], 0, sizeof v->v[0]);
    if (len >= sizeof v->v[0].text)
      return hv_error_set(err, HV_EXIT_INPUT, "hvsph sweep: --vary %s: a value too long", v->key);
    memcpy(v->v[v->n].text, s, len);
    trim(v->v[v->n].text);
    if (!v->v[v->n].text[0])
      return hv_error_set(err, HV_EXIT_INPUT, "hvsph sweep: --vary %s: an empty value in '%s'",
                          v->key, eq + 1);
    v->n++;
    s = comma ? comma + 1 : s + len;
  }
  if (v->n == 0)
    return hv_error_set(err, HV_EXIT_INPUT, "hvsph sweep: --vary %s: no values", v->key);
  w->nvary++;
  return 0;
}

/* "KEY=LO..HI" */
static int parse_bisect(struct sweep *w, const char *arg, struct hv_error *err)
{
  const char *eq = strchr(arg, '='), *dots = eq ? strstr(eq, "..") : NULL;
  if (!eq || eq == arg || !dots || (size_t)(eq - arg) >= sizeof w->b.key)
    return hv_error_set(err, HV_EXIT_INPUT, "hvsph sweep: --bisect '%s': expected KEY=LO..HI", arg);
  memset(w->b.key, 0, sizeof w->b.key);
  memcpy(w->b.key, arg, (size_t)(eq - arg));
  trim(w->b.key);
  const size_t nlo = (size_t)(dots - eq - 1);
  if (nlo >= sizeof w->b.lo.text || strlen(dots + 2) >= sizeof w->b.hi.text)
    return hv_error_set(err, HV_EXIT_INPUT, "hvsph sweep: --bisect '%s': too long", arg);
  memcpy(w->b.lo.text, eq + 1, nlo);
  w->b.lo.text[nlo] = '\0';
  snprintf(w->b.hi.text, sizeof w->b.hi.text, "%s", dots + 2);
  trim(w->b.lo.text);
  trim(w->b.hi.text);
  if (!w->b.lo.text[0] || !w->b.hi.text[0])
    return hv_error_set(err, HV_EXIT_INPUT, "hvsph sweep: --bisect %s: an empty end in '%s'",
                        w->b.key, eq + 1);
  w->has_bisect = 1;
  return 0;
}

/* ---- the case's own sweep (a `sweep:` section) ----------------------------------- */

/* A key of the mapping at path that is not among `known` (NULL-terminated) is bad input
 * naming its line: a misspelt `tolerence` would otherwise be ignored. */
static int known_keys(struct cfg *c, const char *path, const char *const *known,
                      struct hv_error *err)
{
  const char *const *names;
  char where[256];
  if (!cfg_is_map(c, path))
    return hv_error_set(err, HV_EXIT_INPUT, "%s: %s: a mapping expected",
                        cfg_where(c, path, where, sizeof where), path);
  const int n = cfg_keys(c, path, &names);
  for (int k = 0; k < n; k++) {
    int ok = 0;
    for (const char *const *q = known; *q && !ok; q++) ok = !strcmp(names[k], *q);
    if (!ok) {
      char full[400];
      snprintf(full, sizeof full, "%s.%s", path, names[k]);
      return hv_error_set(err, HV_EXIT_INPUT,
                          "%s: unknown key '%s' (docs/cli.md, \"hvsph "
                          "sweep\")",
                          cfg_where(c, full, where, sizeof where), full);
    }
  }
  return 0;
}

static int read_case_sweep(struct sweep *w, struct cfg *c, int cli_vary, int cli_bisect,
                           struct hv_error *err)
{
  char key[320], arg[1024];
  const char *s;
  if (!cfg_has(c, "sweep")) return 0;
  static const char *const top[] = {"vary", "bisect", "measure", "ble", NULL};
  static const char *const bis[] = {"key", "low", "high", "tolerance", NULL};
  static const char *const var[] = {"key", "values", NULL};
  static const char *const ble[] = {"type", "bumper",     "bumper_density",     "standoff",
                                    "wall", "wall_yield", "projectile_density", NULL};
  if (known_keys(c, "sweep", top, err) ||
      (cfg_has(c, "sweep.bisect") && known_keys(c, "sweep.bisect", bis, err)) ||
      (cfg_has(c, "sweep.ble") && known_keys(c, "sweep.ble", ble, err)))
    return -1;
  for (int k = 0; k < cfg_len(c, "sweep.vary"); k++) {
    snprintf(key, sizeof key, "sweep.vary[%d]", k);
    if (known_keys(c, key, var, err)) return -1;
  }
  if (!cli_vary && cfg_has(c, "sweep.vary")) {
    const int n = cfg_len(c, "sweep.vary");
    if (n <= 0)
      return hv_error_set(err, HV_EXIT_INPUT,
                          "%s: sweep.vary: a list of {key, values} "
                          "expected, not empty",
                          cfg_where(c, "sweep.vary", key, sizeof key));
    for (int k = 0; k < n; k++) {
      const char *vkey;
      snprintf(key, sizeof key, "sweep.vary[%d].key", k);
      if (cfg_get_string(c, key, NULL, &vkey, err)) return -1;
      snprintf(key, sizeof key, "sweep.vary[%d].values", k);
      const int nv = cfg_len(c, key);
      if (nv <= 0)
        return hv_error_set(err, HV_EXIT_INPUT, "%s: %s: an empty list of values",
                            cfg_where(c, key, arg, sizeof arg), key);
      size_t len = (size_t)snprintf(arg, sizeof arg, "%s=", vkey);
      for (int j = 0; j < nv && len < sizeof arg; j++) {
        snprintf(key, sizeof key, "sweep.vary[%d].values[%d]", k, j);
        if (cfg_get_string(c, key, NULL, &s, err)) return -1;
        len += (size_t)snprintf(arg + len, sizeof arg - len, "%s%s", j ? "," : "", s);
      }
      if (parse_vary(w, arg, err)) return -1;
    }
  }
  if (!cli_bisect && cfg_has(c, "sweep.bisect")) {
    const char *bkey, *lo, *hi;
    if (cfg_get_string(c, "sweep.bisect.key", NULL, &bkey, err) ||
        cfg_get_string(c, "sweep.bisect.low", NULL, &lo, err) ||
        cfg_get_string(c, "sweep.bisect.high", NULL, &hi, err))
      return -1;
    snprintf(arg, sizeof arg, "%s=%s..%s", bkey, lo, hi);
    if (parse_bisect(w, arg, err)) return -1;
    if (!w->b.tol_given && cfg_has(c, "sweep.bisect.tolerance")) {
      if (cfg_get_string(c, "sweep.bisect.tolerance", NULL, &s, err)) return -1;
      snprintf(w->tol_text, sizeof w->tol_text, "%s", s); /* parsed in check_bisect */
      w->b.tol_given = 2;
    }
  }
  if (!w->measure[0] && cfg_has(c, "sweep.measure")) {
    if (cfg_get_string(c, "sweep.measure", NULL, &s, err)) return -1;
    snprintf(w->measure, sizeof w->measure, "%s", s);
  }
  if (cfg_has(c, "sweep.ble")) {
    const char *type;
    if (cfg_get_string(c, "sweep.ble.type", NULL, &type, err)) return -1;
    if (strcmp(type, "whipple"))
      return hv_error_set(err, HV_EXIT_INPUT, "%s: sweep.ble.type: '%s' is not known (whipple)",
                          cfg_where(c, "sweep.ble.type", key, sizeof key), type);
    struct ble_whipple *b = &w->ble;
    if (cfg_get_quantity(c, "sweep.ble.bumper", UNIT_LENGTH, NULL, 0, HUGE_VAL,
                         &b->bumper_thickness, err) ||
        cfg_get_quantity(c, "sweep.ble.bumper_density", UNIT_DENSITY, NULL, 0, HUGE_VAL,
                         &b->bumper_density, err) ||
        cfg_get_quantity(c, "sweep.ble.standoff", UNIT_LENGTH, NULL, 0, HUGE_VAL, &b->standoff,
                         err) ||
        cfg_get_quantity(c, "sweep.ble.wall", UNIT_LENGTH, NULL, 0, HUGE_VAL, &b->wall_thickness,
                         err) ||
        cfg_get_quantity(c, "sweep.ble.wall_yield", UNIT_PRESSURE, NULL, 0, HUGE_VAL,
                         &b->wall_yield, err) ||
        cfg_get_quantity(c, "sweep.ble.projectile_density", UNIT_DENSITY, NULL, 0, HUGE_VAL,
                         &b->projectile_density, err))
      return -1;
    w->has_ble = 1;
  }
  return 0;
}

/* ---- checks before any run ------------------------------------------------------ */

static int check_bisect(struct sweep *w, struct cfg *c, const char *tol_text, struct hv_error *err)
{
  struct bisect *b = &w->b;
  if (case_has(c, b->key, "--bisect", err) || check_value(c, b->key, "--bisect", &b->lo, err) ||
      check_value(c, b->key, "--bisect", &b->hi, err))
    return -1;
  if (isnan(b->lo.si) || isnan(b->hi.si))
    return hv_error_set(err, HV_EXIT_INPUT, "hvsph sweep: --bisect %s: the ends must be numbers",
                        b->key);
  if (!(b->lo.si < b->hi.si))
    return hv_error_set(err, HV_EXIT_INPUT,
                        "hvsph sweep: --bisect %s=%s..%s: an empty range "
                        "(LO must be below HI)",
                        b->key, b->lo.text, b->hi.text);
  const char *u = unit_part(b->lo.text);
  snprintf(b->unit, sizeof b->unit, "%s", u ? u : "");
  b->unit_si = 1.0;
  if (b->unit[0]) {
    char one[96], msg[256];
    snprintf(one, sizeof one, "1 %s", b->unit);
    const int d = text_dim(one);
    if (d < 0 || units_parse(one, (enum unit_dim)d, &b->unit_si, msg, sizeof msg)) b->unit_si = 1;
  }
  if (tol_text) {
    struct sval t = {0};
    snprintf(t.text, sizeof t.text, "%s", tol_text);
    trim(t.text);
    if (check_value(c, b->key, "--tol", &t, err)) return -1;
    if (!(t.si > 0) || isnan(t.si))
      return hv_error_set(err, HV_EXIT_INPUT,
                          "hvsph sweep: --tol %s: a positive tolerance "
                          "expected",
                          tol_text);
    b->tol = t.si;
  } else {
    b->tol = (b->hi.si - b->lo.si) / 8.0; /* three bisection steps */
  }
  return 0;
}

/* ---- names, folders, files ------------------------------------------------------ */

/* The last component of a key ("bodies[0].speed" -> "speed"). */
static const char *short_key(const char *key)
{
  const char *dot = strrchr(key, '.');
  return dot ? dot + 1 : key;
}

static void name_append(char *name, size_t len, const char *key, const char *text)
{
  size_t n = strlen(name);
  if (n && n + 1 < len) name[n++] = ',';
  for (const char *s = short_key(key); *s && n + 2 < len; s++)
    name[n++] = isalnum((unsigned char)*s) || *s == '_' || *s == '-' ? *s : '_';
  if (n + 1 < len) name[n++] = '=';
  for (const char *s = text; *s && n + 2 < len; s++) {
    if (isspace((unsigned char)*s)) continue;
    name[n++] = isalnum((unsigned char)*s) || *s == '.' || *s == '-' || *s == '+' ? *s : '_';
  }
  name[n] = '\0';
}

static void combo_name(const struct sweep *w, const struct combo *co, char *name, size_t len)
{
  name[0] = '\0';
  for (int k = 0; k < w->nvary; k++)
    name_append(name, len, w->vary[k].key, w->vary[k].v[co->idx[k]].text);
}

static int file_exists(const char *path)
{
  struct stat st;
  return stat(path, &st) == 0;
}

/* Reads DIR/points/<name>.done: "status wall"; 0 when present. */
static int read_done(const struct sweep *w, struct point *p)
{
  char path[5200];
  snprintf(path, sizeof path, "%s/points/%s.done", w->dir, p->name);
  FILE *f = fopen(path, "r");
  if (!f) return -1;
  const int ok = fscanf(f, "%d %lf", &p->status, &p->wall) == 2;
  fclose(f);
  return ok ? 0 : -1;
}

static void write_done(const struct sweep *w, const struct point *p)
{
  char path[5200];
  struct hv_error err = {0};
  struct atomic_file af;
  snprintf(path, sizeof path, "%s/points/%s.done", w->dir, p->name);
  if (atomic_file_open(&af, path, &err) ||
      atomic_file_printf(&af, &err, "%d %.3f\n", p->status, p->wall) ||
      atomic_file_commit(&af, &err)) {
    atomic_file_abort(&af);
    hv_warn("hvsph sweep: %s", err.msg);
  }
}

/* The object measured for the yes/no answer: --measure QUANTITY@OBJECT, else the case's
 * measure.backwall (its first body). */
static void default_object(struct sweep *w, struct cfg *c)
{
  char *at = strchr(w->measure, '@');
  if (at) {
    *at = '\0';
    snprintf(w->object, sizeof w->object, "%s", at + 1);
    return;
  }
  const char *s;
  struct hv_error e = {0};
  if (cfg_has(c, "measure.backwall")) {
    if (cfg_len(c, "measure.backwall") > 0) {
      if (!cfg_get_string(c, "measure.backwall[0]", NULL, &s, &e))
        snprintf(w->object, sizeof w->object, "%s", s);
    } else if (!cfg_get_string(c, "measure.backwall", NULL, &s, &e)) {
      snprintf(w->object, sizeof w->object, "%s", s);
    }
  }
}

/* A finished point's measurements: the answer (yes if yes at any output), the largest
 * crater depth, the hole diameters at the last time, what went through the wall. */
static void read_point(const struct sweep *w, struct point *p)
{
  char path[5200];
  struct meas_table t;
  struct hv_error err = {0};
  p->answer = -1;
  p->crater = p->through_v = p->through_m = p->layers = NAN;
  p->holes[0] = '\0';
  snprintf(path, sizeof path, "%s/points/%s/measurements.csv", w->dir, p->name);
  meas_table_init(&t);
  if (meas_table_read(&t, path, &err)) {
    meas_table_free(&t);
    return;
  }
  double tend = -HUGE_VAL;
  for (size_t i = 0; i < t.n; i++) tend = fmax(tend, t.rows[i].time);
  size_t nh = 0;
  for (size_t i = 0; i < t.n; i++) {
    const struct meas_row *r = &t.rows[i];
    const int mine = !w->object[0] || !strcmp(r->object, w->object);
    if (!strcmp(r->quantity, "crater_depth") && mine && isfinite(r->value))
      p->crater = isnan(p->crater) ? r->value : fmax(p->crater, r->value);
    if (!strcmp(r->quantity, "wall_layers") && mine) p->layers = r->value; /* at t = 0 */
    /* what went through: its largest mass over the run (debris behind the wall may
       leave the domain through an absorbing face before the end), and its velocity then */
    if (!strcmp(r->quantity, "through_mass") && mine && isfinite(r->value) &&
        (isnan(p->through_m) || r->value > p->through_m)) {
      p->through_m = r->value;
      for (size_t j = 0; j < t.n; j++)
        if (t.rows[j].time == r->time && !strcmp(t.rows[j].quantity, "through_velocity") &&
            !strcmp(t.rows[j].object, r->object))
          p->through_v = t.rows[j].value;
    }
    /* the answer: yes when the quantity read yes at any output, not only the last
       (spall or debris that went through may leave by an absorbing face before the
       end, and a line of sight once opened is a perforation); no when it never did */
    if (!strcmp(r->quantity, w->measure) && mine && !isnan(r->value))
      p->answer = p->answer == 1 || r->value > 0.5;
    if (r->time != tend) continue;
    if (!strcmp(r->quantity, "hole_diameter"))
      nh += (size_t)snprintf(p->holes + nh, nh < sizeof p->holes ? sizeof p->holes - nh : 0,
                             "%s%s:%.6g", nh ? ";" : "", r->object, r->value);
  }
  meas_table_free(&t);
}

/* The wall time [s] of a run folder over all its segments (run and restarts): the sum
 * of run_segments.csv's wall_s column; 0 when it cannot be read. */
static double segments_wall(const struct sweep *w, const struct point *p)
{
  char path[5200], line[1024];
  snprintf(path, sizeof path, "%s/points/%s/run_segments.csv", w->dir, p->name);
  FILE *f = fopen(path, "r");
  if (!f) return 0.0;
  int col = -1;
  double sum = 0.0;
  while (fgets(line, sizeof line, f)) {
    if (line[0] == '#') continue;
    int k = 0;
    char *save = NULL;
    if (col < 0) { /* the header: find wall_s */
      for (char *t = strtok_r(line, ",\n", &save); t; t = strtok_r(NULL, ",\n", &save), k++)
        if (!strcmp(t, "wall_s")) col = k;
      if (col < 0) break;
      continue;
    }
    for (char *t = strtok_r(line, ",\n", &save); t; t = strtok_r(NULL, ",\n", &save), k++)
      if (k == col) sum += strtod(t, NULL);
  }
  fclose(f);
  return sum;
}

/* ---- running points ------------------------------------------------------------- */

static void format_value(const struct bisect *b, double si, char *buf, size_t len)
{
  if (b->unit[0])
    snprintf(buf, len, "%.6g %s", si / b->unit_si, b->unit);
  else
    snprintf(buf, len, "%.6g", si);
}

/* Starts point p of combo co: returns the child's pid, or -1. */
static pid_t start_point(const struct sweep *w, const struct combo *co, const struct point *p,
                         int threads)
{
  char rundir[5200], log[5200], ckpt[5400], thr[32];
  snprintf(rundir, sizeof rundir, "%s/points/%s", w->dir, p->name);
  snprintf(log, sizeof log, "%s/points/%s.log", w->dir, p->name);
  snprintf(ckpt, sizeof ckpt, "%s/checkpoint.hvc", rundir);
  snprintf(thr, sizeof thr, "%d", threads);
  const int restart = file_exists(ckpt);
  const char **args = calloc((size_t)(2 * (w->nsets + w->nvary) + 20), sizeof *args);
  char(*sets)[400] = calloc((size_t)(w->nvary + 1), sizeof *sets);
  int n = 0;
  args[n++] = "hvsph";
  if (restart) {
    args[n++] = "restart";
    args[n++] = rundir;
  } else {
    args[n++] = "run";
    args[n++] = w->case_path;
    args[n++] = "-o";
    args[n++] = rundir;
    args[n++] = "--overwrite";
    for (int k = 0; k < w->nsets; k++) {
      args[n++] = "--set";
      args[n++] = w->sets[k];
    }
    for (int k = 0; k < w->nvary; k++) {
      snprintf(sets[k], sizeof sets[k], "%s=%s", w->vary[k].key, w->vary[k].v[co->idx[k]].text);
      args[n++] = "--set";
      args[n++] = sets[k];
    }
    if (w->has_bisect) {
      snprintf(sets[w->nvary], sizeof sets[0], "%s=%s", w->b.key, p->btext);
      args[n++] = "--set";
      args[n++] = sets[w->nvary];
    }
  }
  args[n++] = "--threads";
  args[n++] = thr;
  args[n++] = "--quiet";
  args[n] = NULL;
  if (!w->quiet)
    fprintf(stderr, "hvsph sweep: %s %s\n", restart ? "continuing" : "running", p->name);
  fflush(NULL);
  const pid_t pid = fork();
  if (pid == 0) {
    FILE *f = freopen(log, "a", stdout);
    if (f) (void)dup2(fileno(stdout), 2);
    execv("/proc/self/exe", (char *const *)args);
    perror("hvsph sweep: exec");
    _exit(127);
  }
  free(args);
  free(sets);
  return pid;
}

/* The next point combo co needs, or NULL (waiting for one that runs, or done). */
static struct point *next_point(struct combo *co)
{
  if (co->done) return NULL;
  for (int k = 0; k < co->npts; k++)
    if (co->pts[k].state == 1) return NULL; /* one at a time per grid point */
  if (co->npts > 0 && co->pts[co->npts - 1].state == 0) return &co->pts[co->npts - 1];
  return NULL;
}

static struct point *add_point(const struct sweep *w, struct combo *co, double v)
{
  if (co->npts == co->cap) {
    co->cap = co->cap ? 2 * co->cap : 8;
    co->pts = hv_realloc(co->pts, (size_t)co->cap * sizeof *co->pts, "sweep points");
  }
  struct point *p = &co->pts[co->npts++];
  memset(p, 0, sizeof *p);
  p->bval = v;
  p->answer = -1;
  p->status = -1;
  combo_name(w, co, p->name, sizeof p->name);
  if (w->has_bisect) {
    format_value(&w->b, v, p->btext, sizeof p->btext);
    name_append(p->name, sizeof p->name, w->b.key, p->btext);
  }
  if (!p->name[0]) snprintf(p->name, sizeof p->name, "case");
  if (!read_done(w, p)) {
    p->state = 2;
    const double segs = segments_wall(w, p); /* the run's record, over its segments */
    if (segs > 0) p->wall = round(segs * 1e3) / 1e3;
    read_point(w, p);
  }
  return p;
}

/* After a point of co finished (or was found finished): the next step of its bisection. */
static void advance(const struct sweep *w, struct combo *co)
{
  for (;;) {
    if (co->done || co->npts == 0) return;
    struct point *p = &co->pts[co->npts - 1];
    if (p->state != 2) return;
    if (p->status != 0 || p->answer < 0) {
      co->failed = p->status != 0 ? 1 : 2; /* 2: ran, but without the measurement */
      co->done = 1;
      return;
    }
    if (!w->has_bisect) {
      co->done = 1;
      return;
    }
    if (co->npts == 1) { /* LO ran: HI next */
      co->alo = p->answer;
      add_point(w, co, co->hi);
      continue;
    }
    if (co->npts == 2) {
      co->ahi = p->answer;
      if (co->alo == co->ahi) {
        co->outside = 1;
        co->done = 1;
        return;
      }
    } else {
      if (p->answer == co->alo)
        co->lo = p->bval;
      else
        co->hi = p->bval;
    }
    if (co->hi - co->lo <= w->b.tol * (1 + 1e-9) || co->npts >= SWEEP_MAX_STEPS) {
      co->done = 1;
      return;
    }
    add_point(w, co, 0.5 * (co->lo + co->hi));
  }
}

static volatile sig_atomic_t stop_signal = 0;
static void on_signal(int sig) { stop_signal = sig; }

/* Runs (or, collecting, only gathers) every combo; returns 0, or 3 when a point failed. */
static int run_all(struct sweep *w)
{
  for (int c = 0; c < w->ncombos; c++) {
    struct combo *co = &w->combos[c];
    co->alo = co->ahi = -1;
    if (w->has_bisect) {
      co->lo = w->b.lo.si;
      co->hi = w->b.hi.si;
    }
    add_point(w, co, w->has_bisect ? w->b.lo.si : (double)NAN);
    advance(w, co);
  }
  if (w->collect) return 0;
  const int per = w->threads / w->jobs > 0 ? w->threads / w->jobs : 1;
  pid_t *pids = calloc((size_t)w->jobs, sizeof *pids);
  struct point **running = calloc((size_t)w->jobs, sizeof *running);
  struct combo **rcombo = calloc((size_t)w->jobs, sizeof *rcombo);
  double *t0 = calloc((size_t)w->jobs, sizeof *t0);
  struct sigaction sa, old_int, old_term;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_signal;
  sigaction(SIGINT, &sa, &old_int);
  sigaction(SIGTERM, &sa, &old_term);
  int nrun = 0;
  for (;;) {
    for (int c = 0; c < w->ncombos && nrun < w->jobs && !stop_signal; c++) {
      if (w->only >= 0 && c != w->only) continue;
      struct point *p = next_point(&w->combos[c]);
      if (!p) continue;
      int slot = 0;
      while (pids[slot]) slot++;
      pids[slot] = start_point(w, &w->combos[c], p, per);
      if (pids[slot] < 0) {
        pids[slot] = 0;
        p->state = 2;
        p->status = -1;
        advance(w, &w->combos[c]);
        continue;
      }
      p->state = 1;
      running[slot] = p;
      rcombo[slot] = &w->combos[c];
      t0[slot] = omp_get_wtime();
      nrun++;
    }
    if (nrun == 0) break;
    int wst;
    const pid_t pid = waitpid(-1, &wst, 0);
    if (pid < 0) {
      if (errno == EINTR) {
        for (int k = 0; k < w->jobs; k++)
          if (pids[k]) kill(pids[k], stop_signal ? stop_signal : SIGTERM);
        continue;
      }
      break;
    }
    for (int k = 0; k < w->jobs; k++) {
      if (pids[k] != pid) continue;
      struct point *p = running[k];
      p->wall = omp_get_wtime() - t0[k];
      p->status = WIFEXITED(wst) ? WEXITSTATUS(wst) : -1;
      pids[k] = 0;
      nrun--;
      if (p->status == 130 || stop_signal) { /* stopped: resumable, not finished */
        p->state = 0;
        break;
      }
      /* the run's own record of every segment (a stopped and continued point), else
         the time this process waited for it */
      const double segs = segments_wall(w, p);
      if (segs > 0) p->wall = segs;
      p->state = 2;
      p->wall = round(p->wall * 1e3) / 1e3; /* as .done keeps it: a resumed sweep.csv is the same */
      write_done(w, p);
      read_point(w, p);
      if (!w->quiet)
        fprintf(stderr, "hvsph sweep: %s: %s (%.1f s)%s\n", p->name,
                p->status == 0 ? "ok" : "failed", p->wall,
                p->status == 0 && p->answer >= 0 ? (p->answer ? ", yes" : ", no") : "");
      advance(w, rcombo[k]);
      break;
    }
  }
  sigaction(SIGINT, &old_int, NULL);
  sigaction(SIGTERM, &old_term, NULL);
  free(pids);
  free(running);
  free(rcombo);
  free(t0);
  if (stop_signal) return HV_EXIT_INTERRUPTED;
  for (int c = 0; c < w->ncombos; c++)
    if (w->combos[c].failed) return HV_EXIT_RUN;
  return 0;
}

/* ---- results -------------------------------------------------------------------- */

static void csv_text(struct atomic_file *af, struct hv_error *err, const char *s)
{
  if (strpbrk(s, ",\"\n")) {
    atomic_file_printf(af, err, "\"");
    for (; *s; s++) atomic_file_printf(af, err, *s == '"' ? "\"\"" : "%c", *s);
    atomic_file_printf(af, err, "\"");
  } else {
    atomic_file_printf(af, err, "%s", s);
  }
}

static int write_sweep_csv(const struct sweep *w, struct hv_error *err)
{
  char path[4200];
  struct atomic_file af;
  snprintf(path, sizeof path, "%s/sweep.csv", w->dir);
  if (atomic_file_open(&af, path, err)) return -1;
  atomic_file_printf(&af, err, "# hvsph %s sweep of %s; measurement %s%s%s\npoint", HVSPH_VERSION,
                     w->case_path, w->measure, w->object[0] ? " of " : "", w->object);
  for (int k = 0; k < w->nvary; k++) {
    atomic_file_printf(&af, err, ",");
    csv_text(&af, err, w->vary[k].key);
  }
  if (w->has_bisect) {
    atomic_file_printf(&af, err, ",");
    csv_text(&af, err, w->b.key);
    atomic_file_printf(&af, err, ",%s [SI]", w->b.key);
  }
  atomic_file_printf(&af, err,
                     ",%s,crater_depth_max [m],hole_diameters [m],through_velocity [m/s],"
                     "through_mass [kg],wall_layers,status,exit,wall_time [s]\n",
                     w->measure);
  for (int c = 0; c < w->ncombos; c++) {
    const struct combo *co = &w->combos[c];
    for (int k = 0; k < co->npts; k++) {
      const struct point *p = &co->pts[k];
      if (p->state != 2) continue;
      csv_text(&af, err, p->name);
      for (int j = 0; j < w->nvary; j++) {
        atomic_file_printf(&af, err, ",");
        csv_text(&af, err, w->vary[j].v[co->idx[j]].text);
      }
      if (w->has_bisect) atomic_file_printf(&af, err, ",%s,%.9g", p->btext, p->bval);
      const char *st = p->status != 0                       ? "failed"
                       : !isnan(p->layers) && p->layers < 4 ? "ok-coarse"
                                                            : "ok";
      atomic_file_printf(&af, err, ",%s,%.6g,",
                         p->answer < 0 ? ""
                         : p->answer   ? "1"
                                       : "0",
                         p->crater);
      csv_text(&af, err, p->holes);
      atomic_file_printf(&af, err, ",%.6g,%.6g,%.6g,%s,%d,%.2f\n", p->through_v, p->through_m,
                         p->layers, st, p->status, p->wall);
    }
  }
  if (err->code) {
    atomic_file_abort(&af);
    return -1;
  }
  return atomic_file_commit(&af, err);
}

/* The speed [m/s] and obliquity [deg] of a grid point: its varied values of keys named
 * `speed`, `obliquity` or `impact_angle` (90° − obliquity), else those of the case's
 * projectile, the body of the largest `speed` (or `velocity`). */
static void speed_angle(const struct sweep *w, struct cfg *c, const struct combo *co, double *speed,
                        double *obl)
{
  const double deg = 180 / 3.14159265358979323846;
  *speed = NAN;
  *obl = 0.0;
  char key[320];
  struct hv_error e = {0};
  const int nb = cfg_len(c, "bodies");
  for (int b = 0; b < nb; b++) {
    double v = NAN, vel[3], a;
    snprintf(key, sizeof key, "bodies[%d].speed", b);
    if (cfg_has(c, key) && cfg_get_quantity(c, key, UNIT_VELOCITY, NULL, 0, HUGE_VAL, &v, &e))
      v = NAN;
    snprintf(key, sizeof key, "bodies[%d].velocity", b);
    if (isnan(v) && cfg_has(c, key) && !cfg_get_vec3(c, key, UNIT_VELOCITY, NULL, vel, &e))
      v = sqrt(vel[0] * vel[0] + vel[1] * vel[1] + vel[2] * vel[2]);
    if (isnan(v) || (!isnan(*speed) && v <= *speed)) continue;
    *speed = v;
    *obl = 0.0;
    snprintf(key, sizeof key, "bodies[%d].obliquity", b);
    if (cfg_has(c, key) && !cfg_get_quantity(c, key, UNIT_ANGLE, NULL, -HUGE_VAL, HUGE_VAL, &a, &e))
      *obl = a * deg;
    snprintf(key, sizeof key, "bodies[%d].impact_angle", b);
    if (cfg_has(c, key) && !cfg_get_quantity(c, key, UNIT_ANGLE, NULL, -HUGE_VAL, HUGE_VAL, &a, &e))
      *obl = 90.0 - a * deg;
  }
  for (int k = 0; k < w->nvary; k++) {
    const char *s = short_key(w->vary[k].key);
    const double x = w->vary[k].v[co->idx[k]].si;
    if (!strcmp(s, "speed"))
      *speed = x;
    else if (!strcmp(s, "obliquity"))
      *obl = x * deg;
    else if (!strcmp(s, "impact_angle"))
      *obl = 90.0 - x * deg;
  }
}

/* The bisected value as a diameter: a radius doubled. */
static double as_diameter(const struct sweep *w, double v)
{
  return !strcmp(short_key(w->b.key), "radius") ? 2.0 * v : v;
}

static int write_limits(const struct sweep *w, struct cfg *c, struct hv_error *err)
{
  char path[4200];
  struct atomic_file af;
  snprintf(path, sizeof path, "%s/ballistic_limit.csv", w->dir);
  struct ble_plot_point *pp = calloc((size_t)w->ncombos + 1, sizeof *pp);
  int npp = 0;
  if (atomic_file_open(&af, path, err)) {
    free(pp);
    return -1;
  }
  atomic_file_printf(&af, err,
                     "# hvsph %s sweep of %s: critical %s by bisection on %s%s%s, tolerance "
                     "%.6g (SI); critical_diameter = the bracket's midpoint, +- half_bracket\n"
                     "speed,obliquity,critical_diameter,half_bracket,ble_critical_diameter,note\n",
                     HVSPH_VERSION, w->case_path, w->b.key, w->measure, w->object[0] ? " of " : "",
                     w->object, w->b.tol);
  for (int k = 0; k < w->ncombos; k++) {
    const struct combo *co = &w->combos[k];
    double speed, obl;
    speed_angle(w, c, co, &speed, &obl);
    const double ble = w->has_ble && isfinite(speed)
                           ? ble_whipple_dc(&w->ble, speed, obl * 3.14159265358979323846 / 180)
                           : (double)NAN;
    const char *note = "";
    double dc = NAN, half = NAN;
    if (!co->done)
      note = "unfinished";
    else if (co->failed == 2)
      note = "a point has no such measurement (see --measure)";
    else if (co->failed)
      note = "a point failed";
    else if (co->outside)
      note = co->alo ? "outside the range: yes at both ends (the limit lies below LO)"
                     : "outside the range: no at both ends (the limit lies above HI)";
    else {
      dc = as_diameter(w, 0.5 * (co->lo + co->hi));
      half = as_diameter(w, 0.5 * (co->hi - co->lo));
    }
    atomic_file_printf(&af, err, "%.6g,%.6g,%.6g,%.6g,%.6g,%s\n", speed, obl, dc, half, ble, note);
    struct ble_plot_point *q = &pp[npp++];
    q->speed = speed;
    q->obliquity = obl;
    q->lo = as_diameter(w, co->lo);
    q->hi = as_diameter(w, co->hi);
    q->state = co->done && !co->failed && !co->outside ? 0 : co->outside ? (co->alo ? 1 : 2) : 3;
  }
  if (err->code) {
    atomic_file_abort(&af);
    free(pp);
    return -1;
  }
  if (atomic_file_commit(&af, err)) {
    free(pp);
    return -1;
  }
  snprintf(path, sizeof path, "%s/ballistic_limit.png", w->dir);
  struct ble_plot bp = {.points = pp, .npoints = npp, .has_ble = w->has_ble, .ble = w->ble};
  snprintf(bp.title, sizeof bp.title, "%s", cfg_file(c));
  const int rc = ble_plot_write(&bp, path, err);
  free(pp);
  return rc;
}

static int emit_slurm(const struct sweep *w, struct hv_error *err)
{
  char path[4200];
  struct atomic_file af;
  snprintf(path, sizeof path, "%s/sweep.slurm", w->dir);
  if (atomic_file_open(&af, path, err)) return -1;
  atomic_file_printf(&af, err,
                     "#!/bin/bash\n"
                     "# hvsph %s: the sweep of %s as a Slurm job array, one task per grid point\n"
                     "# (with its whole bisection). Submit: sbatch %s\n"
                     "# Then gather: hvsph sweep --collect %s\n"
                     "#SBATCH --job-name=hvsph-sweep\n"
                     "#SBATCH --array=0-%d\n"
                     "#SBATCH --cpus-per-task=%d\n"
                     "#SBATCH --output=%s/points/slurm-%%a.out\n"
                     "exec ${HVSPH:-hvsph} sweep --only \"$SLURM_ARRAY_TASK_ID\" --threads "
                     "\"$SLURM_CPUS_PER_TASK\" --args-from %s/sweep_args.txt\n",
                     HVSPH_VERSION, w->case_path, path, w->dir, w->ncombos - 1, w->threads, w->dir,
                     w->dir);
  if (err->code) {
    atomic_file_abort(&af);
    return -1;
  }
  if (atomic_file_commit(&af, err)) return -1;
  chmod(path, 0755);
  return 0;
}

/* ---- options -------------------------------------------------------------------- */

/* What the command line gives besides struct sweep's fields, read before the case. */
struct sweep_cli {
  struct sweep *w;
  struct hv_error *err;
  const char *out, *tol, *emit;
  int vary, bisect; /* given on the command line: replaces the `sweep:` section's own */
  struct cli_list sets;
};

/* Every mistake on sweep's command line reads the same, exit status 1: an unknown
 * option, an option without its value at the end, a second case, a --set beyond
 * SWEEP_MAX_SETS (the wording the hand-written walk over argv had). */
static int sweep_fail(const struct cli_cmd *c, enum cli_error e, const char *arg)
{
  (void)c;
  (void)e;
  fprintf(stderr, "hvsph sweep: unexpected argument '%s' (see hvsph sweep --help)\n", arg);
  return HV_EXIT_USAGE;
}

/* A mistake found in a value (a --vary or --bisect): its message, exit status 2. */
static int sweep_bad(const struct hv_error *err)
{
  fprintf(stderr, "%s\n", err->msg);
  return err->code ? err->code : HV_EXIT_INPUT;
}

static int vary_opt(const struct cli_cmd *c, const struct cli_opt *o, const char *opt,
                    const char *val)
{
  (void)c;
  (void)opt;
  struct sweep_cli *s = o->dest;
  if (parse_vary(s->w, val, s->err)) return sweep_bad(s->err);
  s->vary = 1;
  return CLI_GO_ON;
}

static int bisect_opt(const struct cli_cmd *c, const struct cli_opt *o, const char *opt,
                      const char *val)
{
  (void)c;
  (void)opt;
  struct sweep_cli *s = o->dest;
  if (parse_bisect(s->w, val, s->err)) return sweep_bad(s->err);
  s->bisect = 1;
  return CLI_GO_ON;
}

/* --tol: checked against the bisected key's unit once the case is read */
static int tol_opt(const struct cli_cmd *c, const struct cli_opt *o, const char *opt,
                   const char *val)
{
  (void)c;
  (void)opt;
  struct sweep_cli *s = o->dest;
  s->tol = val;
  s->w->b.tol_given = 1;
  return CLI_GO_ON;
}

static int measure_opt(const struct cli_cmd *c, const struct cli_opt *o, const char *opt,
                       const char *val)
{
  (void)c;
  (void)opt;
  struct sweep *w = o->dest;
  snprintf(w->measure, sizeof w->measure, "%s", val);
  return CLI_GO_ON;
}

/* --jobs, --threads: a count in [o->lo, o->hi], decimal digits, into an int */
static int count_opt(const struct cli_cmd *c, const struct cli_opt *o, const char *opt,
                     const char *val)
{
  (void)c;
  long v;
  if (cli_decimal(val, o->lo, o->hi, &v)) {
    fprintf(stderr, "hvsph sweep: %s needs a positive integer, not '%s'\n", opt, val);
    return HV_EXIT_USAGE;
  }
  *(int *)o->dest = (int)v;
  return CLI_GO_ON;
}

/* --only: a grid point's index; whether the grid has it is known once the case is read */
static int index_opt(const struct cli_cmd *c, const struct cli_opt *o, const char *opt,
                     const char *val)
{
  (void)c;
  long v;
  if (cli_decimal(val, o->lo, o->hi, &v)) {
    fprintf(stderr, "hvsph sweep: %s needs a grid point's index, not '%s'\n", opt, val);
    return HV_EXIT_USAGE;
  }
  *(int *)o->dest = (int)v;
  return CLI_GO_ON;
}

/* ---- command line --------------------------------------------------------------- */

static int write_args(const struct sweep *w, int argc, char **argv, struct hv_error *err)
{
  char path[4200];
  struct atomic_file af;
  snprintf(path, sizeof path, "%s/sweep_args.txt", w->dir);
  if (atomic_file_open(&af, path, err)) return -1;
  atomic_file_printf(&af, err, "%s\n", w->case_path);
  for (int i = 0; i < argc; i++) {
    const char *a = argv[i];
    /* the case is written first (absolute); the per-run options are not kept */
    if (a == w->case_abs) continue;
    if (!strcmp(a, "--only") || !strcmp(a, "--threads") || !strcmp(a, "--jobs")) {
      i++;
      continue;
    }
    if (!strcmp(a, "--emit")) {
      i++;
      continue;
    }
    atomic_file_printf(&af, err, "%s\n", a);
  }
  if (err->code) {
    atomic_file_abort(&af);
    return -1;
  }
  return atomic_file_commit(&af, err);
}

/* Reads DIR/sweep_args.txt into an argument vector (the lines; the strings leak with
 * the vector, which lives as long as the program). */
static char **read_args(const char *path, int *argc, struct hv_error *err)
{
  FILE *f = fopen(path, "r");
  if (!f) {
    hv_error_set(err, HV_EXIT_INPUT, "hvsph sweep: %s: %s (not a sweep folder?)", path,
                 strerror(errno));
    return NULL;
  }
  char **v = NULL;
  int n = 0;
  char line[8192];
  while (fgets(line, sizeof line, f)) {
    line[strcspn(line, "\n")] = '\0';
    v = hv_realloc(v, (size_t)(n + 2) * sizeof *v, "sweep args");
    v[n] = hv_malloc(strlen(line) + 1, "sweep arg");
    strcpy(v[n++], line);
  }
  fclose(f);
  if (v) v[n] = NULL;
  *argc = n;
  return v;
}

/* Where --collect DIR or --args-from FILE sends the parse: the stored command line. */
struct stored {
  const char *file; /* NULL: none */
  int collect;
};

static int collect_opt(const struct cli_cmd *c, const struct cli_opt *o, const char *opt,
                       const char *val)
{
  (void)c;
  (void)opt;
  static char path[4200]; /* lives as long as the program, as the arguments do */
  struct stored *s = o->dest;
  snprintf(path, sizeof path, "%s/sweep_args.txt", val);
  s->file = path;
  s->collect = 1;
  return CLI_GO_ON;
}

static int args_from_opt(const struct cli_cmd *c, const struct cli_opt *o, const char *opt,
                         const char *val)
{
  (void)c;
  (void)opt;
  ((struct stored *)o->dest)->file = val;
  return CLI_GO_ON;
}

/* The first look: only --collect and --args-from, wherever they stand; everything else
 * waits for the second, whole parse (a mistake there is told there). */
static int skip_fail(const struct cli_cmd *c, enum cli_error e, const char *arg)
{
  (void)c;
  (void)e;
  (void)arg;
  return CLI_GO_ON;
}

/* Finds --collect DIR or --args-from FILE (the last one given) in argv. */
static struct stored find_stored(int argc, char **argv)
{
  struct stored s = {0};
  const struct cli_opt opts[] = {
      {"--collect", NULL, CLI_VALUE, .dest = &s, .convert = collect_opt},
      {"--args-from", NULL, CLI_VALUE, .dest = &s, .convert = args_from_opt},
  };
  const struct cli_cmd cmd = {.name = "sweep",
                              .opts = opts,
                              .nopts = (int)(sizeof opts / sizeof opts[0]),
                              .fail = skip_fail};
  cli_parse(&cmd, argc, argv);
  return s;
}

/* The command line to parse: argv itself, or the stored one from s->file followed by
 * argv's own options less --collect and --args-from with their values. Returns NULL
 * after the message when the file cannot be read. */
static char **with_stored(const struct stored *s, int argc, char **argv, int *nall)
{
  *nall = argc;
  if (!s->file) return argv;
  struct hv_error err = {0};
  int na;
  char **a = read_args(s->file, &na, &err);
  if (!a) {
    fprintf(stderr, "%s\n", err.msg);
    return NULL;
  }
  char **all = hv_malloc((size_t)(na + argc + 1) * sizeof *all, "sweep args");
  int n = 0;
  for (int i = 0; i < na; i++) all[n++] = a[i];
  for (int i = 0; i < argc; i++) {
    if (!strcmp(argv[i], "--collect") || !strcmp(argv[i], "--args-from")) {
      i++;
      continue;
    }
    all[n++] = argv[i];
  }
  all[n] = NULL;
  *nall = n;
  return all;
}

/* Parses the whole command line (after with_stored) into w and s, in order, stopping at
 * the first mistake. --collect and --args-from are not in the table: with their value
 * with_stored has taken them out, and without it (the last argument, or a line of the
 * stored file) they are an unexpected argument, as any other. --help never arrives:
 * main answers it with the usage lines before calling cli_sweep. */
static int parse_options(struct sweep *w, struct sweep_cli *s, int argc, char **argv)
{
  s->sets = (struct cli_list){.v = w->sets, .max = SWEEP_MAX_SETS};
  const struct cli_opt opts[] = {
      {"--output", "-o", CLI_VALUE, .dest = &s->out},
      {"--vary", NULL, CLI_VALUE, .dest = s, .convert = vary_opt},
      {"--bisect", NULL, CLI_VALUE, .dest = s, .convert = bisect_opt},
      {"--tol", NULL, CLI_VALUE, .dest = s, .convert = tol_opt},
      {"--measure", NULL, CLI_VALUE, .dest = w, .convert = measure_opt},
      {"--set", NULL, CLI_LIST, .dest = &s->sets},
      {"--jobs", NULL, CLI_VALUE, .dest = &w->jobs, .convert = count_opt, .lo = 1, .hi = 4096},
      {"--threads", NULL, CLI_VALUE, .dest = &w->threads, .convert = count_opt, .lo = 1,
       .hi = 4096},
      {"--only", NULL, CLI_VALUE, .dest = &w->only, .convert = index_opt, .lo = 0, .hi = 1 << 30},
      {"--emit", NULL, CLI_VALUE, .dest = &s->emit},
      {"--quiet", "-q", CLI_FLAG, .dest = &w->quiet, .flag = 1},
  };
  const struct cli_cmd cmd = {.name = "sweep",
                              .opts = opts,
                              .nopts = (int)(sizeof opts / sizeof opts[0]),
                              .positional = &w->case_abs,
                              .fail = sweep_fail};
  const int st = cli_parse(&cmd, argc, argv);
  w->nsets = s->sets.n;
  return st;
}

/* path made absolute against the working folder: the points and a job array's tasks
 * run from anywhere. */
static void absolute(const char *path, char *out, size_t len)
{
  if (path[0] == '/') {
    snprintf(out, len, "%s", path);
    return;
  }
  char cwd[2048];
  if (!getcwd(cwd, sizeof cwd)) cwd[0] = '\0';
  snprintf(out, len, "%s/%s", cwd, path);
}

/* The options that need no case: a case and a folder given, a known --emit, the case
 * readable. Returns CLI_GO_ON or the exit status after the message. */
static int check_options(struct sweep *w, const struct sweep_cli *s)
{
  if (!w->case_abs || !s->out) {
    fprintf(stderr, "hvsph sweep: %s (see hvsph sweep --help)\n",
            !w->case_abs ? "missing case file" : "missing -o DIR");
    return HV_EXIT_USAGE;
  }
  if (s->emit && strcmp(s->emit, "slurm")) {
    fprintf(stderr, "hvsph sweep: --emit %s: only 'slurm' is known\n", s->emit);
    return HV_EXIT_USAGE;
  }
  w->emit_slurm = s->emit != NULL;
  if (w->threads == 0) w->threads = omp_get_max_threads();
  absolute(w->case_abs, w->case_path, sizeof w->case_path);
  if (access(w->case_path, R_OK)) {
    fprintf(stderr, "hvsph sweep: %s: %s\n", w->case_abs, strerror(errno));
    return HV_EXIT_INPUT;
  }
  absolute(s->out, w->dir, sizeof w->dir);
  return CLI_GO_ON;
}

/* The sweep checked against the case c (with the --set overrides): its section read
 * where the command line has no --vary or --bisect, every key present, every value of
 * the key's dimension, the bisection's range and tolerance. Returns 0 or -1 (err). */
static int check_against_case(struct sweep *w, struct cfg *c, const struct sweep_cli *s,
                              struct hv_error *err)
{
  const char *tol = s->tol;
  for (int k = 0; k < w->nsets; k++)
    if (cfg_apply_set(c, w->sets[k], err)) return -1;
  if (read_case_sweep(w, c, s->vary, s->bisect, err)) return -1;
  if (w->b.tol_given == 2) tol = w->tol_text;
  if (!w->measure[0]) snprintf(w->measure, sizeof w->measure, "perforated");
  default_object(w, c);
  if (w->nvary == 0 && !w->has_bisect) {
    hv_error_set(err, HV_EXIT_INPUT,
                 "hvsph sweep: nothing to sweep: give --vary or --bisect, "
                 "or a `sweep:` section in %s",
                 w->case_path);
    return -1;
  }
  for (int k = 0; k < w->nvary; k++) {
    if (case_has(c, w->vary[k].key, "--vary", err)) return -1;
    for (int j = 0; j < w->vary[k].n; j++)
      if (check_value(c, w->vary[k].key, "--vary", &w->vary[k].v[j], err)) return -1;
    if (w->has_bisect && !strcmp(w->vary[k].key, w->b.key)) {
      hv_error_set(err, HV_EXIT_INPUT, "hvsph sweep: %s is both varied and bisected", w->b.key);
      return -1;
    }
  }
  if (w->has_bisect && check_bisect(w, c, tol, err)) return -1;
  return 0;
}

/* The grid points, every combination of the --vary values (the last key fastest), and
 * --only checked against their number. Returns 0 or -1 (err). */
static int make_grid(struct sweep *w, struct hv_error *err)
{
  w->ncombos = 1;
  for (int k = 0; k < w->nvary; k++) w->ncombos *= w->vary[k].n;
  if (w->only >= w->ncombos) {
    hv_error_set(err, HV_EXIT_INPUT,
                 "hvsph sweep: --only %d: the sweep has %d grid points "
                 "(0 to %d)",
                 w->only, w->ncombos, w->ncombos - 1);
    return -1;
  }
  w->combos = calloc((size_t)w->ncombos, sizeof *w->combos);
  for (int c0 = 0; c0 < w->ncombos; c0++) {
    w->combos[c0].idx = calloc((size_t)w->nvary + 1, sizeof(int));
    int r = c0;
    for (int k = w->nvary - 1; k >= 0; k--) {
      w->combos[c0].idx[k] = r % w->vary[k].n;
      r /= w->vary[k].n;
    }
  }
  return 0;
}

/* Prints each grid point's bisection outcome (the limit's bracket, or why none). */
static void print_limits(const struct sweep *w)
{
  for (int k = 0; k < w->ncombos; k++) {
    const struct combo *co = &w->combos[k];
    char name[512];
    combo_name(w, co, name, sizeof name);
    const char *nm = name[0] ? name : "case";
    char lo[160], hi[160];
    format_value(&w->b, co->lo, lo, sizeof lo);
    format_value(&w->b, co->hi, hi, sizeof hi);
    if (co->outside)
      printf("  %s: %s at both ends: the limit lies outside %s..%s\n", nm, co->alo ? "yes" : "no",
             w->b.lo.text, w->b.hi.text);
    else if (co->failed == 2)
      printf("  %s: a point's measurements.csv has no %s%s%s\n", nm, w->measure,
             w->object[0] ? " of " : "", w->object);
    else if (co->failed)
      printf("  %s: a point failed\n", nm);
    else if (!co->done)
      printf("  %s: unfinished, bracket %s..%s\n", nm, lo, hi);
    else
      printf("  %s: %s between %s and %s\n", nm, w->b.key, lo, hi);
  }
}

/* Writes the sweep's tables of the whole grid (not of one --only task) and says where.
 * Returns the sweep's exit status, run_all's unless the writing fails. */
static int write_results(struct sweep *w, struct cfg *c, int status)
{
  struct hv_error err = {0};
  if (w->only >= 0 && !w->collect) return status;
  if (write_sweep_csv(w, &err) || (w->has_bisect && write_limits(w, c, &err))) {
    fprintf(stderr, "%s\n", err.msg);
    return err.code ? err.code : HV_EXIT_RUN;
  }
  if (w->quiet) return status;
  printf("hvsph sweep: %s/sweep.csv%s\n", w->dir,
         w->has_bisect ? ", ballistic_limit.csv, ballistic_limit.png" : "");
  if (w->has_bisect) print_limits(w);
  return status;
}

/* Writes the job array instead of running: DIR/sweep.slurm. Returns the exit status. */
static int emit_job_array(struct sweep *w)
{
  struct hv_error err = {0};
  if (emit_slurm(w, &err)) return sweep_bad(&err);
  printf("hvsph sweep: wrote %s/sweep.slurm (%d task%s); after the job, run hvsph "
         "sweep --collect %s\n",
         w->dir, w->ncombos, w->ncombos == 1 ? "" : "s", w->dir);
  return 0;
}

/* Runs, or writes the job array of, the checked sweep w of case c: the points folder
 * and sweep_args.txt first. Returns the exit status. */
static int run_sweep(struct sweep *w, struct cfg *c, int nall, char **all)
{
  struct hv_error err = {0};
  char pdir[4200];
  snprintf(pdir, sizeof pdir, "%s/points", w->dir);
  if (io_mkdir_p(pdir, &err)) return sweep_bad(&err);
  if (!w->collect && write_args(w, nall, all, &err)) return sweep_bad(&err);
  if (w->emit_slurm) return emit_job_array(w);
  return write_results(w, c, run_all(w));
}

int cli_sweep(int argc, char **argv)
{
  struct sweep w;
  struct hv_error err = {0};
  memset(&w, 0, sizeof w);
  w.jobs = 1;
  w.threads = 0;
  w.only = -1;
  struct sweep_cli s = {.w = &w, .err = &err};
  /* --collect DIR and --args-from FILE read the command line a sweep wrote */
  const struct stored st = find_stored(argc, argv);
  w.collect = st.collect;
  int nall;
  char **all = with_stored(&st, argc, argv, &nall);
  if (!all) return HV_EXIT_INPUT;
  int rc = parse_options(&w, &s, nall, all);
  if (rc == CLI_GO_ON) rc = check_options(&w, &s);
  if (rc != CLI_GO_ON) return rc;
  struct cfg *c = cfg_load(w.case_path, &err);
  if (!c) return sweep_bad(&err);
  if (check_against_case(&w, c, &s, &err) || make_grid(&w, &err))
    rc = sweep_bad(&err);
  else
    rc = run_sweep(&w, c, nall, all);
  cfg_free(c);
  return rc;
}
