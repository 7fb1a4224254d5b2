/* measure_table.c — measurements.csv rows; see measure_table.h. */
#include "diag/measure_table.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/infile.h"
#include "io/atomic_file.h"

void meas_table_init(struct meas_table *t) { memset(t, 0, sizeof *t); }

void meas_table_free(struct meas_table *t)
{
  for (size_t k = 0; k < t->n; k++) {
    free(t->rows[k].quantity);
    free(t->rows[k].unit);
    free(t->rows[k].object);
  }
  free(t->rows);
  memset(t, 0, sizeof *t);
}

static char *dup(const char *s)
{
  s = s ? s : "";
  const size_t l = strlen(s) + 1;
  char *d = hv_malloc(l, "measurement text");
  memcpy(d, s, l);
  return d;
}

static int same(const char *a, const char *b) { return strcmp(a, b ? b : "") == 0; }

void meas_table_add(struct meas_table *t, double time, const char *quantity, double value,
                    const char *unit, const char *object)
{
  /* rows come in time order: look back through the rows of this time only */
  for (size_t k = t->n; k-- > 0;) {
    struct meas_row *r = &t->rows[k];
    if (memcmp(&r->time, &time, sizeof time) != 0) break;
    if (same(r->quantity, quantity) && same(r->object, object)) {
      r->value = value;
      free(r->unit);
      r->unit = dup(unit);
      return;
    }
  }
  if (t->n == t->cap) {
    t->cap = t->cap ? 2 * t->cap : 64;
    t->rows = hv_realloc(t->rows, t->cap * sizeof *t->rows, "measurement rows");
  }
  t->rows[t->n++] = (struct meas_row){time, dup(quantity), value, dup(unit), dup(object)};
}

/* One CSV text field, quoted when it needs to be. */
static int put_text(struct atomic_file *af, const char *s, struct hv_error *err)
{
  if (!strpbrk(s, ",\"\r\n")) return atomic_file_printf(af, err, "%s", s);
  if (atomic_file_printf(af, err, "\"")) return -1;
  for (const char *c = s; *c; c++) {
    const int rc =
        *c == '"' ? atomic_file_printf(af, err, "\"\"") : atomic_file_printf(af, err, "%c", *c);
    if (rc) return -1;
  }
  return atomic_file_printf(af, err, "\"");
}

static int put_number(struct atomic_file *af, double v, struct hv_error *err)
{
  if (isnan(v)) return atomic_file_printf(af, err, "nan");
  if (isinf(v)) return atomic_file_printf(af, err, v > 0 ? "inf" : "-inf");
  return atomic_file_printf(af, err, "%.17g", v);
}

static int write_body(struct atomic_file *af, const struct meas_table *t, const char *comment,
                      struct hv_error *err)
{
  for (const char *s = comment; s && *s;) {
    const size_t l = strcspn(s, "\n");
    if (atomic_file_printf(af, err, "# %.*s\n", (int)l, s)) return -1;
    s += l;
    if (*s == '\n') s++;
  }
  if (atomic_file_printf(af, err, "time,quantity,value,unit,object\n")) return -1;
  for (size_t k = 0; k < t->n; k++) {
    const struct meas_row *r = &t->rows[k];
    if (put_number(af, r->time, err) || atomic_file_printf(af, err, ",") ||
        put_text(af, r->quantity, err) || atomic_file_printf(af, err, ",") ||
        put_number(af, r->value, err) || atomic_file_printf(af, err, ",") ||
        put_text(af, r->unit, err) || atomic_file_printf(af, err, ",") ||
        put_text(af, r->object, err) || atomic_file_printf(af, err, "\n"))
      return -1;
  }
  return 0;
}

int meas_table_write(const struct meas_table *t, const char *path, const char *comment,
                     struct hv_error *err)
{
  struct atomic_file af;
  if (atomic_file_open(&af, path, err)) return -1;
  if (write_body(&af, t, comment, err)) {
    atomic_file_abort(&af);
    return -1;
  }
  return atomic_file_commit(&af, err);
}

#define RAD2DEG (180.0 / HV_MEAS_PI)

void meas_table_add_cavity(struct meas_table *t, double time, const char *object,
                           const struct meas_cavity *r)
{
  meas_table_add(t, time, "penetration_depth", r->L, "m", object);
  meas_table_add(t, time, "cavity_diameter", r->D, "m", object);
  meas_table_add(t, time, "cavity_diameter_mean", r->D_mean, "m", object);
  meas_table_add(t, time, "cavity_diameter_wall", r->D_wall, "m", object);
  meas_table_add(t, time, "cavity_diameter_wall_mean", r->D_wall_mean, "m", object);
  meas_table_add(t, time, "perforated", r->perforated, "", object);
}

void meas_table_add_plate(struct meas_table *t, double time, const char *object,
                          const struct meas_plate *r)
{
  meas_table_add(t, time, "perforated", r->perforated, "", object);
  meas_table_add(t, time, "hole_diameter", r->d_circle, "m", object);
  meas_table_add(t, time, "hole_diameter_equiv", r->d_equiv, "m", object);
  meas_table_add(t, time, "hole_diameter_at_impact", r->d_circle_impact, "m", object);
  meas_table_add(t, time, "hole_area", r->area, "m2", object);
  meas_table_add(t, time, "hole_open", r->hole_open, "", object);
}

void meas_table_add_debris(struct meas_table *t, double time, const char *object,
                           const struct meas_debris *r)
{
  meas_table_add(t, time, "cloud_particles", (double)r->count, "", object);
  meas_table_add(t, time, "cloud_mass", r->m, "kg", object);
  meas_table_add(t, time, "cloud_velocity_mean", r->v_mean, "m/s", object);
  meas_table_add(t, time, "cloud_velocity_lead", r->v_lead, "m/s", object);
  meas_table_add(t, time, "cloud_velocity_max", r->v_max, "m/s", object);
  meas_table_add(t, time, "cloud_lead_distance", r->x_lead, "m", object);
  meas_table_add(t, time, "cloud_half_angle", r->half_angle * RAD2DEG, "deg", object);
  meas_table_add(t, time, "cloud_half_angle_front", r->half_angle_front * RAD2DEG, "deg", object);
  meas_table_add(t, time, "cloud_gap", r->gap, "m", object);
}

void meas_table_add_backwall(struct meas_table *t, double time, const char *object,
                             const struct meas_backwall *r)
{
  meas_table_add(t, time, "crater_depth", r->crater_depth, "m", object);
  meas_table_add(t, time, "wall_shift", r->wall_shift, "m", object);
  meas_table_add(t, time, "crater_depth_local", r->crater_depth_local, "m", object);
  meas_table_add(t, time, "crater_local_ref", r->crater_local_ref, "m", object);
  meas_table_add(t, time, "damage_radius", r->r_damage, "m", object);
  meas_table_add(t, time, "crater_radius", r->r_crater, "m", object);
  meas_table_add(t, time, "damage_radius_particles", r->r_damage_particles, "m", object);
  meas_table_add(t, time, "damaged_mass", r->m_damaged, "kg", object);
}

void meas_table_add_gas(struct meas_table *t, double time, const char *object,
                        const struct meas_gas_front *r)
{
  meas_table_add(t, time, "shock_front_axial", r->x_axial, "m", object);
  meas_table_add(t, time, "shock_front_radial", r->r_radial, "m", object);
  meas_table_add(t, time, "shock_front_distance", r->r_max, "m", object);
  meas_table_add(t, time, "shocked_particles", (double)r->n_shocked, "", object);
}

void meas_table_add_fragments(struct meas_table *t, double time, const char *object,
                              const struct fof_result *r)
{
  double m1 = 0.0, m2 = 0.0, m2sum = 0.0;
  /* the largest and second largest of the full picture (a twin pair is two fragments) */
  for (size_t f = 0; f < r->nfrag; f++) {
    const double m = r->frag[f].m;
    for (int k = 0; k < r->frag[f].multiplicity; k++) {
      if (m > m1) {
        m2 = m1;
        m1 = m;
      } else if (m > m2) {
        m2 = m;
      }
    }
    m2sum += m * m * r->frag[f].multiplicity;
  }
  meas_table_add(t, time, "fragments_count", (double)r->n_full, "", object);
  meas_table_add(t, time, "fragments_count_multi", (double)fof_count_min(r, 2), "", object);
  meas_table_add(t, time, "fragment_mass_largest", m1, "kg", object);
  meas_table_add(t, time, "fragment_mass_second", m2, "kg", object);
  meas_table_add(t, time, "fragment_mass_mean", r->m_total > 0 ? m2sum / r->m_total : 0.0, "kg",
                 object);
  meas_table_add(t, time, "fragments_mass", r->m_total, "kg", object);
}

/* The next CSV field of *s (RFC 4180 quotes undone) into buf; advances *s past the
 * comma. Returns 0, or -1 at the end of the line. */
static int next_field(const char **s, char *buf, size_t len)
{
  const char *c = *s;
  size_t k = 0;
  if (!c) return -1;
  if (*c == '"') {
    for (c++; *c; c++) {
      if (*c == '"' && c[1] == '"')
        c++;
      else if (*c == '"') {
        c++;
        break;
      }
      if (k + 1 < len) buf[k++] = *c;
    }
  } else {
    for (; *c && *c != ',' && *c != '\n' && *c != '\r'; c++)
      if (k + 1 < len) buf[k++] = *c;
  }
  buf[k] = 0;
  *s = *c == ',' ? c + 1 : NULL;
  return 0;
}

int meas_table_read(struct meas_table *t, const char *path, struct hv_error *err)
{
  FILE *f = hv_open_input(path, NULL, 0, NULL, err); /* a FIFO would block the open */
  if (!f) return -1;
  char *line = NULL, *more = NULL;
  size_t cap = 0, mcap = 0;
  int header = 1;
  while (getline(&line, &cap, f) >= 0) {
    if (line[0] == '#') continue;
    /* a quoted field may hold a line break (RFC 4180): the record goes on while a quote
       is open (an odd count of '"' so far) */
    size_t nq = 0;
    for (const char *c = line; *c; c++) nq += *c == '"';
    while (nq % 2) {
      const ssize_t l = getline(&more, &mcap, f);
      if (l < 0) break;
      for (const char *c = more; *c; c++) nq += *c == '"';
      const size_t len = strlen(line);
      if (len + (size_t)l + 1 > cap) {
        cap = len + (size_t)l + 1;
        line = hv_realloc(line, cap, "measurement line");
      }
      memcpy(line + len, more, (size_t)l + 1);
    }
    if (header) { /* time,quantity,value,unit,object */
      header = 0;
      continue;
    }
    char fld[5][512];
    const char *s = line;
    int k = 0;
    while (k < 5 && next_field(&s, fld[k], sizeof fld[k]) == 0) k++;
    if (k < 5) continue;
    meas_table_add(t, strtod(fld[0], NULL), fld[1], strtod(fld[2], NULL), fld[3], fld[4]);
  }
  free(line);
  free(more);
  fclose(f);
  return 0;
}
