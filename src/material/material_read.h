/* material_read.h — reading materials from a case file or the library, and listing them.
 *
 * The one header of material/ that includes the config layer: .c files that read or
 * list materials include it (the models' files among them, for the helpers below);
 * physics headers (material.h, eos.h, strength.h) do not.
 */
#ifndef HV_MATERIAL_READ_H
#define HV_MATERIAL_READ_H

#include <stdio.h>

#include "config/config.h"
#include "material/material.h"

/* Reads the material defined at `path` (a mapping, e.g. "materials.steel") from the
 * case, after grafting the library entry it names (`library: NAME`) under it: keys the
 * case gives override the library's (cfg_graft). Keys: see docs/models.md, "Material
 * library". Errors name the file and line (the library's for library values), the key
 * path (which holds the material name) and the rule broken. */
int material_read(struct cfg *c, const char *path, const char *name, struct material *m,
                  struct hv_error *err);

/* ---- helpers for the models' readers (material.c) ---- */

/* "path.key" into buf; returns buf. */
const char *material_key(char *buf, size_t len, const char *path, const char *key);
/* "file:line: key: message" (the line of the key, or of the deepest node present) in
 * err, exit status 2; returns -1. */
int material_key_error(struct cfg *c, const char *key, struct hv_error *err, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
/* The key is present and written in the case itself, not grafted from the library. */
int material_from_case(struct cfg *c, const char *key);
/* The quantity path.key in unit dimension dim, within [lo, hi]; def NULL: required. */
int material_get_q(struct cfg *c, const char *path, const char *key, enum unit_dim dim,
                   const double *def, double lo, double hi, double *out, struct hv_error *err);
/* A key the chosen model does not use: an error (`why`) if the case wrote it; the
 * library's is ignored, so that a case may switch a library material to another model
 * (material.c's header). */
int material_not_used_here(struct cfg *c, const char *path, const char *key, const char *why,
                           struct hv_error *err);
/* One parameter of `hvsph materials NAME`: name, SI value and unit, and a familiar unit
 * alongside (library.c). */
void material_print_quantity(FILE *f, const char *name, double v, const char *unit);

/* ---- the material library, data/materials.yaml (material/library.c) ---- */

/* The library file: $HVSPH_DATA/materials.yaml if HVSPH_DATA is set; else
 * HVSPH_DATA_DIR/materials.yaml if that compile definition exists and the file is there;
 * else <folder of the running program>/../data/materials.yaml (the build folder inside
 * the source tree), then <program folder>/../share/hvsph/materials.yaml (installed). */
int material_library_path(char *buf, size_t len, struct hv_error *err);
/* Loads the library (path NULL: material_library_path()). *lib is freed with cfg_free. */
int material_library_load(const char *path, struct cfg **lib, struct hv_error *err);
/* Reads library entry `name` as the case's material: grafts it into the case as
 * materials.NAME (so used_parameters.yaml records it) and reads it from there.
 * Unknown name: error listing the library's names. */
int material_read_from_library(struct cfg *c, const char *name, struct material *m,
                               struct hv_error *err);
/* The material a key names (e.g. key_path "bodies[0].material", value `name`): its index
 * in mats[0 .. *nmat) if already read; else the case's materials.NAME or, failing that,
 * the library entry NAME, read into mats[*nmat] (and *nmat incremented). Returns the
 * index, or -1: "case.yaml:12: bodies[0].material: unknown material 'x' (the case
 * defines: a, b; the library data/materials.yaml has: ...)". */
int material_find_or_load(struct cfg *c, const char *key_path, const char *name,
                          struct material *mats, int *nmat, int max, struct hv_error *err);
/* Prints every parameter of a material with its unit (hvsph materials NAME). */
void material_print(FILE *f, const struct material *m);
/* `hvsph materials [NAME]`: lists the library (name NULL), or one entry in full.
 * Returns the exit status (2 for an unknown name or a bad library). */
int material_library_list(const char *name);
/* The usage of `hvsph materials`. */
void material_library_usage(FILE *f);

#endif
