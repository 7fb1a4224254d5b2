/* config.h — the case file: YAML (libfyaml) with units, line numbers and key tracking.
 *
 * Paths name nodes: "time.end", "bodies[1].velocity", "materials.gas.gamma".
 * Every getter records the path and the value it returned (defaults included), so
 * that cfg_write_used() can write used_parameters.yaml and cfg_check_unused() can
 * reject every key the program never asked for (typos: "yeild").
 * Errors name the file, line and key: "case.yaml:14: bodies[0].velocity: unit 'kg'
 * is a mass, expected a velocity". All errors carry code HV_EXIT_INPUT.
 */
#ifndef HV_CONFIG_H
#define HV_CONFIG_H

#include "core/error.h"
#include "core/units.h"

struct cfg;

/* Reads and parses a YAML case file. NULL (and err) on a missing file or YAML error. */
struct cfg *cfg_load(const char *path, struct hv_error *err);
/* An empty document (for programs that build cases in code, e.g. bench, tests). */
struct cfg *cfg_new_empty(const char *name);
/* Parses YAML from a string (tests; `name` stands for the file in messages). */
struct cfg *cfg_load_string(const char *yaml, const char *name, struct hv_error *err);
void cfg_free(struct cfg *c);
const char *cfg_file(const struct cfg *c);

/* Applies "a.b[0].c=value" (the --set option): replaces or creates the key;
 * the value is parsed as YAML flow (so "[1, 2, 3]" or "6 km/s" work). Logs it. */
int cfg_apply_set(struct cfg *c, const char *assignment, struct hv_error *err);

/* Structure queries (these do not mark anything as used). */
int cfg_has(struct cfg *c, const char *path);
int cfg_len(struct cfg *c, const char *path); /* sequence length, -1 if none */
int cfg_is_map(struct cfg *c, const char *path);
/* Keys of a mapping in document order; *names valid until cfg_free. Returns count or -1. */
int cfg_keys(struct cfg *c, const char *path, const char *const **names);
/* Marks a whole subtree as used (e.g. a section another module reads itself). */
void cfg_mark_used(struct cfg *c, const char *path);
/* "case.yaml:14" for a path (or just "case.yaml" if absent). */
const char *cfg_where(struct cfg *c, const char *path, char *buf, size_t len);

/* Grafts: copies the mapping at src_path of document src (NULL or "" for its root) into
 * dst at dst_path (created as a mapping if missing), key by key, where dst has no such
 * key; mappings present in both are merged the same way, so any key dst gives overrides
 * src's. Copied nodes keep their file name and line, so messages about them name
 * e.g. "data/materials.yaml:31". Copied nodes count as used: the reader of dst decides
 * which of them apply (a case that switches the EOS of a library material leaves the
 * library's EOS parameters unread), and src is checked for unknown keys on its own.
 * src may be freed afterwards. Used for `library: NAME` in materials. */
int cfg_graft(struct cfg *dst, const char *dst_path, struct cfg *src, const char *src_path,
              struct hv_error *err);
/* The file a node came from: its graft source, or cfg_file(c) (also for absent paths). */
const char *cfg_node_file(struct cfg *c, const char *path);

/* Typed getters. `def` NULL means required. Range [lo, hi] inclusive after unit
 * conversion; use -HUGE_VAL/HUGE_VAL for none. Return 0 or -1 with err set. */
int cfg_get_quantity(struct cfg *c, const char *path, enum unit_dim dim, const double *def,
                     double lo, double hi, double *out, struct hv_error *err);
/* Wrong units: a value at path written as a bare number (no unit, so SI) whose
 * magnitude lies outside [lo, hi], the range `what` spans in real materials ("bulk sound
 * speeds of condensed materials"), is an error naming the file, line and key, with the
 * likely unit when one brings it into the range ("5.35 ... was it 5.35 km/s?"). A value
 * written with its unit, 0, and an absent key pass: a unit says the value is meant; so
 * does a value of a run's used_parameters.yaml, whose numbers hvsph wrote in SI (unless
 * a --set gives it anew). */
int cfg_check_typical(struct cfg *c, const char *path, enum unit_dim dim, double lo, double hi,
                      const char *what, struct hv_error *err);
/* Whether the value at path is a number written without a unit in input (as for
 * cfg_check_typical: not one of a used_parameters.yaml's SI numbers, unless a --set's). */
int cfg_is_bare(struct cfg *c, const char *path);
/* A sequence of three quantities ("[0, 1.5 mm, 0]"). */
int cfg_get_vec3(struct cfg *c, const char *path, enum unit_dim dim, const double *def,
                 double out[3], struct hv_error *err);
/* A sequence of quantities of any length; *out malloc'ed (caller frees). */
int cfg_get_list(struct cfg *c, const char *path, enum unit_dim dim, double **out, int *n,
                 struct hv_error *err);
int cfg_get_int(struct cfg *c, const char *path, const long *def, long lo, long hi, long *out,
                struct hv_error *err);
int cfg_get_bool(struct cfg *c, const char *path, const int *def, int *out, struct hv_error *err);
/* *out valid until cfg_free. */
int cfg_get_string(struct cfg *c, const char *path, const char *def, const char **out,
                   struct hv_error *err);
/* Records the string `value` for path in used_parameters.yaml, in place of what a getter
 * recorded there (or as a new key): what the program used where it differs from what
 * was written, so that the file runs the same from anywhere (an EOS table's path,
 * resolved; its checksum). Marks nothing used. */
void cfg_record_string(struct cfg *c, const char *path, const char *value);
/* One of `choices` (NULL-terminated); *out is its index. */
int cfg_get_choice(struct cfg *c, const char *path, const char *def, const char *const *choices,
                   int *out, struct hv_error *err);

/* Error for every key in the document never queried: lists them all with lines
 * ("case.yaml:7: unknown key 'sph.etta'"). */
int cfg_check_unused(struct cfg *c, struct hv_error *err);
/* Writes every queried value (SI, with unit comments; defaults marked) as YAML,
 * headed by the hvsph version and the case file name; atomically (tmp + rename). */
int cfg_write_used(struct cfg *c, const char *path, const char *version, struct hv_error *err);

#endif
