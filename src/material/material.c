/* material.c — the table of models, and reading a material from a case file (or the
 * library).
 *
 * The table maps a name to a model's row of operations: eos_models[] (enum eos_kind
 * order) and yield_models[] (enum yield_kind order). A model's row, its parameters'
 * reader, its listing and its physics are in its own file (eos/<name>.c,
 * strength/<name>.c); this file reads what every material has (library, source, the
 * choice of the models, the shear modulus, fracture) and calls the rows.
 *
 * A material is a mapping of keys (docs/models.md, "Material library"):
 *   library: NAME        take the entry NAME of data/materials.yaml; any key given here
 *                        overrides the library's (config graft, see cfg_graft)
 *   source, note         text (where the values come from)
 *   eos: NAME            ideal-gas | mie-gruneisen | tillotson | table, and its parameters
 *   strength: {...}      von Mises elastic–plastic (absent: a fluid)
 *   fracture: {...}      none | tresca | cumulative
 * Every value is read with its unit (cfg_get_quantity) and range-checked; errors name the
 * file and line (the library's, for values that come from it) and the key path.
 *
 * Overrides of alternatives: where a case gives one of two alternative keys and the
 * library the other (shear_modulus vs poisson), or a key the case's choice does not use
 * (hardening under model: constant, eps_f under tresca), the case's choice wins and the
 * library's key is ignored; the same conflict within one file is an error.
 */
#include "material/material_read.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eos/eos.h"
#include "fracture/fracture_read.h"

/* ---------------------------------------------------------------- the table of models */

/* Adding a model: its file, its kind in material.h's enum, and its row here. */
extern const struct eos_model eos_ideal_gas_model, eos_mie_gruneisen_model, eos_tillotson_model,
    eos_table_model;
const struct eos_model *const eos_models[EOS_KIND_COUNT] = {
    [EOS_IDEAL_GAS] = &eos_ideal_gas_model,
    [EOS_MIE_GRUNEISEN] = &eos_mie_gruneisen_model,
    [EOS_TILLOTSON] = &eos_tillotson_model,
    [EOS_TABLE] = &eos_table_model,
};

extern const struct yield_model yield_constant_model, yield_linear_model, yield_johnson_cook_model;
const struct yield_model *const yield_models[YIELD_KIND_COUNT] = {
    [YIELD_CONSTANT] = &yield_constant_model,
    [YIELD_LINEAR] = &yield_linear_model,
    [YIELD_JOHNSON_COOK] = &yield_johnson_cook_model,
};

/* The models' names in table order, NULL-terminated (cfg_get_choice's list). */
static void eos_names(const char *names[EOS_KIND_COUNT + 1])
{
  for (int k = 0; k < EOS_KIND_COUNT; k++) names[k] = eos_models[k]->name;
  names[EOS_KIND_COUNT] = NULL;
}

static void yield_names(const char *names[YIELD_KIND_COUNT + 1])
{
  for (int k = 0; k < YIELD_KIND_COUNT; k++) names[k] = yield_models[k]->name;
  names[YIELD_KIND_COUNT] = NULL;
}

/* ---------------------------------------------------------------- helpers for readers */

const char *material_key(char *buf, size_t len, const char *path, const char *key)
{
  snprintf(buf, len, "%s.%s", path, key);
  return buf;
}

int material_key_error(struct cfg *c, const char *key, struct hv_error *err, const char *fmt, ...)
{
  char where[512], msg[1200];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);
  return hv_error_set(err, HV_EXIT_INPUT, "%s: %s: %s", cfg_where(c, key, where, sizeof where), key,
                      msg);
}

int material_from_case(struct cfg *c, const char *key)
{
  return cfg_has(c, key) && !strcmp(cfg_node_file(c, key), cfg_file(c));
}

int material_get_q(struct cfg *c, const char *path, const char *key, enum unit_dim dim,
                   const double *def, double lo, double hi, double *out, struct hv_error *err)
{
  char k[320];
  return cfg_get_quantity(c, material_key(k, sizeof k, path, key), dim, def, lo, hi, out, err);
}

/* ---------------------------------------------------------------- strength */

/* Which of two alternative keys applies: 1 a, 2 b, 0 error (both or neither, set in err). */
static int pick_alternative(struct cfg *c, const char *ka, const char *kb, struct hv_error *err)
{
  const int ha = cfg_has(c, ka), hb = cfg_has(c, kb);
  if (ha && !hb) return 1;
  if (hb && !ha) return 2;
  if (!ha) {
    material_key_error(c, ka, err, "missing: give %s or %s", strrchr(ka, '.') + 1,
                       strrchr(kb, '.') + 1);
    return 0;
  }
  const int ca = material_from_case(c, ka), cb = material_from_case(c, kb);
  if (ca && !cb) return 1; /* the case overrides the library's alternative */
  if (cb && !ca) return 2;
  material_key_error(c, kb, err, "give %s or %s, not both", strrchr(ka, '.') + 1,
                     strrchr(kb, '.') + 1);
  return 0;
}

int material_not_used_here(struct cfg *c, const char *path, const char *key, const char *why,
                           struct hv_error *err)
{
  char k[320];
  material_key(k, sizeof k, path, key);
  if (material_from_case(c, k)) return material_key_error(c, k, err, "%s", why);
  return 0;
}

static int read_shear_modulus(struct cfg *c, const char *sp, struct material *m,
                              struct hv_error *err)
{
  struct strength_params *s = &m->str;
  char kg[320], kn[320], ke[320];
  material_key(kg, sizeof kg, sp, "shear_modulus");
  material_key(kn, sizeof kn, sp, "poisson");
  material_key(ke, sizeof ke, sp, "youngs_modulus");
  const int which = pick_alternative(c, kg, kn, err);
  if (!which) return -1;
  if (which == 1) {
    if (material_not_used_here(c, sp, "youngs_modulus",
                               "youngs_modulus goes with poisson, not with "
                               "shear_modulus",
                               err))
      return -1;
    return cfg_get_quantity(c, kg, UNIT_PRESSURE, NULL, 0.0, HUGE_VAL, &s->G, err);
  }
  if (cfg_get_quantity(c, kn, UNIT_NONE, NULL, -HUGE_VAL, HUGE_VAL, &s->nu, err)) return -1;
  if (!(s->nu > -1.0 && s->nu < 0.5))
    return material_key_error(c, kn, err, "Poisson's ratio %g is outside (-1, 0.5)", s->nu);
  if (cfg_has(c, ke)) { /* G = E / (2(1 + ν)) */
    double E;
    if (cfg_get_quantity(c, ke, UNIT_PRESSURE, NULL, 0.0, HUGE_VAL, &E, err)) return -1;
    s->G = E / (2.0 * (1.0 + s->nu));
    return 0;
  }
  if (!(m->K0 > 0.0))
    return material_key_error(
        c, kn, err,
        "G from Poisson's ratio needs the bulk modulus K = rho0 c0^2 "
        "(mie-gruneisen) or A (tillotson); EOS '%s' has none: give shear_modulus "
        "or youngs_modulus",
        eos_models[m->eos]->name);
  s->G = 3.0 * m->K0 * (1.0 - 2.0 * s->nu) / (2.0 * (1.0 + s->nu));
  return 0;
}

static int read_strength(struct cfg *c, const char *path, struct material *m, struct hv_error *err)
{
  char sp[300], k[320];
  snprintf(sp, sizeof sp, "%s.strength", path);
  struct strength_params *s = &m->str;
  memset(s, 0, sizeof *s);
  if (!cfg_has(c, sp)) return 0; /* a fluid */
  if (!cfg_is_map(c, sp))
    return material_key_error(c, sp, err,
                              "expected a mapping like {shear_modulus: 80 GPa, yield: 1 GPa}");
  int model;
  const char *names[YIELD_KIND_COUNT + 1];
  yield_names(names);
  if (cfg_get_choice(c, material_key(k, sizeof k, sp, "model"), "constant", names, &model, err) ||
      read_shear_modulus(c, sp, m, err))
    return -1;
  s->yield = (enum yield_kind)model;
  const struct yield_model *ym = yield_models[s->yield];
  if (ym->read(c, sp, m, err)) return -1;
  s->enabled = s->G > 0.0 && ym->yield_max(s) > 0.0; /* G = 0 or Y = 0: a fluid */
  return 0;
}

/* ---------------------------------------------------------------- the material */

/* Grafts library entry `lname` under `path`. */
static int graft_library(struct cfg *c, const char *path, const char *key, const char *lname,
                         struct hv_error *err)
{
  struct cfg *lib;
  char where[512];
  if (material_library_load(NULL, &lib, err))
    return hv_error_prefix(err, "%s: %s: ", cfg_where(c, key, where, sizeof where), key);
  int rc = 0;
  char sub[320];
  if (strpbrk(lname, ".[]") || !cfg_is_map(lib, lname)) {
    const char *const *names;
    int n = cfg_keys(lib, "", &names);
    char list[1200];
    size_t k = 0;
    list[0] = '\0';
    for (int i = 0; i < n && k < sizeof list; i++)
      k += (size_t)snprintf(list + k, sizeof list - k, "%s%s", i ? ", " : "", names[i]);
    rc = material_key_error(c, key, err, "unknown library material '%s' (%s has: %s)", lname,
                            cfg_file(lib), list);
  } else if (cfg_has(lib, material_key(sub, sizeof sub, lname, "library"))) {
    rc = hv_error_set(err, HV_EXIT_INPUT, "%s: %s: a library entry cannot name another",
                      cfg_where(lib, sub, where, sizeof where), sub);
  } else {
    rc = cfg_graft(c, path, lib, lname, err);
  }
  cfg_free(lib);
  return rc;
}

/* The keys of `list` (ended by {NULL}) that the case writes, against their spans. */
static int check_typical(struct cfg *c, const char *path, const struct material_typical *list,
                         struct hv_error *err)
{
  for (const struct material_typical *t = list; t->key; t++) {
    char k[340];
    material_key(k, sizeof k, path, t->key);
    if (material_from_case(c, k) &&
        cfg_check_typical(c, k, (enum unit_dim)t->dim, t->lo, t->hi, t->what, err))
      return -1;
  }
  return 0;
}

/* Wrong units: a parameter of a condensed material that the case writes as a bare
 * number far outside what real materials span (a density in g/cm3, a sound speed in
 * km/s or a strength in GPa written without its unit) is an error (cfg_check_typical).
 * The EOS's keys and spans are its row's (`typical`, NULL for a gas); the strength's and
 * fracture's are here.
 * Only values the case writes: the library's are ours. A gas is left alone (its tests
 * are often in scaled units), and so is 0, which switches a strength or a criterion off. */
static int check_units(struct cfg *c, const char *path, const struct material *m,
                       struct hv_error *err)
{
  static const struct material_typical solid[] = {
      {"strength.shear_modulus", UNIT_PRESSURE, 1e5, 1e13, "elastic moduli of solids"},
      {"strength.youngs_modulus", UNIT_PRESSURE, 1e5, 1e13, "elastic moduli of solids"},
      {"strength.yield", UNIT_PRESSURE, 1e4, 1e11, "strengths of solids"},
      {"strength.A", UNIT_PRESSURE, 1e4, 1e11, "strengths of solids"},
      {"strength.B", UNIT_PRESSURE, 1e4, 1e11, "strengths of solids"},
      {"fracture.sigma_c", UNIT_PRESSURE, 1e4, 1e11, "tensile strengths of solids"},
      {NULL, 0, 0.0, 0.0, NULL},
  };
  const struct material_typical *eos = eos_models[m->eos]->typical;
  if (!eos) return 0; /* a gas */
  return check_typical(c, path, eos, err) || check_typical(c, path, solid, err) ? -1 : 0;
}

int material_read(struct cfg *c, const char *path, const char *name, struct material *m,
                  struct hv_error *err)
{
  char key[320];
  memset(m, 0, sizeof *m);
  snprintf(m->name, sizeof m->name, "%s", name);
  if (!cfg_is_map(c, path))
    return material_key_error(c, path, err,
                              "material '%s' must be a mapping of its parameters "
                              "(eos: ..., or library: NAME)",
                              name);
  material_key(key, sizeof key, path, "library");
  if (cfg_has(c, key)) {
    const char *lname;
    if (cfg_get_string(c, key, NULL, &lname, err) || graft_library(c, path, key, lname, err))
      return -1;
    snprintf(m->library, sizeof m->library, "%s", lname);
  }
  const char *text;
  if (cfg_has(c, material_key(key, sizeof key, path, "source"))) {
    if (cfg_get_string(c, key, NULL, &text, err)) return -1;
    snprintf(m->source, sizeof m->source, "%s", text);
  }
  if (cfg_has(c, material_key(key, sizeof key, path, "note")) &&
      cfg_get_string(c, key, NULL, &text, err))
    return -1;
  int kind;
  const char *names[EOS_KIND_COUNT + 1];
  eos_names(names);
  if (cfg_get_choice(c, material_key(key, sizeof key, path, "eos"), NULL, names, &kind, err))
    return -1;
  m->eos = (enum eos_kind)kind;
  if (eos_models[m->eos]->read(c, path, m, err) || read_strength(c, path, m, err) ||
      fracture_read(c, path, m, err) || check_units(c, path, m, err)) {
    material_free(m);
    return -1;
  }
  return 0;
}

void material_free(struct material *m)
{
  if ((unsigned)m->eos < EOS_KIND_COUNT && eos_models[m->eos]->release)
    eos_models[m->eos]->release(m);
}
