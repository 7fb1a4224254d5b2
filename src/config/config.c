/* config.c — the case file: YAML read with libfyaml into a tree of our own.
 *
 * The YAML event stream (libfyaml's parser) is turned into cfg_node trees:
 * mappings (ordered keys), sequences and scalars, each with the 1-based line that
 * names it (a mapping value carries its key's line) and a `used` flag. Aliases are
 * expanded by copying the anchored subtree (not one inside the value it names, and at
 * most CFG_ALIAS_MAX_NODES values in all), nested at most CFG_MAX_DEPTH deep. The
 * text must be UTF-8: libfyaml let a stray Latin-1 byte in a comment end the document
 * silently, so it is checked first. libfyaml's diagnostics are collected, never
 * printed: a syntax error becomes one message "case.yaml:3:7: YAML syntax error:
 * <reason>".
 *
 * Also here: the documents (load, free), key paths ("bodies[0].velocity") and the
 * structure queries, --set and cfg_graft. Values set with --set carry the line
 * CFG_LINE_SET and are reported as "--set" in messages. The typed getters are in
 * config_get.c, the unknown-key check and used_parameters.yaml in config_used.c.
 */
#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <libfyaml.h>

#include "config/config_internal.h"
#include "core/infile.h"
#include "core/utf8.h"

/* ---------------------------------------------------------------- nodes */

char *cfg_strndup(const char *s, size_t n)
{
  char *d = hv_malloc(n + 1, "config string");
  memcpy(d, s, n);
  d[n] = '\0';
  return d;
}

char *cfg_strdup(const char *s) { return cfg_strndup(s, strlen(s)); }

struct cfg_node *cfg_node_new(enum cfg_kind kind, int line)
{
  struct cfg_node *n = hv_calloc(1, sizeof *n, "config node");
  n->kind = kind;
  n->line = n->vline = line;
  return n;
}

void cfg_node_free(struct cfg_node *n)
{
  if (!n) return;
  for (int i = 0; i < n->n; i++) {
    cfg_node_free(n->items[i]);
    if (n->keys) free(n->keys[i]);
  }
  free(n->items);
  free(n->keys);
  free(n->text);
  free(n);
}

/* Appends a child (key NULL for sequences); takes ownership of key. */
void cfg_node_add(struct cfg_node *p, char *key, struct cfg_node *child)
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

int cfg_node_find(const struct cfg_node *p, const char *key, size_t klen)
{
  if (p->kind != CFG_MAP) return -1;
  for (int i = 0; i < p->n; i++)
    if (strlen(p->keys[i]) == klen && !memcmp(p->keys[i], key, klen)) return i;
  return -1;
}

static struct cfg_node *node_copy(const struct cfg_node *s)
{
  struct cfg_node *d = cfg_node_new(s->kind, s->line);
  d->vline = s->vline;
  d->plain = s->plain;
  d->file = s->file;
  if (s->text) d->text = cfg_strdup(s->text);
  for (int i = 0; i < s->n; i++)
    cfg_node_add(d, s->kind == CFG_MAP ? cfg_strdup(s->keys[i]) : NULL, node_copy(s->items[i]));
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

const char *cfg_kind_name(enum cfg_kind k)
{
  return k == CFG_MAP ? "a mapping" : k == CFG_SEQ ? "a sequence" : "a single value";
}

/* ---------------------------------------------------------------- YAML → tree */

struct anchor {
  char *name;
  const struct cfg_node *node;
  int open; /* a mapping or sequence still being read: an alias to it is recursive */
};

/* Values that aliases may copy in one document, all together: a few aliases of aliases
 * (each line ten aliases of the one before) would otherwise grow tenfold a line until
 * memory runs out. Real case files copy a few hundred. */
#define CFG_ALIAS_MAX_NODES 1000000L

struct builder {
  struct fy_parser *fyp;
  struct fy_diag *diag;
  const char *name; /* file name for messages */
  int positions;    /* put line:column into syntax errors (not for --set values) */
  struct hv_error *err;
  struct anchor *anchors;
  int nanchors, capanchors;
  long alias_nodes;   /* values copied by aliases so far (CFG_ALIAS_MAX_NODES) */
  int depth;          /* mappings and sequences open (at most CFG_MAX_DEPTH) */
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

/* ":12" to follow the name in a message about a line of the text read; "" for a --set
 * value (its lines are not the file's: "--set a", not "--set a:1"). Returns buf. */
static const char *bline(const struct builder *b, int line, char *buf, size_t len)
{
  if (b->positions && line > 0)
    snprintf(buf, len, ":%d", line);
  else if (len)
    buf[0] = '\0';
  return buf;
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
  return s ? cfg_strndup(s, len) : cfg_strdup("");
}

/* Registers anchor t for node n; returns its index (-1 if t is NULL). */
static int anchor_add(struct builder *b, struct fy_token *t, const struct cfg_node *n, int open)
{
  if (!t) return -1;
  if (b->nanchors == b->capanchors) {
    b->capanchors = b->capanchors ? 2 * b->capanchors : 8;
    b->anchors = hv_realloc(b->anchors, (size_t)b->capanchors * sizeof *b->anchors, "anchors");
  }
  b->anchors[b->nanchors] = (struct anchor){token_text(t), n, open};
  return b->nanchors++;
}

static long node_count(const struct cfg_node *n)
{
  long k = 1;
  for (int i = 0; i < n->n; i++) k += node_count(n->items[i]);
  return k;
}

static struct cfg_node *build_node(struct builder *b, struct fy_event *e);

/* Reads key/value pairs up to MAPPING_END into map m. */
static int build_map_body(struct builder *b, struct cfg_node *m)
{
  char at[16];
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
      return hv_error_set(b->err, HV_EXIT_INPUT, "%s%s: mapping keys must be plain names", b->name,
                          bline(b, kline, at, sizeof at));
    }
    char *key = token_text(e->scalar.value);
    fy_parser_event_free(b->fyp, e);
    int dup = cfg_node_find(m, key, strlen(key));
    if (dup >= 0) {
      char first[32] = "";
      if (b->positions) snprintf(first, sizeof first, " (first at line %d)", m->items[dup]->line);
      hv_error_set(b->err, HV_EXIT_INPUT, "%s%s: duplicate key '%s'%s", b->name,
                   bline(b, kline, at, sizeof at), key, first);
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
    cfg_node_add(m, key, child);
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
    cfg_node_add(s, NULL, child);
  }
}

static struct cfg_node *build_alias(struct builder *b, struct fy_event *e, int line)
{
  char at[16];
  char *name = token_text(e->alias.anchor);
  fy_parser_event_free(b->fyp, e);
  for (int i = b->nanchors - 1; i >= 0; i--) {
    if (strcmp(b->anchors[i].name, name)) continue;
    if (b->anchors[i].open) {
      hv_error_set(b->err, HV_EXIT_INPUT,
                   "%s%s: alias '*%s' inside the value it names (a recursive alias)", b->name,
                   bline(b, line, at, sizeof at), name);
      free(name);
      return NULL;
    }
    b->alias_nodes += node_count(b->anchors[i].node);
    if (b->alias_nodes > CFG_ALIAS_MAX_NODES) {
      hv_error_set(b->err, HV_EXIT_INPUT,
                   "%s%s: alias '*%s': aliases copy more than %ld values in all (aliases of "
                   "aliases?)",
                   b->name, bline(b, line, at, sizeof at), name, CFG_ALIAS_MAX_NODES);
      free(name);
      return NULL;
    }
    free(name);
    struct cfg_node *n = node_copy(b->anchors[i].node);
    n->line = n->vline = line;
    return n;
  }
  hv_error_set(b->err, HV_EXIT_INPUT, "%s%s: unknown alias '*%s'", b->name,
               bline(b, line, at, sizeof at), name);
  free(name);
  return NULL;
}

/* Builds the node starting with event e (consumed). NULL with b->err set on error. */
static struct cfg_node *build_node(struct builder *b, struct fy_event *e)
{
  int line = event_line(e);
  struct cfg_node *n;
  int rc = 0;
  char at[16];
  switch (e->type) {
  case FYET_SCALAR:
    n = cfg_node_new(CFG_SCALAR, line);
    n->text = token_text(e->scalar.value);
    n->plain = fy_token_scalar_style(e->scalar.value) == FYSS_PLAIN;
    anchor_add(b, e->scalar.anchor, n, 0);
    fy_parser_event_free(b->fyp, e);
    return n;
  case FYET_MAPPING_START:
  case FYET_SEQUENCE_START: {
    int map = e->type == FYET_MAPPING_START;
    if (b->depth == CFG_MAX_DEPTH) { /* deeper than a key path reaches (and the stack) */
      fy_parser_event_free(b->fyp, e);
      hv_error_set(b->err, HV_EXIT_INPUT, "%s%s: values nested more than %d deep", b->name,
                   bline(b, line, at, sizeof at), CFG_MAX_DEPTH);
      return NULL;
    }
    n = cfg_node_new(map ? CFG_MAP : CFG_SEQ, line);
    int a = anchor_add(b, map ? e->mapping_start.anchor : e->sequence_start.anchor, n, 1);
    fy_parser_event_free(b->fyp, e);
    b->depth++;
    rc = map ? build_map_body(b, n) : build_seq_body(b, n);
    b->depth--;
    if (rc) {
      cfg_node_free(n); /* the anchor table may point into n: no more aliases are read */
      return NULL;
    }
    if (a >= 0) b->anchors[a].open = 0;
    return n;
  }
  case FYET_ALIAS: return build_alias(b, e, line);
  default:
    fy_parser_event_free(b->fyp, e);
    hv_error_set(b->err, HV_EXIT_INPUT, "%s%s: unexpected YAML event", b->name,
                 bline(b, line, at, sizeof at));
    return NULL;
  }
}

/* Expects one event of the given type (consumed). */
static int expect_event(struct builder *b, enum fy_event_type type)
{
  char at[16];
  struct fy_event *e = next_event(b);
  if (!e) return -1;
  int ok = e->type == type;
  int line = event_line(e);
  fy_parser_event_free(b->fyp, e);
  if (!ok)
    return hv_error_set(b->err, HV_EXIT_INPUT, "%s%s: only one YAML document is allowed", b->name,
                        bline(b, line, at, sizeof at));
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
    struct cfg_node *n = cfg_node_new(CFG_SCALAR, 0);
    n->text = cfg_strdup("");
    n->plain = 1;
    return n;
  }
  fy_parser_event_free(b->fyp, e); /* DOCUMENT_START */
  e = next_event(b);
  struct cfg_node *root = e ? build_node(b, e) : NULL;
  if (root && (expect_event(b, FYET_DOCUMENT_END) || expect_event(b, FYET_STREAM_END))) {
    cfg_node_free(root);
    return NULL;
  }
  return root;
}

/* Refuses text that is not UTF-8, naming the line and column (in characters) of the
 * first bad byte. */
static int check_utf8(const char *text, size_t len, const char *name, int positions,
                      struct hv_error *err)
{
  const unsigned char *s = (const unsigned char *)text;
  size_t bad = hv_utf8_valid_prefix(s, len);
  if (bad == len) return 0;
  if (!positions)
    return hv_error_set(err, HV_EXIT_INPUT, "%s: not valid UTF-8 (byte 0x%02x)", name, s[bad]);
  long line = 1, col = 1;
  for (size_t i = 0; i < bad; i++) {
    if (s[i] == '\n') {
      line++;
      col = 1;
    } else if ((s[i] & 0xc0) != 0x80) {
      col++;
    }
  }
  return hv_error_set(err, HV_EXIT_INPUT,
                      "%s:%ld:%ld: not valid UTF-8 (byte 0x%02x); save the file as UTF-8", name,
                      line, col, s[bad]);
}

static struct cfg_node *parse_yaml(const char *text, size_t len, const char *name, int positions,
                                   struct hv_error *err)
{
  if (check_utf8(text, len, name, positions, err)) return NULL;
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
  c->name = cfg_strdup(name ? name : "(case)");
  c->root = root;
  return c;
}

struct cfg *cfg_new_empty(const char *name) { return cfg_alloc(name, cfg_node_new(CFG_MAP, 0)); }

struct cfg *cfg_load_string(const char *yaml, const char *name, struct hv_error *err)
{
  if (!name) name = "(string)";
  struct cfg_node *root = parse_yaml(yaml ? yaml : "", yaml ? strlen(yaml) : 0, name, 1, err);
  if (!root) return NULL;
  if (root->kind == CFG_SCALAR && root->plain && !root->text[0]) {
    cfg_node_free(root); /* an empty document: no keys */
    root = cfg_node_new(CFG_MAP, 0);
  }
  if (root->kind != CFG_MAP) {
    hv_error_set(err, HV_EXIT_INPUT, "%s:%d: the document must be a mapping of keys, not %s", name,
                 root->vline, cfg_kind_name(root->kind));
    cfg_node_free(root);
    return NULL;
  }
  root->line = root->vline = 0; /* messages about the root name just the file */
  struct cfg *c = cfg_alloc(name, root);
  c->si_record = yaml && !strncmp(yaml, CFG_USED_HEADER, strlen(CFG_USED_HEADER));
  return c;
}

/* The largest case file read: 1 MiB. hvsph's case files and used_parameters.yaml are
 * 1-7 kB (the largest in the tree, data/paper_results.yaml, 7 kB); the most a case can
 * describe (64 bodies and 64 materials, each key on a line of its own, with comments)
 * stays under 100 kB, a tenth of the limit. Above it lies no case but a wrong file
 * (`hvsph run /dev/zero` read until the kernel stopped it; infile.h refuses devices and
 * FIFOs, this the regular file that is too large), and a time: the parser's
 * duplicate-key check is quadratic in the keys of one mapping, so the time to refuse a
 * file of one huge mapping grows with the square of its size: tens of seconds at this
 * limit, hours at 16 times it (docs/case-files.md, "The rules"). */
#define CFG_MAX_FILE_BYTES (1LL << 20)

/* Reads a whole file into a malloc'ed, NUL-terminated buffer. */
static char *read_file(const char *path, size_t *len, struct hv_error *err)
{
  long long size;
  FILE *f = hv_open_input(path, "case file", CFG_MAX_FILE_BYTES, &size, err);
  if (!f) return NULL;
  /* sized by fstat; a file that grows while it is read is read on, up to the limit */
  size_t cap = (size_t)size + 2, n = 0;
  char *buf = hv_malloc(cap, "case file");
  size_t r;
  while (n <= (size_t)CFG_MAX_FILE_BYTES && (r = fread(buf + n, 1, cap - 1 - n, f)) > 0) {
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
  if (n > (size_t)CFG_MAX_FILE_BYTES) {
    free(buf);
    hv_error_set(err, HV_EXIT_INPUT,
                 "case file '%s' grew past %lld bytes (1 MiB) while it "
                 "was read: is it the right file?",
                 path, CFG_MAX_FILE_BYTES);
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
  cfg_node_free(c->root);
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
int cfg_path_parse(const char *path, struct path_comp *comp, int max)
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
struct cfg_node *cfg_lookup(struct cfg *c, const char *path, struct cfg_node **deepest)
{
  struct path_comp comp[CFG_MAX_DEPTH];
  int nc = cfg_path_parse(path, comp, CFG_MAX_DEPTH);
  struct cfg_node *n = c->root;
  if (deepest) *deepest = n;
  if (nc < 0 || !n) return NULL;
  for (int k = 0; k < nc; k++) {
    int i = comp[k].key ? cfg_node_find(n, comp[k].key, comp[k].klen)
                        : (n->kind == CFG_SEQ && comp[k].index < n->n ? comp[k].index : -1);
    if (i < 0) return NULL;
    n = n->items[i];
    if (deepest) *deepest = n;
  }
  return n;
}

/* "file:line" of a node: `file` is the node's own (grafts) or NULL for the document's. */
const char *cfg_where_line(const struct cfg *c, const char *file, int line, char *buf, size_t len)
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
  struct cfg_node *n = cfg_lookup(c, path, NULL);
  return cfg_where_line(c, n ? n->file : NULL, n ? n->line : 0, buf, len);
}

const char *cfg_node_file(struct cfg *c, const char *path)
{
  struct cfg_node *n = (path && *path) ? cfg_lookup(c, path, NULL) : c->root;
  return n && n->file ? n->file : c->name;
}

int cfg_has(struct cfg *c, const char *path) { return cfg_lookup(c, path, NULL) != NULL; }

int cfg_len(struct cfg *c, const char *path)
{
  struct cfg_node *n = cfg_lookup(c, path, NULL);
  return n && n->kind == CFG_SEQ ? n->n : -1;
}

int cfg_is_map(struct cfg *c, const char *path)
{
  struct cfg_node *n = cfg_lookup(c, path, NULL);
  return n && n->kind == CFG_MAP;
}

int cfg_keys(struct cfg *c, const char *path, const char *const **names)
{
  struct cfg_node *n = (path && *path) ? cfg_lookup(c, path, NULL) : c->root;
  if (!n || n->kind != CFG_MAP) return -1;
  *names = (const char *const *)n->keys;
  return n->n;
}

void cfg_mark_used(struct cfg *c, const char *path)
{
  struct cfg_node *n = (path && *path) ? cfg_lookup(c, path, NULL) : c->root;
  if (n) node_mark(n);
}

/* ---------------------------------------------------------------- --set */

/* A key written with no value (`time:` and nothing below) takes --set's keys as an
 * empty mapping or sequence would: YAML reads it as null, not as a value to keep. */
static void null_to(struct cfg_node *p, enum cfg_kind kind)
{
  if (cfg_scalar_is_null(p)) {
    free(p->text);
    p->text = NULL;
    p->kind = kind;
  }
}

/* The child of p named by comp, created (kind `kind`) if missing; NULL if impossible. */
static struct cfg_node *set_step(struct cfg_node *p, const struct path_comp *comp,
                                 enum cfg_kind kind, const char **why)
{
  null_to(p, comp->key ? CFG_MAP : CFG_SEQ);
  if (comp->key) {
    if (p->kind != CFG_MAP) {
      *why = "is not a mapping";
      return NULL;
    }
    int i = cfg_node_find(p, comp->key, comp->klen);
    if (i >= 0) return p->items[i];
    cfg_node_add(p, cfg_strndup(comp->key, comp->klen), cfg_node_new(kind, CFG_LINE_SET));
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
  cfg_node_add(p, NULL, cfg_node_new(kind, CFG_LINE_SET));
  return p->items[p->n - 1];
}

/* Replaces (or appends) the last component of the path with value v. */
static int set_last(struct cfg_node *p, const struct path_comp *comp, struct cfg_node *v,
                    const char **why)
{
  int i;
  null_to(p, comp->key ? CFG_MAP : CFG_SEQ);
  if (comp->key) {
    if (p->kind != CFG_MAP) {
      *why = "is not a mapping";
      return -1;
    }
    i = cfg_node_find(p, comp->key, comp->klen);
    if (i < 0) {
      cfg_node_add(p, cfg_strndup(comp->key, comp->klen), v);
      return 0;
    }
  } else {
    if (p->kind != CFG_SEQ) {
      *why = "is not a sequence";
      return -1;
    }
    i = comp->index;
    if (i == p->n) {
      cfg_node_add(p, NULL, v);
      return 0;
    }
    if (i > p->n) {
      *why = "has fewer entries (an index may append only at the end)";
      return -1;
    }
  }
  cfg_node_free(p->items[i]);
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
  int nc = cfg_path_parse(key, comp, CFG_MAX_DEPTH);
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
    cfg_node_free(v);
    /* name the node that could not take the component k_fail, and where it is written */
    int plen = (int)(comp[k_fail].start - key) - (comp[k_fail].key ? 1 : 0);
    char where[1300];
    if (plen <= 0)
      return hv_error_set(err, HV_EXIT_INPUT, "%s: --set %s: the top level %s",
                          cfg_where_line(c, NULL, 0, where, sizeof where), key, why);
    char parent[1024];
    snprintf(parent, sizeof parent, "%.*s", plen, key);
    const struct cfg_node *pn = cfg_lookup(c, parent, NULL);
    if (!pn || pn->line == CFG_LINE_SET) /* itself from an earlier --set */
      return hv_error_set(err, HV_EXIT_INPUT, "--set %s: '%s' %s", key, parent, why);
    return hv_error_set(err, HV_EXIT_INPUT, "%s: --set %s: '%s' %s",
                        cfg_where(c, parent, where, sizeof where), key, parent, why);
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
  return c->files[c->nfiles++] = cfg_strdup(name);
}

/* A deep copy of src-document node s for document dst: every node keeps the file it came
 * from, and counts as used (see cfg_graft). */
static struct cfg_node *graft_copy(struct cfg *dst, const struct cfg *src, const struct cfg_node *s)
{
  struct cfg_node *d = cfg_node_new(s->kind, s->line);
  d->vline = s->vline;
  d->plain = s->plain;
  d->used = 1;
  d->file = intern_file(dst, s->file ? s->file : src->name);
  if (s->text) d->text = cfg_strdup(s->text);
  for (int i = 0; i < s->n; i++)
    cfg_node_add(d, s->kind == CFG_MAP ? cfg_strdup(s->keys[i]) : NULL,
                 graft_copy(dst, src, s->items[i]));
  return d;
}

/* Adds to mapping d every key of mapping s that d lacks; mappings present in both merge. */
static void graft_merge(struct cfg *dst, const struct cfg *src, struct cfg_node *d,
                        const struct cfg_node *s)
{
  for (int i = 0; i < s->n; i++) {
    int j = cfg_node_find(d, s->keys[i], strlen(s->keys[i]));
    if (j < 0)
      cfg_node_add(d, cfg_strdup(s->keys[i]), graft_copy(dst, src, s->items[i]));
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
  int nc = cfg_path_parse(dst_path, comp, CFG_MAX_DEPTH);
  if (nc < 0)
    return hv_error_set(err, HV_EXIT_INPUT, "%s: bad key path '%s'", dst->name,
                        dst_path ? dst_path : "");
  struct cfg_node *s = (src_path && *src_path) ? cfg_lookup(src, src_path, NULL) : src->root;
  if (!s) return hv_error_set(err, HV_EXIT_INPUT, "%s: no entry '%s'", src->name, src_path);
  if (s->kind != CFG_MAP)
    return hv_error_set(err, HV_EXIT_INPUT, "%s: '%s' must be a mapping of keys, not %s",
                        cfg_where_line(src, s->file, s->line, where, sizeof where), src_path,
                        cfg_kind_name(s->kind));
  /* walk to the destination, creating missing mappings (they carry the source's line) */
  struct cfg_node *d = dst->root;
  for (int k = 0; k < nc; k++) {
    if (!comp[k].key || d->kind != CFG_MAP)
      return hv_error_set(err, HV_EXIT_INPUT, "%s: cannot graft onto '%s' (not a mapping)",
                          dst->name, dst_path);
    int i = cfg_node_find(d, comp[k].key, comp[k].klen);
    if (i < 0) {
      struct cfg_node *m = cfg_node_new(CFG_MAP, s->line);
      m->file = intern_file(dst, s->file ? s->file : src->name);
      cfg_node_add(d, cfg_strndup(comp[k].key, comp[k].klen), m);
      i = d->n - 1;
    }
    d = d->items[i];
  }
  if (d->kind != CFG_MAP)
    return hv_error_set(err, HV_EXIT_INPUT, "%s: %s: expected a mapping of keys, found %s",
                        cfg_where_line(dst, d->file, d->vline, where, sizeof where), dst_path,
                        cfg_kind_name(d->kind));
  graft_merge(dst, src, d, s);
  return 0;
}
