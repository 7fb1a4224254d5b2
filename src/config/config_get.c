/* config_get.c — the typed getters of the case file and the records they leave.
 *
 * Getters look a path up ("bodies[0].velocity"), convert with units_parse(), check
 * ranges, mark the node used and append a record (path, SI value as YAML text,
 * SI unit, default or not, line). A later query of the same path replaces its
 * record. The records drive cfg_write_used() (the file used_parameters.yaml) and
 * the "did you mean" hints of cfg_check_unused(), both in config_used.c.
 * Errors name the file, line and key: "case.yaml:12: bodies[0].density: <message>".
 */
#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "config/config_internal.h"

/* ---------------------------------------------------------------- records */

/* Shortest "%.*g" that reads back to the same double. */
static void fmt_double(char *buf, size_t len, double v)
{
  for (int prec = 6; prec <= 17; prec++) {
    snprintf(buf, len, "%.*g", prec, v);
    if (strtod(buf, NULL) == v) return;
  }
}

/* A YAML double-quoted string (escapes ", \ and control characters). */
char *cfg_yaml_quote(const char *s)
{
  size_t n = strlen(s);
  char *q = hv_malloc(4 * n + 3, "quoted string"), *d = q;
  *d++ = '"';
  for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
    if (*p == '"' || *p == '\\') {
      *d++ = '\\';
      *d++ = (char)*p;
    } else if (*p == '\n') {
      *d++ = '\\';
      *d++ = 'n';
    } else if (*p < 0x20 || *p == 0x7f) {
      d += sprintf(d, "\\x%02x", *p);
    } else {
      *d++ = (char)*p;
    }
  }
  *d++ = '"';
  *d = '\0';
  return q;
}

/* Records what a getter returned (a later query of the same path replaces it). */
static void record(struct cfg *c, const char *path, char *value, const char *unit, int is_default,
                   int line)
{
  for (int i = 0; i < c->nrec; i++) {
    if (strcmp(c->rec[i].path, path)) continue;
    free(c->rec[i].value);
    c->rec[i].value = value;
    c->rec[i].unit = unit;
    c->rec[i].is_default = is_default;
    c->rec[i].line = line;
    return;
  }
  if (c->nrec == c->caprec) {
    c->caprec = c->caprec ? 2 * c->caprec : 32;
    c->rec = hv_realloc(c->rec, (size_t)c->caprec * sizeof *c->rec, "config records");
  }
  c->rec[c->nrec++] = (struct cfg_record){cfg_strdup(path), value, unit, is_default, line};
}

static void record_doubles(struct cfg *c, const char *path, const double *v, int n, int list,
                           enum unit_dim dim, int is_default, int line)
{
  size_t cap = 32 * (size_t)n + 8, k = 0;
  char *s = hv_malloc(cap, "config value");
  if (list) s[k++] = '[';
  for (int i = 0; i < n; i++) {
    char num[40];
    fmt_double(num, sizeof num, v[i]);
    k += (size_t)snprintf(s + k, cap - k, "%s%s", i ? ", " : "", num);
  }
  if (list) s[k++] = ']';
  s[k] = '\0';
  record(c, path, s, units_si_symbol(dim), is_default, line);
}

/* ---------------------------------------------------------------- getters */

static int value_error(struct cfg *c, const struct cfg_node *n, const char *path,
                       struct hv_error *err, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));

/* "case.yaml:12: bodies[0].density: <message>" */
static int value_error(struct cfg *c, const struct cfg_node *n, const char *path,
                       struct hv_error *err, const char *fmt, ...)
{
  char where[512], msg[1024];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);
  cfg_where_line(c, n ? n->file : NULL, n ? n->vline : 0, where, sizeof where);
  return hv_error_set(err, HV_EXIT_INPUT, "%s: %s: %s", where, path, msg);
}

/* A required key is missing, but its mapping holds a key no getter has read that is
 * one or two edits from it (`time: {ennd: 0.02}` for time.end): that key (and *node its
 * value, *want the key asked for), else NULL. The same distance as the unknown-key hints
 * (config_used.c), so the two messages agree on what a misspelling is. */
static const char *missing_near_miss(struct cfg *c, const char *path,
                                     const struct cfg_node *deepest, const struct cfg_node **node,
                                     const char **want)
{
  struct path_comp comp[CFG_MAX_DEPTH];
  const int nc = cfg_path_parse(path, comp, CFG_MAX_DEPTH);
  if (nc < 1 || !comp[nc - 1].key || deepest->kind != CFG_MAP) return NULL;
  /* the mapping reached must be the key's own parent (not a mapping higher up) */
  char parent[1024];
  const int plen = (int)(comp[nc - 1].start - path) - 1;
  const struct cfg_node *p = c->root;
  if (plen > 0) {
    if ((size_t)plen >= sizeof parent) return NULL;
    snprintf(parent, sizeof parent, "%.*s", plen, path);
    p = cfg_lookup(c, parent, NULL);
  }
  if (p != deepest) return NULL;
  const char *key = comp[nc - 1].key, *best = NULL;
  const size_t klen = comp[nc - 1].klen;
  int bdist = 3;
  for (int i = 0; i < p->n; i++) {
    if (p->items[i]->used) continue;
    const int d = cfg_edit_distance(p->keys[i], strlen(p->keys[i]), key, klen);
    if (d < bdist && d < (int)klen) {
      bdist = d;
      best = p->keys[i];
      *node = p->items[i];
    }
  }
  *want = key; /* the last component runs to the end of the path */
  return best;
}

/* Finds the node of a getter: 1 found, 0 absent (and has_def), -1 error. */
static int fetch(struct cfg *c, const char *path, int has_def, struct cfg_node **out,
                 struct hv_error *err)
{
  struct path_comp comp[CFG_MAX_DEPTH];
  if (cfg_path_parse(path, comp, CFG_MAX_DEPTH) < 0)
    return hv_error_set(err, HV_EXIT_INPUT, "%s: bad key path '%s'", c->name, path ? path : "");
  struct cfg_node *deepest;
  *out = cfg_lookup(c, path, &deepest);
  if (*out) {
    (*out)->used = 1;
    return 1;
  }
  if (has_def) return 0;
  char where[512];
  const struct cfg_node *near;
  const char *want, *near_key = missing_near_miss(c, path, deepest, &near, &want);
  if (near_key) /* `time: {ennd: 0.02}`: the misspelt key's line, and the key meant */
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: missing required key '%s': this line has "
                        "'%s' instead; did you mean '%s'?",
                        cfg_where_line(c, near->file, near->line, where, sizeof where), path,
                        near_key, want);
  return hv_error_set(err, HV_EXIT_INPUT, "%s: missing required key '%s'",
                      cfg_where_line(c, deepest->file, deepest->line, where, sizeof where), path);
}

int cfg_scalar_is_null(const struct cfg_node *n)
{
  return n->kind == CFG_SCALAR && (!n->text || (n->plain && (!n->text[0] || !strcmp(n->text, "~") ||
                                                             !strcmp(n->text, "null"))));
}

/* The text of a scalar node that has a value. */
static const char *scalar_text(struct cfg *c, const struct cfg_node *n, const char *path,
                               struct hv_error *err)
{
  if (n->kind != CFG_SCALAR) {
    value_error(c, n, path, err, "expected a single value, found %s", cfg_kind_name(n->kind));
    return NULL;
  }
  if (cfg_scalar_is_null(n)) {
    value_error(c, n, path, err, "the key has no value");
    return NULL;
  }
  return n->text;
}

static int read_quantity(struct cfg *c, const struct cfg_node *n, const char *path,
                         enum unit_dim dim, double *v, struct hv_error *err)
{
  const char *t = scalar_text(c, n, path, err);
  if (!t) return -1;
  char msg[512];
  if (units_parse(t, dim, v, msg, sizeof msg)) return value_error(c, n, path, err, "%s", msg);
  return 0;
}

/* "must be > 0", "must be >= 1 m", "must be <= 5 Pa", "must be in [0, 1]". */
static void range_text(char *buf, size_t len, double lo, double hi, const char *unit)
{
  char a[40], b[40];
  const char *sp = unit[0] ? " " : "";
  fmt_double(a, sizeof a, lo);
  fmt_double(b, sizeof b, hi);
  int pos = lo > 0.0 && lo < 1e-300; /* DBL_MIN and the like stand for "> 0" */
  if (pos && isinf(hi))
    snprintf(buf, len, "must be > 0");
  else if (pos)
    snprintf(buf, len, "must be in (0, %s]%s%s", b, sp, unit);
  else if (isinf(hi))
    snprintf(buf, len, "must be >= %s%s%s", a, sp, unit);
  else if (isinf(lo))
    snprintf(buf, len, "must be <= %s%s%s", b, sp, unit);
  else
    snprintf(buf, len, "must be in [%s, %s]%s%s", a, b, sp, unit);
}

static int check_range(struct cfg *c, const struct cfg_node *n, const char *path, double v,
                       double lo, double hi, enum unit_dim dim, struct hv_error *err)
{
  if (v >= lo && v <= hi) return 0;
  const char *unit = units_si_symbol(dim);
  char rng[160], num[40], shown[300];
  range_text(rng, sizeof rng, lo, hi, unit);
  fmt_double(num, sizeof num, v);
  snprintf(shown, sizeof shown, "%s%s%s", num, unit[0] ? " " : "", unit);
  if (n && n->kind == CFG_SCALAR && strcmp(n->text, shown) && strcmp(n->text, num))
    return value_error(c, n, path, err, "'%s' (%s) is out of range (%s)", n->text, shown, rng);
  return value_error(c, n, path, err, "%s is out of range (%s)%s", shown, rng,
                     n ? "" : " [default]");
}

int cfg_get_quantity(struct cfg *c, const char *path, enum unit_dim dim, const double *def,
                     double lo, double hi, double *out, struct hv_error *err)
{
  struct cfg_node *n;
  int found = fetch(c, path, def != NULL, &n, err);
  if (found < 0) return -1;
  double v = found ? 0.0 : *def;
  if (found && read_quantity(c, n, path, dim, &v, err)) return -1;
  if (check_range(c, found ? n : NULL, path, v, lo, hi, dim, err)) return -1;
  record_doubles(c, path, &v, 1, 0, dim, !found, found ? n->vline : 0);
  *out = v;
  return 0;
}

/* Units that a bare number of this dimension is most often meant in, and whose value
 * a message suggests when it falls in the typical range (the first that does). */
static const char *const *likely_units(enum unit_dim dim)
{
  static const char *const density[] = {"g/cm3", NULL}, *const velocity[] = {"km/s", NULL},
                           *const pressure[] = {"GPa", "MPa", "kbar", "bar", NULL},
                           *const senergy[] = {"MJ/kg", "kJ/kg", NULL}, *const none[] = {NULL};
  switch (dim) {
  case UNIT_DENSITY: return density;
  case UNIT_VELOCITY: return velocity;
  case UNIT_PRESSURE: return pressure;
  case UNIT_SPECIFIC_ENERGY: return senergy;
  default: return none;
  }
}

/* The node at path when its value is a finite number written without a unit in input
 * (not a number hvsph wrote to a used_parameters.yaml, see struct cfg), else NULL. */
static struct cfg_node *bare_number(struct cfg *c, const char *path, double *v)
{
  struct cfg_node *deepest, *n = cfg_lookup(c, path, &deepest);
  if (!n || n->kind != CFG_SCALAR || !n->text) return NULL;
  /* a run's used_parameters.yaml (a restart, hvsph measure, or run as a case) holds SI
     numbers by construction, each checked when its case was read; a --set is new input */
  if (c->si_record && !n->file && n->line != CFG_LINE_SET) return NULL;
  char *end;
  *v = strtod(n->text, &end);
  while (isspace((unsigned char)*end)) end++;
  return end == n->text || *end || !isfinite(*v) ? NULL : n; /* a unit, or no number */
}

int cfg_is_bare(struct cfg *c, const char *path)
{
  double v;
  return bare_number(c, path, &v) != NULL;
}

int cfg_check_typical(struct cfg *c, const char *path, enum unit_dim dim, double lo, double hi,
                      const char *what, struct hv_error *err)
{
  double v;
  struct cfg_node *n = bare_number(c, path, &v);
  if (!n || v == 0.0 || (fabs(v) >= lo && fabs(v) <= hi)) return 0;
  const char *si = units_si_symbol(dim);
  char guess[160] = "";
  for (const char *const *u = likely_units(dim); *u; u++) {
    char text[96], msg[160];
    double w;
    snprintf(text, sizeof text, "%s %s", n->text, *u);
    if (!units_parse(text, dim, &w, msg, sizeof msg) && fabs(w) >= lo && fabs(w) <= hi) {
      snprintf(guess, sizeof guess, "; was it %s %s?", n->text, *u);
      break;
    }
  }
  char a[40], b[40];
  fmt_double(a, sizeof a, lo);
  fmt_double(b, sizeof b, hi);
  return value_error(c, n, path, err,
                     "the bare number %s is read as %s %s (a number without a "
                     "unit is SI), outside the %s, %s to %s %s%s%s the value with its unit "
                     "('%s %s' keeps this one)",
                     n->text, n->text, si, what, a, b, si, guess, guess[0] ? " Write" : "; write",
                     n->text, si);
}

/* Reads every entry of a sequence node as a quantity (n entries into v). */
static int read_seq(struct cfg *c, struct cfg_node *s, const char *path, enum unit_dim dim,
                    double *v, struct hv_error *err)
{
  for (int i = 0; i < s->n; i++) {
    char ipath[512];
    snprintf(ipath, sizeof ipath, "%s[%d]", path, i);
    s->items[i]->used = 1;
    if (read_quantity(c, s->items[i], ipath, dim, &v[i], err)) return -1;
  }
  return 0;
}

int cfg_get_vec3(struct cfg *c, const char *path, enum unit_dim dim, const double *def,
                 double out[3], struct hv_error *err)
{
  struct cfg_node *n;
  int found = fetch(c, path, def != NULL, &n, err);
  if (found < 0) return -1;
  double v[3];
  if (!found) {
    memcpy(v, def, sizeof v);
  } else {
    if (n->kind != CFG_SEQ || n->n != 3)
      return value_error(c, n, path, err,
                         "expected a list of 3 values like [0, 1.5 mm, 0], found %s",
                         n->kind == CFG_SEQ ? "a list of another length" : cfg_kind_name(n->kind));
    if (read_seq(c, n, path, dim, v, err)) return -1;
  }
  record_doubles(c, path, v, 3, 1, dim, !found, found ? n->vline : 0);
  memcpy(out, v, sizeof v);
  return 0;
}

int cfg_get_list(struct cfg *c, const char *path, enum unit_dim dim, double **out, int *n,
                 struct hv_error *err)
{
  struct cfg_node *s;
  if (fetch(c, path, 0, &s, err) < 0) return -1;
  if (s->kind != CFG_SEQ)
    return value_error(c, s, path, err, "expected a list like [1, 2 mm], found %s",
                       cfg_kind_name(s->kind));
  double *v = hv_malloc((size_t)s->n * sizeof *v, "config list");
  if (read_seq(c, s, path, dim, v, err)) {
    free(v);
    return -1;
  }
  record_doubles(c, path, v, s->n, 1, dim, 0, s->vline);
  *out = v;
  *n = s->n;
  return 0;
}

/* Integer text: decimal, or a number in exponent form that is integral ("1e6"). */
static int parse_long(const char *t, long *v)
{
  char *end;
  errno = 0;
  long i = strtol(t, &end, 10);
  while (isspace((unsigned char)*end)) end++;
  if (end != t && !*end && errno != ERANGE) {
    *v = i;
    return 0;
  }
  for (const char *p = t; *p; p++)
    if (!isdigit((unsigned char)*p) && !strchr(".+-eE \t", *p)) return -1;
  errno = 0;
  double d = strtod(t, &end); /* ERANGE: 1e-400 is no integer 0 */
  while (isspace((unsigned char)*end)) end++;
  if (end == t || *end || errno == ERANGE || !isfinite(d) || d != floor(d) || fabs(d) >= 9.2e18)
    return -1;
  *v = (long)d;
  return 0;
}

int cfg_get_int(struct cfg *c, const char *path, const long *def, long lo, long hi, long *out,
                struct hv_error *err)
{
  struct cfg_node *n;
  int found = fetch(c, path, def != NULL, &n, err);
  if (found < 0) return -1;
  long v = found ? 0 : *def;
  if (found) {
    const char *t = scalar_text(c, n, path, err);
    if (!t) return -1;
    if (parse_long(t, &v)) return value_error(c, n, path, err, "'%s' is not an integer", t);
  }
  if (v < lo || v > hi) {
    char rng[96];
    if (hi == LONG_MAX)
      snprintf(rng, sizeof rng, "must be >= %ld", lo);
    else if (lo == LONG_MIN)
      snprintf(rng, sizeof rng, "must be <= %ld", hi);
    else
      snprintf(rng, sizeof rng, "must be in [%ld, %ld]", lo, hi);
    return value_error(c, found ? n : NULL, path, err, "%ld is out of range (%s)", v, rng);
  }
  char *s = hv_malloc(24, "config value");
  snprintf(s, 24, "%ld", v);
  record(c, path, s, "", !found, found ? n->vline : 0);
  *out = v;
  return 0;
}

int cfg_get_bool(struct cfg *c, const char *path, const int *def, int *out, struct hv_error *err)
{
  static const char *yes[] = {"true", "yes", "on"}, *no[] = {"false", "no", "off"};
  struct cfg_node *n;
  int found = fetch(c, path, def != NULL, &n, err);
  if (found < 0) return -1;
  int v = found ? -1 : !!*def;
  if (found) {
    const char *t = scalar_text(c, n, path, err);
    if (!t) return -1;
    for (int i = 0; i < 3; i++) {
      if (!strcasecmp(t, yes[i])) v = 1;
      if (!strcasecmp(t, no[i])) v = 0;
    }
    if (v < 0)
      return value_error(c, n, path, err, "'%s' is not a yes/no value (use true or false)", t);
  }
  record(c, path, cfg_strdup(v ? "true" : "false"), "", !found, found ? n->vline : 0);
  *out = v;
  return 0;
}

/* Looks up a string without recording it; *s valid until cfg_free. */
static int fetch_string(struct cfg *c, const char *path, const char *def, const char **s,
                        struct cfg_node **n, struct hv_error *err)
{
  int found = fetch(c, path, def != NULL, n, err);
  if (found < 0) return -1;
  if (!found) {
    if (c->nstrs == c->capstrs) {
      c->capstrs = c->capstrs ? 2 * c->capstrs : 8;
      c->strs = hv_realloc(c->strs, (size_t)c->capstrs * sizeof *c->strs, "config strings");
    }
    *s = c->strs[c->nstrs++] = cfg_strdup(def);
    *n = NULL;
    return 0;
  }
  *s = scalar_text(c, *n, path, err);
  return *s ? 0 : -1;
}

int cfg_get_string(struct cfg *c, const char *path, const char *def, const char **out,
                   struct hv_error *err)
{
  struct cfg_node *n;
  const char *s;
  if (fetch_string(c, path, def, &s, &n, err)) return -1;
  record(c, path, cfg_yaml_quote(s), "", n == NULL, n ? n->vline : 0);
  *out = s;
  return 0;
}

void cfg_record_string(struct cfg *c, const char *path, const char *value)
{
  int line = 0;
  for (int i = 0; i < c->nrec; i++)
    if (!strcmp(c->rec[i].path, path)) line = c->rec[i].line;
  record(c, path, cfg_yaml_quote(value), "", 0, line);
}

int cfg_get_choice(struct cfg *c, const char *path, const char *def, const char *const *choices,
                   int *out, struct hv_error *err)
{
  struct cfg_node *n;
  const char *s;
  if (fetch_string(c, path, def, &s, &n, err)) return -1;
  for (int i = 0; choices[i]; i++) {
    if (strcmp(s, choices[i])) continue;
    record(c, path, cfg_yaml_quote(s), "", n == NULL, n ? n->vline : 0);
    *out = i;
    return 0;
  }
  char list[1024];
  size_t k = 0;
  list[0] = '\0';
  for (int i = 0; choices[i] && k < sizeof list; i++)
    k += (size_t)snprintf(list + k, sizeof list - k, "%s'%s'", i ? ", " : "", choices[i]);
  return value_error(c, n, path, err, "'%s' is not one of %s", s, list);
}
