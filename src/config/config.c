/* config.c — the case file: YAML read with libfyaml into a tree of our own.
 *
 * The YAML event stream (libfyaml's parser) is turned into cfg_node trees:
 * mappings (ordered keys), sequences and scalars, each with the 1-based line that
 * names it (a mapping value carries its key's line) and a `used` flag. Aliases are
 * expanded by copying the anchored subtree. libfyaml's diagnostics are collected,
 * never printed: a syntax error becomes one message "case.yaml:3:7: YAML syntax
 * error: <reason>".
 *
 * Getters look a path up ("bodies[0].velocity"), convert with units_parse(), check
 * ranges, mark the node used and append a record (path, SI value as YAML text,
 * SI unit, default or not, line). The records drive cfg_write_used() (the file
 * used_parameters.yaml, rebuilt as nested YAML) and the "did you mean" hints of
 * cfg_check_unused(). Values set with --set carry the line CFG_LINE_SET and are
 * reported as "--set" in messages.
 */
#include "config/config.h"

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <time.h>
#include <unistd.h>

#include <libfyaml.h>

#define CFG_LINE_SET (-1) /* line of nodes created by --set */
#define CFG_MAX_DEPTH 64  /* components in a path */

enum cfg_kind { CFG_SCALAR, CFG_SEQ, CFG_MAP };

struct cfg_record;

struct cfg_node {
  enum cfg_kind kind;
  int line;                     /* 1-based line naming the node (key line for mapping values);
                                   CFG_LINE_SET for --set; 0 if none */
  int vline;                    /* 1-based line where the value itself starts */
  const char *file;             /* file the node came from if not the document's own (a graft,
                                   cfg_graft); owned by struct cfg (files); NULL otherwise */
  char *text;                   /* scalar text, escapes resolved (NULL for SEQ/MAP) */
  int plain;                    /* scalar was unquoted (so "" means null) */
  int used;                     /* a getter or cfg_mark_used read it */
  int n, cap;                   /* children */
  struct cfg_node **items;      /* values (MAP) or entries (SEQ) */
  char **keys;                  /* MAP keys, parallel to items */
  const struct cfg_record *rec; /* cfg_write_used's tree only: the record of a leaf */
};

struct cfg_record {
  char *path;
  char *value;      /* YAML text of the value, in SI */
  const char *unit; /* SI symbol, "" for none (static string) */
  int is_default;
  int line; /* source line of the value (0 default, -1 --set) */
};

struct cfg {
  char *name;            /* file name used in messages */
  struct cfg_node *root; /* always a mapping */
  struct cfg_record *rec;
  int nrec, caprec;
  char **strs; /* strings handed out by cfg_get_string for defaults */
  int nstrs, capstrs;
  char **files; /* names of the files grafted nodes came from (cfg_graft) */
  int nfiles, capfiles;
};

/* One path component: a key (key != NULL) or a sequence index. */
struct path_comp {
  const char *start; /* where the component starts in the path text */
  const char *key;
  size_t klen;
  int index;
};

/* ---------------------------------------------------------------- nodes */

static char *xstrndup(const char *s, size_t n)
{
  char *d = hv_malloc(n + 1, "config string");
  memcpy(d, s, n);
  d[n] = '\0';
  return d;
}

static char *xstrdup(const char *s) { return xstrndup(s, strlen(s)); }

static struct cfg_node *node_new(enum cfg_kind kind, int line)
{
  struct cfg_node *n = hv_calloc(1, sizeof *n, "config node");
  n->kind = kind;
  n->line = n->vline = line;
  return n;
}

static void node_free(struct cfg_node *n)
{
  if (!n) return;
  for (int i = 0; i < n->n; i++) {
    node_free(n->items[i]);
    if (n->keys) free(n->keys[i]);
  }
  free(n->items);
  free(n->keys);
  free(n->text);
  free(n);
}

/* Appends a child (key NULL for sequences); takes ownership of key. */
static void node_add(struct cfg_node *p, char *key, struct cfg_node *child)
{
  if (p->n == p->cap) {
    p->cap = p->cap ? 2 * p->cap : 8;
    p->items = hv_realloc(p->items, (size_t)p->cap * sizeof *p->items, "config children");
    if (p->kind == CFG_MAP)
      p->keys = hv_realloc(p->keys, (size_t)p->cap * sizeof *p->keys, "config keys");
  }
  p->items[p->n] = child;
  if (p->kind == CFG_MAP) p->keys[p->n] = key;
  p->n++;
}

static int node_find(const struct cfg_node *p, const char *key, size_t klen)
{
  if (p->kind != CFG_MAP) return -1;
  for (int i = 0; i < p->n; i++)
    if (strlen(p->keys[i]) == klen && !memcmp(p->keys[i], key, klen)) return i;
  return -1;
}

static struct cfg_node *node_copy(const struct cfg_node *s)
{
  struct cfg_node *d = node_new(s->kind, s->line);
  d->vline = s->vline;
  d->plain = s->plain;
  d->file = s->file;
  if (s->text) d->text = xstrdup(s->text);
  for (int i = 0; i < s->n; i++)
    node_add(d, s->kind == CFG_MAP ? xstrdup(s->keys[i]) : NULL, node_copy(s->items[i]));
  return d;
}

static void node_set_lines(struct cfg_node *n, int line)
{
  n->line = n->vline = line;
  for (int i = 0; i < n->n; i++) node_set_lines(n->items[i], line);
}

static void node_mark(struct cfg_node *n)
{
  n->used = 1;
  for (int i = 0; i < n->n; i++) node_mark(n->items[i]);
}

static int node_any_used(const struct cfg_node *n)
{
  if (n->used) return 1;
  for (int i = 0; i < n->n; i++)
    if (node_any_used(n->items[i])) return 1;
  return 0;
}

static const char *kind_name(enum cfg_kind k)
{
  return k == CFG_MAP ? "a mapping" : k == CFG_SEQ ? "a sequence" : "a single value";
}

/* ---------------------------------------------------------------- YAML → tree */

struct anchor {
  char *name;
  const struct cfg_node *node;
};

struct builder {
  struct fy_parser *fyp;
  struct fy_diag *diag;
  const char *name; /* file name for messages */
  int positions;    /* put line:column into syntax errors (not for --set values) */
  struct hv_error *err;
  struct anchor *anchors;
  int nanchors, capanchors;
  char diagtext[512]; /* last diagnostic line (fallback if none collected) */
};

static void diag_output(struct fy_diag *diag, void *user, const char *buf, size_t len)
{
  (void)diag;
  struct builder *b = user;
  while (len && (buf[len - 1] == '\n' || buf[len - 1] == '\r')) len--;
  if (len >= sizeof b->diagtext) len = sizeof b->diagtext - 1;
  memcpy(b->diagtext, buf, len);
  b->diagtext[len] = '\0';
}

static int builder_init(struct builder *b, const char *name, struct hv_error *err)
{
  memset(b, 0, sizeof *b);
  b->name = name;
  b->err = err;
  struct fy_diag_cfg dc;
  fy_diag_cfg_default(&dc);
  dc.fp = NULL;
  dc.output_fn = diag_output;
  dc.user = b;
  dc.colorize = false;
  dc.level = FYET_ERROR;
  b->diag = fy_diag_create(&dc);
  if (!b->diag)
    return hv_error_set(err, HV_EXIT_INPUT, "%s: cannot create the YAML diagnostics", name);
  fy_diag_set_collect_errors(b->diag, true);
  struct fy_parse_cfg pc = {.flags = FYPCF_QUIET | FYPCF_COLLECT_DIAG, .diag = b->diag};
  b->fyp = fy_parser_create(&pc);
  if (!b->fyp) {
    fy_diag_destroy(b->diag);
    return hv_error_set(err, HV_EXIT_INPUT, "%s: cannot create the YAML parser", name);
  }
  return 0;
}

static void builder_done(struct builder *b)
{
  for (int i = 0; i < b->nanchors; i++) free(b->anchors[i].name);
  free(b->anchors);
  if (b->fyp) fy_parser_destroy(b->fyp);
  if (b->diag) fy_diag_destroy(b->diag);
}

/* The first collected libfyaml error as "file:line:col: YAML syntax error: reason". */
static int syntax_error(struct builder *b)
{
  void *it = NULL;
  struct fy_diag_error *de;
  while ((de = fy_diag_errors_iterate(b->diag, &it)) != NULL)
    if (de->type >= FYET_ERROR && b->positions)
      return hv_error_set(b->err, HV_EXIT_INPUT, "%s:%d:%d: YAML syntax error: %s", b->name,
                          de->line, de->column, de->msg ? de->msg : "(no reason given)");
    else if (de->type >= FYET_ERROR)
      return hv_error_set(b->err, HV_EXIT_INPUT, "%s: YAML syntax error: %s", b->name,
                          de->msg ? de->msg : "(no reason given)");
  return hv_error_set(b->err, HV_EXIT_INPUT, "%s: YAML syntax error: %s", b->name,
                      b->diagtext[0] ? b->diagtext : "unexpected end of input");
}

static struct fy_event *next_event(struct builder *b)
{
  struct fy_event *e = fy_parser_parse(b->fyp);
  if (!e) syntax_error(b);
  return e;
}

static int event_line(struct fy_event *e)
{
  const struct fy_mark *m = fy_event_start_mark(e);
  return m ? m->line + 1 : 0;
}

static char *token_text(struct fy_token *t)
{
  size_t len = 0;
  const char *s = t ? fy_token_get_text(t, &len) : NULL;
  return s ? xstrndup(s, len) : xstrdup("");
}

static void anchor_add(struct builder *b, struct fy_token *t, const struct cfg_node *n)
{
  if (!t) return;
  if (b->nanchors == b->capanchors) {
    b->capanchors = b->capanchors ? 2 * b->capanchors : 8;
    b->anchors = hv_realloc(b->anchors, (size_t)b->capanchors * sizeof *b->anchors, "anchors");
  }
  b->anchors[b->nanchors++] = (struct anchor){token_text(t), n};
}

static struct cfg_node *build_node(struct builder *b, struct fy_event *e);

/* Reads key/value pairs up to MAPPING_END into map m. */
static int build_map_body(struct builder *b, struct cfg_node *m)
{
  for (;;) {
    struct fy_event *e = next_event(b);
    if (!e) return -1;
    if (e->type == FYET_MAPPING_END) {
      fy_parser_event_free(b->fyp, e);
      return 0;
    }
    int kline = event_line(e);
    if (e->type != FYET_SCALAR) {
      fy_parser_event_free(b->fyp, e);
      return hv_error_set(b->err, HV_EXIT_INPUT, "%s:%d: mapping keys must be plain names", b->name,
                          kline);
    }
    char *key = token_text(e->scalar.value);
    fy_parser_event_free(b->fyp, e);
    int dup = node_find(m, key, strlen(key));
    if (dup >= 0) {
      hv_error_set(b->err, HV_EXIT_INPUT, "%s:%d: duplicate key '%s' (first at line %d)", b->name,
                   kline, key, m->items[dup]->line);
      free(key);
      return -1;
    }
    struct fy_event *v = next_event(b);
    struct cfg_node *child = v ? build_node(b, v) : NULL;
    if (!child) {
      free(key);
      return -1;
    }
    child->line = kline;
    if (child->vline <= 0) child->vline = kline; /* empty values have no position */
    node_add(m, key, child);
  }
}

static int build_seq_body(struct builder *b, struct cfg_node *s)
{
  for (;;) {
    struct fy_event *e = next_event(b);
    if (!e) return -1;
    if (e->type == FYET_SEQUENCE_END) {
      fy_parser_event_free(b->fyp, e);
      return 0;
    }
    struct cfg_node *child = build_node(b, e);
    if (!child) return -1;
    if (child->vline <= 0) child->line = child->vline = s->vline;
    node_add(s, NULL, child);
  }
}

static struct cfg_node *build_alias(struct builder *b, struct fy_event *e, int line)
{
  char *name = token_text(e->alias.anchor);
  fy_parser_event_free(b->fyp, e);
  for (int i = b->nanchors - 1; i >= 0; i--) {
    if (strcmp(b->anchors[i].name, name)) continue;
    free(name);
    struct cfg_node *n = node_copy(b->anchors[i].node);
    n->line = n->vline = line;
    return n;
  }
  hv_error_set(b->err, HV_EXIT_INPUT, "%s:%d: unknown alias '*%s'", b->name, line, name);
  free(name);
  return NULL;
}

/* Builds the node starting with event e (consumed). NULL with b->err set on error. */
static struct cfg_node *build_node(struct builder *b, struct fy_event *e)
{
  int line = event_line(e);
  struct cfg_node *n;
  int rc = 0;
  switch (e->type) {
  case FYET_SCALAR:
    n = node_new(CFG_SCALAR, line);
    n->text = token_text(e->scalar.value);
    n->plain = fy_token_scalar_style(e->scalar.value) == FYSS_PLAIN;
    anchor_add(b, e->scalar.anchor, n);
    fy_parser_event_free(b->fyp, e);
    return n;
  case FYET_MAPPING_START:
  case FYET_SEQUENCE_START: {
    int map = e->type == FYET_MAPPING_START;
    n = node_new(map ? CFG_MAP : CFG_SEQ, line);
    anchor_add(b, map ? e->mapping_start.anchor : e->sequence_start.anchor, n);
    fy_parser_event_free(b->fyp, e);
    rc = map ? build_map_body(b, n) : build_seq_body(b, n);
    if (rc) {
      node_free(n); /* the anchor table may point into n: no more aliases are read */
      return NULL;
    }
    return n;
  }
  case FYET_ALIAS:
    return build_alias(b, e, line);
  default:
    fy_parser_event_free(b->fyp, e);
    hv_error_set(b->err, HV_EXIT_INPUT, "%s:%d: unexpected YAML event", b->name, line);
    return NULL;
  }
}

/* Expects one event of the given type (consumed). */
static int expect_event(struct builder *b, enum fy_event_type type)
{
  struct fy_event *e = next_event(b);
  if (!e) return -1;
  int ok = e->type == type;
  int line = event_line(e);
  fy_parser_event_free(b->fyp, e);
  if (!ok)
    return hv_error_set(b->err, HV_EXIT_INPUT, "%s:%d: only one YAML document is allowed", b->name,
                        line);
  return 0;
}

/* Parses a whole stream of at most one document; an empty stream gives an empty scalar. */
static struct cfg_node *build_stream(struct builder *b, const char *text, size_t len)
{
  if (fy_parser_set_string(b->fyp, text, len)) {
    hv_error_set(b->err, HV_EXIT_INPUT, "%s: cannot start the YAML parser", b->name);
    return NULL;
  }
  if (expect_event(b, FYET_STREAM_START)) return NULL;
  struct fy_event *e = next_event(b);
  if (!e) return NULL;
  if (e->type == FYET_STREAM_END) {
    fy_parser_event_free(b->fyp, e);
    struct cfg_node *n = node_new(CFG_SCALAR, 0);
    n->text = xstrdup("");
    n->plain = 1;
    return n;
  }
  fy_parser_event_free(b->fyp, e); /* DOCUMENT_START */
  e = next_event(b);
  struct cfg_node *root = e ? build_node(b, e) : NULL;
  if (root && (expect_event(b, FYET_DOCUMENT_END) || expect_event(b, FYET_STREAM_END))) {
    node_free(root);
    return NULL;
  }
  return root;
}

static struct cfg_node *parse_yaml(const char *text, size_t len, const char *name, int positions,
                                   struct hv_error *err)
{
  struct builder b;
  if (builder_init(&b, name, err)) return NULL;
  b.positions = positions;
  struct cfg_node *n = build_stream(&b, text, len);
  builder_done(&b);
  return n;
}

/* ---------------------------------------------------------------- documents */

static struct cfg *cfg_alloc(const char *name, struct cfg_node *root)
{
  struct cfg *c = hv_calloc(1, sizeof *c, "config");
  c->name = xstrdup(name ? name : "(case)");
  c->root = root;
  return c;
}

struct cfg *cfg_new_empty(const char *name) { return cfg_alloc(name, node_new(CFG_MAP, 0)); }

struct cfg *cfg_load_string(const char *yaml, const char *name, struct hv_error *err)
{
  if (!name) name = "(string)";
  struct cfg_node *root = parse_yaml(yaml ? yaml : "", yaml ? strlen(yaml) : 0, name, 1, err);
  if (!root) return NULL;
  if (root->kind == CFG_SCALAR && root->plain && !root->text[0]) {
    node_free(root); /* an empty document: no keys */
    root = node_new(CFG_MAP, 0);
  }
  if (root->kind != CFG_MAP) {
    hv_error_set(err, HV_EXIT_INPUT, "%s:%d: the document must be a mapping of keys, not %s", name,
                 root->vline, kind_name(root->kind));
    node_free(root);
    return NULL;
  }
  root->line = root->vline = 0; /* messages about the root name just the file */
  return cfg_alloc(name, root);
}

/* Reads a whole file into a malloc'ed, NUL-terminated buffer. */
static char *read_file(const char *path, size_t *len, struct hv_error *err)
{
  FILE *f = fopen(path, "rb");
  if (!f) {
    hv_error_set(err, HV_EXIT_INPUT, "cannot open case file '%s': %s", path, strerror(errno));
    return NULL;
  }
  size_t cap = 4096, n = 0;
  char *buf = hv_malloc(cap, "case file");
  size_t r;
  while ((r = fread(buf + n, 1, cap - 1 - n, f)) > 0) {
    n += r;
    if (n == cap - 1) {
      cap *= 2;
      buf = hv_realloc(buf, cap, "case file");
    }
  }
  int bad = ferror(f);
  int e = errno;
  if (fclose(f) && !bad) {
    bad = 1;
    e = errno;
  }
  if (bad) {
    free(buf);
    hv_error_set(err, HV_EXIT_INPUT, "cannot read case file '%s': %s", path, strerror(e));
    return NULL;
  }
  buf[n] = '\0';
  *len = n;
  return buf;
}

struct cfg *cfg_load(const char *path, struct hv_error *err)
{
  size_t len;
  char *text = read_file(path, &len, err);
  if (!text) return NULL;
  if (memchr(text, '\0', len)) {
    free(text);
    hv_error_set(err, HV_EXIT_INPUT, "%s: not a text file (contains NUL bytes)", path);
    return NULL;
  }
  struct cfg *c = cfg_load_string(text, path, err);
  free(text);
  return c;
}

void cfg_free(struct cfg *c)
{
  if (!c) return;
  node_free(c->root);
  for (int i = 0; i < c->nrec; i++) {
    free(c->rec[i].path);
    free(c->rec[i].value);
  }
  free(c->rec);
  for (int i = 0; i < c->nstrs; i++) free(c->strs[i]);
  free(c->strs);
  for (int i = 0; i < c->nfiles; i++) free(c->files[i]);
  free(c->files);
  free(c->name);
  free(c);
}

const char *cfg_file(const struct cfg *c) { return c->name; }

/* ---------------------------------------------------------------- paths */

/* Splits "a.b[2].c" into components; returns the count or -1 if malformed. */
static int path_parse(const char *path, struct path_comp *comp, int max)
{
  int k = 0;
  const char *p = path;
  if (!p || !*p) return -1;
  for (;;) {
    if (k == max) return -1;
    if (*p == '[') {
      char *end;
      if (!isdigit((unsigned char)p[1])) return -1;
      long i = strtol(p + 1, &end, 10);
      if (*end != ']' || i > INT_MAX) return -1;
      comp[k++] = (struct path_comp){p, NULL, 0, (int)i};
      p = end + 1;
    } else {
      size_t n = strcspn(p, ".[]");
      if (!n) return -1;
      comp[k++] = (struct path_comp){p, p, n, -1};
      p += n;
    }
    if (!*p) return k;
    if (*p == '.') {
      p++;
      if (*p == '[' || !*p) return -1;
    } else if (*p != '[') {
      return -1;
    }
  }
}

/* Walks the path; *deepest gets the last node reached (for messages). */
static struct cfg_node *lookup(struct cfg *c, const char *path, struct cfg_node **deepest)
{
  struct path_comp comp[CFG_MAX_DEPTH];
  int nc = path_parse(path, comp, CFG_MAX_DEPTH);
  struct cfg_node *n = c->root;
  if (deepest) *deepest = n;
  if (nc < 0) return NULL;
  for (int k = 0; k < nc; k++) {
    int i = comp[k].key ? node_find(n, comp[k].key, comp[k].klen)
                        : (n->kind == CFG_SEQ && comp[k].index < n->n ? comp[k].index : -1);
    if (i < 0) return NULL;
    n = n->items[i];
    if (deepest) *deepest = n;
  }
  return n;
}

/* "file:line" of a node: `file` is the node's own (grafts) or NULL for the document's. */
static const char *where_line(const struct cfg *c, const char *file, int line, char *buf,
                              size_t len)
{
  const char *name = file ? file : c->name;
  if (line == CFG_LINE_SET)
    snprintf(buf, len, "--set");
  else if (line > 0)
    snprintf(buf, len, "%s:%d", name, line);
  else
    snprintf(buf, len, "%s", name);
  return buf;
}

const char *cfg_where(struct cfg *c, const char *path, char *buf, size_t len)
{
  struct cfg_node *n = lookup(c, path, NULL);
  return where_line(c, n ? n->file : NULL, n ? n->line : 0, buf, len);
}

const char *cfg_node_file(struct cfg *c, const char *path)
{
  struct cfg_node *n = (path && *path) ? lookup(c, path, NULL) : c->root;
  return n && n->file ? n->file : c->name;
}

int cfg_has(struct cfg *c, const char *path) { return lookup(c, path, NULL) != NULL; }

int cfg_len(struct cfg *c, const char *path)
{
  struct cfg_node *n = lookup(c, path, NULL);
  return n && n->kind == CFG_SEQ ? n->n : -1;
}

int cfg_is_map(struct cfg *c, const char *path)
{
  struct cfg_node *n = lookup(c, path, NULL);
  return n && n->kind == CFG_MAP;
}

int cfg_keys(struct cfg *c, const char *path, const char *const **names)
{
  struct cfg_node *n = (path && *path) ? lookup(c, path, NULL) : c->root;
  if (!n || n->kind != CFG_MAP) return -1;
  *names = (const char *const *)n->keys;
  return n->n;
}

void cfg_mark_used(struct cfg *c, const char *path)
{
  struct cfg_node *n = (path && *path) ? lookup(c, path, NULL) : c->root;
  if (n) node_mark(n);
}

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
static char *yaml_quote(const char *s)
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
  c->rec[c->nrec++] = (struct cfg_record){xstrdup(path), value, unit, is_default, line};
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
  where_line(c, n ? n->file : NULL, n ? n->vline : 0, where, sizeof where);
  return hv_error_set(err, HV_EXIT_INPUT, "%s: %s: %s", where, path, msg);
}

/* Finds the node of a getter: 1 found, 0 absent (and has_def), -1 error. */
static int fetch(struct cfg *c, const char *path, int has_def, struct cfg_node **out,
                 struct hv_error *err)
{
  struct path_comp comp[CFG_MAX_DEPTH];
  if (path_parse(path, comp, CFG_MAX_DEPTH) < 0)
    return hv_error_set(err, HV_EXIT_INPUT, "%s: bad key path '%s'", c->name, path ? path : "");
  struct cfg_node *deepest;
  *out = lookup(c, path, &deepest);
  if (*out) {
    (*out)->used = 1;
    return 1;
  }
  if (has_def) return 0;
  char where[512];
  return hv_error_set(err, HV_EXIT_INPUT, "%s: missing required key '%s'",
                      where_line(c, deepest->file, deepest->line, where, sizeof where), path);
}

/* The text of a scalar node that has a value. */
static const char *scalar_text(struct cfg *c, const struct cfg_node *n, const char *path,
                               struct hv_error *err)
{
  if (n->kind != CFG_SCALAR) {
    value_error(c, n, path, err, "expected a single value, found %s", kind_name(n->kind));
    return NULL;
  }
  if (n->plain && (!n->text[0] || !strcmp(n->text, "~") || !strcmp(n->text, "null"))) {
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
                         n->kind == CFG_SEQ ? "a list of another length" : kind_name(n->kind));
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
                       kind_name(s->kind));
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
  double d = strtod(t, &end);
  while (isspace((unsigned char)*end)) end++;
  if (end == t || *end || !isfinite(d) || d != floor(d) || fabs(d) >= 9.2e18) return -1;
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
  record(c, path, xstrdup(v ? "true" : "false"), "", !found, found ? n->vline : 0);
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
    *s = c->strs[c->nstrs++] = xstrdup(def);
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
  record(c, path, yaml_quote(s), "", n == NULL, n ? n->vline : 0);
  *out = s;
  return 0;
}

int cfg_get_choice(struct cfg *c, const char *path, const char *def, const char *const *choices,
                   int *out, struct hv_error *err)
{
  struct cfg_node *n;
  const char *s;
  if (fetch_string(c, path, def, &s, &n, err)) return -1;
  for (int i = 0; choices[i]; i++) {
    if (strcmp(s, choices[i])) continue;
    record(c, path, yaml_quote(s), "", n == NULL, n ? n->vline : 0);
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

/* ---------------------------------------------------------------- --set */

/* The child of p named by comp, created (kind `kind`) if missing; NULL if impossible. */
static struct cfg_node *set_step(struct cfg_node *p, const struct path_comp *comp,
                                 enum cfg_kind kind, const char **why)
{
  if (comp->key) {
    if (p->kind != CFG_MAP) {
      *why = "is not a mapping";
      return NULL;
    }
    int i = node_find(p, comp->key, comp->klen);
    if (i >= 0) return p->items[i];
    node_add(p, xstrndup(comp->key, comp->klen), node_new(kind, CFG_LINE_SET));
    return p->items[p->n - 1];
  }
  if (p->kind != CFG_SEQ) {
    *why = "is not a sequence";
    return NULL;
  }
  if (comp->index < p->n) return p->items[comp->index];
  if (comp->index > p->n) {
    *why = "has fewer entries (an index may append only at the end)";
    return NULL;
  }
  node_add(p, NULL, node_new(kind, CFG_LINE_SET));
  return p->items[p->n - 1];
}

/* Replaces (or appends) the last component of the path with value v. */
static int set_last(struct cfg_node *p, const struct path_comp *comp, struct cfg_node *v,
                    const char **why)
{
  int i;
  if (comp->key) {
    if (p->kind != CFG_MAP) {
      *why = "is not a mapping";
      return -1;
    }
    i = node_find(p, comp->key, comp->klen);
    if (i < 0) {
      node_add(p, xstrndup(comp->key, comp->klen), v);
      return 0;
    }
  } else {
    if (p->kind != CFG_SEQ) {
      *why = "is not a sequence";
      return -1;
    }
    i = comp->index;
    if (i == p->n) {
      node_add(p, NULL, v);
      return 0;
    }
    if (i > p->n) {
      *why = "has fewer entries (an index may append only at the end)";
      return -1;
    }
  }
  node_free(p->items[i]);
  p->items[i] = v;
  return 0;
}

static void trim(const char **s, size_t *n)
{
  while (*n && isspace((unsigned char)**s)) (*s)++, (*n)--;
  while (*n && isspace((unsigned char)(*s)[*n - 1])) (*n)--;
}

int cfg_apply_set(struct cfg *c, const char *assignment, struct hv_error *err)
{
  const char *eq = assignment ? strchr(assignment, '=') : NULL;
  if (!eq)
    return hv_error_set(err, HV_EXIT_INPUT, "--set '%s': expected key=value",
                        assignment ? assignment : "");
  const char *k = assignment, *val = eq + 1;
  size_t klen = (size_t)(eq - assignment), vlen = strlen(val);
  trim(&k, &klen);
  trim(&val, &vlen);
  char key[1024];
  struct path_comp comp[CFG_MAX_DEPTH];
  if (!klen) return hv_error_set(err, HV_EXIT_INPUT, "--set '%s': empty key", assignment);
  if (klen >= sizeof key) return hv_error_set(err, HV_EXIT_INPUT, "--set: key too long");
  memcpy(key, k, klen);
  key[klen] = '\0';
  int nc = path_parse(key, comp, CFG_MAX_DEPTH);
  if (nc < 0)
    return hv_error_set(err, HV_EXIT_INPUT, "--set '%s': bad key path '%s'", assignment, key);
  char what[1100];
  snprintf(what, sizeof what, "--set %s", key);
  struct cfg_node *v = parse_yaml(val, vlen, what, 0, err);
  if (!v) return -1;
  node_set_lines(v, CFG_LINE_SET);
  struct cfg_node *p = c->root;
  const char *why = NULL;
  int k_fail = nc - 1;
  for (int i = 0; i < nc - 1 && p; i++) {
    p = set_step(p, &comp[i], comp[i + 1].key ? CFG_MAP : CFG_SEQ, &why);
    if (!p) k_fail = i;
  }
  if (!p || set_last(p, &comp[nc - 1], v, &why)) {
    node_free(v);
    /* name the node that could not take the component k_fail */
    int plen = (int)(comp[k_fail].start - key) - (comp[k_fail].key ? 1 : 0);
    if (plen <= 0) return hv_error_set(err, HV_EXIT_INPUT, "--set %s: the top level %s", key, why);
    return hv_error_set(err, HV_EXIT_INPUT, "--set %s: '%.*s' %s", key, plen, key, why);
  }
  hv_info("override: %s = %.*s", key, (int)vlen, val);
  return 0;
}

/* ---------------------------------------------------------------- grafts */

/* The copy of file name `name` owned by c (one per distinct name). */
static const char *intern_file(struct cfg *c, const char *name)
{
  for (int i = 0; i < c->nfiles; i++)
    if (!strcmp(c->files[i], name)) return c->files[i];
  if (c->nfiles == c->capfiles) {
    c->capfiles = c->capfiles ? 2 * c->capfiles : 4;
    c->files = hv_realloc(c->files, (size_t)c->capfiles * sizeof *c->files, "config files");
  }
  return c->files[c->nfiles++] = xstrdup(name);
}

/* A deep copy of src-document node s for document dst: every node keeps the file it came
 * from, and counts as used (see cfg_graft). */
static struct cfg_node *graft_copy(struct cfg *dst, const struct cfg *src, const struct cfg_node *s)
{
  struct cfg_node *d = node_new(s->kind, s->line);
  d->vline = s->vline;
  d->plain = s->plain;
  d->used = 1;
  d->file = intern_file(dst, s->file ? s->file : src->name);
  if (s->text) d->text = xstrdup(s->text);
  for (int i = 0; i < s->n; i++)
    node_add(d, s->kind == CFG_MAP ? xstrdup(s->keys[i]) : NULL, graft_copy(dst, src, s->items[i]));
  return d;
}

/* Adds to mapping d every key of mapping s that d lacks; mappings present in both merge. */
static void graft_merge(struct cfg *dst, const struct cfg *src, struct cfg_node *d,
                        const struct cfg_node *s)
{
  for (int i = 0; i < s->n; i++) {
    int j = node_find(d, s->keys[i], strlen(s->keys[i]));
    if (j < 0)
      node_add(d, xstrdup(s->keys[i]), graft_copy(dst, src, s->items[i]));
    else if (d->items[j]->kind == CFG_MAP && s->items[i]->kind == CFG_MAP)
      graft_merge(dst, src, d->items[j], s->items[i]);
    /* else: the destination's value overrides the source's */
  }
}

int cfg_graft(struct cfg *dst, const char *dst_path, struct cfg *src, const char *src_path,
              struct hv_error *err)
{
  struct path_comp comp[CFG_MAX_DEPTH];
  char where[512];
  int nc = path_parse(dst_path, comp, CFG_MAX_DEPTH);
  if (nc < 0)
    return hv_error_set(err, HV_EXIT_INPUT, "%s: bad key path '%s'", dst->name,
                        dst_path ? dst_path : "");
  struct cfg_node *s = (src_path && *src_path) ? lookup(src, src_path, NULL) : src->root;
  if (!s)
    return hv_error_set(err, HV_EXIT_INPUT, "%s: no entry '%s'", src->name, src_path);
  if (s->kind != CFG_MAP)
    return hv_error_set(err, HV_EXIT_INPUT, "%s: '%s' must be a mapping of keys, not %s",
                        where_line(src, s->file, s->line, where, sizeof where), src_path,
                        kind_name(s->kind));
  /* walk to the destination, creating missing mappings (they carry the source's line) */
  struct cfg_node *d = dst->root;
  for (int k = 0; k < nc; k++) {
    if (!comp[k].key || d->kind != CFG_MAP)
      return hv_error_set(err, HV_EXIT_INPUT, "%s: cannot graft onto '%s' (not a mapping)",
                          dst->name, dst_path);
    int i = node_find(d, comp[k].key, comp[k].klen);
    if (i < 0) {
      struct cfg_node *m = node_new(CFG_MAP, s->line);
      m->file = intern_file(dst, s->file ? s->file : src->name);
      node_add(d, xstrndup(comp[k].key, comp[k].klen), m);
      i = d->n - 1;
    }
    d = d->items[i];
  }
  if (d->kind != CFG_MAP)
    return hv_error_set(err, HV_EXIT_INPUT, "%s: %s: expected a mapping of keys, found %s",
                        where_line(dst, d->file, d->vline, where, sizeof where), dst_path,
                        kind_name(d->kind));
  graft_merge(dst, src, d, s);
  return 0;
}

/* ---------------------------------------------------------------- unknown keys */

/* Optimal string alignment distance (edits and adjacent swaps), capped at 9. */
static int edit_distance(const char *a, size_t la, const char *b, size_t lb)
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
  int dist = edit_distance(cand, len, key, strlen(key));
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
    if (node_any_used(ch)) {
      if (ch->kind != CFG_SCALAR) find_unused(c, ch, sub, u);
      continue;
    }
    char where[512], hint[160] = "", line[1800];
    if (n->kind == CFG_MAP) suggest(c, n, path, n->keys[i], hint, sizeof hint);
    snprintf(line, sizeof line, "%s: unknown %s '%s'%s",
             where_line(c, ch->file, ch->line, where, sizeof where),
             n->kind == CFG_MAP ? "key" : "entry",
             sub, hint);
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
  int nc = path_parse(r->path, comp, CFG_MAX_DEPTH);
  struct cfg_node *p = t;
  for (int k = 0; k < nc; k++) {
    enum cfg_kind want = k == nc - 1 ? CFG_SCALAR : comp[k + 1].key ? CFG_MAP : CFG_SEQ;
    struct cfg_node *ch;
    if (comp[k].key) {
      if (p->kind != CFG_MAP) return;
      int i = node_find(p, comp[k].key, comp[k].klen);
      if (i < 0) {
        node_add(p, xstrndup(comp[k].key, comp[k].klen), node_new(want, 0));
        i = p->n - 1;
      }
      ch = p->items[i];
    } else {
      if (p->kind != CFG_SEQ) return;
      while (p->n <= comp[k].index) node_add(p, NULL, node_new(CFG_MAP, 0)); /* "{}" if unfilled */
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
  char *q = yaml_quote(key);
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
  wr(w, "# Parameters used by hvsph %s\n", version ? version : "(unknown version)");
  wr(w, "# case file: %s\n# written: %s\n", c->name, date);
  wr(w, "# Values are in SI units (the unit is in the comment); \"default\" marks values\n"
        "# the case file did not set. This file can be run as a case file.\n");
}

/* Writes the used parameters to an open file; returns 0 or an errno value. */
static int write_used_to(struct cfg *c, FILE *f, const char *version)
{
  struct writer w = {f, 0};
  struct cfg_node *t = node_new(CFG_MAP, 0);
  for (int i = 0; i < c->nrec; i++) used_insert(t, &c->rec[i]);
  write_header(&w, c, version);
  write_tree(&w, t, 0, 0);
  node_free(t);
  return w.err_no;
}

int cfg_write_used(struct cfg *c, const char *path, const char *version, struct hv_error *err)
{
  char tmp[4096];
  if (snprintf(tmp, sizeof tmp, "%s.tmp.%ld", path, (long)getpid()) >= (int)sizeof tmp)
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
