/* table.c — the EOS `table`: a tabulated equation of state, p(ρ, e) (and optionally
 * c(ρ, e)) on a rectangular grid, interpolated bilinearly. Keys: file (relative to the
 * folder of the file that names it), file_crc32 (optional: pins the table), rho0
 * (default 0), cs_floor (default 0.01 of the table's largest sound speed).
 *
 * File format (text, SI units; docs/models.md shows an example):
 *
 *   # comments start with '#' and run to the end of the line; blank lines are ignored
 *   rho_count N e_count M          header: N, M >= 2
 *   ρ_1 … ρ_N                      N densities [kg/m3], > 0, strictly increasing
 *   e_1 … e_M                      M specific energies [J/kg], strictly increasing
 *   p(ρ_1, e_1) … p(ρ_1, e_M)      N pressure rows [Pa], one line per density,
 *   …                              M values each
 *   p(ρ_N, e_1) … p(ρ_N, e_M)
 *   c(ρ_1, e_1) … c(ρ_1, e_M)      optional: N sound-speed rows [m/s], > 0
 *   …
 *
 * The axis values may be spread over several lines; each row starts on a new line.
 * Every value must be a finite number: a missing value ("hole"), "nan" or "inf" is an
 * error naming the file and line, as are unsorted axes and wrong counts.
 *
 * Interpolation in the cell [ρ_i, ρ_i+1] × [e_j, e_j+1], t = (ρ − ρ_i)/Δρ, s = (e − e_j)/Δe:
 *   p = (1 − t)(1 − s) p_ij + t(1 − s) p_i+1,j + (1 − t)s p_i,j+1 + ts p_i+1,j+1,
 * exact for p linear in ρ and in e separately; for a smooth p its error is at most
 * (Δρ²/8) max|∂²p/∂ρ²| + (Δe²/8) max|∂²p/∂e²| (the bound checked in test_eos.c).
 * The sound speed is interpolated the same way from the c rows, or, without them, is
 * c² = ∂p/∂ρ + (p/ρ²) ∂p/∂e from the bilinear p of the cell; floored at cs_floor.
 * A state outside the grid is not extrapolated: eos_evaluate returns
 * EOS_ERR_OUTSIDE_TABLE and eos_describe() names the material, (ρ, e) and the ranges.
 */
#define _XOPEN_SOURCE 700 /* realpath */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "core/infile.h"
#include "eos/eos.h"
#include "material/material_read.h"

/* ---------------------------------------------------------------- reading */

#define TAB_MAX_VALUES 100000000L /* N·M limit (800 MB per array) */

struct tab_reader {
  FILE *f;
  unsigned char chunk[1 << 16]; /* the file is read by chunks, each added to the CRC */
  size_t clen, cpos;
  unsigned long crc;
  const char *path;
  int line;  /* number of the last line read */
  char *buf; /* current line, comments removed */
  size_t cap;
  char *cur; /* next unread character of buf */
  struct hv_error *err;
};

/* The next byte of the file, EOF at its end (or a read error: ferror). */
static int tab_getc(struct tab_reader *r)
{
  if (r->cpos == r->clen) {
    r->clen = fread(r->chunk, 1, sizeof r->chunk, r->f);
    r->cpos = 0;
    if (!r->clen) return EOF;
    r->crc = crc32(r->crc, r->chunk, (uInt)r->clen);
  }
  return r->chunk[r->cpos++];
}

/* Reads the next line into r->buf (comment cut); 0 at end of file. */
static int tab_next_line(struct tab_reader *r)
{
  size_t n = 0;
  int ch, any = 0;
  while ((ch = tab_getc(r)) != EOF) {
    any = 1;
    if (n + 2 > r->cap) {
      r->cap = r->cap ? 2 * r->cap : 256;
      r->buf = hv_realloc(r->buf, r->cap, "table line");
    }
    if (ch == '\n') break;
    r->buf[n++] = (char)ch;
  }
  if (!any) return 0;
  if (!r->buf) r->buf = hv_malloc(r->cap = 256, "table line");
  r->buf[n] = '\0';
  char *hash = strchr(r->buf, '#');
  if (hash) *hash = '\0';
  r->line++;
  r->cur = r->buf;
  return 1;
}

/* The next token on the current line (NULL if none); *len its length. */
static const char *tab_token_here(struct tab_reader *r, size_t *len)
{
  while (*r->cur && isspace((unsigned char)*r->cur)) r->cur++;
  if (!*r->cur) return NULL;
  const char *t = r->cur;
  while (*r->cur && !isspace((unsigned char)*r->cur)) r->cur++;
  *len = (size_t)(r->cur - t);
  return t;
}

/* The next token, reading lines as needed (NULL at end of file). */
static const char *tab_token(struct tab_reader *r, size_t *len)
{
  for (;;) {
    const char *t = r->cur ? tab_token_here(r, len) : NULL;
    if (t) return t;
    if (!tab_next_line(r)) return NULL;
  }
}

/* Moves to the next line holding a token (without consuming it); 0 at end of file. */
static int tab_next_nonblank(struct tab_reader *r)
{
  for (;;) {
    if (!tab_next_line(r)) return 0;
    char *s = r->buf;
    while (*s && isspace((unsigned char)*s)) s++;
    if (*s) return 1;
  }
}

/* Parses a token as a finite number. */
static int tab_number(struct tab_reader *r, const char *t, size_t len, const char *what, double *v)
{
  char tmp[64];
  if (len >= sizeof tmp)
    return hv_error_set(r->err, HV_EXIT_INPUT, "%s:%d: %s: '%.40s...' is not a number", r->path,
                        r->line, what, t);
  memcpy(tmp, t, len);
  tmp[len] = '\0';
  char *end;
  errno = 0;
  *v = strtod(tmp, &end);
  if (end == tmp || *end)
    return hv_error_set(r->err, HV_EXIT_INPUT, "%s:%d: %s: '%s' is not a number", r->path, r->line,
                        what, tmp);
  if (!isfinite(*v))
    return hv_error_set(r->err, HV_EXIT_INPUT,
                        "%s:%d: %s: '%s' is not a finite number (holes are not allowed)", r->path,
                        r->line, what, tmp);
  return 0;
}

static int tab_header(struct tab_reader *r, long *nrho, long *ne)
{
  const char *want[2] = {"rho_count", "e_count"};
  long *val[2] = {nrho, ne};
  for (int k = 0; k < 2; k++) {
    size_t len;
    const char *t = tab_token(r, &len);
    if (!t || len != strlen(want[k]) || strncmp(t, want[k], len))
      return hv_error_set(r->err, HV_EXIT_INPUT,
                          "%s:%d: expected the header 'rho_count N e_count M'%s", r->path, r->line,
                          t ? "" : " (the file is empty)");
    t = tab_token(r, &len);
    double v = 0.0;
    char what[32];
    snprintf(what, sizeof what, "%s", want[k]);
    if (!t)
      return hv_error_set(r->err, HV_EXIT_INPUT, "%s:%d: %s: missing count", r->path, r->line,
                          want[k]);
    if (tab_number(r, t, len, what, &v)) return -1;
    if (v != floor(v) || v < 2 || v > 1e8)
      return hv_error_set(r->err, HV_EXIT_INPUT, "%s:%d: %s must be an integer >= 2 (got %g)",
                          r->path, r->line, want[k], v);
    *val[k] = (long)v;
  }
  if (*nrho * *ne > TAB_MAX_VALUES)
    return hv_error_set(r->err, HV_EXIT_INPUT, "%s:%d: the table is too large (%ld x %ld)", r->path,
                        r->line, *nrho, *ne);
  return 0;
}

/* Reads n increasing axis values. */
static int tab_axis(struct tab_reader *r, const char *name, double *x, long n, double lo)
{
  for (long i = 0; i < n; i++) {
    size_t len;
    const char *t = tab_token(r, &len);
    if (!t)
      return hv_error_set(r->err, HV_EXIT_INPUT,
                          "%s:%d: expected %ld %s values, found %ld "
                          "(the file ends)",
                          r->path, r->line, n, name, i);
    char what[48];
    snprintf(what, sizeof what, "%s[%ld]", name, i + 1);
    if (tab_number(r, t, len, what, &x[i])) return -1;
    if (x[i] <= lo)
      return hv_error_set(r->err, HV_EXIT_INPUT, "%s:%d: %s = %g must be > %g", r->path, r->line,
                          what, x[i], lo);
    if (i > 0 && !(x[i] > x[i - 1]))
      return hv_error_set(r->err, HV_EXIT_INPUT,
                          "%s:%d: %s values must increase strictly (%s = %g after %g)", r->path,
                          r->line, name, what, x[i], x[i - 1]);
  }
  return 0;
}

/* Reads nrow rows of ncol values, one row per line; `first` = a line is already loaded. */
static int tab_rows(struct tab_reader *r, const char *name, const double *rho, double *v, long nrow,
                    long ncol, int first, double lo, double hi)
{
  for (long i = 0; i < nrow; i++) {
    if (!(first && i == 0) && !tab_next_nonblank(r))
      return hv_error_set(r->err, HV_EXIT_INPUT,
                          "%s:%d: expected %ld %s rows of %ld values, "
                          "found %ld (the file ends)",
                          r->path, r->line, nrow, name, ncol, i);
    long k = 0;
    size_t len;
    const char *t;
    while ((t = tab_token_here(r, &len)) != NULL) {
      char what[64];
      snprintf(what, sizeof what, "%s row %ld value %ld", name, i + 1, k + 1);
      double x;
      if (tab_number(r, t, len, what, &x)) return -1;
      if (k < ncol) v[i * ncol + k] = x;
      if (x <= lo)
        return hv_error_set(r->err, HV_EXIT_INPUT, "%s:%d: %s = %g must be > %g", r->path, r->line,
                            what, x, lo);
      if (x > hi) /* a sound speed past the speed of light: not SI (the file is in m/s) */
        return hv_error_set(r->err, HV_EXIT_INPUT,
                            "%s:%d: %s = %g m/s is faster than light "
                            "(%g m/s): the table is in SI units",
                            r->path, r->line, what, x, hi);
      k++;
    }
    if (k != ncol)
      return hv_error_set(r->err, HV_EXIT_INPUT,
                          "%s:%d: %s row %ld (rho = %g kg/m3) has %ld values, expected %ld "
                          "(e_count)",
                          r->path, r->line, name, i + 1, rho[i], k, ncol);
  }
  return 0;
}

/* Largest sound speed of the table: c rows, or c² from the cell-centre derivatives. */
static double tab_cs_max(const struct eos_table *t)
{
  double cmax = 0.0;
  const int ne = t->ne;
  if (t->cs) {
    for (long k = 0; k < (long)t->nrho * ne; k++)
      if (t->cs[k] > cmax) cmax = t->cs[k];
    return cmax;
  }
  for (int i = 0; i + 1 < t->nrho; i++)
    for (int j = 0; j + 1 < ne; j++) {
      struct eos_state st;
      eos_table_evaluate(t, 0.5 * (t->rho[i] + t->rho[i + 1]), 0.5 * (t->e[j] + t->e[j + 1]), &st);
      if (st.cs > cmax) cmax = st.cs;
    }
  return cmax;
}

/* The table's values, read from r into t (arrays allocated; freed by the caller). */
static int tab_read(struct tab_reader *r, struct eos_table *t)
{
  const char *path = r->path;
  struct hv_error *err = r->err;
  long nrho = 0, ne = 0;
  int rc = tab_header(r, &nrho, &ne);
  if (!rc) {
    t->nrho = (int)nrho;
    t->ne = (int)ne;
    t->rho = hv_malloc((size_t)nrho * sizeof *t->rho, "EOS table");
    t->e = hv_malloc((size_t)ne * sizeof *t->e, "EOS table");
    t->p = hv_malloc((size_t)(nrho * ne) * sizeof *t->p, "EOS table");
    rc = tab_axis(r, "rho", t->rho, nrho, 0.0) || tab_axis(r, "e", t->e, ne, -HUGE_VAL);
  }
  if (!rc) {
    size_t len;
    if (tab_token_here(r, &len))
      rc = hv_error_set(err, HV_EXIT_INPUT,
                        "%s:%d: more values than e_count = %ld on the line "
                        "of the last e value (each pressure row starts on a new line)",
                        path, r->line, ne);
  }
  if (!rc) rc = tab_rows(r, "pressure", t->rho, t->p, nrho, ne, 0, -HUGE_VAL, HUGE_VAL);
  if (!rc && tab_next_nonblank(r)) {
    t->cs = hv_malloc((size_t)(nrho * ne) * sizeof *t->cs, "EOS table");
    rc = tab_rows(r, "sound-speed", t->rho, t->cs, nrho, ne, 1, 0.0, 299792458.0);
    if (!rc && tab_next_nonblank(r))
      rc = hv_error_set(err, HV_EXIT_INPUT,
                        "%s:%d: unexpected values after the %ld sound-speed "
                        "rows",
                        path, r->line, nrho);
  }
  return rc;
}

int eos_table_load(const char *path, struct eos_table *t, struct hv_error *err)
{
  memset(t, 0, sizeof *t);
  snprintf(t->path, sizeof t->path, "%s", path);
  /* a regular file only: a FIFO would block the open, a device might never end */
  FILE *f = hv_open_input(path, "EOS table", 0, NULL, err);
  if (!f) return -1;
  struct tab_reader *r = hv_calloc(1, sizeof *r, "EOS table reader"); /* 64 KiB chunk */
  r->f = f;
  r->path = path;
  r->err = err;
  r->crc = crc32(0L, Z_NULL, 0);
  int rc = tab_read(r, t);
  /* the CRC covers the whole file, also comments after the last value */
  while (!rc && tab_getc(r) != EOF) continue;
  if (!rc && ferror(f))
    rc = hv_error_set(err, HV_EXIT_INPUT, "cannot read EOS table '%s': %s", path, strerror(errno));
  fclose(f);
  t->crc32 = r->crc;
  free(r->buf);
  free(r);
  if (rc) {
    eos_table_free(t);
    return -1;
  }
  t->cs_max = tab_cs_max(t);
  return 0;
}

void eos_table_free(struct eos_table *t)
{
  free(t->rho);
  free(t->e);
  free(t->p);
  free(t->cs);
  t->rho = t->e = t->p = t->cs = NULL;
  t->nrho = t->ne = 0;
}

/* ---------------------------------------------------------------- evaluation */

/* Index i with x[i] <= v <= x[i+1] (n >= 2), or -1 outside [x[0], x[n-1]]. */
static int tab_find(const double *x, int n, double v)
{
  if (!(v >= x[0] && v <= x[n - 1])) return -1;
  int lo = 0, hi = n - 1;
  while (hi - lo > 1) {
    int mid = lo + (hi - lo) / 2;
    if (x[mid] <= v)
      lo = mid;
    else
      hi = mid;
  }
  return lo;
}

int eos_table_evaluate(const struct eos_table *t, double rho, double e, struct eos_state *out)
{
  const int i = tab_find(t->rho, t->nrho, rho), j = tab_find(t->e, t->ne, e);
  if (i < 0 || j < 0) return EOS_ERR_OUTSIDE_TABLE;
  const int ne = t->ne;
  const double dr = t->rho[i + 1] - t->rho[i], de = t->e[j + 1] - t->e[j];
  const double tx = (rho - t->rho[i]) / dr, ty = (e - t->e[j]) / de;
  const double *p0 = t->p + (size_t)i * ne + j, *p1 = p0 + ne;
  const double p =
      (1 - tx) * (1 - ty) * p0[0] + tx * (1 - ty) * p1[0] + (1 - tx) * ty * p0[1] + tx * ty * p1[1];
  double c2;
  if (t->cs) {
    const double *c0 = t->cs + (size_t)i * ne + j, *c1 = c0 + ne;
    const double c = (1 - tx) * (1 - ty) * c0[0] + tx * (1 - ty) * c1[0] + (1 - tx) * ty * c0[1] +
                     tx * ty * c1[1];
    c2 = c * c;
  } else {
    const double dpdr = ((1 - ty) * (p1[0] - p0[0]) + ty * (p1[1] - p0[1])) / dr;
    const double dpde = ((1 - tx) * (p0[1] - p0[0]) + tx * (p1[1] - p1[0])) / de;
    c2 = dpdr + p / (rho * rho) * dpde;
  }
  const double f2 = t->cs_floor * t->cs_floor;
  if (!(c2 > f2)) c2 = f2;
  out->p = p;
  out->cs = sqrt(c2);
  return EOS_OK;
}

/* At fixed ρ the bilinear p is piecewise linear in e: the first segment that brackets p. */
int eos_table_energy_from_pressure(const struct eos_table *t, double rho, double p, double *e)
{
  const int i = tab_find(t->rho, t->nrho, rho);
  if (i < 0) return EOS_ERR_OUTSIDE_TABLE;
  const int ne = t->ne;
  const double tx = (rho - t->rho[i]) / (t->rho[i + 1] - t->rho[i]);
  const double *p0 = t->p + (size_t)i * ne, *p1 = p0 + ne;
  double pa = (1 - tx) * p0[0] + tx * p1[0];
  for (int j = 0; j + 1 < ne; j++) {
    const double pb = (1 - tx) * p0[j + 1] + tx * p1[j + 1];
    if ((p >= pa && p <= pb) || (p <= pa && p >= pb)) {
      const double s = pb != pa ? (p - pa) / (pb - pa) : 0.0;
      *e = t->e[j] + s * (t->e[j + 1] - t->e[j]);
      return EOS_OK;
    }
    pa = pb;
  }
  return EOS_ERR_NO_SOLUTION;
}

/* ---------------------------------------------------------------- the model's row */

static int table_evaluate(const struct material *m, double rho, double e, struct eos_state *out)
{
  return eos_table_evaluate(&m->eosp.tab, rho, e, out);
}

static int table_energy(const struct material *m, double rho, double p, double *e)
{
  return eos_table_energy_from_pressure(&m->eosp.tab, rho, p, e);
}

/* The table file, relative to the folder of the file the key was written in.
 * used_parameters.yaml records the file's absolute path (resolved when it was read), so
 * that `hvsph restart` and a rerun of that file, which lies in another folder, find the
 * same table from any working folder, and the file's CRC-32 as file_crc32: a table
 * changed since (a rerun or restart would continue under another equation of state) is
 * refused. A case may give file_crc32 too, to pin its table. */
static int table_read_keys(struct cfg *c, const char *path, struct material *m,
                           struct hv_error *err)
{
  char k[320], kc[320], full[1024], where[512];
  const char *file;
  material_key(k, sizeof k, path, "file");
  material_key(kc, sizeof kc, path, "file_crc32");
  if (cfg_get_string(c, k, NULL, &file, err)) return -1;
  const char *src = cfg_node_file(c, k), *slash = strrchr(src, '/');
  if (file[0] == '/' || !slash)
    snprintf(full, sizeof full, "%s", file);
  else
    snprintf(full, sizeof full, "%.*s/%s", (int)(slash - src), src, file);
  if (eos_table_load(full, &m->eosp.tab, err))
    return hv_error_prefix(err, "%s: %s: ", cfg_where(c, k, where, sizeof where), k);
  char *abs = realpath(full, NULL); /* the file exists: it was just read */
  cfg_record_string(c, k, abs ? abs : full);
  char crc[16];
  snprintf(crc, sizeof crc, "%08lx", m->eosp.tab.crc32 & 0xffffffffUL);
  if (cfg_has(c, kc)) {
    const char *want;
    if (cfg_get_string(c, kc, NULL, &want, err)) return -1;
    char *end;
    const unsigned long w = strtoul(want, &end, 16);
    if (strlen(want) != 8 || *end || !isxdigit((unsigned char)want[0])) {
      free(abs);
      return material_key_error(c, kc, err,
                                "'%s' is not a CRC-32 (8 hexadecimal digits, as "
                                "hvsph writes it in used_parameters.yaml)",
                                want);
    }
    if (w != (m->eosp.tab.crc32 & 0xffffffffUL)) {
      material_key_error(c, kc, err,
                         "EOS table '%s' has CRC-32 %s, not the %s recorded here: "
                         "the table changed since the run that used it (restore it, or remove "
                         "file_crc32 to run with the table as it is now)",
                         abs ? abs : full, crc, want);
      free(abs);
      return -1;
    }
  }
  free(abs);
  cfg_record_string(c, kc, crc);
  const double zero = 0.0, floor_def = m->eosp.tab.cs_max / 100.0;
  if (material_get_q(c, path, "rho0", UNIT_DENSITY, &zero, 0.0, HUGE_VAL, &m->rho0, err) ||
      material_get_q(c, path, "cs_floor", UNIT_VELOCITY, &floor_def, 0.0, HUGE_VAL,
                     &m->eosp.tab.cs_floor, err))
    return -1;
  return 0;
}

static void table_print(FILE *f, const struct material *m)
{
  const struct eos_table *t = &m->eosp.tab;
  fprintf(f, "    %-15s %s\n", "file", t->path);
  fprintf(f, "    %-15s %d x %d%s\n", "grid (rho x e)", t->nrho, t->ne,
          t->cs ? ", with sound speeds" : ", c from dp");
  material_print_quantity(f, "rho min", t->rho[0], "kg/m3");
  material_print_quantity(f, "rho max", t->rho[t->nrho - 1], "kg/m3");
  material_print_quantity(f, "e min", t->e[0], "J/kg");
  material_print_quantity(f, "e max", t->e[t->ne - 1], "J/kg");
  material_print_quantity(f, "rho0", m->rho0, "kg/m3");
  material_print_quantity(f, "cs_floor", t->cs_floor, "m/s");
}

static void table_release(struct material *m) { eos_table_free(&m->eosp.tab); }

/* " 'x.txt'" after the EOS's name in eos_describe's messages */
static void table_describe_name(const struct material *m, char *buf, size_t len)
{
  snprintf(buf, len, " '%s'", m->eosp.tab.path);
}

/* " (rho 7000 to 9000 kg/m3, e 0 to 1e6 J/kg)" after "is outside the table" */
static void table_describe_outside(const struct material *m, char *buf, size_t len)
{
  const struct eos_table *t = &m->eosp.tab;
  if (t->nrho >= 2 && t->ne >= 2)
    snprintf(buf, len, " (rho %.6g to %.6g kg/m3, e %.6g to %.6g J/kg)", t->rho[0],
             t->rho[t->nrho - 1], t->e[0], t->e[t->ne - 1]);
  else if (len)
    buf[0] = '\0';
}

static const struct material_typical table_typical[] = {
    {"rho0", UNIT_DENSITY, HV_RHO_CONDENSED_LO, HV_RHO_CONDENSED_HI, HV_RHO_CONDENSED_WHAT},
    {NULL, 0, 0.0, 0.0, NULL},
};

const struct eos_model eos_table_model = {
    .name = "table",
    .read = table_read_keys,
    .print = table_print,
    .evaluate = table_evaluate,
    .energy_from_pressure = table_energy,
    .typical = table_typical,
    .release = table_release,
    .describe_name = table_describe_name,
    .describe_outside = table_describe_outside,
};
