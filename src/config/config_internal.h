/* config_internal.h — the document tree shared by config.c (loading, paths, --set,
 * grafts), config_get.c (typed getters, records) and config_used.c (unknown keys,
 * used_parameters.yaml). Not for use outside src/config/.
 */
#ifndef HV_CONFIG_INTERNAL_H
#define HV_CONFIG_INTERNAL_H

#include <stddef.h>

#include "config/config.h"

#define CFG_LINE_SET  (-1) /* line of nodes created by --set */
#define CFG_MAX_DEPTH 64   /* components in a path */

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
  int si_record; /* the document is a used_parameters.yaml (it starts with CFG_USED_HEADER):
                    every number in it is SI, written so by hvsph (cfg_check_typical) */
};

/* The first words of used_parameters.yaml (cfg_write_used). */
#define CFG_USED_HEADER "# Parameters used by hvsph "

/* One path component: a key (key != NULL) or a sequence index. */
struct path_comp {
  const char *start; /* where the component starts in the path text */
  const char *key;
  size_t klen;
  int index;
};

/* config.c: nodes. Strings and nodes are allocated with hv_malloc (never NULL). */
char *cfg_strndup(const char *s, size_t n);
char *cfg_strdup(const char *s);
struct cfg_node *cfg_node_new(enum cfg_kind kind, int line);
void cfg_node_free(struct cfg_node *n); /* the whole subtree; NULL is ignored */
/* Appends a child (key NULL for sequences); takes ownership of key. */
void cfg_node_add(struct cfg_node *p, char *key, struct cfg_node *child);
/* Index of key (klen bytes) in mapping p; -1 if absent or p is not a mapping. */
int cfg_node_find(const struct cfg_node *p, const char *key, size_t klen);
/* "a mapping", "a sequence", "a single value" (for messages). */
const char *cfg_kind_name(enum cfg_kind k);

/* config.c: paths. */
/* Splits "a.b[2].c" into components; returns the count or -1 if malformed. */
int cfg_path_parse(const char *path, struct path_comp *comp, int max);
/* Walks the path; *deepest (if not NULL) gets the last node reached (for messages). */
struct cfg_node *cfg_lookup(struct cfg *c, const char *path, struct cfg_node **deepest);
/* "file:line" of a node: `file` is the node's own (grafts) or NULL for the document's;
 * "--set" for CFG_LINE_SET, just the file for line 0. Returns buf. */
const char *cfg_where_line(const struct cfg *c, const char *file, int line, char *buf, size_t len);
/* A scalar written without a value: empty, `~` or `null`, unquoted (YAML's null). */
int cfg_scalar_is_null(const struct cfg_node *n);

/* config_used.c: optimal string alignment distance of a (la bytes) and b (lb bytes):
 * edits and adjacent swaps, capped at 9 (the "did you mean" hints). */
int cfg_edit_distance(const char *a, size_t la, const char *b, size_t lb);

/* config_get.c: a YAML double-quoted string (escapes ", \ and control characters);
 * malloc'ed. */
char *cfg_yaml_quote(const char *s);

#endif
