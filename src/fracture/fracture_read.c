/* fracture_read.c — the fracture mapping of a material (fracture_read.h): the model and
 * the split, and the checks between the rules; each rule reads its own keys in its file
 * (read.h). Errors name the file and line (the library's, for values that come from it)
 * and the key path, as material.c's. */
#include "fracture/read.h"

#include <stdio.h>
#include <string.h>

static const char *const fracture_names[] = {"none", "tresca", "cumulative", NULL};
static const char *const split_names[] = {"fluid", "no-tension", "crack", NULL};

/* The split (any model but none) and its checks against the other rules' keys. */
static int read_split(struct cfg *c, const char *fp, struct material *m, struct hv_error *err)
{
  struct fracture_params *f = &m->frac;
  char k[320];
  int split;
  if (cfg_get_choice(c, material_key(k, sizeof k, fp, "split"), "fluid", split_names, &split, err))
    return -1;
  f->split = (enum split_kind)split;
  const char *sname = split_names[f->split];
  if (f->split != SPLIT_FLUID && !m->str.enabled)
    return material_key_error(c, k, err,
                              "split: %s keeps the deviatoric stress of split "
                              "material, but the material has no strength (give strength "
                              "with shear modulus and yield > 0)",
                              sname);
  if (f->split != SPLIT_FLUID && f->energy > 0.0)
    return material_key_error(c, material_key(k, sizeof k, fp, "energy"), err,
                              "energy (a cohesive opening before the split) ends in the "
                              "paper's split (split: fluid); with split: %s leave it out",
                              sname);
  if (f->split != SPLIT_FLUID && f->friction > 0.0)
    return material_key_error(c, k, err,
                              "split: %s keeps the yield stress of split "
                              "material; friction (which limits it to min(Y, mu p)) applies "
                              "to split: fluid only",
                              sname);
  if (f->split != SPLIT_CRACK)
    return material_not_used_here(c, fp, "crack_eps_f",
                                  "crack_eps_f is the strain to "
                                  "failure of a cracked particle: it applies to split: crack "
                                  "only",
                                  err);
  return fracture_read_crack_eps_f(c, fp, f, err);
}

int fracture_read(struct cfg *c, const char *path, struct material *m, struct hv_error *err)
{
  char fp[300], k[320];
  snprintf(fp, sizeof fp, "%s.fracture", path);
  struct fracture_params *f = &m->frac;
  memset(f, 0, sizeof *f);
  if (!cfg_has(c, fp)) return 0;
  if (!cfg_is_map(c, fp))
    return material_key_error(c, fp, err,
                              "expected a mapping like {model: tresca, sigma_c: -0.39 GPa}");
  int model;
  if (cfg_get_choice(c, material_key(k, sizeof k, fp, "model"), NULL, fracture_names, &model, err))
    return -1;
  f->kind = (enum fracture_kind)model;
  switch (f->kind) {
  case FRACTURE_NONE:
    if (material_not_used_here(c, fp, "friction",
                               "friction applies to split material: model "
                               "tresca or cumulative",
                               err) ||
        material_not_used_here(c, fp, "split",
                               "split applies to split material: model "
                               "tresca or cumulative",
                               err) ||
        material_not_used_here(c, fp, "energy",
                               "energy (a cohesive opening before the "
                               "split) applies to model: tresca",
                               err) ||
        material_not_used_here(c, fp, "crack_eps_f",
                               "crack_eps_f applies to split: crack "
                               "(model tresca or cumulative)",
                               err))
      return -1;
    return 0;
  case FRACTURE_TRESCA:
    if (fracture_read_tresca(c, fp, m, err)) return -1;
    break;
  case FRACTURE_CUMULATIVE:
    if (fracture_read_cumulative(c, fp, m, err)) return -1;
    break;
  case FRACTURE_KIND_COUNT: break;
  }
  if (fracture_read_friction(c, fp, m, err)) return -1;
  return read_split(c, fp, m, err);
}
