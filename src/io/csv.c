/* csv.c — particle snapshots as CSV text, written and read back.
 *
 * File layout:
 *   # hvsph <version> case <name> time <t> s step <k>
 *   # materials 0=<name> 1=<name> ...            (only when materials are known)
 *   # geometry: axisymmetric                     (only for an axisymmetric run: x the
 *                                                 axis, y = r >= 0, z = 0, m the ring mass)
 *   id,x,y,z,vx,vy,vz,m,rho,p,e,h,mat,<other PF_OUT fields in list order>
 *   <one row per real particle>
 * Units are SI: x [m], v [m/s], m [kg], rho [kg/m3], p [Pa], e [J/kg], h [m],
 * and as listed in particles.h for the others. Doubles are printed with %.17g,
 * which reads back bit for bit with strtod; integers as integers.
 */
#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>

#include "io/atomic_file.h"
#include "core/infile.h"
#include "io/io_internal.h"
#include "io/snapshot.h"

#define CSV_MAX_COLS (HV_MAX_FIELDS * 3)

struct csv_col {
  char name[64];
  int field; /* index into the particles_fields() view */
  int comp;  /* component, 0 for scalars */
};

/* The first 13 columns, always in this order. */
static const struct {
  const char *col, *field;
  int comp;
} csv_fixed[] = {
    {"id", "id", 0}, {"x", "x", 0},  {"y", "x", 1},     {"z", "x", 2},     {"vx", "v", 0},
    {"vy", "v", 1},  {"vz", "v", 2}, {"m", "m", 0},     {"rho", "rho", 0}, {"p", "p", 0},
    {"e", "e", 0},   {"h", "h", 0},  {"mat", "mat", 0},
};
#define CSV_NFIXED ((int)(sizeof csv_fixed / sizeof csv_fixed[0]))

static int field_index(const struct pfield *f, int nf, const char *name)
{
  for (int k = 0; k < nf; k++)
    if (strcmp(f[k].name, name) == 0) return k;
  return -1;
}

/* The columns of a particle CSV for the field list f; returns their count. */
static int csv_columns(const struct pfield *f, int nf, struct csv_col *cols)
{
  unsigned char used[HV_MAX_FIELDS] = {0};
  int nc = 0;
  for (int k = 0; k < CSV_NFIXED; k++) {
    int fi = field_index(f, nf, csv_fixed[k].field);
    HV_CHECK(fi >= 0, "particle field '%s' missing for the CSV columns", csv_fixed[k].field);
    snprintf(cols[nc].name, sizeof cols[nc].name, "%s", csv_fixed[k].col);
    cols[nc].field = fi;
    cols[nc++].comp = csv_fixed[k].comp;
    used[fi] = 1;
  }
  static const char *sfx3[3] = {"_x", "_y", "_z"};
  static const char *sfx6[6] = {"_xx", "_yy", "_zz", "_xy", "_yz", "_xz"}; /* VTK order */
  for (int k = 0; k < nf; k++) {
    if (used[k] || !(f[k].flags & PF_OUT)) continue;
    for (int c = 0; c < f[k].ncomp; c++) {
      snprintf(cols[nc].name, sizeof cols[nc].name, "%s%s", f[k].name,
               f[k].ncomp == 3   ? sfx3[c]
               : f[k].ncomp == 6 ? sfx6[c]
                                 : "");
      cols[nc].field = k;
      cols[nc++].comp = c;
    }
  }
  return nc;
}

/* Appends the text of column value i to line at *len (room is ample: 32 bytes a value). */
static void csv_value(char *line, size_t *len, size_t cap, const struct pfield *f, int comp,
                      size_t i)
{
  const void *a = f->comp[comp];
  int r;
  if (f->type == PF_INT32)
    r = snprintf(line + *len, cap - *len, "%" PRId32, ((const int32_t *)a)[i]);
  else if (f->type == PF_INT64)
    r = snprintf(line + *len, cap - *len, "%" PRId64, ((const int64_t *)a)[i]);
  else
    r = snprintf(line + *len, cap - *len, "%.17g", ((const double *)a)[i]);
  HV_CHECK(r > 0 && (size_t)r < cap - *len, "CSV line buffer too small");
  *len += (size_t)r;
}

static int csv_body(struct atomic_file *af, struct particles *p, const struct snapshot_meta *meta,
                    struct hv_error *err)
{
  struct pfield f[HV_MAX_FIELDS];
  struct csv_col cols[CSV_MAX_COLS];
  int nf = particles_fields(p, f);
  int nc = csv_columns(f, nf, cols);
  char ver[256], name[1024];
  io_clean_text(ver, sizeof ver, meta ? meta->version : NULL, "unknown", 0);
  io_clean_text(name, sizeof name, meta ? meta->case_name : NULL, "unnamed", 0);
  if (atomic_file_printf(af, err, "# hvsph %s case %s time %.17g s step %ld\n", ver, name,
                         meta ? meta->time : 0.0, meta ? meta->step : 0L) ||
      io_put_materials(af, meta, "# ", "\n", 0, err) ||
      (p->axisym && atomic_file_printf(af, err, "# geometry: axisymmetric\n")))
    return -1;
  for (int c = 0; c < nc; c++)
    if (atomic_file_printf(af, err, "%s%s", c ? "," : "", cols[c].name)) return -1;
  if (atomic_file_printf(af, err, "\n")) return -1;
  char line[CSV_MAX_COLS * 32 + 2];
  for (size_t i = 0; i < p->n; i++) {
    size_t len = 0;
    for (int c = 0; c < nc; c++) {
      if (c) line[len++] = ',';
      csv_value(line, &len, sizeof line - 1, &f[cols[c].field], cols[c].comp, i);
    }
    line[len++] = '\n';
    if (atomic_file_write(af, line, len, err)) return -1;
  }
  return 0;
}

int io_write_particles_csv(const char *path, struct particles *p, const struct snapshot_meta *meta,
                           struct hv_error *err)
{
  struct atomic_file af;
  if (atomic_file_open(&af, path, err)) return -1;
  if (csv_body(&af, p, meta, err)) {
    atomic_file_abort(&af);
    return -1;
  }
  return atomic_file_commit(&af, err);
}

/* ---- reading ---------------------------------------------------------- */

struct csv_reader {
  const char *path;
  long lineno;
  int ncols;                   /* columns in the file's header; 0 until the header is read */
  int *map;                    /* file column -> index into cols[], or -1 (ignored) */
  char **tok;                  /* ncols token pointers, reused for every row */
  int nknown;                  /* entries in cols[] */
  int solid;                   /* the file has solid fields (PF_SOLID) */
  int av;                      /* the file has the viscosity switch's fields (PF_AV) */
  int crack;                   /* the file has the crack normals (PF_CRACK) */
  int axisym;                  /* "# geometry: axisymmetric" before the header */
  const struct pfield *fields; /* particles_fields_all() view the cols refer to */
  struct csv_col cols[CSV_MAX_COLS];
};

static int csv_count(const char *line)
{
  int n = 1;
  for (const char *s = line; *s; s++) n += *s == ',';
  return n;
}

/* Splits line in place at the commas into n tokens (n from csv_count). */
static void csv_split(char *line, char **tok, int n)
{
  char *s = line;
  for (int k = 0; k < n; k++) {
    tok[k] = s;
    char *c = strchr(s, ',');
    if (!c) break;
    *c = '\0';
    s = c + 1;
  }
}

static int csv_header(struct csv_reader *r, char *line, struct hv_error *err)
{
  int n = csv_count(line);
  r->tok = hv_malloc((size_t)n * sizeof *r->tok, "CSV tokens");
  r->map = hv_malloc((size_t)n * sizeof *r->map, "CSV column map");
  r->ncols = n;
  csv_split(line, r->tok, n);
  int have[4] = {0, 0, 0, 0}; /* cols[0..3] are id, x, y, z */
  for (int c = 0; c < n; c++) {
    r->map[c] = -1;
    for (int k = 0; k < r->nknown; k++)
      if (strcmp(r->tok[c], r->cols[k].name) == 0) r->map[c] = k;
    if (r->map[c] >= 0 && r->map[c] < 4) have[r->map[c]] = 1;
    if (r->map[c] >= 0 && (r->fields[r->cols[r->map[c]].field].flags & PF_SOLID))
      r->solid = 1; /* a solid field in the file: the store needs its solid arrays */
    if (r->map[c] >= 0 && (r->fields[r->cols[r->map[c]].field].flags & PF_AV)) r->av = 1;
    if (r->map[c] >= 0 && (r->fields[r->cols[r->map[c]].field].flags & PF_CRACK)) r->crack = 1;
  }
  for (int k = 0; k < 4; k++)
    if (!have[k])
      return hv_error_set(err, HV_EXIT_INPUT, "'%s' line %ld: no '%s' column in the header",
                          r->path, r->lineno, r->cols[k].name);
  return 0;
}

/* Parses one value into component comp of field f at slot i; -1 when it is not a number
 * of the field's type. Doubles ignore ERANGE (subnormals read back exactly). */
static int csv_parse(const char *s, const struct pfield *f, int comp, size_t i)
{
  char *end;
  errno = 0;
  if (f->type == PF_DOUBLE) {
    double v = strtod(s, &end);
    if (end == s || *end) return -1;
    ((double *)f->comp[comp])[i] = v;
    return 0;
  }
  long long v = strtoll(s, &end, 10);
  if (end == s || *end || errno == ERANGE) return -1;
  if (f->type == PF_INT64) {
    ((int64_t *)f->comp[comp])[i] = (int64_t)v;
  } else {
    if (v < INT32_MIN || v > INT32_MAX) return -1;
    ((int32_t *)f->comp[comp])[i] = (int32_t)v;
  }
  return 0;
}

static int csv_row(struct csv_reader *r, struct particles *p, char *line, struct hv_error *err)
{
  int n = csv_count(line);
  if (n != r->ncols)
    return hv_error_set(err, HV_EXIT_INPUT, "'%s' line %ld: %d values, the header has %d", r->path,
                        r->lineno, n, r->ncols);
  csv_split(line, r->tok, n);
  size_t i = particles_add(p, 1);
  struct pfield f[HV_MAX_FIELDS];
  particles_fields_all(p, f); /* after particles_add: the arrays may have moved */
  for (int c = 0; c < n; c++) {
    if (r->map[c] < 0) continue;
    const struct csv_col *col = &r->cols[r->map[c]];
    if (csv_parse(r->tok[c], &f[col->field], col->comp, i))
      return hv_error_set(err, HV_EXIT_INPUT, "'%s' line %ld: column '%s': cannot read '%s'",
                          r->path, r->lineno, col->name, r->tok[c]);
  }
  return 0;
}

/* Takes the time [s] from "# hvsph <version> case <name> time <t> s step <k>". */
static void csv_comment_time(const char *line, double *time)
{
  if (strncmp(line, "# hvsph ", 8) != 0) return;
  const char *t = NULL;
  for (const char *s = strstr(line, " time "); s; s = strstr(s + 1, " time ")) t = s;
  if (!t) return;
  char *end;
  double v = strtod(t + 6, &end);
  if (end != t + 6) *time = v;
}

static int csv_lines(struct csv_reader *r, FILE *f, struct particles *p, double *time,
                     struct hv_error *err)
{
  char *line = NULL;
  size_t cap = 0;
  ssize_t len;
  int rc = 0;
  errno = 0;
  while (rc == 0 && (len = getline(&line, &cap, f)) >= 0) {
    r->lineno++;
    while (len > 0 && (line[len - 1] == '\n' || line[len - 1] == '\r')) line[--len] = '\0';
    if (line[0] == '#') {
      if (!r->map && time) csv_comment_time(line, time);
      if (!r->map && !strncmp(line, "# geometry:", 11)) {
        const char *g = line + 11;
        while (*g == ' ') g++;
        if (!strcmp(g, "axisymmetric") || !strcmp(g, "3d"))
          r->axisym = g[0] == 'a';
        else
          rc = hv_error_set(err, HV_EXIT_INPUT,
                            "'%s' line %ld: geometry '%s' is neither 'axisymmetric' nor '3d'",
                            r->path, r->lineno, g);
      }
      continue;
    }
    if (len == 0) continue;
    rc = r->map ? csv_row(r, p, line, err) : csv_header(r, line, err);
    if (!rc && r->solid) particles_enable_solid(p);
    if (!rc && r->av) particles_enable_av(p);
    if (!rc && r->crack) particles_enable_crack(p);
    errno = 0;
  }
  if (rc == 0 && ferror(f))
    rc = hv_error_set(err, HV_EXIT_INPUT, "cannot read '%s': %s", r->path,
                      strerror(errno ? errno : EIO));
  if (rc == 0 && !r->map) rc = hv_error_set(err, HV_EXIT_INPUT, "'%s': no header line", r->path);
  free(line);
  return rc;
}

int io_read_particles_csv(const char *path, struct particles *p, double *time, struct hv_error *err)
{
  if (time) *time = NAN;
  FILE *f = hv_open_input(path, NULL, 0, NULL, err); /* a FIFO would block the open */
  if (!f) return -1;
  struct csv_reader *r = hv_calloc(1, sizeof *r, "CSV reader");
  struct pfield fv[HV_MAX_FIELDS];
  int nf = particles_fields_all(NULL, fv);
  r->fields = fv;
  r->path = path;
  r->nknown = csv_columns(fv, nf, r->cols);
  size_t n0 = p->n;
  int rc = csv_lines(r, f, p, time, err);
  if (fclose(f) != 0 && rc == 0)
    rc = hv_error_set(err, HV_EXIT_INPUT, "cannot read '%s': %s", path, strerror(errno));
  if (rc == 0) rc = io_take_geometry(p, n0, r->axisym, path, err);
  free(r->map);
  free(r->tok);
  free(r);
  if (rc) {
    p->n = n0; /* drop the rows read so far */
    p->n_ghost = 0;
  }
  return rc;
}
