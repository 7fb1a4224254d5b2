/* config_used.c — what the program read of the case file, reported afterwards.
 *
 * cfg_check_unused() lists every key nothing marked used (a getter, cfg_mark_used,
 * cfg_graft), with its line and a "did you mean" hint from the used siblings and the
 * recorded paths (defaults included: "yield" asked for, "yeild" written).
 * cfg_write_used() rebuilds the records of config_get.c as nested YAML, the file
 * used_parameters.yaml: SI values with unit comments, defaults marked.
 */
#include <ctype.h>
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "config/config_internal.h"
#include "core/utf8.h"

/* ---------------------------------------------------------------- unknown keys */

/* n or a node below it was read. */
static int node_any_used(const struct cfg_node *n)
{
  if (n->used) return 1;
  for (int i = 0; i < n->n; i++)
    if (node_any_used(n->items[i])) return 1;
  return 0;
}

/* Optimal string alignment distance (edits and adjacent swaps), capped at 9. */
int cfg_edit_distance(const char *a, size_t la, const char *b, size_t lb)
{
  enum { MAXL = 64 };
  if (la >= MAXL || lb >= MAXL) return 9;
  int d[MAXL][MAXL];
  for (size_t i = 0; i <= la; i++) d[i][0] = (int)i;
  for (size_t j = 0; j <= lb; j++) d[0][j] = (int)j;
  for (size_t i = 1; i <= la; i++)
    for (size_t j = 1; j <= lb; j++) {
      int cost = a[i - 1] != b[j - 1];
      int v = d[i - 1][j - 1] + cost;
      if (d[i - 1][j] + 1 < v) v = d[i - 1][j] + 1;
      if (d[i][j - 1] + 1 < v) v = d[i][j - 1] + 1;
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] && d[i - 2][j - 2] + 1 < v)
        v = d[i - 2][j - 2] + 1;
      d[i][j] = v;
    }
  return d[la][lb];
}

static void consider(const char *cand, size_t len, const char *key, const char **best, size_t *blen,
                     int *bdist)
{
  int dist = cfg_edit_distance(cand, len, key, strlen(key));
  if (dist <= 2 && dist < *bdist && dist < (int)strlen(key)) {
    *best = cand;
    *blen = len;
    *bdist = dist;
  }
}

/* A key the program asked for near `key` in mapping m at `parent`: used siblings and
 * recorded paths (defaults: "yield" asked for, "yeild" written). */
static int suggest(const struct cfg *c, const struct cfg_node *m, const char *parent,
                   const char *key, char *out, size_t outlen)
{
  const char *best = NULL;
  size_t blen = 0, plen = strlen(parent);
  int bdist = 3;
  for (int i = 0; i < m->n; i++)
    if (node_any_used(m->items[i]))
      consider(m->keys[i], strlen(m->keys[i]), key, &best, &blen, &bdist);
  for (int i = 0; i < c->nrec; i++) {
    const char *p = c->rec[i].path;
    if (plen && (strncmp(p, parent, plen) || p[plen] != '.')) continue;
    if (plen) p += plen + 1;
    consider(p, strcspn(p, ".["), key, &best, &blen, &bdist);
  }
  if (best) snprintf(out, outlen, " (did you mean '%.*s'?)", (int)blen, best);
  return best != NULL;
}

struct unused_list {
  char text[1900]; /* the messages, one per line */
  size_t len;
  int count, dropped;
};

static void unused_add(struct unused_list *u, const char *line)
{
  size_t n = strlen(line);
  u->count++;
  if (u->len + n + 2 > sizeof u->text) {
    u->dropped++;
    return;
  }
  if (u->len) u->text[u->len++] = '\n';
  memcpy(u->text + u->len, line, n + 1);
  u->len += n;
}

/* The program asked for a key below `path` (a recorded path starts with it). */
static int path_asked(const struct cfg *c, const char *path)
{
  size_t len = strlen(path);
  for (int i = 0; i < c->nrec; i++) {
    const char *p = c->rec[i].path;
    if (!strncmp(p, path, len) && (p[len] == '.' || p[len] == '[')) return 1;
  }
  return 0;
}

/* Reports every unused key below n (whose own path is `path`, "" for the root). */
static void find_unused(const struct cfg *c, const struct cfg_node *n, const char *path,
                        struct unused_list *u)
{
  for (int i = 0; i < n->n; i++) {
    const struct cfg_node *ch = n->items[i];
    char sub[1024];
    if (n->kind == CFG_MAP)
      snprintf(sub, sizeof sub, "%s%s%s", path, *path ? "." : "", n->keys[i]);
    else
      snprintf(sub, sizeof sub, "%s[%d]", path, i);
    if (node_any_used(ch) || (ch->kind != CFG_SCALAR && path_asked(c, sub))) {
      /* a mapping the program asked into (its keys all defaulted, say `sph: {foo: 1}`)
         is known: report what is unknown inside it, not the mapping */
      if (ch->kind != CFG_SCALAR) find_unused(c, ch, sub, u);
      continue;
    }
    char where[512], hint[160] = "", line[1800];
    if (ch->kind == CFG_SCALAR && path_asked(c, sub)) {
      /* a known key whose value should be a mapping: `output:` left empty, or
         `viscosity: 1` where alpha, beta... were asked for (not "unknown key") */
      const int null = cfg_scalar_is_null(ch);
      snprintf(line, sizeof line, "%s: %s: %s%.200s%s",
               cfg_where_line(c, ch->file, ch->line, where, sizeof where), sub,
               null ? "the key has no value (its keys must be indented below it)"
                    : "expected a mapping of keys below it, found '",
               null ? "" : ch->text, null ? "" : "'");
      unused_add(u, line);
      continue;
    }
    if (n->kind == CFG_MAP) suggest(c, n, path, n->keys[i], hint, sizeof hint);
    snprintf(line, sizeof line, "%s: unknown %s '%s'%s",
             cfg_where_line(c, ch->file, ch->line, where, sizeof where),
             n->kind == CFG_MAP ? "key" : "entry", sub, hint);
    unused_add(u, line);
  }
}

int cfg_check_unused(struct cfg *c, struct hv_error *err)
{
  struct unused_list u = {.len = 0};
  find_unused(c, c->root, "", &u);
  if (!u.count) return 0;
  if (u.dropped)
    return hv_error_set(err, HV_EXIT_INPUT, "%s\n... and %d more unknown keys", u.text, u.dropped);
  return hv_error_set(err, HV_EXIT_INPUT, "%s", u.text);
}

/* ---------------------------------------------------------------- used_parameters.yaml */

/* Adds record r to the output tree t; a path that clashes with earlier ones is skipped. */
static void used_insert(struct cfg_node *t, const struct cfg_record *r)
{
  struct path_comp comp[CFG_MAX_DEPTH];
  int nc = cfg_path_parse(r->path, comp, CFG_MAX_DEPTH);
  struct cfg_node *p = t;
  for (int k = 0; k < nc; k++) {
    enum cfg_kind want = k == nc - 1 ? CFG_SCALAR : comp[k + 1].key ? CFG_MAP : CFG_SEQ;
    struct cfg_node *ch;
    if (comp[k].key) {
      if (p->kind != CFG_MAP) return;
      int i = cfg_node_find(p, comp[k].key, comp[k].klen);
      if (i < 0) {
        cfg_node_add(p, cfg_strndup(comp[k].key, comp[k].klen), cfg_node_new(want, 0));
        i = p->n - 1;
      }
      ch = p->items[i];
    } else {
      if (p->kind != CFG_SEQ) return;
      while (p->n <= comp[k].index)
        cfg_node_add(p, NULL, cfg_node_new(CFG_MAP, 0)); /* "{}" if unfilled */
      ch = p->items[comp[k].index];
    }
    if (ch->kind != CFG_SCALAR && !ch->n && !ch->rec) ch->kind = want; /* still empty: take it */
    if (ch->kind != want || (want == CFG_SCALAR && ch->rec)) return;
    p = ch;
  }
  if (nc > 0) p->rec = r;
}

struct writer {
  FILE *f;
  int err_no; /* errno of the first failed write, 0 while none */
};

static void wr(struct writer *w, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

static void wr(struct writer *w, const char *fmt, ...)
{
  if (w->err_no) return;
  va_list ap;
  va_start(ap, fmt);
  errno = 0;
  if (vfprintf(w->f, fmt, ap) < 0) w->err_no = errno ? errno : EIO;
  va_end(ap);
}

static void write_key(struct writer *w, const char *key)
{
  int plain = key[0] && key[0] != '-';
  for (const char *p = key; *p && plain; p++)
    plain = isalnum((unsigned char)*p) || *p == '_' || *p == '-';
  if (plain) {
    wr(w, "%s:", key);
    return;
  }
  char *q = cfg_yaml_quote(key);
  wr(w, "%s:", q);
  free(q);
}

/* The rest of a line after "key:" or "-" for a leaf: value and comment. */
static void write_leaf(struct writer *w, const struct cfg_node *n)
{
  if (n->kind != CFG_SCALAR) {
    wr(w, " %s\n", n->kind == CFG_MAP ? "{}" : "[]");
    return;
  }
  const struct cfg_record *r = n->rec;
  wr(w, " %s", r->value);
  if (r->unit[0] || r->is_default)
    wr(w, "  # %s%s%s", r->unit, r->unit[0] && r->is_default ? ", " : "",
       r->is_default ? "default" : "");
  wr(w, "\n");
}

/* Writes the children of n; the first line unindented if it follows "- ". */
static void write_tree(struct writer *w, const struct cfg_node *n, int indent, int inline_first)
{
  for (int i = 0; i < n->n; i++) {
    const struct cfg_node *ch = n->items[i];
    wr(w, "%*s", (i == 0 && inline_first) ? 0 : indent, "");
    if (n->kind == CFG_MAP)
      write_key(w, n->keys[i]);
    else
      wr(w, "-");
    if (ch->kind == CFG_SCALAR || ch->n == 0) {
      write_leaf(w, ch);
    } else if (n->kind == CFG_SEQ && ch->kind == CFG_MAP) {
      wr(w, " ");
      write_tree(w, ch, indent + 2, 1);
    } else {
      wr(w, "\n");
      write_tree(w, ch, indent + 2, 0);
    }
  }
}

static void write_header(struct writer *w, const struct cfg *c, const char *version)
{
  char date[64] = "unknown";
  time_t now = time(NULL);
  struct tm tm;
  if (now != (time_t)-1 && gmtime_r(&now, &tm))
    strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", &tm);
  wr(w, CFG_USED_HEADER "%s\n", version ? version : "(unknown version)");
  /* the name in a comment: control characters and bytes that are not UTF-8 as \xNN, so
     that a line break or a Latin-1 file name cannot break the file */
  wr(w, "# case file: ");
  const unsigned char *s = (const unsigned char *)c->name;
  size_t len = strlen(c->name);
  for (size_t i = 0; i < len;) {
    size_t ok = i + hv_utf8_valid_prefix(s + i, len - i);
    for (; i < ok; i++)
      if (s[i] < 0x20 || s[i] == 0x7f)
        wr(w, "\\x%02x", s[i]);
      else
        wr(w, "%c", s[i]);
    if (i < len) wr(w, "\\x%02x", s[i++]);
  }
  wr(w, "\n# written: %s\n", date);
  wr(w, "# Values are in SI units (the unit is in the comment); \"default\" marks values\n"
        "# the case file did not set. This file can be run as a case file.\n");
}

/* Writes the used parameters to an open file; returns 0 or an errno value. */
static int write_used_to(struct cfg *c, FILE *f, const char *version)
{
  struct writer w = {f, 0};
  struct cfg_node *t = cfg_node_new(CFG_MAP, 0);
  for (int i = 0; i < c->nrec; i++) used_insert(t, &c->rec[i]);
  write_header(&w, c, version);
  write_tree(&w, t, 0, 0);
  cfg_node_free(t);
  return w.err_no;
}

int cfg_write_used(struct cfg *c, const char *path, const char *version, struct hv_error *err)
{
  /* ".<name>.tmp.<pid>" beside it, as every output file's temporary (src/io/atomic_file.c):
     hvsph restart removes such a file that a killed writer left */
  char tmp[4096];
  const char *slash = strrchr(path, '/');
  const int dirlen = slash ? (int)(slash - path + 1) : 0;
  if (snprintf(tmp, sizeof tmp, "%.*s.%s.tmp.%ld", dirlen, path, path + dirlen, (long)getpid()) >=
      (int)sizeof tmp)
    return hv_error_set(err, HV_EXIT_INPUT, "cannot write '%s': path too long", path);
  FILE *f = fopen(tmp, "w");
  if (!f) return hv_error_set(err, HV_EXIT_INPUT, "cannot write '%s': %s", path, strerror(errno));
  int e = write_used_to(c, f, version);
  if (!e && fflush(f)) e = errno;
  if (!e && fsync(fileno(f))) e = errno;
  if (fclose(f) && !e) e = errno;
  if (!e && rename(tmp, path)) e = errno;
  if (e) {
    remove(tmp);
    return hv_error_set(err, HV_EXIT_INPUT, "cannot write '%s': %s", path, strerror(e));
  }
  return 0;
}
