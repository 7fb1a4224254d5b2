/* restart.c — see restart.h. */
#include "run/restart.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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
  int rc = ckpt_put(&w, "version", CKPT_BYTES, strlen(HVSPH_VERSION), HVSPH_VERSION, err) ||
           ckpt_put(&w, "case", CKPT_BYTES, strlen(s->case_name), s->case_name, err);
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
         ckpt_put(&w, "out.summary", CKPT_F64, (size_t)o->nrows * RUN_SUMMARY_COLS, o->rows,
                  err) ||
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
  return hv_error_set(err, HV_EXIT_INPUT, "%s: the checkpoint does not belong to this case: "
                      "%s '%s' in the checkpoint, '%s' in the case (a restart continues the "
                      "run that wrote it, with the same case and resolution)", c->path, what,
                      a, b);
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
  if (ckpt_get(c, "out.count.next_k.nrows", CKPT_I64, 3, ints, err) ||
      ckpt_get(c, "out.t_start", CKPT_F64, 1, &o->t_start, err) ||

      ckpt_get(c, "out.summary_cols", CKPT_I64, 1, &ncols, err))
    return -1;
  if (ncols != RUN_SUMMARY_COLS || ints[0] < 0 || ints[0] > 100000000 || ints[2] < 0 ||
      ints[2] > 100000000)
    return hv_error_set(err, HV_EXIT_INPUT, "%s: output bookkeeping not understood by this "
                        "hvsph (%lld summary columns, %lld outputs)", c->path,
                        (long long)ncols, (long long)ints[0]);
  o->count = (int)ints[0];
  o->next_k = (long)ints[1];
  o->nrows = (int)ints[2];
  o->rows = hv_malloc(((size_t)o->nrows * RUN_SUMMARY_COLS + 1) * sizeof *o->rows, "summary");
  if (ckpt_get(c, "out.summary", CKPT_F64, (size_t)o->nrows * RUN_SUMMARY_COLS, o->rows, err))
    return -1;
  char *b;
  size_t len, nt;
  if (ckpt_get_alloc(c, "out.snapshot_files", CKPT_BYTES, (void **)&b, &len, err)) return -1;
  const char **names = hv_malloc(((size_t)o->count + 1) * sizeof *names, "checkpoint");
  o->files = hv_malloc(((size_t)o->count + 1) * sizeof *o->files, "pvd");
  int rc = split(b, len, names, (size_t)o->count);
  for (int k = 0; k < o->count; k++) o->files[k] = rc || !*names[k] ? NULL : strdup(names[k]);
  free(names);
  free(b);
  if (rc)
    return hv_error_set(err, HV_EXIT_INPUT, "%s: checkpoint record 'out.snapshot_files' does "
                        "not hold %d names", c->path, o->count);
  if (ckpt_get_alloc(c, "out.snapshot_times", CKPT_F64, (void **)&o->times, &nt, err)) return -1;
  if (s->out.vtu && nt != (size_t)o->count)
    return hv_error_set(err, HV_EXIT_INPUT, "%s: the run that wrote the checkpoint wrote no "
                        ".vtu snapshots (output.vtu: false); continue it without them",
                        c->path);
  return 0;
}

static int read_measure(struct ckpt_file *c, struct run_outputs *o, struct hv_error *err)
{
  struct measure_run *mr = &o->mr;
  int64_t mk = 0;   /* absent in checkpoints before measure.every: the loop finds it */
  if (ckpt_find(c, "measure.next_k") && ckpt_get(c, "measure.next_k", CKPT_I64, 1, &mk, err))
    return -1;
  o->next_mk = (long)mk;
  double *tv;
  char *b;
  size_t ntv, len;
  if (ckpt_get(c, "measure.peak_pressure", CKPT_F64, 1, &mr->peak_pressure, err) ||
      ckpt_get_alloc(c, "measure.time_value", CKPT_F64, (void **)&tv, &ntv, err))
    return -1;
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
  meas_table_free(&mr->table);
  meas_table_init(&mr->table);
  for (size_t k = 0; k < n && !rc; k++)
    meas_table_add(&mr->table, tv[k], text[3 * k], tv[n + k], text[3 * k + 1], text[3 * k + 2]);
  free(text);
  free(b);
  free(tv);
  return rc ? -1 : 0;
}

int restart_read(struct sim *s, struct run_outputs *o, const char *path, struct hv_error *err)
{
  struct ckpt_file c;
  if (ckpt_open(&c, path, err)) return -1;
  int rc = -1;
  char *cname = NULL;
  size_t len;
  const char *names[64];

  /* another hvsph may continue it, but the numbers then differ from either's own run */
  char *ver = NULL;
  if (ckpt_get_alloc(&c, "version", CKPT_BYTES, (void **)&ver, &len, err)) goto out;
  if (strcmp(ver, HVSPH_VERSION))
    hv_warn("%s was written by hvsph %s; this is hvsph %s: where the two compute differently "
            "the continued run matches neither's own run bit for bit (run_segments.csv "
            "records both)", path, ver, HVSPH_VERSION);
  free(ver);

  /* the same case: name, bodies (and their initial counts), materials */
  if (ckpt_get_alloc(&c, "case", CKPT_BYTES, (void **)&cname, &len, err)) goto out;
  if (strcmp(cname, s->case_name)) {
    mismatch(&c, err, "case name", cname, s->case_name);
    goto out;
  }
  for (int b = 0; b < s->nbody; b++) names[b] = s->body[b].name;
  if (check_names(&c, "bodies", "bodies", names, s->nbody, err)) goto out;
  int64_t counts[64];
  if (ckpt_get(&c, "bodies.count", CKPT_I64, (size_t)s->nbody, counts, err)) goto out;
  for (int b = 0; b < s->nbody; b++)
    if (counts[b] != (int64_t)s->body[b].count) {
      char a[64], bb[64], what[128];
      snprintf(a, sizeof a, "%lld", (long long)counts[b]);
      snprintf(bb, sizeof bb, "%zu", s->body[b].count);
      snprintf(what, sizeof what, "initial particle count of body '%s':", s->body[b].name);
      mismatch(&c, err, what, a, bb);
      goto out;
    }
  for (int m = 0; m < s->nmat; m++) names[m] = s->mat[m].name;
  if (check_names(&c, "materials", "materials", names, s->nmat, err)) goto out;

  /* clock, boundaries */
  double clock[3], ab[6];
  int64_t ints[3], abn;
  if (ckpt_get(&c, "clock", CKPT_F64, 3, clock, err) ||
      ckpt_get(&c, "step.n.solid", CKPT_I64, 3, ints, err) ||
      ckpt_get(&c, "absorbed", CKPT_F64, 6, ab, err) ||
      ckpt_get(&c, "absorbed.n", CKPT_I64, 1, &abn, err))
    goto out;
  if (ints[2] != s->p.solid || ints[1] < 0) {
    mismatch(&c, err, "solid fields", ints[2] ? "present" : "absent",
             s->p.solid ? "present" : "absent");
    goto out;
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

  /* the particles: as many as the checkpoint holds (absorbing faces remove some) */
  struct particles *p = &s->p;
  const size_t n = (size_t)ints[1];
  p->n_ghost = 0;
  if (n > p->n) particles_add(p, n - p->n);
  p->n = n;
  if (p->av && !ckpt_find(&c, "p.alpha")) {
    hv_error_set(err, HV_EXIT_INPUT, "%s: the run was made without sph.viscosity.switch, "
                 "whose per-particle alpha it does not hold: a run cannot take the switch up "
                 "when continued (start it again, or continue it without the switch)", path);
    goto out;
  }
  if (p->cracks && !ckpt_find(&c, "p.crack")) {
    hv_error_set(err, HV_EXIT_INPUT, "%s: the run was made without fracture.split: crack "
                 "or fracture.energy, whose per-particle crack normals it does not hold: a "
                 "run cannot take it up "
                 "when continued (start it again, or continue it without it)", path);
    goto out;
  }
  struct pfield f[HV_MAX_FIELDS];
  const int nf = particles_fields(p, f);
  for (int i = 0; i < nf; i++) {
    if (!(f[i].flags & PF_STATE)) continue;
    char rn[CKPT_NAME_LEN + 1];
    snprintf(rn, sizeof rn, "p.%s", f[i].name);
    if (ckpt_get_parts(&c, rn, ckpt_type_of(f[i].type), n, f[i].comp, f[i].ncomp, err))
      goto out;
  }
  for (size_t i = 0; i < n; i++)
    if (p->mat[i] < 0 || p->mat[i] >= s->nmat || p->body[i] < 0 || p->body[i] >= s->nbody) {
      hv_error_set(err, HV_EXIT_INPUT, "%s: particle %lld has material %d and body %d, "
                   "outside this case's %d materials and %d bodies", path, (long long)p->id[i],
                   p->mat[i], p->body[i], s->nmat, s->nbody);
      goto out;
    }

  if (read_outputs(&c, s, o, err) || read_measure(&c, o, err)) goto out;
  rc = 0;
out:
  free(cname);
  ckpt_close(&c);
  return rc;
}
