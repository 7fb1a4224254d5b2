/* test_docs.c — the documentation against the code, so that neither drifts from the other.
 *
 *   1. docs/case-files.md has every key a run reads. Every example case
 *      (examples/verification/ and examples/getting-started/ as they are,
 *      examples/paper/ and examples/sweeps/ at resolution 0.01) and a case of materials (each of the
 *      library's, and a few that no example has) is set up with --set time.end=0, and
 *      every key of its used_parameters.yaml (defaults included) must be a key of the
 *      table where case-files.md puts it: `sph.viscosity.alpha` is
 *      `viscosity.alpha` of the sph table; `materials.<m>.gamma` is `gamma` of the
 *      materials table or of its EOS's ("EOS `ideal-gas`"); `materials.<m>.strength.yield`
 *      is `yield` of the strength table (fracture likewise); `bodies[i].spacing` is in the
 *      bodies table and every key of a body's shape, `minus` shapes included, in the
 *      shapes table; each top-level key is in the top-level table. A key below one the
 *      table has (`crack_eps_f.d1`) counts when that row names it (`{d1, d2, d3}`).
 *   2. docs/cli.md against the commands. Every `--option` that `hvsph --help` shows in a
 *      command's lines, or the command's own help (`hvsph CMD --help`, or the usage it
 *      prints for that), is in cli.md: in the command's synopsis line or its section
 *      ("## hvsph CMD"). Every option cli.md gives a command (its synopsis line, the
 *      first column of its section's tables, the command lines of its examples) is taken
 *      by the command: a cheap call with it (on a missing case or folder; bench on 512
 *      particles for one step) does not end in exit status 1, a bad command line, as the
 *      same call with an unknown option does.
 *   3. The columns of the Sod run's summary.csv are in docs/output-files.md's section
 *      summary.csv; every column of a particle snapshot (CSV) and every array of its VTU,
 *      of a case that writes every field, in its sections on the two formats; and every
 *      quantity of the paper cases' measurements.csv, with its unit, in
 *      docs/measurements.md's table of quantities.
 *   4. README's validation table against docs/validation.md's results: every value of
 *      the hvsph column of README's section "Validation" ("173.5 mm (−10.4 %)", or two
 *      joined by " / ") is, at the digits README gives, the hvsph value (third cell) and
 *      error against the experiment (sixth cell) of a row of validation.md's section
 *      "Status" with the same unit; and README's mean hole errors ("the mean hole error
 *      is X %, KERNEL's Y %") are the Status's ("mean absolute error is X % against
 *      KERNEL's Y %"). (README's table is what a user reads first; it once kept runs
 *      weeks old after the Status table had newer ones.)
 *
 * Every check is exact, and reports everything missing in one failure that names the
 * page. HVSPH_DOCS_DIR points the test at another copy of docs/ (to see it fail on a
 * doctored page). About 5 s on 2 cores, most of it setting up the 30 cases.
 */
#include <dirent.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "config/config.h"
#include "testlib.h"

/* ------------------------------------------------------------------ text helpers */

/* A growing string. */
struct text {
  char *s;
  size_t n, cap;
};

static void text_add(struct text *t, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void text_add(struct text *t, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  int k = vsnprintf(NULL, 0, fmt, ap);
  va_end(ap);
  if (k < 0) return;
  if (t->n + (size_t)k + 1 > t->cap) {
    size_t cap = 2 * (t->n + (size_t)k + 1) + 256;
    char *s = realloc(t->s, cap);
    if (!s) {
      fprintf(stderr, "out of memory\n");
      exit(1);
    }
    t->s = s;
    t->cap = cap;
  }
  va_start(ap, fmt);
  vsnprintf(t->s + t->n, t->cap - t->n, fmt, ap);
  va_end(ap);
  t->n += (size_t)k;
}

static const char *text_str(const struct text *t) { return t->s ? t->s : ""; }

static void text_free(struct text *t)
{
  free(t->s);
  memset(t, 0, sizeof *t);
}

/* A set of words, kept as "\n<w>\n<w>\n". */
static int set_has(const struct text *set, const char *w)
{
  const char *s = text_str(set);
  size_t l = strlen(w);
  for (const char *p = strstr(s, w); p; p = strstr(p + 1, w))
    if (p > s && p[-1] == '\n' && p[l] == '\n') return 1;
  return 0;
}

static int set_add(struct text *set, const char *w)
{
  if (set_has(set, w)) return 0;
  if (!set->n) text_add(set, "\n");
  text_add(set, "%s\n", w);
  return 1;
}

static int word_char(char c)
{
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

/* w occurs in s[0, len) as a whole word (not inside a longer identifier). */
static int has_word(const char *s, size_t len, const char *w)
{
  size_t l = strlen(w);
  for (size_t i = 0; i + l <= len; i++)
    if (!strncmp(s + i, w, l) && (i == 0 || !word_char(s[i - 1])) &&
        (i + l == len || !word_char(s[i + l])))
      return 1;
  return 0;
}

/* The line at p: its length without the newline. */
static size_t line_len(const char *p) { return strcspn(p, "\n"); }

static const char *next_line(const char *p)
{
  p += line_len(p);
  return *p ? p + 1 : p;
}

static int is_fence(const char *p) { return !strncmp(p, "```", 3); }

/* The section of a Markdown page under the heading line "## title", or "## title (…)"
 * (up to the next heading of level 2 or above, outside code blocks); NULL if there is
 * none. */
static const char *md_section(const char *md, const char *title, size_t *len)
{
  size_t tl = strlen(title);
  int fenced = 0;
  const char *start = NULL;
  for (const char *p = md; *p; p = next_line(p)) {
    if (is_fence(p)) fenced = !fenced;
    if (fenced || p[0] != '#') continue;
    int level = (int)strspn(p, "#");
    if (start && level <= 2) {
      *len = (size_t)(p - start);
      return start;
    }
    if (level == 2 && p[2] == ' ' && !strncmp(p + 3, title, tl) &&
        (line_len(p + 3) == tl || !strncmp(p + 3 + tl, " (", 2)))
      start = p;
  }
  if (start) *len = strlen(start);
  return start;
}

/* What a page's text sets as code: the contents of `backtick spans` and of fenced blocks,
 * each followed by a newline. */
static void md_code(const char *s, size_t len, struct text *out)
{
  int fenced = 0, tick = 0;
  for (size_t i = 0; i < len; i++) {
    if ((i == 0 || s[i - 1] == '\n') && is_fence(s + i)) {
      fenced = !fenced;
      i += line_len(s + i);
      text_add(out, "\n");
      continue;
    }
    if (!fenced && s[i] == '`') {
      tick = !tick;
      if (!tick) text_add(out, "\n");
      continue;
    }
    if (fenced || tick) text_add(out, "%c", s[i]);
  }
}

/* The cells of a table row ("| a | b |"): the start and length of cell k (0-based);
 * an escaped \| does not end a cell. */
static int md_cell(const char *row, int k, const char **cell, size_t *len)
{
  size_t n = line_len(row);
  if (!n || row[0] != '|') return -1;
  size_t i = 1;
  for (int c = 0;; c++) {
    size_t j = i;
    while (j < n && !(row[j] == '|' && row[j - 1] != '\\')) j++;
    if (j >= n) return -1;
    if (c == k) {
      *cell = row + i;
      *len = j - i;
      return 0;
    }
    i = j + 1;
  }
}

static void trim(const char **s, size_t *len)
{
  while (*len && (**s == ' ' || **s == '\t')) (*s)++, (*len)--;
  while (*len && ((*s)[*len - 1] == ' ' || (*s)[*len - 1] == '\t')) (*len)--;
}

/* ----------------------------------------------------------------- the doc pages */

static const char *docs_dir(void)
{
  static char dir[4200];
  const char *d = getenv("HVSPH_DOCS_DIR");
  if (d && *d)
    snprintf(dir, sizeof dir, "%s", d);
  else
    snprintf(dir, sizeof dir, "%s/docs", test_source_dir());
  return dir;
}

static char *read_doc(const char *name)
{
  char path[4400];
  snprintf(path, sizeof path, "%s/%s", docs_dir(), name);
  char *s = test_slurp(path, NULL);
  CHECK(s != NULL, "docs/%s can be read (%s)", name, path);
  return s;
}

/* Every key a page's tables give: the `names` in the first cell of each row, under the
 * heading (of any level) the table stands under. */
struct doc_key {
  char heading[128], key[128];
  const char *row; /* the whole row, for the keys below it that it names */
};
struct doc_keys {
  struct doc_key *k;
  int n, cap;
};

static void doc_keys_parse(const char *md, struct doc_keys *d)
{
  char heading[128] = "";
  int fenced = 0;
  for (const char *p = md; *p; p = next_line(p)) {
    if (is_fence(p)) fenced = !fenced;
    if (fenced) continue;
    if (p[0] == '#') {
      const char *h = p + strspn(p, "#");
      h += strspn(h, " ");
      snprintf(heading, sizeof heading, "%.*s", (int)line_len(h), h);
      continue;
    }
    const char *cell;
    size_t len;
    if (md_cell(p, 0, &cell, &len)) continue;
    for (const char *q = memchr(cell, '`', len); q && q < cell + len;) {
      const char *e = memchr(q + 1, '`', (size_t)(cell + len - q - 1));
      if (!e) break;
      if (d->n == d->cap) {
        d->cap = 2 * d->cap + 64;
        d->k = realloc(d->k, (size_t)d->cap * sizeof *d->k);
        if (!d->k) exit(1);
      }
      struct doc_key *k = &d->k[d->n++];
      snprintf(k->heading, sizeof k->heading, "%s", heading);
      snprintf(k->key, sizeof k->key, "%.*s", (int)(e - q - 1), q + 1);
      k->row = p;
      q = memchr(e + 1, '`', (size_t)(cell + len - e - 1));
    }
  }
}

static const struct doc_key *doc_key_find(const struct doc_keys *d, const char *heading,
                                          const char *key)
{
  for (int i = 0; i < d->n; i++)
    if (!strcmp(d->k[i].heading, heading) && !strcmp(d->k[i].key, key)) return &d->k[i];
  return NULL;
}

static int doc_heading_keys(const struct doc_keys *d, const char *heading)
{
  int n = 0;
  for (int i = 0; i < d->n; i++) n += !strcmp(d->k[i].heading, heading);
  return n;
}

/* rel ("viscosity.alpha", "crack_eps_f.d1") is a key of the table under `heading`, or
 * lies below one whose row names the rest's first part as a word. */
static int doc_documents(const struct doc_keys *d, const char *heading, const char *rel)
{
  if (doc_key_find(d, heading, rel)) return 1;
  char pre[256];
  snprintf(pre, sizeof pre, "%s", rel);
  for (char *dot = strrchr(pre, '.'); dot; dot = strrchr(pre, '.')) {
    *dot = '\0';
    const struct doc_key *k = doc_key_find(d, heading, pre);
    if (k) {
      char first[128];
      snprintf(first, sizeof first, "%.*s", (int)strcspn(dot + 1, "."), dot + 1);
      return has_word(k->row, line_len(k->row), first);
    }
  }
  return 0;
}

/* ----------------------------------------------------------- running the binary */

/* Runs hvsph with `args` (a shell fragment), stdout and stderr into out. */
static int hvsph(const char *args, char *out, size_t len)
{
  struct text cmd = {0};
  text_add(&cmd, "'%s' %s", test_bin(), args);
  int rc = test_run(text_str(&cmd), out, len);
  text_free(&cmd);
  return rc;
}

/* The first line of s, for messages. */
static int first_len(const char *s) { return (int)line_len(s); }

/* ------------------------------------------------------ 1. keys of the case files */

struct key_check {
  const struct doc_keys *doc;
  struct text seen;    /* "heading|rel" checked */
  struct text missing; /* the message */
  int nkeys, nmissing;
};

/* One key of used_parameters.yaml (a value, not a mapping or list of mappings). */
static void check_key(struct cfg *c, const char *path, const char *casename, struct key_check *k)
{
  /* the path's parts without list indices, and as written in a message */
  char parts[16][128], shown[1024] = "";
  int np = 0;
  for (const char *p = path; *p && np < 16;) {
    size_t l = strcspn(p, ".");
    size_t b = strcspn(p, ".[");
    snprintf(parts[np], sizeof parts[np], "%.*s", (int)b, p);
    snprintf(shown + strlen(shown), sizeof shown - strlen(shown), "%s%s%s", np ? "." : "",
             parts[np], b < l ? "[]" : "");
    np++;
    p += l;
    if (*p == '.') p++;
  }
  const char *heading[2] = {NULL, NULL};
  char eos_heading[160] = "", rel[512] = "";
  int from = 1; /* the first part of rel */
  if (np == 1) {
    heading[0] = "Top level";
    from = 0;
  } else if (!strcmp(parts[0], "materials") && np >= 3) {
    if (!strcmp(parts[2], "strength") || !strcmp(parts[2], "fracture")) {
      heading[0] = parts[2];
      from = 3;
    } else {
      char eos_path[600];
      const char *eos = "";
      struct hv_error err;
      snprintf(eos_path, sizeof eos_path, "materials.%s.eos", parts[1]);
      if (cfg_get_string(c, eos_path, "", &eos, &err)) eos = "";
      snprintf(eos_heading, sizeof eos_heading, "EOS `%s`", eos);
      heading[0] = "materials";
      heading[1] = eos_heading;
      from = 2;
    }
  } else if (!strcmp(parts[0], "bodies") && np >= 3 && !strcmp(parts[1], "shape")) {
    heading[0] = "shapes"; /* the shape's own key, in a `minus` shape too */
    from = np - 1;
  } else {
    heading[0] = parts[0];
  }
  for (int i = from; i < np; i++)
    snprintf(rel + strlen(rel), sizeof rel - strlen(rel), "%s%s", i > from ? "." : "", parts[i]);

  /* each top-level key is in the top-level table */
  if (np > 1 && !doc_key_find(k->doc, "Top level", parts[0])) {
    char id[300];
    snprintf(id, sizeof id, "Top level|%s", parts[0]);
    if (set_add(&k->seen, id)) {
      k->nmissing++;
      text_add(&k->missing,
               "\n      `%s` (in used_parameters.yaml of %s): no row `%s` in the "
               "table of \"## Top level\"",
               parts[0], casename, parts[0]);
    }
  }
  char id[800];
  snprintf(id, sizeof id, "%s|%s", heading[1] ? heading[1] : heading[0], rel);
  if (!set_add(&k->seen, id)) return;
  k->nkeys++;
  if (doc_documents(k->doc, heading[0], rel) ||
      (heading[1] && doc_documents(k->doc, heading[1], rel)))
    return;
  k->nmissing++;
  text_add(&k->missing,
           "\n      `%s` (in used_parameters.yaml of %s): no row `%s` in the table "
           "of \"%s\"%s%s%s",
           shown, casename, rel, heading[0], heading[1] ? " or of \"" : "",
           heading[1] ? heading[1] : "", heading[1] ? "\"" : "");
}

static void walk_keys(struct cfg *c, const char *path, const char *casename, struct key_check *k);

static void visit_key(struct cfg *c, const char *path, const char *casename, struct key_check *k)
{
  if (cfg_is_map(c, path)) {
    walk_keys(c, path, casename, k);
    return;
  }
  int n = cfg_len(c, path);
  char item[1200];
  snprintf(item, sizeof item, "%s[0]", path);
  if (n > 0 && cfg_is_map(c, item)) { /* a list of mappings: bodies, minus */
    for (int i = 0; i < n; i++) {
      snprintf(item, sizeof item, "%s[%d]", path, i);
      walk_keys(c, item, casename, k);
    }
    return;
  }
  check_key(c, path, casename, k);
}

static void walk_keys(struct cfg *c, const char *path, const char *casename, struct key_check *k)
{
  const char *const *names;
  int n = cfg_keys(c, path, &names);
  for (int i = 0; i < n; i++) {
    char child[1100];
    snprintf(child, sizeof child, "%s%s%s", path, *path ? "." : "", names[i]);
    visit_key(c, child, casename, k);
  }
}

/* The cases (the examples, examples/<folder>/<name>.yaml, and the case of materials,
 * "library/materials"), set up and written at t = 0 into <tmp>/runs/<folder>/<name>. */
struct example {
  char folder[32], name[128];
};

static int example_cmp(const void *a, const void *b)
{
  const struct example *x = a, *y = b;
  int c = strcmp(x->folder, y->folder);
  return c ? c : strcmp(x->name, y->name);
}

static int list_examples(struct example *ex, int max)
{
  static const char *const folders[] = {"verification", "paper", "getting-started", "sweeps"};
  int n = 0;
  for (int f = 0; f < 4; f++) {
    char dir[4200];
    snprintf(dir, sizeof dir, "%s/examples/%s", test_source_dir(), folders[f]);
    DIR *d = opendir(dir);
    CHECK(d != NULL, "examples/%s can be listed", folders[f]);
    if (!d) continue;
    struct dirent *e;
    while ((e = readdir(d)) && n < max) {
      size_t l = strlen(e->d_name);
      if (l < 6 || strcmp(e->d_name + l - 5, ".yaml") || l - 5 >= sizeof ex[n].name) continue;
      snprintf(ex[n].folder, sizeof ex[n].folder, "%s", folders[f]);
      snprintf(ex[n].name, sizeof ex[n].name, "%.*s", (int)(l - 5), e->d_name);
      n++;
    }
    closedir(d);
  }
  qsort(ex, (size_t)n, sizeof *ex, example_cmp);
  return n;
}

static const char *run_dir(const struct example *e)
{
  static char dir[4][4400];
  static int k = 0;
  char *b = dir[k++ % 4];
  snprintf(b, sizeof dir[0], "%.4000s/runs/%.31s/%.127s", test_tmpdir(), e->folder, e->name);
  return b;
}

/* A case with a small cube of each material of the library (as `hvsph materials` lists
 * them) and of three more that no example has: a tabulated EOS, fracture that splits
 * along a crack, cumulative damage; so that their keys are read too (Tillotson's,
 * Johnson-Cook's, the table's, `crack_eps_f`'s mapping, `eps_f`, `tau`). Its path. */
static const char *write_library_case(void)
{
  char out[16384];
  int rc = hvsph("materials 2>/dev/null", out, sizeof out);
  CHECK(rc == 0, "hvsph materials lists the library (exit %d)", rc);
  test_write_file("library_eos.txt", "rho_count 2 e_count 2\n1000 2000\n0 1e6\n0 4e8\n0 8e8\n");
  struct text yaml = {0};
  text_add(
      &yaml,
      "name: library\n"
      "materials:\n"
      "  table: {eos: table, file: library_eos.txt, rho0: 1000}\n"
      "  crack: {library: al-alloy, fracture: {model: tresca, sigma_c: -0.3 GPa, split: crack,\n"
      "                                        crack_eps_f: {d1: 0.1, d2: 0.2, d3: -1.5}}}\n"
      "  cumulative: {library: steel-target, fracture: {model: cumulative, sigma_c: -1 GPa,\n"
      "                                                 eps_f: 0.5, tau: 1 us}}\n"
      "bodies:\n");
  int n = 0;
  for (const char *p = out; *p; p = next_line(p)) {
    if (p[0] == '#' || !strncmp(p, "name ", 5) || p[0] == ' ' || p[0] == '\n') continue;
    text_add(&yaml,
             "  - material: %.*s\n    shape: {type: box, min: [%d mm, 0, 0], max: [%d mm, "
             "1 mm, 1 mm]}\n    spacing: 0.5 mm\n",
             (int)strcspn(p, " \n"), p, 2 * n, 2 * n + 1);
    n++;
  }
  CHECK(n >= 10, "a case with a cube of each of the library's %d materials", n);
  static const char *const more[] = {"table", "crack", "cumulative"};
  for (int k = 0; k < 3; k++, n++)
    text_add(&yaml,
             "  - material: %s\n    shape: {type: box, min: [%d mm, 0, 0], max: [%d mm, "
             "1 mm, 1 mm]}\n    spacing: 0.5 mm\n",
             more[k], 2 * n, 2 * n + 1);
  text_add(&yaml, "time: {end: 0}\n");
  const char *path = test_write_file("library.yaml", text_str(&yaml));
  text_free(&yaml);
  return path;
}

static int set_up_examples(struct example *ex, int max)
{
  int n = list_examples(ex, max);
  char out[16384];
  struct text cmd = {0};
  text_add(&cmd, "rm -rf '%s/runs'", test_tmpdir());
  test_run(text_str(&cmd), NULL, 0);
  if (n < max) {
    snprintf(ex[n].folder, sizeof ex[n].folder, "library");
    snprintf(ex[n].name, sizeof ex[n].name, "materials");
    n++;
  }
  struct text failed = {0};
  int nfailed = 0;
  for (int i = 0; i < n; i++) {
    cmd.n = 0;
    if (!strcmp(ex[i].folder, "library"))
      text_add(&cmd, "run '%s' -o '%s' --quiet", write_library_case(), run_dir(&ex[i]));
    else
      text_add(&cmd, "run '%s/examples/%s/%s.yaml' -o '%s' --quiet --set time.end=0%s",
               test_source_dir(), ex[i].folder, ex[i].name, run_dir(&ex[i]),
               strcmp(ex[i].folder, "paper") && strcmp(ex[i].folder, "sweeps")
                   ? ""
                   : " --set resolution=0.01");
    int rc = hvsph(text_str(&cmd), out, sizeof out);
    if (rc != 0) {
      nfailed++;
      text_add(&failed, "\n      %s/%s: exit %d: %.*s", ex[i].folder, ex[i].name, rc,
               first_len(out), out);
    }
  }
  CHECK(n >= 20 && nfailed == 0,
        "the %d cases (examples/verification, examples/paper at "
        "resolution 0.01, examples/getting-started, a case of materials) set up with "
        "time.end=0%s%s",
        n, nfailed ? "; failed:" : "", text_str(&failed));
  text_free(&failed);
  text_free(&cmd);
  return n;
}

static void test_case_keys(const struct example *ex, int n)
{
  char *md = read_doc("case-files.md");
  if (!md) return;
  struct doc_keys doc = {0};
  doc_keys_parse(md, &doc);
  /* the page's tables are where the test looks for them */
  static const char *const tables[] = {"Top level", "materials", "EOS `ideal-gas`", "strength",
                                       "fracture",  "bodies",    "shapes",          "domain",
                                       "sph",       "time",      "output",          "measure"};
  for (size_t t = 0; t < sizeof tables / sizeof tables[0]; t++)
    CHECK(doc_heading_keys(&doc, tables[t]) > 0,
          "docs/case-files.md has a table of keys under "
          "the heading \"%s\"",
          tables[t]);

  struct key_check k = {.doc = &doc};
  int read = 0;
  for (int i = 0; i < n; i++) {
    char path[4500];
    snprintf(path, sizeof path, "%s/used_parameters.yaml", run_dir(&ex[i]));
    struct hv_error err;
    struct cfg *c = cfg_load(path, &err);
    if (!c) continue;
    read++;
    char casename[200];
    snprintf(casename, sizeof casename, "%.31s/%.127s", ex[i].folder, ex[i].name);
    walk_keys(c, "", casename, &k);
    cfg_free(c);
  }
  CHECK(read == n && k.nkeys > 100,
        "used_parameters.yaml of %d of %d cases read: %d keys "
        "(distinct by table)",
        read, n, k.nkeys);
  CHECK(k.nmissing == 0,
        "docs/case-files.md documents every key the cases read "
        "(%d keys); %d missing:%s",
        k.nkeys, k.nmissing, text_str(&k.missing));
  text_free(&k.seen);
  text_free(&k.missing);
  free(doc.k);
  free(md);
}

/* -------------------------------------------------------- 2. command-line options */

static const char *const commands[] = {"run",    "restart", "bench",    "materials",
                                       "render", "measure", "validate", "sweep"};
#define NCOMMANDS ((int)(sizeof commands / sizeof commands[0]))

/* Adds to set every long option ("--set", "--no-mirror") in s[0, len). */
static void collect_options(const char *s, size_t len, struct text *set)
{
  for (size_t i = 0; i + 2 < len; i++) {
    if (s[i] != '-' || s[i + 1] != '-' || !(s[i + 2] >= 'a' && s[i + 2] <= 'z')) continue;
    if (i > 0 && (word_char(s[i - 1]) || s[i - 1] == '-')) continue;
    size_t j = i + 2;
    while (j < len && ((s[j] >= 'a' && s[j] <= 'z') || (s[j] >= '0' && s[j] <= '9') || s[j] == '-'))
      j++;
    char opt[64];
    snprintf(opt, sizeof opt, "%.*s", (int)(j - i), s + i);
    set_add(set, opt);
    i = j - 1;
  }
}

/* The lines of a usage text for `cmd`: from the line "<indent>hvsph CMD ..." through the
 * lines after it that are indented deeper (continuations, its description). */
static void usage_block(const char *s, const char *cmd, size_t indent, struct text *set)
{
  size_t cl = strlen(cmd);
  for (const char *p = s; *p; p = next_line(p)) {
    if (strspn(p, " ") != indent || strncmp(p + indent, "hvsph ", 6) ||
        strncmp(p + indent + 6, cmd, cl) ||
        (p[indent + 6 + cl] != ' ' && p[indent + 6 + cl] != '\n'))
      continue;
    const char *q = next_line(p);
    while (*q && strspn(q, " ") > indent && line_len(q) > strspn(q, " ")) q = next_line(q);
    collect_options(p, (size_t)(q - p), set);
  }
}

/* What a cheap call of each command is, and what it ends in when its options are fine. */
static const struct {
  const char *cmd, *base;
} cli_base[] = {
    {"run", "run @/none.yaml"},                                       /* 2: no case file */
    {"restart", "restart @/none"},                                    /* 2: no run there */
    {"bench", "bench --particles 512 --steps 1 --threads 1"},         /* 0 */
    {"materials", "materials"},                                       /* 0 */
    {"render", "render @/none.csv -o @/none.png"},                    /* 2: no snapshot */
    {"measure", "measure @/none"},                                    /* 2: no run there */
    {"validate", "validate --only wp1 --cases @/none -o @/validate"}, /* 2: no case file */
    {"sweep", "sweep @/none.yaml -o @/sweep"},                        /* 2: no case file */
};

/* A value for each option that takes one (the option is tried alone when it is not
 * here: add it when cli.md gains an option with a value). */
static const struct {
  const char *cmd, *args;
} cli_sample[] = {
    {"run", "--output @/out"},
    {"run", "--set time.end=0"},
    {"run", "--material gas=nitrogen"},
    {"run", "--threads 1"},
    {"restart", "--set time.end=0"},
    {"restart", "--threads 1"},
    {"bench", "--particles 512"},
    {"bench", "--steps 1"},
    {"bench", "--threads 1"},
    {"bench", "--set sph.eta=1.2"},
    {"render", "--output @/none.png"},
    {"render", "--mode particles"},
    {"render", "--axis y"},
    {"render", "--color density"},
    {"render", "--colour density"},
    {"render", "--size 400x300"},
    {"render", "--box 0,1mm,0,1mm,0,1mm"},
    {"render", "--mu 0.05"},
    {"render", "--range 1,2 --mode particles --color density"},
    {"measure", "--case @/none.yaml"},
    {"validate", "--scale 0.01"},
    {"validate", "--only wp1"},
    {"validate", "--output @/validate"},
    {"validate", "--threads 1"},
    {"validate", "--cases @/none"},
    {"validate", "--set time.end=0"},
    {"validate", "--material gas=nitrogen"},
    {"sweep", "--output @/sweep"},
    {"sweep", "--vary time.end=1us,2us"},
    {"sweep", "--bisect time.end=1us..2us"},
    {"sweep", "--tol 0.1us"},
    {"sweep", "--measure perforated"},
    {"sweep", "--jobs 2"},
    {"sweep", "--threads 1"},
    {"sweep", "--set time.end=0"},
    {"sweep", "--emit slurm"},
    {"sweep", "--only 0"},
    {"sweep", "--collect @/none"},
    {"sweep", "--args-from @/none"},
};

/* s with each '@' replaced by the quoted scratch folder. */
static void expand(const char *s, struct text *out)
{
  for (; *s; s++) {
    if (*s == '@')
      text_add(out, "'%s'", test_tmpdir());
    else
      text_add(out, "%c", *s);
  }
}

/* Calls `hvsph CMD` cheaply with `opt` (and its sample value); its exit status. */
static int try_option(int c, const char *opt, char *out, size_t len)
{
  const char *args = opt;
  for (size_t k = 0; k < sizeof cli_sample / sizeof cli_sample[0]; k++) {
    size_t l = strlen(opt);
    if (!strcmp(cli_sample[k].cmd, commands[c]) && !strncmp(cli_sample[k].args, opt, l) &&
        cli_sample[k].args[l] == ' ')
      args = cli_sample[k].args;
  }
  struct text cmd = {0};
  expand(cli_base[c].base, &cmd);
  text_add(&cmd, " ");
  expand(args, &cmd);
  text_add(&cmd, " </dev/null");
  int rc = hvsph(text_str(&cmd), out, len);
  text_free(&cmd);
  return rc;
}

static void test_cli_options(void)
{
  char *md = read_doc("cli.md");
  if (!md) return;
  char help[16384], out[16384];
  struct text cmdline = {0};
  text_add(&cmdline, "'%s' --help 2>/dev/null", test_bin());
  int rc = test_run(text_str(&cmdline), help, sizeof help);
  text_free(&cmdline);
  CHECK(rc == 0 && strstr(help, "  hvsph run "), "hvsph --help prints the usage (exit %d)", rc);

  /* the synopsis: cli.md's first code block */
  const char *syn = strstr(md, "```"), *syn_end = syn ? strstr(syn + 3, "\n```") : NULL;
  CHECK(syn && syn_end, "docs/cli.md opens with a synopsis in a code block");
  char *synopsis = syn && syn_end ? strndup(syn, (size_t)(syn_end - syn + 1)) : strdup("");

  struct text missing = {0}, refused = {0};
  int nmissing = 0, nrefused = 0, nlisted = 0, nhelp = 0;
  for (int c = 0; c < NCOMMANDS; c++) {
    const char *cmd = commands[c];
    /* what the help shows */
    struct text shown = {0};
    usage_block(help, cmd, 2, &shown);
    char args[200];
    snprintf(args, sizeof args, "%s --help </dev/null", cmd);
    rc = hvsph(args, out, sizeof out);
    char usage[100];
    snprintf(usage, sizeof usage, "usage: hvsph %s ", cmd);
    if (rc == 0 || !strncmp(out, usage, strlen(usage))) collect_options(out, strlen(out), &shown);

    /* what cli.md gives it: its synopsis line, its section */
    struct text listed = {0}, anywhere = {0};
    usage_block(synopsis, cmd, 0, &listed);
    char title[64];
    snprintf(title, sizeof title, "hvsph %s", cmd);
    size_t slen = 0;
    const char *sec = md_section(md, title, &slen);
    if (sec) {
      collect_options(sec, slen, &anywhere);
      int fenced = 0;
      for (const char *p = sec; p < sec + slen; p = next_line(p)) {
        const char *cell;
        size_t clen;
        if (is_fence(p))
          fenced = !fenced;
        else if (fenced && has_word(p, line_len(p), title)) {
          const char *at = strstr(p, title); /* "build/hvsph run ...": from the command on */
          if (at && at < p + line_len(p)) collect_options(at, line_len(at), &listed);
        } else if (!fenced && !md_cell(p, 0, &cell, &clen))
          collect_options(cell, clen, &listed);
      }
    }

    /* help -> docs */
    const char *s = text_str(&shown);
    for (const char *o = strstr(s, "\n--"); o; o = strstr(o + 1, "\n--")) {
      char opt[64];
      snprintf(opt, sizeof opt, "%.*s", (int)strcspn(o + 1, "\n"), o + 1);
      nhelp++;
      if (!set_has(&listed, opt) && !set_has(&anywhere, opt)) {
        nmissing++;
        text_add(&missing,
                 "\n      hvsph %s %s (its help shows it; not in the synopsis line "
                 "nor in a section \"## hvsph %s\")",
                 cmd, opt, cmd);
      }
    }
    /* docs -> the command takes it */
    s = text_str(&listed);
    for (const char *o = strstr(s, "\n--"); o; o = strstr(o + 1, "\n--")) {
      char opt[64];
      snprintf(opt, sizeof opt, "%.*s", (int)strcspn(o + 1, "\n"), o + 1);
      nlisted++;
      rc = try_option(c, opt, out, sizeof out);
      if (rc == 1) {
        nrefused++;
        text_add(&refused, "\n      hvsph %s %s: exit 1 (bad command line): %.*s", cmd, opt,
                 first_len(out), out);
      }
    }
    /* ... and an option it does not take is refused, so that the call above tells */
    rc = try_option(c, "--no-such-option", out, sizeof out);
    CHECK(rc == 1, "hvsph %s --no-such-option: exit %d (want 1): %.*s", cmd, rc, first_len(out),
          out);
    text_free(&shown);
    text_free(&listed);
    text_free(&anywhere);
  }
  CHECK(nhelp > 20 && nmissing == 0,
        "docs/cli.md has every option the commands' help shows "
        "(%d); %d missing:%s",
        nhelp, nmissing, text_str(&missing));
  CHECK(nlisted > 20 && nrefused == 0,
        "every option docs/cli.md gives a command (%d) is taken by "
        "it; %d refused:%s",
        nlisted, nrefused, text_str(&refused));
  text_free(&missing);
  text_free(&refused);
  free(synopsis);
  free(md);
}

/* ------------------------------------------------------------ 3. output columns */

/* The header line of a CSV table (after its # comments); NULL if none. Caller frees. */
static char *csv_header(const char *text)
{
  for (const char *p = text; p && *p; p = next_line(p))
    if (p[0] != '#') return strndup(p, line_len(p));
  return NULL;
}

/* Each of the names (separated by any of `sep`, in a string that is cut up) is set as
 * code in the page section [sec, sec + slen): the count, with those missing listed in
 * *missing and counted in *nmissing. */
static int names_in_code(const char *sec, size_t slen, char *names, const char *sep,
                         struct text *missing, int *nmissing)
{
  struct text code = {0};
  md_code(sec, slen, &code);
  int n = 0;
  char *save = NULL;
  for (char *w = strtok_r(names, sep, &save); w; w = strtok_r(NULL, sep, &save)) {
    n++;
    if (!has_word(text_str(&code), code.n, w)) {
      (*nmissing)++;
      text_add(missing, " `%s`", w);
    }
  }
  text_free(&code);
  return n;
}

static void test_summary_columns(const struct example *sod)
{
  char *md = read_doc("output-files.md");
  char path[4500];
  snprintf(path, sizeof path, "%s/summary.csv", run_dir(sod));
  char *csv = test_slurp(path, NULL), *header = csv ? csv_header(csv) : NULL;
  CHECK(header != NULL, "the Sod run's summary.csv has a header (%s)", path);
  size_t slen = 0;
  const char *sec = md ? md_section(md, "summary.csv", &slen) : NULL;
  CHECK(sec != NULL, "docs/output-files.md has a section \"## summary.csv\"");
  if (header && sec) {
    struct text missing = {0};
    int nmissing = 0;
    const int n = names_in_code(sec, slen, header, ",", &missing, &nmissing);
    CHECK(n >= 11 && nmissing == 0,
          "docs/output-files.md, section summary.csv, has every "
          "column of summary.csv (%d); %d missing:%s",
          n, nmissing, text_str(&missing));
    text_free(&missing);
  }
  free(header);
  free(csv);
  free(md);
}

/* Whether the n bytes at s hold the text w. */
static int span_has(const char *s, size_t n, const char *w)
{
  const size_t wl = strlen(w);
  for (size_t i = 0; i + wl <= n; i++)
    if (!memcmp(s + i, w, wl)) return 1;
  return 0;
}

/* Every column of a particle snapshot (CSV) and every array of its VTU, of a case that
 * writes all of them (strength, the crack's fields, the viscosity switch), in
 * output-files.md's sections on the two formats. */
static void test_particle_columns(void)
{
  const char *yaml =
      "name: columns\n"
      "materials:\n"
      "  al: {library: al-alloy, fracture: {split: crack}}\n"
      "bodies:\n"
      "  - {name: b, material: al, spacing: 1 mm, shape: {type: box, min: [0, 0, 0], "
      "max: [3 mm, 3 mm, 3 mm]}}\n"
      "sph: {viscosity: {switch: cullen-dehnen}}\n"
      "time: {end: 0}\n"
      "output: {csv: true}\n";
  const char *path = test_write_file("columns.yaml", yaml);
  char dir[4400], args[9000], out[16384], file[4500];
  snprintf(dir, sizeof dir, "%.4000s/runs/columns", test_tmpdir());
  snprintf(args, sizeof args, "run '%s' -o '%s' --overwrite --quiet", path, dir);
  int rc = hvsph(args, out, sizeof out);
  CHECK(rc == 0, "a case writing every particle field runs (exit %d): %.*s", rc, first_len(out),
        out);
  char *md = read_doc("output-files.md");
  static const char *const sections[2] = {"Particle snapshots as CSV",
                                          "Particle snapshots: VTU and PVD (ParaView)"};
  for (int f = 0; f < 2 && md; f++) {
    size_t slen = 0;
    const char *sec = md_section(md, sections[f], &slen);
    CHECK(sec != NULL, "docs/output-files.md has a section \"## %s\"", sections[f]);
    snprintf(file, sizeof file, "%s/particles_00000.%s", dir, f ? "vtu" : "csv");
    size_t size = 0;
    char *text = test_slurp(file, &size);
    CHECK(text != NULL, "the run wrote %s", file);
    if (!sec || !text) {
      free(text);
      continue;
    }
    struct text names = {0}, missing = {0};
    if (f == 0) { /* the header line */
      char *header = csv_header(text);
      text_add(&names, "%s", header ? header : "");
      free(header);
    } else { /* Name="..." of each DataArray, before the appended data */
      const char *end = strstr(text, "<AppendedData");
      for (const char *p = strstr(text, "Name=\""); p && (!end || p < end);
           p = strstr(p + 1, "Name=\"")) {
        /* the FieldData arrays named after the case's materials and bodies ("mat al",
           "body b") are documented by their pattern, checked below */
        if (!strncmp(p + 6, "mat ", 4) || !strncmp(p + 6, "body ", 5)) continue;
        text_add(&names, "%.*s\n", (int)strcspn(p + 6, "\""), p + 6);
      }
      CHECK(strstr(text, "Name=\"mat al\"") && strstr(text, "Name=\"body b\"") &&
                span_has(sec, slen, "`mat <name>`") && span_has(sec, slen, "`body <name>`"),
            "the VTU's FieldData names material al and body b, and the section says so "
            "(`mat <name>`, `body <name>`)");
    }
    int nmissing = 0;
    const int n = names.s ? names_in_code(sec, slen, names.s, ",\n", &missing, &nmissing) : 0;
    CHECK(n >= (f ? 17 : 28) && nmissing == 0,
          "docs/output-files.md, section %s, has every "
          "%s of %s (%d); %d missing:%s",
          sections[f], f ? "array" : "column", file, n, nmissing, text_str(&missing));
    text_free(&names);
    text_free(&missing);
    free(text);
  }
  free(md);
}

/* Every complete case among the pages' examples (a ```yaml block with `bodies:` and
 * `time:`) sets up: an example a reader copies must run. */
static void test_example_blocks(void)
{
  static const char *const pages[] = {"../README.md",    "case-files.md", "units.md",
                                      "verification.md", "validation.md", "models.md"};
  struct text failed = {0};
  int nblocks = 0, nfailed = 0;
  for (size_t k = 0; k < sizeof pages / sizeof pages[0]; k++) {
    char *md = NULL;
    if (!strncmp(pages[k], "../", 3)) { /* the README of this source tree */
      char path[4400];
      snprintf(path, sizeof path, "%s/%s", test_source_dir(), pages[k] + 3);
      md = test_slurp(path, NULL);
      CHECK(md != NULL, "%s can be read", path);
    } else {
      md = read_doc(pages[k]);
    }
    int line = 1;
    for (const char *p = md; p && *p; p = next_line(p), line++) {
      if (strncmp(p, "```yaml", 7) || p[7] != '\n') continue;
      const int start = line;
      struct text block = {0};
      for (p = next_line(p), line++; *p && !is_fence(p); p = next_line(p), line++)
        text_add(&block, "%.*s\n", (int)line_len(p), p);
      const char *b = text_str(&block);
      if (strstr(b, "\nbodies:") && (strstr(b, "\ntime:") || !strncmp(b, "time:", 5))) {
        char name[64], dir[4400], args[9000], out[16384];
        snprintf(name, sizeof name, "example_%d.yaml", nblocks);
        const char *path = test_write_file(name, b);
        snprintf(dir, sizeof dir, "%.4000s/runs/example_%d", test_tmpdir(), nblocks);
        snprintf(args, sizeof args, "run '%s' -o '%s' --overwrite --quiet --set time.end=0", path,
                 dir);
        const int rc = hvsph(args, out, sizeof out);
        nblocks++;
        if (rc != 0) {
          nfailed++;
          text_add(&failed, "\n      %s:%d: exit %d: %.*s", pages[k], start, rc, first_len(out),
                   out);
        }
      }
      text_free(&block);
      if (!*p) break;
    }
    free(md);
  }
  CHECK(nblocks >= 6 && nfailed == 0,
        "the %d complete example cases of README.md and docs/ "
        "set up with time.end=0%s%s",
        nblocks, nfailed ? "; failed:" : "", text_str(&failed));
  text_free(&failed);
}

/* ------------------------------------------------- README's validation table (part 4) */

/* A value as a page prints it: "173.5 mm (−10.4 %)" → 173.5, 1 decimal, unit "mm",
 * error −10.4 with 1 decimal. "−" (U+2212) is a minus. Returns 0 when the text does not
 * start with a number. */
struct shown {
  double v, err;
  int dv, derr, has_err;
  char unit[16];
};

static int parse_number(const char *s, size_t len, size_t *used, double *v, int *dec)
{
  char buf[64];
  size_t i = 0, k = 0;
  while (i < len && s[i] == ' ') i++;
  if (i < len && s[i] == '+')
    i++;
  else if (i + 2 < len && !strncmp(s + i, "\xe2\x88\x92", 3))
    buf[k++] = '-', i += 3;
  else if (i < len && s[i] == '-')
    buf[k++] = '-', i++;
  const size_t d0 = i;
  int dot = -1;
  while (i < len && k < sizeof buf - 1 &&
         ((s[i] >= '0' && s[i] <= '9') || (s[i] == '.' && dot < 0))) {
    if (s[i] == '.') dot = (int)(i - d0);
    buf[k++] = s[i++];
  }
  if (i == d0) return 0;
  buf[k] = 0;
  *v = strtod(buf, NULL);
  *dec = dot < 0 ? 0 : (int)(i - d0) - dot - 1;
  *used = i;
  return 1;
}

static int parse_shown(const char *s, size_t len, struct shown *o)
{
  memset(o, 0, sizeof *o);
  size_t i;
  if (!parse_number(s, len, &i, &o->v, &o->dv)) return 0;
  while (i < len && s[i] == ' ') i++;
  size_t u = 0;
  while (i < len && s[i] != ' ' && s[i] != '(' && s[i] != ',' && u < sizeof o->unit - 1)
    o->unit[u++] = s[i++];
  o->unit[u] = 0;
  const char *par = memchr(s + i, '(', len - i);
  if (par) {
    size_t used;
    const size_t rest = len - (size_t)(par + 1 - s);
    if (parse_number(par + 1, rest, &used, &o->err, &o->derr) && used < rest &&
        memchr(par + 1 + used, '%', rest - used))
      o->has_err = 1;
  }
  return 1;
}

/* x rounded to d decimals is y (y as printed with d decimals). */
static int same_at(double x, double y, int d)
{
  return fabs(x - y) <= 0.5 * pow(10.0, -d) * (1.0 + 1e-9);
}

/* The number after the first `lead` within s[0, len): X of "lead X %", or NAN. */
static double number_after(const char *s, size_t len, const char *lead)
{
  const size_t ll = strlen(lead);
  for (size_t i = 0; i + ll <= len; i++) {
    if (strncmp(s + i, lead, ll)) continue;
    double v;
    int d;
    size_t used;
    if (!parse_number(s + i + ll, len - i - ll, &used, &v, &d)) break;
    return v;
  }
  return NAN;
}

static void test_readme_validation(void)
{
  char path[4400];
  snprintf(path, sizeof path, "%s/README.md", test_source_dir());
  char *readme = test_slurp(path, NULL);
  char *val = read_doc("validation.md");
  CHECK(readme && val, "README.md and docs/validation.md can be read");
  if (!readme || !val) {
    free(readme);
    free(val);
    return;
  }
  size_t rlen = 0, slen = 0;
  const char *rs = md_section(readme, "Validation", &rlen);
  const char *ss = md_section(val, "Status", &slen);
  CHECK(rs != NULL && ss != NULL, "README.md has a section \"Validation\" and "
                                  "docs/validation.md one \"Status\"");
  if (!rs || !ss) {
    free(readme);
    free(val);
    return;
  }
  /* the Status rows: hvsph value (cell 2) and its error against the experiment (cell 5) */
  struct shown st[256];
  int nst = 0;
  for (const char *p = ss; p < ss + slen && nst < 256; p = next_line(p)) {
    const char *c;
    size_t n;
    if (md_cell(p, 2, &c, &n) || !parse_shown(c, n, &st[nst])) continue;
    const char *e;
    size_t en;
    struct shown err;
    st[nst].has_err = 0;
    if (!md_cell(p, 5, &e, &en) && parse_shown(e, en, &err) && !strcmp(err.unit, "%")) {
      st[nst].has_err = 1;
      st[nst].err = err.v;
      st[nst].derr = err.dv;
    }
    nst++;
  }
  struct text bad = {0};
  int nvals = 0;
  for (const char *p = rs; p < rs + rlen; p = next_line(p)) {
    const char *c;
    size_t n;
    if (md_cell(p, 2, &c, &n)) continue;
    trim(&c, &n);
    while (n) { /* the parts of "a (e) / b (e)" */
      const char *sl = NULL;
      for (size_t i = 0; i + 3 <= n && !sl; i++)
        if (!strncmp(c + i, " / ", 3)) sl = c + i;
      const size_t pn = sl ? (size_t)(sl - c) : n;
      struct shown r;
      if (parse_shown(c, pn, &r)) {
        nvals++;
        int found = 0;
        for (int k = 0; k < nst && !found; k++)
          found = !strcmp(st[k].unit, r.unit) && same_at(st[k].v, r.v, r.dv) &&
                  (!r.has_err || (st[k].has_err && same_at(st[k].err, r.err, r.derr)));
        if (!found) text_add(&bad, "\n      README: %.*s", (int)pn, c);
      }
      if (!sl) break;
      n -= pn + 3;
      c = sl + 3;
    }
  }
  CHECK(nvals >= 20 && !bad.n,
        "the %d values of README's validation table are the Status "
        "table's of docs/validation.md (value and error at README's digits)%s%s",
        nvals, bad.n ? "; not found there:" : "", text_str(&bad));
  text_free(&bad);
  /* the mean hole errors, hvsph's and KERNEL's */
  const double sh = number_after(ss, slen, "mean absolute error is ");
  const double sk = number_after(ss, slen, "% against KERNEL's ");
  const double rh = number_after(rs, rlen, "mean hole error is ");
  const double rk = number_after(rs, rlen, "%, KERNEL's ");
  CHECK(!isnan(sh) && !isnan(sk) && sh == rh && sk == rk,
        "README's mean hole errors (%g %%, "
        "KERNEL %g %%) are the Status's (%g %%, %g %%)",
        rh, rk, sh, sk);
  free(readme);
  free(val);
}

/* The quantities of measurements.md's table in its section measurements.csv: "name\tunit". */
static void doc_quantities(const char *sec, size_t slen, struct text *q)
{
  for (const char *p = sec; p < sec + slen; p = next_line(p)) {
    const char *names, *unit;
    size_t nl, ul;
    if (md_cell(p, 0, &names, &nl) || md_cell(p, 1, &unit, &ul)) continue;
    trim(&unit, &ul);
    if (ul == strlen("–") && !strncmp(unit, "–", ul)) ul = 0; /* – : no unit */
    for (const char *a = memchr(names, '`', nl); a && a < names + nl;) {
      const char *e = memchr(a + 1, '`', (size_t)(names + nl - a - 1));
      if (!e) break;
      char entry[200];
      snprintf(entry, sizeof entry, "%.*s\t%.*s", (int)(e - a - 1), a + 1, (int)ul, unit);
      set_add(q, entry);
      a = memchr(e + 1, '`', (size_t)(names + nl - e - 1));
    }
  }
}

static void test_measurement_quantities(const struct example *ex, int n)
{
  char *md = read_doc("measurements.md");
  size_t slen = 0;
  const char *sec = md ? md_section(md, "measurements.csv", &slen) : NULL;
  CHECK(sec != NULL, "docs/measurements.md has a section \"## measurements.csv\"");
  if (!sec) {
    free(md);
    return;
  }
  struct text doc = {0}, seen = {0}, missing = {0};
  doc_quantities(sec, slen, &doc);
  int files = 0, nq = 0, nmissing = 0, nbad = 0;
  for (int i = 0; i < n; i++) {
    if (strcmp(ex[i].folder, "paper")) continue;
    char path[4500];
    snprintf(path, sizeof path, "%s/measurements.csv", run_dir(&ex[i]));
    char *csv = test_slurp(path, NULL);
    char *header = csv ? csv_header(csv) : NULL;
    if (!header) {
      free(csv);
      continue;
    }
    files++;
    /* the columns quantity and unit, by name */
    int cq = -1, cu = -1, col = 0;
    for (char *h = strtok(header, ","); h; h = strtok(NULL, ","), col++) {
      if (!strcmp(h, "quantity")) cq = col;
      if (!strcmp(h, "unit")) cu = col;
    }
    if (cq < 0 || cu < 0) {
      nbad++;
      text_add(&missing, "\n      %s: no column quantity or unit", path);
    }
    int past_header = 0;
    for (const char *p = csv; *p && cq >= 0 && cu >= 0; p = next_line(p)) {
      if (p[0] == '#') continue;
      if (!past_header++) continue;
      char field[2][128] = {"", ""};
      const char *f = p;
      for (int k = 0; k <= cq || k <= cu; k++) {
        size_t l = strcspn(f, ",\n");
        if (k == cq) snprintf(field[0], sizeof field[0], "%.*s", (int)l, f);
        if (k == cu) snprintf(field[1], sizeof field[1], "%.*s", (int)l, f);
        f += l;
        if (*f != ',') break;
        f++;
      }
      char entry[300];
      snprintf(entry, sizeof entry, "%s\t%s", field[0], field[1]);
      if (!set_add(&seen, entry)) continue;
      nq++;
      if (set_has(&doc, entry)) continue;
      nmissing++;
      /* the name with another unit, or not at all */
      char name_tab[200];
      snprintf(name_tab, sizeof name_tab, "\n%s\t", field[0]);
      const char *other = strstr(text_str(&doc), name_tab);
      if (other)
        text_add(&missing, "\n      `%s` [%s] (in %s/%s): the table gives the unit [%.*s]",
                 field[0], field[1], ex[i].folder, ex[i].name,
                 (int)strcspn(other + strlen(name_tab), "\n"), other + strlen(name_tab));
      else
        text_add(&missing, "\n      `%s` [%s] (in %s/%s): not in the table", field[0], field[1],
                 ex[i].folder, ex[i].name);
    }
    free(header);
    free(csv);
  }
  CHECK(files >= 3 && nq > 30 && nmissing + nbad == 0,
        "docs/measurements.md, section "
        "measurements.csv, has every quantity (with its unit) of the paper cases' "
        "measurements.csv (%d files, %d quantities); %d missing:%s",
        files, nq, nmissing, text_str(&missing));
  text_free(&doc);
  text_free(&seen);
  text_free(&missing);
  free(md);
}

int main(void)
{
  /* the material library of this source tree, also for builds outside it */
  char data[4200];
  snprintf(data, sizeof data, "%s/data", test_source_dir());
  setenv("HVSPH_DATA", data, 0);
  printf("  docs: %s\n", docs_dir());

  static struct example ex[256];
  int n = set_up_examples(ex, 256);
  test_case_keys(ex, n);
  test_cli_options();
  const struct example *sod = NULL;
  for (int i = 0; i < n; i++)
    if (!strcmp(ex[i].folder, "verification") && !strcmp(ex[i].name, "sod")) sod = &ex[i];
  CHECK(sod != NULL, "examples/verification/sod.yaml is among the cases");
  if (sod) test_summary_columns(sod);
  test_particle_columns();
  test_example_blocks();
  test_measurement_quantities(ex, n);
  test_readme_validation();
  return test_finish();
}
