/* library.c — the material library data/materials.yaml: finding and loading it, reading
 * a case's materials from it, and the `hvsph materials [NAME]` listing.
 *
 * The library is a YAML mapping from material names to material mappings, in the same
 * keys a case file uses under `materials:` (docs/models.md, "Material library").
 * A case refers to an entry with `library: NAME` (and may override any key), or simply
 * names it as a body's material.
 */
#define _XOPEN_SOURCE 700 /* realpath */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "material/material_read.h"

static int file_exists(const char *path) { return access(path, R_OK) == 0; }

int material_library_path(char *buf, size_t len, struct hv_error *err)
{
  const char *env = getenv("HVSPH_DATA");
  if (env && *env) {
    snprintf(buf, len, "%s/materials.yaml", env);
    if (file_exists(buf)) return 0;
    return hv_error_set(err, HV_EXIT_INPUT, "HVSPH_DATA=%s: no readable materials.yaml there", env);
  }
#ifdef HVSPH_DATA_DIR
  snprintf(buf, len, "%s/materials.yaml", HVSPH_DATA_DIR);
  if (file_exists(buf)) return 0;
#endif
  char exe[4096];
  ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (n > 0) {
    exe[n] = '\0';
    char *slash = strrchr(exe, '/');
    if (slash) {
      *slash = '\0';
      snprintf(buf, len, "%s/../data/materials.yaml", exe);
      if (file_exists(buf)) return 0;
      snprintf(buf, len, "%s/../share/hvsph/materials.yaml", exe);
      if (file_exists(buf)) return 0;
    }
  }
  return hv_error_set(err, HV_EXIT_INPUT,
                      "cannot find the material library materials.yaml "
                      "(looked next to the program in ../data and ../share/hvsph); set "
                      "HVSPH_DATA to the folder that holds it");
}

int material_library_load(const char *path, struct cfg **lib, struct hv_error *err)
{
  char buf[4096];
  if (!path) {
    if (material_library_path(buf, sizeof buf, err)) return -1;
    path = buf;
  }
  char real[PATH_MAX];
  if (realpath(path, real)) path = real; /* "build/../data/x" -> "data/x" in messages */
  *lib = cfg_load(path, err);
  return *lib ? 0 : -1;
}

/* "a, b, c" from the keys of a mapping. */
static void name_list(struct cfg *c, const char *path, char *buf, size_t len)
{
  const char *const *names;
  int n = cfg_keys(c, path, &names);
  size_t k = 0;
  buf[0] = '\0';
  for (int i = 0; i < n && k < len; i++)
    k += (size_t)snprintf(buf + k, len - k, "%s%s", i ? ", " : "", names[i]);
  if (n <= 0) snprintf(buf, len, "none");
}

int material_read_from_library(struct cfg *c, const char *name, struct material *m,
                               struct hv_error *err)
{
  struct cfg *lib;
  if (material_library_load(NULL, &lib, err)) return -1;
  int rc;
  char path[320];
  snprintf(path, sizeof path, "materials.%s", name);
  if (strpbrk(name, ".[]") || !cfg_is_map(lib, name)) {
    char list[1200];
    name_list(lib, "", list, sizeof list);
    rc = hv_error_set(err, HV_EXIT_INPUT, "unknown library material '%s' (%s has: %s)", name,
                      cfg_file(lib), list);
  } else {
    rc = cfg_graft(c, path, lib, name, err);
  }
  cfg_free(lib);
  if (rc || material_read(c, path, name, m, err)) return -1;
  snprintf(m->library, sizeof m->library, "%s", name);
  return 0;
}

int material_find_or_load(struct cfg *c, const char *key_path, const char *name,
                          struct material *mats, int *nmat, int max, struct hv_error *err)
{
  char where[512], path[320];
  for (int i = 0; i < *nmat; i++)
    if (!strcmp(mats[i].name, name)) return i;
  cfg_where(c, key_path, where, sizeof where);
  if (strpbrk(name, ".[]") || !name[0])
    return hv_error_set(err, HV_EXIT_INPUT, "%s: %s: '%s' is not a material name", where, key_path,
                        name);
  snprintf(path, sizeof path, "materials.%s", name);
  const int in_case = cfg_is_map(c, path);
  struct cfg *lib = NULL;
  struct hv_error lerr = {0};
  if (!in_case && material_library_load(NULL, &lib, &lerr)) lib = NULL;
  if (!in_case && (!lib || !cfg_is_map(lib, name))) {
    char cl[800], ll[1200];
    name_list(c, "materials", cl, sizeof cl);
    if (lib) {
      name_list(lib, "", ll, sizeof ll);
      hv_error_set(err, HV_EXIT_INPUT,
                   "%s: %s: unknown material '%s' (the case defines: %s; "
                   "the library %s has: %s)",
                   where, key_path, name, cl, cfg_file(lib), ll);
    } else {
      hv_error_set(err, HV_EXIT_INPUT,
                   "%s: %s: unknown material '%s' (the case defines: %s; "
                   "no library: %s)",
                   where, key_path, name, cl, lerr.msg);
    }
    cfg_free(lib);
    return -1;
  }
  cfg_free(lib);
  if (*nmat >= max)
    return hv_error_set(err, HV_EXIT_INPUT, "%s: %s: at most %d materials", where, key_path, max);
  int rc = in_case ? material_read(c, path, name, &mats[*nmat], err)
                   : material_read_from_library(c, name, &mats[*nmat], err);
  if (rc) return -1;
  return (*nmat)++;
}

/* ---------------------------------------------------------------- printing */

void material_print_quantity(FILE *f, const char *name, double v, const char *unit)
{
  char extra[64] = "";
  if (!strcmp(unit, "Pa") && fabs(v) >= 1e5 && fabs(v) < 1e20)
    snprintf(extra, sizeof extra, "(%.6g %s)", fabs(v) >= 1e8 ? v / 1e9 : v / 1e6,
             fabs(v) >= 1e8 ? "GPa" : "MPa");
  else if (!strcmp(unit, "kg/m3") && v >= 100.0)
    snprintf(extra, sizeof extra, "(%.6g g/cm3)", v / 1e3);
  else if (!strcmp(unit, "m/s") && v >= 1e3)
    snprintf(extra, sizeof extra, "(%.6g km/s)", v / 1e3);
  else if (!strcmp(unit, "J/kg") && v != 0.0)
    snprintf(extra, sizeof extra, "(%.6g MJ/kg)", v / 1e6);
  fprintf(f, "    %-15s %-14.9g %-7s %s\n", name, v, unit, extra);
}

/* The EOS's and the yield model's parameters are listed by their rows (material.h). */
void material_print(FILE *f, const struct material *m)
{
  static const char *const fracs[] = {"none", "tresca", "cumulative"};
  fprintf(f, "%s\n", m->name);
  if (m->library[0] && strcmp(m->library, m->name)) fprintf(f, "  library: %s\n", m->library);
  if (m->source[0]) fprintf(f, "  source: %s\n", m->source);
  fprintf(f, "  eos: %s\n", eos_models[m->eos]->name);
  eos_models[m->eos]->print(f, m);
  const struct strength_params *s = &m->str;
  if (!s->enabled && s->G == 0.0 && s->Y0 == 0.0 && s->jc_A == 0.0) {
    fprintf(f, "  strength: none (fluid)\n");
  } else {
    fprintf(f, "  strength: von Mises, model %s%s\n", yield_models[s->yield]->name,
            s->enabled ? "" : " (G = 0 or Y = 0: treated as a fluid)");
    material_print_quantity(f, "shear_modulus", s->G, "Pa");
    if (s->nu != 0.0) material_print_quantity(f, "poisson", s->nu, "");
    yield_models[s->yield]->print(f, s);
  }
  const struct fracture_params *fr = &m->frac;
  fprintf(f, "  fracture: %s\n", fracs[fr->kind]);
  if (fr->kind != FRACTURE_NONE && fr->sigma_c != 0.0)
    material_print_quantity(f, "sigma_c", fr->sigma_c, "Pa");
  if (fr->kind == FRACTURE_CUMULATIVE) {
    material_print_quantity(f, "eps_f", fr->eps_f, "");
    material_print_quantity(f, "tau", fr->tau, "s");
  }
  if (fr->kind == FRACTURE_TRESCA && fr->energy > 0.0)
    material_print_quantity(f, "energy", fr->energy, "J/m2");
  if (fr->kind != FRACTURE_NONE && fr->friction > 0.0)
    material_print_quantity(f, "friction", fr->friction, "");
  if (fr->kind != FRACTURE_NONE && fr->split != SPLIT_FLUID)
    fprintf(f, "  split: %s\n", fr->split == SPLIT_NO_TENSION ? "no-tension" : "crack");
  if (fr->split == SPLIT_CRACK && fr->crack_eps_f_on)
    fprintf(f, "  crack_eps_f: %.6g + %.6g exp(%.6g sigma*)\n", fr->crack_d[0], fr->crack_d[1],
            fr->crack_d[2]);
}

/* ---------------------------------------------------------------- hvsph materials */

void material_library_usage(FILE *f)
{
  fprintf(f, "usage: hvsph materials [NAME]\n"
             "  lists the material library (name, EOS, reference density, source), or every\n"
             "  parameter of one entry with its unit; HVSPH_DATA names the folder of\n"
             "  materials.yaml\n");
}

int material_library_list(const char *name)
{
  struct hv_error err = {0};
  struct cfg *lib;
  if (material_library_load(NULL, &lib, &err)) {
    fprintf(stderr, "hvsph materials: %s\n", err.msg);
    return HV_EXIT_INPUT;
  }
  const char *const *names;
  int n = cfg_keys(lib, "", &names), st = HV_EXIT_OK;
  if (name && !cfg_is_map(lib, name)) {
    char list[1200];
    name_list(lib, "", list, sizeof list);
    fprintf(stderr, "hvsph materials: unknown material '%s'; %s has: %s\n", name, cfg_file(lib),
            list);
    cfg_free(lib);
    return HV_EXIT_INPUT;
  }
  if (!name)
    printf("# %s\n%-20s %-14s %-13s %s\n", cfg_file(lib), "name", "eos", "rho0 [kg/m3]", "source");
  for (int i = 0; i < n && st == HV_EXIT_OK; i++) {
    if (name && strcmp(names[i], name)) continue;
    struct material m;
    if (material_read(lib, names[i], names[i], &m, &err)) {
      fprintf(stderr, "hvsph materials: %s\n", err.msg);
      st = HV_EXIT_INPUT;
      break;
    }
    if (name)
      material_print(stdout, &m);
    else
      printf("%-20s %-14s %-13.6g %s\n", m.name, eos_models[m.eos]->name, m.rho0, m.source);
    material_free(&m);
  }
  if (st == HV_EXIT_OK && !name && cfg_check_unused(lib, &err)) {
    fprintf(stderr, "hvsph materials: %s\n", err.msg);
    st = HV_EXIT_INPUT;
  }
  cfg_free(lib);
  return st;
}
