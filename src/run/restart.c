/* restart.c — see restart.h. */
#include "run/restart.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fracture/fracture.h"
#include "io/checkpoint.h"
#include "version.h"

void restart_path(const char *dir, char *buf, size_t len)
{
  snprintf(buf, len, "%s/checkpoint.hvc", dir);
}

static enum ckpt_type ckpt_type_of(enum pf_type t)
{
  return t == PF_INT32 ? CKPT_I32 : t == PF_INT64 ? CKPT_I64 : CKPT_F64;
}

/* Strings joined with their NULs into one buffer (NULL reads as ""). */
static char *join(const char *const *s, size_t n, size_t *len)
{
  size_t total = 0;
  for (size_t i = 0; i < n; i++) total += strlen(s[i] ? s[i] : "") + 1;
  char *b = hv_malloc(total + 1, "checkpoint strings"), *q = b;
  for (size_t i = 0; i < n; i++) {
    const char *t = s[i] ? s[i] : "";
    memcpy(q, t, strlen(t) + 1);
    q += strlen(t) + 1;
  }
  *len = total;
  return b;
}

/* Splits a joined buffer into exactly n strings (pointers into b); -1 otherwise. */
static int split(char *b, size_t len, const char **out, size_t n)
{
  size_t k = 0, pos = 0;
  while (pos < len && k < n) {
    out[k++] = b + pos;
    pos += strlen(b + pos) + 1;
  }
  return k == n && pos == len ? 0 : -1;
}

int restart_write(const struct sim *s, const struct run_outputs *o, struct hv_error *err)
{
  char path[4200];
  restart_path(o->dir, path, sizeof path);
  struct ckpt_writer w;
  if (ckpt_write_open(&w, path, err)) return -1;
  const struct particles *p = &s->p;
  const size_t n = p->n;

  /* what this is */
  _Static_assert(HV_MAX_MATERIALS <= 64, "name lists hold 64 bodies or materials");
  const char *names[64];
  size_t len;
  const int64_t geometry = p->axisym; /* 1: axisymmetric; a checkpoint without it is 3D */
  int rc = ckpt_put(&w, "version", CKPT_BYTES, strlen(HVSPH_VERSION), HVSPH_VERSION, err) ||
           ckpt_put(&w, "case", CKPT_BYTES, strlen(s->case_name), s->case_name, err) ||
           ckpt_put(&w, "geometry", CKPT_I64, 1, &geometry, err);
  if (!rc) {
    for (int b = 0; b < s->nbody; b++) names[b] = s->body[b].name;
    char *j = join(names, (size_t)s->nbody, &len);
    int64_t counts[64];
    for (int b = 0; b < s->nbody; b++) counts[b] = (int64_t)s->body[b].count;
    rc = ckpt_put(&w, "bodies", CKPT_BYTES, len, j, err) ||
         ckpt_put(&w, "bodies.count", CKPT_I64, (size_t)s->nbody, counts, err);
    free(j);
  }
  if (!rc) {
    for (int m = 0; m < s->nmat; m++) names[m] = s->mat[m].name;
    char *j = join(names, (size_t)s->nmat, &len);
    rc = ckpt_put(&w, "materials", CKPT_BYTES, len, j, err);
    free(j);
  }

  /* the clock and the boundaries */
  if (!rc) {
    const double clock[3] = {s->t, s->dt, s->dt_prop};
    const int64_t ints[3] = {s->step, (int64_t)n, p->solid};
    const struct absorbed *a = &s->bnd.absorbed;
    const double ab[6] = {a->mass, a->mom[0], a->mom[1], a->mom[2], a->e_kin, a->e_int};
    const int64_t abn = a->n;
    rc = ckpt_put(&w, "clock", CKPT_F64, 3, clock, err) ||
         ckpt_put(&w, "step.n.solid", CKPT_I64, 3, ints, err) ||
         ckpt_put(&w, "absorbed", CKPT_F64, 6, ab, err) ||
         ckpt_put(&w, "absorbed.n", CKPT_I64, 1, &abn, err);
  }

  /* the particles' state */
  struct pfield f[HV_MAX_FIELDS];
  const int nf = particles_fields((struct particles *)p, f);
  for (int i = 0; i < nf && !rc; i++) {
    if (!(f[i].flags & PF_STATE)) continue;
    char rn[CKPT_NAME_LEN + 1];
    snprintf(rn, sizeof rn, "p.%s", f[i].name);
    rc = ckpt_put_parts(&w, rn, ckpt_type_of(f[i].type), n, (const void *const *)f[i].comp,
                        f[i].ncomp, err);
  }

  /* outputs so far */
  if (!rc) {
    const int64_t ints[3] = {o->count, o->next_k, o->nrows};
    const int64_t ncols = RUN_SUMMARY_COLS;
    char *j = join((const char *const *)o->files, (size_t)o->count, &len);
    const size_t ntimes = s->out.vtu ? (size_t)o->count : 0;
    rc = ckpt_put(&w, "out.count.next_k.nrows", CKPT_I64, 3, ints, err) ||
         ckpt_put(&w, "out.t_start", CKPT_F64, 1, &o->t_start, err) ||

         ckpt_put(&w, "out.summary_cols", CKPT_I64, 1, &ncols, err) ||
         ckpt_put(&w, "out.summary", CKPT_F64, (size_t)o->nrows * RUN_SUMMARY_COLS, o->rows, err) ||
         ckpt_put(&w, "out.snapshot_files", CKPT_BYTES, len, j, err) ||
         ckpt_put(&w, "out.snapshot_times", CKPT_F64, ntimes, o->times, err);
    free(j);
  }

  /* measurements so far */
  if (!rc) {
    const struct meas_table *t = &o->mr.table;
    double *tv = hv_malloc((2 * t->n + 1) * sizeof *tv, "checkpoint");
    const char **text = hv_malloc((3 * t->n + 1) * sizeof *text, "checkpoint");
    for (size_t k = 0; k < t->n; k++) {
      tv[k] = t->rows[k].time;
      tv[t->n + k] = t->rows[k].value;
      text[3 * k] = t->rows[k].quantity;
      text[3 * k + 1] = t->rows[k].unit;
      text[3 * k + 2] = t->rows[k].object;
    }
    char *j = join(text, 3 * t->n, &len);
    const int64_t mk = o->next_mk;
    rc = ckpt_put(&w, "measure.peak_pressure", CKPT_F64, 1, &o->mr.peak_pressure, err) ||
         ckpt_put(&w, "measure.next_k", CKPT_I64, 1, &mk, err) ||
         ckpt_put(&w, "measure.time_value", CKPT_F64, 2 * t->n, tv, err) ||
         ckpt_put(&w, "measure.text", CKPT_BYTES, len, j, err);
    free(j);
    free(tv);
    free(text);
  }
  if (rc) return hv_error_prefix(err, "checkpoint at t = %g s: ", s->t);
  return ckpt_write_commit(&w, err);
}

static int mismatch(struct ckpt_file *c, struct hv_error *err, const char *what, const char *a,
                    const char *b)
{
  return hv_error_set(err, HV_EXIT_INPUT,
                      "%s: the checkpoint does not belong to this case: "
                      "%s '%s' in the checkpoint, '%s' in the case (a restart continues the "
                      "run that wrote it, with the same case and resolution)",
                      c->path, what, a, b);
}

static int bad_record(const struct ckpt_file *c, const char *rec, struct hv_error *err,
                      const char *fmt, ...) __attribute__((format(printf, 4, 5)));

/* A record whose values hvsph never writes (the CRC matched, so the file was made so):
 * "PATH: checkpoint record 'REC': what is wrong". Every value is checked before it is
 * used: a count of 10^8 summary rows ended in SIGSEGV, a particle count of 2^40 asked
 * for 11.7 TB, an output index of 2^62 never ended, a NaN time went into run.pvd. */
static int bad_record(const struct ckpt_file *c, const char *rec, struct hv_error *err,
                      const char *fmt, ...)
{
  char msg[1024];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);
  return hv_error_set(err, HV_EXIT_INPUT,
                      "%s: checkpoint record '%s': %s (hvsph writes no "
                      "such value: the file was made or altered by something else)",
                      c->path, rec, msg);
}

/* The most outputs (and output or measurement time indices) a checkpoint may count:
 * 10^8, as many as summary rows of 144 bytes fill 14 GB; the loops that step an index
 * to the checkpoint's time run at most that many times (a fraction of a second). */
#define RESTART_MAX_OUTPUTS 100000000LL

/* Record `rec` holds exactly `count` elements (checked before anything is allocated
 * for them: a count in another record must agree with the data the file holds). */
static int want_count(const struct ckpt_file *c, const char *rec, enum ckpt_type type,
                      uint64_t count, const char *from, struct hv_error *err)
{
  const struct ckpt_record *r = ckpt_find(c, rec);
  if (!r)
    return hv_error_set(err, HV_EXIT_INPUT, "%s: the checkpoint has no record '%s'", c->path, rec);
  if (r->type != type)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: checkpoint record '%s' holds values of "
                        "another type than this hvsph writes there",
                        c->path, rec);
  if (r->count == count) return 0;
  return bad_record(c, from, err, "it counts %llu elements for record '%s', which holds %llu",
                    (unsigned long long)count, rec, (unsigned long long)r->count);
}

/* Compares a joined name list with the case's. */
static int check_names(struct ckpt_file *c, const char *rec, const char *what,
                       const char *const *names, int n, struct hv_error *err)
{
  char *b;
  size_t len;
  if (ckpt_get_alloc(c, rec, CKPT_BYTES, (void **)&b, &len, err)) return -1;
  const char *got[64];
  int rc = 0;
  if (n > 64 || split(b, len, got, (size_t)n)) {
    char num[32];
    snprintf(num, sizeof num, "%d", n);
    rc = mismatch(c, err, what, "another count of", num);
  } else {
    for (int k = 0; k < n && !rc; k++)
      if (strcmp(got[k], names[k])) rc = mismatch(c, err, what, got[k], names[k]);
  }
  free(b);
  return rc;
}

static int read_outputs(struct ckpt_file *c, const struct sim *s, struct run_outputs *o,
                        struct hv_error *err)
{
  int64_t ints[3], ncols;
  const char *const ro = "out.count.next_k.nrows";
  if (ckpt_get(c, ro, CKPT_I64, 3, ints, err) ||
      ckpt_get(c, "out.t_start", CKPT_F64, 1, &o->t_start, err) ||
      ckpt_get(c, "out.summary_cols", CKPT_I64, 1, &ncols, err))
    return -1;
  if (ncols != RUN_SUMMARY_COLS)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: output bookkeeping not understood by this "
                        "hvsph (%lld summary columns, %d expected)",
                        c->path, (long long)ncols, RUN_SUMMARY_COLS);
  /* one summary row per output, written together (run.c, write_outputs) */
  if (ints[0] < 0 || ints[0] > RESTART_MAX_OUTPUTS || ints[2] != ints[0])
    return bad_record(c, ro, err,
                      "%lld outputs and %lld summary rows (a run writes one "
                      "row per output, at most %lld)",
                      (long long)ints[0], (long long)ints[2], RESTART_MAX_OUTPUTS);
  if (ints[1] < 1 || ints[1] > RESTART_MAX_OUTPUTS)
    return bad_record(c, ro, err, "index of the next output time %lld (from 1 to %lld)",
                      (long long)ints[1], RESTART_MAX_OUTPUTS);
  if (!isfinite(o->t_start) || o->t_start < 0 || o->t_start > s->t)
    return bad_record(c, "out.t_start", err,
                      "start time %g s (finite, from 0 to the "
                      "checkpoint's time %g s)",
                      o->t_start, s->t);
  const int count = (int)ints[0];
  o->next_k = (long)ints[1];
  if (want_count(c, "out.summary", CKPT_F64, (uint64_t)count * RUN_SUMMARY_COLS, ro, err))
    return -1;
  o->rows = hv_malloc(((size_t)count * RUN_SUMMARY_COLS + 1) * sizeof *o->rows, "summary");
  o->nrows = count;
  if (ckpt_get(c, "out.summary", CKPT_F64, (size_t)count * RUN_SUMMARY_COLS, o->rows, err))
    return -1;
  for (int k = 0; k < count; k++) { /* finite; step and time (columns 0, 1) in order */
    const double *row = o->rows + (size_t)k * RUN_SUMMARY_COLS;
    for (int q = 0; q < RUN_SUMMARY_COLS; q++)
      if (!isfinite(row[q]))
        return bad_record(c, "out.summary", err, "row %d column %d is %g", k, q + 1, row[q]);
    if (row[0] < 0 || row[0] > (double)s->step || row[1] < o->t_start || row[1] > s->t ||
        (k > 0 && (row[0] < row[-RUN_SUMMARY_COLS] || row[1] < row[1 - RUN_SUMMARY_COLS])))
      return bad_record(c, "out.summary", err,
                        "row %d: step %g at t = %g s, not in order "
                        "between the start (t = %g s) and the checkpoint (step %ld, t = %g s)",
                        k, row[0], row[1], o->t_start, s->step, s->t);
  }
  char *b;
  size_t len, nt;
  if (ckpt_get_alloc(c, "out.snapshot_files", CKPT_BYTES, (void **)&b, &len, err)) return -1;
  const char **names = hv_malloc(((size_t)count + 1) * sizeof *names, "checkpoint");
  int rc = split(b, len, names, (size_t)count);
  if (rc) bad_record(c, "out.snapshot_files", err, "it does not hold %d names", count);
  /* each name is the one write_outputs gives output k, or empty (no .vtu): run.pvd
     lists them, and no other name may get into it */
  for (int k = 0; k < count && !rc; k++) {
    char want[32];
    snprintf(want, sizeof want, "particles_%05d.vtu", k);
    if (*names[k] && strcmp(names[k], want))
      rc = bad_record(c, "out.snapshot_files", err, "name %d is '%.80s', not '%s'", k, names[k],
                      want);
  }
  if (!rc) {
    o->files = hv_malloc(((size_t)count + 1) * sizeof *o->files, "pvd");
    for (int k = 0; k < count; k++) o->files[k] = *names[k] ? strdup(names[k]) : NULL;
    o->count = count; /* outputs_free frees count names: set only once they exist */
  }
  free(names);
  free(b);
  if (rc) return -1;
  if (ckpt_get_alloc(c, "out.snapshot_times", CKPT_F64, (void **)&o->times, &nt, err)) return -1;
  if (nt != 0 && nt != (size_t)o->count)
    return bad_record(c, "out.snapshot_times", err, "%zu times for %d outputs", nt, o->count);
  if (s->out.vtu && nt != (size_t)o->count)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: the run that wrote the checkpoint wrote no "
                        ".vtu snapshots (output.vtu: false); continue it without them",
                        c->path);
  for (size_t k = 0; k < nt; k++)
    if (!isfinite(o->times[k]) || o->times[k] != o->rows[k * RUN_SUMMARY_COLS + 1])
      return bad_record(c, "out.snapshot_times", err,
                        "time %zu is %g s, where summary row "
                        "%zu has t = %g s",
                        k, o->times[k], k, o->rows[k * RUN_SUMMARY_COLS + 1]);
  return 0;
}

static int read_measure(struct ckpt_file *c, const struct sim *s, struct run_outputs *o,
                        struct hv_error *err)
{
  struct measure_run *mr = &o->mr;
  int64_t mk = 0; /* absent in checkpoints before measure.every: the loop finds it */
  if (ckpt_find(c, "measure.next_k") && ckpt_get(c, "measure.next_k", CKPT_I64, 1, &mk, err))
    return -1;
  if (mk < 0 || mk > RESTART_MAX_OUTPUTS)
    return bad_record(c, "measure.next_k", err,
                      "index of the next measurement time %lld "
                      "(from 0 to %lld)",
                      (long long)mk, RESTART_MAX_OUTPUTS);
  o->next_mk = (long)mk;
  double *tv;
  char *b;
  size_t ntv, len;
  if (ckpt_get(c, "measure.peak_pressure", CKPT_F64, 1, &mr->peak_pressure, err)) return -1;
  if (isnan(mr->peak_pressure) || mr->peak_pressure == HUGE_VAL) /* -inf: none yet */
    return bad_record(c, "measure.peak_pressure", err, "peak pressure %g Pa", mr->peak_pressure);
  if (ckpt_get_alloc(c, "measure.time_value", CKPT_F64, (void **)&tv, &ntv, err)) return -1;
  if (ckpt_get_alloc(c, "measure.text", CKPT_BYTES, (void **)&b, &len, err)) {
    free(tv);
    return -1;
  }
  const size_t n = ntv / 2;
  const char **text = hv_malloc((3 * n + 1) * sizeof *text, "checkpoint");
  int rc = ntv % 2 || split(b, len, text, 3 * n);
  if (rc)
    hv_error_set(err, HV_EXIT_INPUT, "%s: the checkpoint's measurement records do not match",
                 c->path);
  /* times of the outputs so far, in order; texts that measurements.csv can hold */
  for (size_t k = 0; k < n && !rc; k++)
    if (!isfinite(tv[k]) || tv[k] < o->t_start || tv[k] > s->t || (k > 0 && tv[k] < tv[k - 1]))
      rc = bad_record(c, "measure.time_value", err,
                      "time %zu is %g s, not in order between "
                      "the start (%g s) and the checkpoint (%g s)",
                      k, tv[k], o->t_start, s->t);
  for (size_t q = 0; q < len && !rc; q++)
    if (b[q] && (unsigned char)b[q] < 0x20)
      rc = bad_record(c, "measure.text", err, "control character 0x%02x at byte %zu",
                      (unsigned char)b[q], q);
  meas_table_free(&mr->table);
  meas_table_init(&mr->table);
  for (size_t k = 0; k < n && !rc; k++)
    meas_table_add(&mr->table, tv[k], text[3 * k], tv[n + k], text[3 * k + 1], text[3 * k + 2]);
  free(text);
  free(b);
  free(tv);
  return rc ? -1 : 0;
}

/* Every state value finite, and m, h, rho > 0, as every step leaves them (step.c's
 * check_state, the EOS): a NaN position or a smoothing length of 0 would reach the
 * neighbour grid. Names the first offender's record, particle and component. */
static int check_particles(const struct ckpt_file *c, const struct particles *p,
                           const struct pfield *f, int nf, struct hv_error *err)
{
  for (int i = 0; i < nf; i++) {
    if (!(f[i].flags & PF_STATE) || f[i].type != PF_DOUBLE) continue;
    const int positive =
        !strcmp(f[i].name, "m") || !strcmp(f[i].name, "h") || !strcmp(f[i].name, "rho");
    for (int q = 0; q < f[i].ncomp; q++) {
      const double *v = f[i].comp[q];
      for (size_t k = 0; k < p->n; k++)
        if (!isfinite(v[k]) || (positive && !(v[k] > 0))) {
          char rn[CKPT_NAME_LEN + 1], comp[32] = "";
          snprintf(rn, sizeof rn, "p.%s", f[i].name);
          if (f[i].ncomp > 1) snprintf(comp, sizeof comp, ", component %d", q + 1);
          return bad_record(c, rn, err, "particle %lld%s: %s = %g %s%s", (long long)p->id[k], comp,
                            f[i].name, v[k], f[i].unit, positive ? " (must be > 0)" : "");
        }
    }
  }
  return 0;
}

/* The checkpoint is of this case: its version said when another's, the same case name,
 * bodies (with their initial counts) and materials. Returns 0 or -1 with err set. */
static int restart_same_case(struct ckpt_file *c, const struct sim *s, const char *path,
                             struct hv_error *err)
{
  size_t len;
  const char *names[64];
  /* another hvsph may continue it, but the numbers then differ from either's own run */
  char *ver = NULL;
  if (ckpt_get_alloc(c, "version", CKPT_BYTES, (void **)&ver, &len, err)) return -1;
  if (strcmp(ver, HVSPH_VERSION))
    hv_warn("%s was written by hvsph %s; this is hvsph %s: where the two compute differently "
            "the continued run matches neither's own run bit for bit (run_segments.csv "
            "records both)",
            path, ver, HVSPH_VERSION);
  free(ver);

  /* the same case: name, bodies (and their initial counts), materials */
  char *cname = NULL;
  if (ckpt_get_alloc(c, "case", CKPT_BYTES, (void **)&cname, &len, err)) return -1;
  const int other = strcmp(cname, s->case_name);
  if (other) mismatch(c, err, "case name", cname, s->case_name);
  free(cname);
  if (other) return -1;
  /* the same geometry: an axisymmetric run's rings are no 3D particles (record absent:
     written before the record existed, 3D) */
  int64_t geometry = 0;
  if (ckpt_find(c, "geometry") && ckpt_get(c, "geometry", CKPT_I64, 1, &geometry, err)) return -1;
  if (geometry != s->p.axisym) {
    const char *g[2] = {"3d", "axisymmetric"};
    char what[64] = "geometry (record 'geometry'):";
    if (geometry == 0 || geometry == 1) return mismatch(c, err, what, g[geometry], g[s->p.axisym]);
    return hv_error_set(err, HV_EXIT_INPUT, "%s: record 'geometry' holds %lld, not 0 or 1", c->path,
                        (long long)geometry);
  }
  for (int b = 0; b < s->nbody; b++) names[b] = s->body[b].name;
  if (check_names(c, "bodies", "bodies", names, s->nbody, err)) return -1;
  int64_t counts[64];
  if (ckpt_get(c, "bodies.count", CKPT_I64, (size_t)s->nbody, counts, err)) return -1;
  for (int b = 0; b < s->nbody; b++)
    if (counts[b] != (int64_t)s->body[b].count) {
      char a[64], bb[64], what[128];
      snprintf(a, sizeof a, "%lld", (long long)counts[b]);
      snprintf(bb, sizeof bb, "%zu", s->body[b].count);
      snprintf(what, sizeof what, "initial particle count of body '%s':", s->body[b].name);
      mismatch(c, err, what, a, bb);
      return -1;
    }
  for (int m = 0; m < s->nmat; m++) names[m] = s->mat[m].name;
  if (check_names(c, "materials", "materials", names, s->nmat, err)) return -1;

  return 0;
}

/* The clock, the step and the absorbing faces' tallies read and checked into s; *n the
 * particles the checkpoint holds. Returns 0 or -1 with err set. */
static int restart_clock(struct ckpt_file *c, struct sim *s, size_t *n, struct hv_error *err)
{
  /* clock, boundaries */
  double clock[3], ab[6];
  int64_t ints[3], abn;
  if (ckpt_get(c, "clock", CKPT_F64, 3, clock, err) ||
      ckpt_get(c, "step.n.solid", CKPT_I64, 3, ints, err) ||
      ckpt_get(c, "absorbed", CKPT_F64, 6, ab, err) ||
      ckpt_get(c, "absorbed.n", CKPT_I64, 1, &abn, err))
    return -1;
  if (ints[2] != s->p.solid) {
    mismatch(c, err, "solid fields", ints[2] ? "present" : "absent",
             s->p.solid ? "present" : "absent");
    return -1;
  }
  /* the clock: a time, a next step and a proposed one that a run reaches */
  if (!isfinite(clock[0]) || clock[0] < 0 || !isfinite(clock[1]) || !(clock[1] > 0) ||
      !isfinite(clock[2]) || clock[2] < 0) {
    bad_record(c, "clock", err,
               "t = %g s, dt = %g s, proposed dt = %g s (t finite and "
               ">= 0, dt finite and > 0)",
               clock[0], clock[1], clock[2]);
    return -1;
  }
  if (ints[0] < 0 || ints[1] < 0) {
    bad_record(c, "step.n.solid", err, "step %lld, %lld particles", (long long)ints[0],
               (long long)ints[1]);
    return -1;
  }
  /* what absorbing faces removed: at most the particles there were, finite tallies */
  if (abn < 0 || abn > ints[1] + (int64_t)s->p.n) {
    bad_record(c, "absorbed.n", err, "%lld particles absorbed", (long long)abn);
    return -1;
  }
  for (int k = 0; k < 6; k++)
    if (!isfinite(ab[k]) || (k == 0 && ab[k] < 0)) {
      bad_record(c, "absorbed", err, "value %d is %g", k + 1, ab[k]);
      return -1;
    }
  s->t = clock[0];
  s->dt = clock[1];
  s->dt_prop = clock[2];
  s->step = (long)ints[0];
  struct absorbed *a = &s->bnd.absorbed;
  a->n = (long)abn;
  a->mass = ab[0];
  for (int k = 0; k < 3; k++) a->mom[k] = ab[1 + k];
  a->e_kin = ab[4];
  a->e_int = ab[5];

  *n = (size_t)ints[1];
  return 0;
}

/* The n particles' state read and checked into s->p (absorbing faces remove some, so n
 * is the checkpoint's count). Returns 0 or -1 with err set. */
static int restart_particles(struct ckpt_file *c, struct sim *s, size_t n, const char *path,
                             struct hv_error *err)
{
  /* the particles: as many as the checkpoint holds (absorbing faces remove some) */
  struct particles *p = &s->p;
  if (p->av && !ckpt_find(c, "p.alpha")) {
    hv_error_set(err, HV_EXIT_INPUT,
                 "%s: the run was made without sph.viscosity.switch, "
                 "whose per-particle alpha it does not hold: a run cannot take the switch up "
                 "when continued (start it again, or continue it without the switch)",
                 path);
    return -1;
  }
  if (p->cracks && !ckpt_find(c, "p.crack")) {
    hv_error_set(err, HV_EXIT_INPUT,
                 "%s: the run was made without fracture.split: crack "
                 "or fracture.energy, whose per-particle crack normals it does not hold: a "
                 "run cannot take it up "
                 "when continued (start it again, or continue it without it)",
                 path);
    return -1;
  }
  /* a checkpoint from before the fracture state was a field (no p.fstate): the state
     follows from the damage (fracture_states_from_damage), exactly */
  const int old_states = p->solid && !ckpt_find(c, "p.fstate");
  /* an axisymmetric checkpoint from before the rings kept their initial radius (no
     p.r0): r0 stays 0, h follows every stretch, and the run continues as it was made,
     bit for bit */
  const int old_rings = p->rings && !ckpt_find(c, "p.r0");
  /* the count against the data the file holds, before the particles are allocated (a
     count of 2^40 asked for 11.7 TB): every state field's record, n elements a part */
  struct pfield f[HV_MAX_FIELDS];
  int nf = particles_fields(p, f);
  for (int i = 0; i < nf; i++) {
    if (!(f[i].flags & PF_STATE) || (old_states && !strcmp(f[i].name, "fstate")) ||
        (old_rings && !strcmp(f[i].name, "r0")))
      continue;
    char rn[CKPT_NAME_LEN + 1];
    snprintf(rn, sizeof rn, "p.%s", f[i].name);
    if (want_count(c, rn, ckpt_type_of(f[i].type), (uint64_t)n * (uint64_t)f[i].ncomp,
                   "step.n.solid", err))
      return -1;
  }
  p->n_ghost = 0;
  if (n > p->n) particles_add(p, n - p->n);
  p->n = n;
  nf = particles_fields(p, f);
  for (int i = 0; i < nf; i++) {
    if (!(f[i].flags & PF_STATE) || (old_states && !strcmp(f[i].name, "fstate")) ||
        (old_rings && !strcmp(f[i].name, "r0")))
      continue;
    char rn[CKPT_NAME_LEN + 1];
    snprintf(rn, sizeof rn, "p.%s", f[i].name);
    if (ckpt_get_parts(c, rn, ckpt_type_of(f[i].type), n, f[i].comp, f[i].ncomp, err)) return -1;
  }
  for (size_t i = 0; i < n; i++)
    if (p->mat[i] < 0 || p->mat[i] >= s->nmat || p->body[i] < 0 || p->body[i] >= s->nbody) {
      hv_error_set(err, HV_EXIT_INPUT,
                   "%s: particle %lld has material %d and body %d, "
                   "outside this case's %d materials and %d bodies",
                   path, (long long)p->id[i], p->mat[i], p->body[i], s->nmat, s->nbody);
      return -1;
    }
  if (check_particles(c, p, f, nf, err)) return -1;
  if (old_states) fracture_states_from_damage(p, s->mat);
  if (old_rings) memset(p->r0, 0, n * sizeof *p->r0);
  if (p->solid) { /* each fracture state one its damage and material allow */
    const size_t k = fracture_check_states(p, s->mat);
    if (k != (size_t)-1) {
      bad_record(c, "p.fstate", err,
                 "particle %lld: fracture state %d with damage %g, which "
                 "material '%s' does not allow",
                 (long long)p->id[k], (int)p->fstate[k], p->damage[k], s->mat[p->mat[k]].name);
      return -1;
    }
  }
  return 0;
}

int restart_read(struct sim *s, struct run_outputs *o, const char *path, struct hv_error *err)
{
  struct ckpt_file c;
  if (ckpt_open(&c, path, err)) return -1;
  size_t n = 0;
  const int rc = restart_same_case(&c, s, path, err) || restart_clock(&c, s, &n, err) ||
                         restart_particles(&c, s, n, path, err) || read_outputs(&c, s, o, err) ||
                         read_measure(&c, s, o, err)
                     ? -1
                     : 0;
  ckpt_close(&c);
  return rc;
}
