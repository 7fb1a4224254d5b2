/* snapshot.c — the ParaView collection (.pvd), generic CSV tables, and the
 * helpers shared by the snapshot writers (vtu.c, csv.c).
 *
 * A .pvd is a small XML index of (time [s], file) pairs that ParaView opens as
 * one time series; it is rewritten whole after every snapshot, so a run that
 * stops leaves a valid index of the snapshots written so far.
 */
#include "io/snapshot.h"

#include <ctype.h>
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/infile.h"
#include "core/utf8.h"
#include "io/atomic_file.h"
#include "io/io_internal.h"

void io_clean_text(char *dst, size_t len, const char *src, const char *fallback, int xml_comment)
{
  if (len == 0) return;
  if (!src || !*src) src = fallback ? fallback : "";
  size_t k = 0;
  const char *const src_end = src + strlen(src);
  for (const char *s = src; *s && k + 1 < len; s++) {
    unsigned char c = (unsigned char)*s;
    if (c >= 0x80) { /* XML (and UTF-8 CSV readers) refuse malformed UTF-8: keep only */
      /* whole, valid characters */
      const size_t n = hv_utf8_char((const unsigned char *)s, (size_t)(src_end - s));
      if (n && k + n < len) {
        memcpy(dst + k, s, n);
        k += n;
        s += n - 1;
        continue;
      }
      if (n) break; /* a valid character that does not fit: end here, not in its middle */
      c = '_';
    }
    if (c < 0x20 || c == 0x7f)
      c = '_';
    else if (xml_comment && c == '-' && k > 0 && dst[k - 1] == '-')
      c = '_';
    dst[k++] = (char)c;
  }
  /* An XML comment must not end in '-' either ("--->"). */
  if (xml_comment && k > 0 && dst[k - 1] == '-') dst[k - 1] = '_';
  dst[k] = '\0';
}

int io_put_materials(struct atomic_file *af, const struct snapshot_meta *meta, const char *prefix,
                     const char *suffix, int xml_comment, struct hv_error *err)
{
  if (!meta || !meta->material_names || meta->nmat <= 0) return 0;
  if (atomic_file_printf(af, err, "%smaterials", prefix)) return -1;
  for (int k = 0; k < meta->nmat; k++) {
    char name[256];
    io_clean_text(name, sizeof name, meta->material_names[k], "?", xml_comment);
    for (char *q = name; *q; q++)
      if (*q == ' ') *q = '_'; /* keep "index=name" pairs space-separated */
    if (atomic_file_printf(af, err, " %d=%s", k, name)) return -1;
  }
  return atomic_file_printf(af, err, "%s", suffix);
}

int io_put_xml_attr(struct atomic_file *af, const char *s, struct hv_error *err)
{
  for (; *s; s++) {
    const char *rep = NULL;
    switch (*s) {
    case '&': rep = "&amp;"; break;
    case '<': rep = "&lt;"; break;
    case '>': rep = "&gt;"; break;
    case '"': rep = "&quot;"; break;
    case '\'': rep = "&apos;"; break;
    default: break;
    }
    if (rep ? atomic_file_printf(af, err, "%s", rep) : atomic_file_write(af, s, 1, err)) return -1;
  }
  return 0;
}

int io_put_xml_prologue(struct atomic_file *af, const struct snapshot_meta *meta,
                        struct hv_error *err)
{
  char ver[256], name[1024];
  io_clean_text(ver, sizeof ver, meta ? meta->version : NULL, "unknown", 1);
  io_clean_text(name, sizeof name, meta ? meta->case_name : NULL, "unnamed", 1);
  return atomic_file_printf(af, err, "<?xml version=\"1.0\"?>\n<!-- hvsph %s case %s -->\n", ver,
                            name);
}

int io_take_geometry(struct particles *p, size_t n0, int axisym, const char *path,
                     struct hv_error *err)
{
  if (n0 > 0 && p->axisym != axisym)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "'%s' is %s, the particles read before it %s: one picture or "
                        "measurement cannot mix them",
                        path, axisym ? "axisymmetric" : "3D", p->axisym ? "axisymmetric" : "3D");
  for (size_t i = n0; axisym && i < p->n; i++)
    if (!(p->x[1][i] >= 0.0) || p->x[2][i] != 0.0)
      return hv_error_set(err, HV_EXIT_INPUT,
                          "'%s': particle %zu (id %lld) lies at y = %.17g m, z = %.17g m; an "
                          "axisymmetric snapshot holds rings at r = y >= 0, z = 0",
                          path, i - n0, (long long)p->id[i], p->x[1][i], p->x[2][i]);
  p->axisym = axisym;
  return 0;
}

const char *io_byte_order(void)
{
  const unsigned short one = 1;
  unsigned char first;
  memcpy(&first, &one, 1);
  return first ? "LittleEndian" : "BigEndian";
}

static int pvd_body(struct atomic_file *af, const double *times, const char *const *files, int n,
                    const struct snapshot_meta *meta, struct hv_error *err)
{
  if (io_put_xml_prologue(af, meta, err) ||
      atomic_file_printf(af, err,
                         "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"%s\">\n"
                         "  <Collection>\n",
                         io_byte_order()))
    return -1;
  for (int k = 0; k < n; k++) {
    if (atomic_file_printf(af, err, "    <DataSet timestep=\"%.17g\" group=\"\" part=\"0\" file=\"",
                           times[k]) ||
        io_put_xml_attr(af, files[k] ? files[k] : "", err) || atomic_file_printf(af, err, "\"/>\n"))
      return -1;
  }
  return atomic_file_printf(af, err, "  </Collection>\n</VTKFile>\n");
}

int io_write_pvd(const char *path, const double *times, const char *const *files, int n,
                 const struct snapshot_meta *meta, struct hv_error *err)
{
  struct atomic_file af;
  if (atomic_file_open(&af, path, err)) return -1;
  if (pvd_body(&af, times, files, n, meta, err)) {
    atomic_file_abort(&af);
    return -1;
  }
  return atomic_file_commit(&af, err);
}

/* Formats one table value: integral values with |v| < 2^53 as integers
 * (exact), anything else with %.17g (round-trip exact). */
static void table_value(char *buf, size_t len, double v)
{
  if (isfinite(v) && v == floor(v) && fabs(v) < 9007199254740992.0)
    snprintf(buf, len, "%.0f", v);
  else
    snprintf(buf, len, "%.17g", v);
}

static int table_comment(struct atomic_file *af, const char *comment, struct hv_error *err)
{
  const char *s = comment;
  while (*s) {
    size_t l = strcspn(s, "\n");
    if (atomic_file_printf(af, err, "# %.*s\n", (int)l, s)) return -1;
    s += l;
    if (*s == '\n') s++;
  }
  return 0;
}

static int table_body(struct atomic_file *af, const char *const *cols, int ncols,
                      const double *rows, int nrows, const char *comment, struct hv_error *err)
{
  if (comment && table_comment(af, comment, err)) return -1;
  for (int c = 0; c < ncols; c++)
    if (atomic_file_printf(af, err, "%s%s", c ? "," : "", cols[c])) return -1;
  if (atomic_file_printf(af, err, "\n")) return -1;
  for (int r = 0; r < nrows; r++) {
    for (int c = 0; c < ncols; c++) {
      char v[40];
      table_value(v, sizeof v, rows[(size_t)r * (size_t)ncols + (size_t)c]);
      if (atomic_file_printf(af, err, "%s%s", c ? "," : "", v)) return -1;
    }
    if (atomic_file_printf(af, err, "\n")) return -1;
  }
  return 0;
}

int io_write_table_csv(const char *path, const char *const *cols, int ncols, const double *rows,
                       int nrows, const char *comment, struct hv_error *err)
{
  for (int c = 0; c < ncols; c++)
    if (!cols[c] || !*cols[c] || strpbrk(cols[c], ",\"\r\n"))
      return hv_error_set(err, HV_EXIT_RUN, "cannot write '%s': bad column name '%s'", path,
                          cols[c] ? cols[c] : "(null)");
  struct atomic_file af;
  if (atomic_file_open(&af, path, err)) return -1;
  if (table_body(&af, cols, ncols, rows, nrows, comment, err)) {
    atomic_file_abort(&af);
    return -1;
  }
  return atomic_file_commit(&af, err);
}

int io_read_table_column(const char *path, const char *col, double **vals, struct hv_error *err)
{
  *vals = NULL;
  FILE *f = hv_open_input(path, NULL, 0, NULL, err); /* a FIFO would block the open */
  if (!f) return -1;
  char line[8192];
  int which = -1, n = 0;
  errno = 0;
  while (fgets(line, sizeof line, f)) {
    if (line[0] == '#') continue;
    line[strcspn(line, "\r\n")] = 0;
    if (which < 0) { /* the header */
      int c = 0;
      for (char *save = NULL, *t = strtok_r(line, ",", &save); t;
           t = strtok_r(NULL, ",", &save), c++)
        if (!strcmp(t, col)) which = c;
      if (which < 0) {
        fclose(f);
        return hv_error_set(err, HV_EXIT_INPUT, "%s: no column '%s'", path, col);
      }
      continue;
    }
    const char *s = line;
    for (int c = 0; c < which && s; c++) {
      s = strchr(s, ',');
      if (s) s++;
    }
    if (!s || !*s) continue;
    *vals = hv_realloc(*vals, (size_t)(n + 1) * sizeof **vals, "table column");
    (*vals)[n++] = strtod(s, NULL);
  }
  const int e = ferror(f) ? (errno ? errno : EIO) : 0;
  fclose(f);
  if (e || which < 0) { /* unreadable, or no header line: not "no rows" */
    free(*vals);
    *vals = NULL;
    if (e) return hv_error_set(err, HV_EXIT_INPUT, "cannot read '%s': %s", path, strerror(e));
    return hv_error_set(err, HV_EXIT_INPUT, "%s: no header line (no column '%s')", path, col);
  }
  return n;
}

static int int_cmp(const void *a, const void *b)
{
  const int x = *(const int *)a, y = *(const int *)b;
  return (x > y) - (x < y);
}

int io_list_snapshots(const char *dir, const char *ext, int **nums)
{
  *nums = NULL;
  DIR *d = opendir(dir);
  if (!d) return -1;
  char want[32];
  snprintf(want, sizeof want, ".%s", ext);
  int n = 0;
  struct dirent *e;
  while ((e = readdir(d))) {
    int k, len = 0;
    if (sscanf(e->d_name, "particles_%d%n", &k, &len) == 1 && k >= 0 &&
        !strcmp(e->d_name + len, want)) {
      *nums = hv_realloc(*nums, (size_t)(n + 1) * sizeof **nums, "snapshot list");
      (*nums)[n++] = k;
    }
  }
  closedir(d);
  if (n) qsort(*nums, (size_t)n, sizeof **nums, int_cmp);
  return n;
}

const char *io_list_readable_snapshots(const char *dir, int **nums, int *n)
{
  *n = io_list_snapshots(dir, "csv", nums);
  if (*n != 0) return "csv";
  free(*nums);
  *n = io_list_snapshots(dir, "vtu", nums);
  return "vtu";
}

int io_xml_attr(const char *s, const char *end, const char *name, char *buf, size_t len)
{
  static const struct {
    const char *ent;
    char c;
  } ents[] = {{"amp;", '&'}, {"lt;", '<'}, {"gt;", '>'}, {"quot;", '"'}, {"apos;", '\''}};
  const size_t nl = strlen(name);
  for (const char *q = s + 1; q + nl + 2 <= end; q++) {
    if (!isspace((unsigned char)q[-1]) || strncmp(q, name, nl) || q[nl] != '=' ||
        (q[nl + 1] != '"' && q[nl + 1] != '\''))
      continue;
    const char quote = q[nl + 1];
    const char *v = q + nl + 2;
    size_t k = 0;
    while (v < end && *v != quote) {
      char c = *v++;
      if (c == '&') {
        size_t e = 0;
        while (e < sizeof ents / sizeof ents[0] && ((size_t)(end - v) < strlen(ents[e].ent) ||
                                                    strncmp(v, ents[e].ent, strlen(ents[e].ent))))
          e++;
        if (e == sizeof ents / sizeof ents[0]) return -1;
        c = ents[e].c;
        v += strlen(ents[e].ent);
      }
      if (k + 1 >= len) return -1;
      buf[k++] = c;
    }
    if (v >= end) return -1;
    buf[k] = '\0';
    return 0;
  }
  return -1;
}

int io_read_pvd(const char *path, double **times, char ***files, struct hv_error *err)
{
  *times = NULL;
  *files = NULL;
  FILE *f = hv_open_input(path, NULL, 0, NULL, err); /* a FIFO would block the open */
  if (!f) return -1;
  char *text = NULL;
  size_t len = 0, cap = 0, got;
  errno = 0;
  do {
    if (cap - len < 4096) {
      cap = 2 * cap + 65536;
      text = hv_realloc(text, cap, "run.pvd");
    }
    got = fread(text + len, 1, cap - len - 1, f);
    len += got;
  } while (got > 0);
  const int e = ferror(f) ? (errno ? errno : EIO) : 0;
  fclose(f);
  text[len] = '\0';
  int n = 0, rc = 0;
  /* searched for from the root element on: the comment before it holds the case's name,
     which may contain "<DataSet" (its text is one line, cleaned of control characters, so
     it cannot hold "\n<VTKFile"); a file of another writer is read from its start */
  const char *root = strstr(text, "\n<VTKFile");
  const char *coll = memchr(text, '\0', len) ? NULL : strstr(root ? root : text, "<Collection");
  if (e)
    rc = hv_error_set(err, HV_EXIT_INPUT, "cannot read '%s': %s", path, strerror(e));
  else if (!coll)
    rc = hv_error_set(err, HV_EXIT_INPUT,
                      "%s: not a ParaView collection (no <Collection> "
                      "element)",
                      path);
  for (const char *q = coll; !rc && (q = strstr(q, "<DataSet")) != NULL; n++) {
    const char *end = strchr(q, '>');
    char name[4096], ts[128], *tend;
    if (!end || io_xml_attr(q, end, "file", name, sizeof name) ||
        io_xml_attr(q, end, "timestep", ts, sizeof ts)) {
      rc = hv_error_set(err, HV_EXIT_INPUT,
                        "%s: DataSet entry %d has no readable file and "
                        "timestep",
                        path, n + 1);
      break;
    }
    const double t = strtod(ts, &tend);
    if (tend == ts || *tend) {
      rc = hv_error_set(err, HV_EXIT_INPUT,
                        "%s: DataSet entry %d: timestep '%s' is not a "
                        "number",
                        path, n + 1, ts);
      break;
    }
    *times = hv_realloc(*times, (size_t)(n + 1) * sizeof **times, "run.pvd");
    *files = hv_realloc(*files, (size_t)(n + 1) * sizeof **files, "run.pvd");
    (*times)[n] = t;
    (*files)[n] = hv_malloc(strlen(name) + 1, "run.pvd");
    memcpy((*files)[n], name, strlen(name) + 1);
    q = end;
  }
  free(text);
  if (rc) {
    for (int k = 0; k < n; k++) free((*files)[k]);
    free(*files);
    free(*times);
    *files = NULL;
    *times = NULL;
    return -1;
  }
  return n;
}

int io_snapshot_in_run(int k, double t, const double *times, int nt)
{
  return nt < 0 || (k >= 0 && k < nt && fabs(t - times[k]) <= 1e-9 * fmax(fabs(t), 1e-30));
}

int io_run_snapshots(const char *dir, const char *prefer, struct io_run_snapshot **list,
                     struct hv_error *err)
{
  *list = NULL;
  const char *other = strcmp(prefer, "vtu") ? "vtu" : "csv";
  prefer = strcmp(prefer, "vtu") ? "csv" : "vtu";
  char path[4400];
  int *nums = NULL, n;
  snprintf(path, sizeof path, "%s/run.pvd", dir);
  if (access(path, F_OK) == 0) {
    double *times;
    char **files;
    n = io_read_pvd(path, &times, &files, err);
    if (n < 0) return -1;
    nums = hv_malloc((size_t)(n ? n : 1) * sizeof *nums, "snapshot list");
    int bad = -1;
    for (int k = 0; k < n; k++) { /* particles_NNNNN.vtu exactly, as the run writes it */
      char again[64];
      int len = 0;
      nums[k] = -1;
      if (sscanf(files[k], "particles_%d%n", &nums[k], &len) == 1 && nums[k] >= 0)
        snprintf(again, sizeof again, "particles_%05d.vtu", nums[k]);
      else
        again[0] = '\0';
      if (strcmp(again, files[k]) && bad < 0) bad = k;
    }
    if (bad >= 0)
      hv_error_set(err, HV_EXIT_INPUT,
                   "%s: entry %d names '%s', not a particles_NNNNN.vtu "
                   "snapshot of the folder",
                   path, bad + 1, files[bad]);
    for (int k = 0; k < n; k++) free(files[k]);
    free(files);
    free(times);
    if (bad >= 0) {
      free(nums);
      return -1;
    }
  } else {
    n = io_list_snapshots(dir, prefer, &nums);
    if (n == 0) {
      free(nums);
      n = io_list_snapshots(dir, other, &nums);
    }
    if (n < 0)
      return hv_error_set(err, HV_EXIT_INPUT, "cannot open the run folder '%s': %s", dir,
                          strerror(errno));
  }
  *list = hv_malloc((size_t)(n ? n : 1) * sizeof **list, "snapshot list");
  for (int k = 0; k < n; k++) {
    (*list)[k].num = nums[k];
    (*list)[k].ext = prefer;
    snprintf(path, sizeof path, "%s/particles_%05d.%s", dir, nums[k], prefer);
    if (access(path, F_OK) == 0) continue;
    snprintf(path, sizeof path, "%s/particles_%05d.%s", dir, nums[k], other);
    if (access(path, F_OK) == 0) (*list)[k].ext = other;
  }
  free(nums);
  return n;
}
