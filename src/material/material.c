/* material.c — reading a material's parameters from a case file (or the library).
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
#define _XOPEN_SOURCE 700 /* realpath */
#include "material/material.h"

#include <ctype.h>
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eos/eos.h"
#include "fracture/fracture_read.h"

const char *const eos_kind_names[] = {"ideal-gas", "mie-gruneisen", "tillotson", "table", NULL};

static const char *const yield_names[] = {"constant", "linear", "johnson-cook", NULL};

/* "path.key" into buf. */
static const char *key_of(char *buf, size_t len, const char *path, const char *key)
{
  snprintf(buf, len, "%s.%s", path, key);
  return buf;
}

static int key_error(struct cfg *c, const char *key, struct hv_error *err, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

/* "file:line: key: message" (the line of the key, or of the deepest node present). */
static int key_error(struct cfg *c, const char *key, struct hv_error *err, const char *fmt, ...)
{
  char where[512], msg[1200];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);
  return hv_error_set(err, HV_EXIT_INPUT, "%s: %s: %s", cfg_where(c, key, where, sizeof where),
                      key, msg);
}

/* The key is present and written in the document itself, not grafted from the library. */
static int from_case(struct cfg *c, const char *key)
{
  return cfg_has(c, key) && !strcmp(cfg_node_file(c, key), cfg_file(c));
}

/* A quantity path.key; def NULL: required. */
static int get_q(struct cfg *c, const char *path, const char *key, enum unit_dim dim,
                 const double *def, double lo, double hi, double *out, struct hv_error *err)
{
  char k[320];
  return cfg_get_quantity(c, key_of(k, sizeof k, path, key), dim, def, lo, hi, out, err);
}

/* ---------------------------------------------------------------- EOS */

static int read_ideal_gas(struct cfg *c, const char *path, struct material *m,
                          struct hv_error *err)
{
  const double zero = 0.0;
  if (get_q(c, path, "gamma", UNIT_NONE, NULL, 1.0 + 1e-12, 10.0, &m->eosp.gas.gamma, err) ||
      get_q(c, path, "rho0", UNIT_DENSITY, &zero, 0.0, HUGE_VAL, &m->rho0, err))
    return -1;
  return 0;
}

static int read_mie_gruneisen(struct cfg *c, const char *path, struct material *m,
                              struct hv_error *err)
{
  struct eos_mie_gruneisen *g = &m->eosp.mg;
  if (get_q(c, path, "rho0", UNIT_DENSITY, NULL, DBL_MIN, HUGE_VAL, &g->rho0, err) ||
      get_q(c, path, "c0", UNIT_VELOCITY, NULL, DBL_MIN, HUGE_VAL, &g->c0, err) ||
      get_q(c, path, "n", UNIT_NONE, NULL, 1.0, 100.0, &g->n, err) ||
      get_q(c, path, "gamma", UNIT_NONE, NULL, 0.0, 100.0, &g->Gamma, err))
    return -1;
  const double floor_def = g->c0 / 10.0;
  if (get_q(c, path, "cs_floor", UNIT_VELOCITY, &floor_def, 0.0, HUGE_VAL, &g->cs_floor, err))
    return -1;
  m->rho0 = g->rho0;
  m->K0 = g->rho0 * g->c0 * g->c0;
  return 0;
}

static int read_tillotson(struct cfg *c, const char *path, struct material *m,
                          struct hv_error *err)
{
  struct eos_tillotson *t = &m->eosp.til;
  const double inf = HUGE_VAL, zero = 0.0;
  char k[320];
  if (get_q(c, path, "rho0", UNIT_DENSITY, NULL, DBL_MIN, inf, &t->rho0, err) ||
      get_q(c, path, "a", UNIT_NONE, NULL, 0.0, inf, &t->a, err) ||
      get_q(c, path, "b", UNIT_NONE, NULL, 0.0, inf, &t->b, err) ||
      get_q(c, path, "A", UNIT_PRESSURE, NULL, DBL_MIN, inf, &t->A, err) ||
      get_q(c, path, "B", UNIT_PRESSURE, NULL, -inf, inf, &t->B, err) ||
      get_q(c, path, "E0", UNIT_SPECIFIC_ENERGY, NULL, DBL_MIN, inf, &t->E0, err) ||
      get_q(c, path, "alpha", UNIT_NONE, NULL, 0.0, inf, &t->alpha, err) ||
      get_q(c, path, "beta", UNIT_NONE, NULL, 0.0, inf, &t->beta, err) ||
      get_q(c, path, "E_iv", UNIT_SPECIFIC_ENERGY, NULL, 0.0, inf, &t->E_iv, err) ||
      get_q(c, path, "E_cv", UNIT_SPECIFIC_ENERGY, NULL, 0.0, inf, &t->E_cv, err))
    return -1;
  if (!(t->E_cv > t->E_iv))
    return key_error(c, key_of(k, sizeof k, path, "E_cv"), err,
                     "E_cv = %.9g J/kg must be greater than E_iv = %.9g J/kg (complete "
                     "vaporisation after incipient)", t->E_cv, t->E_iv);
  if (get_q(c, path, "rho_iv", UNIT_DENSITY, &zero, 0.0, inf, &t->rho_iv, err)) return -1;
  if (!(t->rho_iv < t->rho0))
    return key_error(c, key_of(k, sizeof k, path, "rho_iv"), err,
                     "rho_iv = %.9g kg/m3 must be below rho0 = %.9g kg/m3", t->rho_iv, t->rho0);
  const double floor_def = sqrt(t->A / t->rho0) / 100.0;
  if (get_q(c, path, "cs_floor", UNIT_VELOCITY, &floor_def, 0.0, inf, &t->cs_floor, err))
    return -1;
  m->rho0 = t->rho0;
  m->K0 = t->A;
  return 0;
}

/* The table file, relative to the folder of the file the key was written in.
 * used_parameters.yaml records the file's absolute path (resolved when it was read), so
 * that `hvsph restart` and a rerun of that file, which lies in another folder, find the
 * same table from any working folder, and the file's CRC-32 as file_crc32: a table
 * changed since (a rerun or restart would continue under another equation of state) is
 * refused. A case may give file_crc32 too, to pin its table. */
static int read_table(struct cfg *c, const char *path, struct material *m, struct hv_error *err)
{
  char k[320], kc[320], full[1024], where[512];
  const char *file;
  key_of(k, sizeof k, path, "file");
  key_of(kc, sizeof kc, path, "file_crc32");
  if (cfg_get_string(c, k, NULL, &file, err)) return -1;
  const char *src = cfg_node_file(c, k), *slash = strrchr(src, '/');
  if (file[0] == '/' || !slash)
    snprintf(full, sizeof full, "%s", file);
  else
    snprintf(full, sizeof full, "%.*s/%s", (int)(slash - src), src, file);
  if (eos_table_load(full, &m->eosp.tab, err))
    return hv_error_prefix(err, "%s: %s: ", cfg_where(c, k, where, sizeof where), k);
  char *abs = realpath(full, NULL);   /* the file exists: it was just read */
  cfg_record_string(c, k, abs ? abs : full);
  char crc[16];
  snprintf(crc, sizeof crc, "%08lx", m->eosp.tab.crc32 & 0xffffffffUL);
  if (cfg_has(c, kc)) {
    const char *want;
    if (cfg_get_string(c, kc, NULL, &want, err)) return -1;
    char *end;
    const unsigned long w = strtoul(want, &end, 16);
    if (strlen(want) != 8 || *end || !isxdigit((unsigned char)want[0])) {
      free(abs);
      return key_error(c, kc, err, "'%s' is not a CRC-32 (8 hexadecimal digits, as hvsph "
                       "writes it in used_parameters.yaml)", want);
    }
    if (w != (m->eosp.tab.crc32 & 0xffffffffUL)) {
      key_error(c, kc, err, "EOS table '%s' has CRC-32 %s, not the %s recorded here: the "
                "table changed since the run that used it (restore it, or remove file_crc32 "
                "to run with the table as it is now)", abs ? abs : full, crc, want);
      free(abs);
      return -1;
    }
  }
  free(abs);
  cfg_record_string(c, kc, crc);
  const double zero = 0.0, floor_def = m->eosp.tab.cs_max / 100.0;
  if (get_q(c, path, "rho0", UNIT_DENSITY, &zero, 0.0, HUGE_VAL, &m->rho0, err) ||
      get_q(c, path, "cs_floor", UNIT_VELOCITY, &floor_def, 0.0, HUGE_VAL,
            &m->eosp.tab.cs_floor, err))
    return -1;
  return 0;
}

/* ---------------------------------------------------------------- strength */

/* Which of two alternative keys applies: 1 a, 2 b, 0 error (both or neither, set in err). */
static int pick_alternative(struct cfg *c, const char *ka, const char *kb, struct hv_error *err)
{
  const int ha = cfg_has(c, ka), hb = cfg_has(c, kb);
  if (ha && !hb) return 1;
  if (hb && !ha) return 2;
  if (!ha) {
    key_error(c, ka, err, "missing: give %s or %s", strrchr(ka, '.') + 1, strrchr(kb, '.') + 1);
    return 0;
  }
  const int ca = from_case(c, ka), cb = from_case(c, kb);
  if (ca && !cb) return 1; /* the case overrides the library's alternative */
  if (cb && !ca) return 2;
  key_error(c, kb, err, "give %s or %s, not both", strrchr(ka, '.') + 1, strrchr(kb, '.') + 1);
  return 0;
}

/* A key the chosen model does not use: an error if the case wrote it (the library's is
 * ignored, see the file header). */
static int not_used_here(struct cfg *c, const char *path, const char *key, const char *why,
                         struct hv_error *err)
{
  char k[320];
  key_of(k, sizeof k, path, key);
  if (from_case(c, k)) return key_error(c, k, err, "%s", why);
  return 0;
}

static int read_shear_modulus(struct cfg *c, const char *sp, struct material *m,
                              struct hv_error *err)
{
  struct strength_params *s = &m->str;
  char kg[320], kn[320], ke[320];
  key_of(kg, sizeof kg, sp, "shear_modulus");
  key_of(kn, sizeof kn, sp, "poisson");
  key_of(ke, sizeof ke, sp, "youngs_modulus");
  const int which = pick_alternative(c, kg, kn, err);
  if (!which) return -1;
  if (which == 1) {
    if (not_used_here(c, sp, "youngs_modulus", "youngs_modulus goes with poisson, not with "
                      "shear_modulus", err))
      return -1;
    return cfg_get_quantity(c, kg, UNIT_PRESSURE, NULL, 0.0, HUGE_VAL, &s->G, err);
  }
  if (cfg_get_quantity(c, kn, UNIT_NONE, NULL, -HUGE_VAL, HUGE_VAL, &s->nu, err)) return -1;
  if (!(s->nu > -1.0 && s->nu < 0.5))
    return key_error(c, kn, err, "Poisson's ratio %g is outside (-1, 0.5)", s->nu);
  if (cfg_has(c, ke)) { /* G = E / (2(1 + ν)) */
    double E;
    if (cfg_get_quantity(c, ke, UNIT_PRESSURE, NULL, 0.0, HUGE_VAL, &E, err)) return -1;
    s->G = E / (2.0 * (1.0 + s->nu));
    return 0;
  }
  if (!(m->K0 > 0.0))
    return key_error(c, kn, err, "G from Poisson's ratio needs the bulk modulus K = rho0 c0^2 "
                     "(mie-gruneisen) or A (tillotson); EOS '%s' has none: give shear_modulus "
                     "or youngs_modulus", eos_kind_names[m->eos]);
  s->G = 3.0 * m->K0 * (1.0 - 2.0 * s->nu) / (2.0 * (1.0 + s->nu));
  return 0;
}

static int read_johnson_cook(struct cfg *c, const char *sp, struct strength_params *s,
                             struct hv_error *err)
{
  const double inf = HUGE_VAL, zero = 0.0, one = 1.0, rate0 = 1.0, tref = 293.15;
  char ky[320], ka[320];
  key_of(ky, sizeof ky, sp, "yield");
  key_of(ka, sizeof ka, sp, "A");
  /* A defaults to `yield` (the initial yield stress); if both are given, A is used */
  if (!cfg_has(c, ka) && cfg_has(c, ky)) {
    if (cfg_get_quantity(c, ky, UNIT_PRESSURE, NULL, 0.0, inf, &s->jc_A, err)) return -1;
  } else {
    if (cfg_get_quantity(c, ka, UNIT_PRESSURE, NULL, 0.0, inf, &s->jc_A, err)) return -1;
    if (cfg_has(c, ky)) cfg_mark_used(c, ky);
  }
  if (get_q(c, sp, "B", UNIT_PRESSURE, NULL, 0.0, inf, &s->jc_B, err) ||
      get_q(c, sp, "N", UNIT_NONE, NULL, 0.0, inf, &s->jc_N, err) ||
      get_q(c, sp, "C", UNIT_NONE, &zero, 0.0, inf, &s->jc_C, err) ||
      get_q(c, sp, "M", UNIT_NONE, &one, DBL_MIN, inf, &s->jc_M, err) ||
      get_q(c, sp, "rate0", UNIT_RATE, &rate0, DBL_MIN, inf, &s->jc_rate0, err) ||
      get_q(c, sp, "T_ref", UNIT_TEMPERATURE, &tref, 0.0, inf, &s->T_ref, err) ||
      get_q(c, sp, "T_melt", UNIT_TEMPERATURE, NULL, 0.0, inf, &s->T_melt, err) ||
      get_q(c, sp, "cv", UNIT_SPECIFIC_HEAT, NULL, DBL_MIN, inf, &s->cv, err))
    return -1;
  if (!(s->T_melt > s->T_ref)) {
    char k[320];
    return key_error(c, key_of(k, sizeof k, sp, "T_melt"), err,
                     "T_melt = %.9g K must be above T_ref = %.9g K", s->T_melt, s->T_ref);
  }
  s->Y0 = s->jc_A;
  return 0;
}

static int read_strength(struct cfg *c, const char *path, struct material *m,
                         struct hv_error *err)
{
  char sp[300], k[320];
  snprintf(sp, sizeof sp, "%s.strength", path);
  struct strength_params *s = &m->str;
  memset(s, 0, sizeof *s);
  if (!cfg_has(c, sp)) return 0; /* a fluid */
  if (!cfg_is_map(c, sp))
    return key_error(c, sp, err, "expected a mapping like {shear_modulus: 80 GPa, yield: 1 GPa}");
  int model;
  if (cfg_get_choice(c, key_of(k, sizeof k, sp, "model"), "constant", yield_names, &model, err) ||
      read_shear_modulus(c, sp, m, err))
    return -1;
  s->yield = (enum yield_kind)model;
  const double zero = 0.0;
  switch (s->yield) {
  case YIELD_CONSTANT:
    if (not_used_here(c, sp, "hardening", "hardening applies to model: linear only", err) ||
        get_q(c, sp, "yield", UNIT_PRESSURE, NULL, 0.0, HUGE_VAL, &s->Y0, err))
      return -1;
    break;
  case YIELD_LINEAR:
    if (get_q(c, sp, "yield", UNIT_PRESSURE, NULL, 0.0, HUGE_VAL, &s->Y0, err) ||
        get_q(c, sp, "hardening", UNIT_PRESSURE, &zero, 0.0, HUGE_VAL, &s->H, err))
      return -1;
    break;
  case YIELD_JOHNSON_COOK:
    if (not_used_here(c, sp, "hardening", "hardening applies to model: linear only (Johnson-"
                      "Cook hardens through B and N)", err) ||
        read_johnson_cook(c, sp, s, err))
      return -1;
    break;
  case YIELD_KIND_COUNT:
    break;
  }
  const double Ymax = s->yield == YIELD_JOHNSON_COOK ? s->jc_A + s->jc_B : s->Y0;
  s->enabled = s->G > 0.0 && Ymax > 0.0; /* G = 0 or Y = 0: a fluid */
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
    rc = key_error(c, key, err, "unknown library material '%s' (%s has: %s)", lname,
                   cfg_file(lib), list);
  } else if (cfg_has(lib, key_of(sub, sizeof sub, lname, "library"))) {
    rc = hv_error_set(err, HV_EXIT_INPUT, "%s: %s: a library entry cannot name another",
                      cfg_where(lib, sub, where, sizeof where), sub);
  } else {
    rc = cfg_graft(c, path, lib, lname, err);
  }
  cfg_free(lib);
  return rc;
}

/* Wrong units: a parameter of a condensed material that the case writes as a bare
 * number far outside what real materials span (a density in g/cm3, a sound speed in
 * km/s or a strength in GPa written without its unit) is an error (cfg_check_typical).
 * Only values the case writes: the library's are ours. A gas is left alone (its tests
 * are often in scaled units), and so is 0, which switches a strength or a criterion off. */
static int check_units(struct cfg *c, const char *path, const struct material *m,
                       struct hv_error *err)
{
  static const struct {
    const char *key;
    enum unit_dim dim;
    double lo, hi;
    const char *what;
  } typical[] = {
      {"rho0", UNIT_DENSITY, HV_RHO_CONDENSED_LO, HV_RHO_CONDENSED_HI, HV_RHO_CONDENSED_WHAT},
      {"c0", UNIT_VELOCITY, 100.0, 5e4, "bulk sound speeds of condensed materials"},
      {"A", UNIT_PRESSURE, 1e6, 1e13, "bulk moduli of condensed materials (Tillotson A)"},
      {"E0", UNIT_SPECIFIC_ENERGY, 1e4, 1e10, "Tillotson E0 of real materials"},
      {"E_iv", UNIT_SPECIFIC_ENERGY, 1e4, 1e10, "vaporisation energies of real materials"},
      {"E_cv", UNIT_SPECIFIC_ENERGY, 1e4, 1e10, "vaporisation energies of real materials"},
      {"strength.shear_modulus", UNIT_PRESSURE, 1e5, 1e13, "elastic moduli of solids"},
      {"strength.youngs_modulus", UNIT_PRESSURE, 1e5, 1e13, "elastic moduli of solids"},
      {"strength.yield", UNIT_PRESSURE, 1e4, 1e11, "strengths of solids"},
      {"strength.A", UNIT_PRESSURE, 1e4, 1e11, "strengths of solids"},
      {"strength.B", UNIT_PRESSURE, 1e4, 1e11, "strengths of solids"},
      {"fracture.sigma_c", UNIT_PRESSURE, 1e4, 1e11, "tensile strengths of solids"},
  };
  if (m->eos == EOS_IDEAL_GAS) return 0;
  for (size_t i = 0; i < sizeof typical / sizeof typical[0]; i++) {
    char k[340];
    key_of(k, sizeof k, path, typical[i].key);
    if (from_case(c, k) && cfg_check_typical(c, k, typical[i].dim, typical[i].lo, typical[i].hi,
                                             typical[i].what, err))
      return -1;
  }
  return 0;
}

int material_read(struct cfg *c, const char *path, const char *name, struct material *m,
                  struct hv_error *err)
{
  char key[320];
  memset(m, 0, sizeof *m);
  snprintf(m->name, sizeof m->name, "%s", name);
  if (!cfg_is_map(c, path))
    return key_error(c, path, err, "material '%s' must be a mapping of its parameters "
                     "(eos: ..., or library: NAME)", name);
  key_of(key, sizeof key, path, "library");
  if (cfg_has(c, key)) {
    const char *lname;
    if (cfg_get_string(c, key, NULL, &lname, err) || graft_library(c, path, key, lname, err))
      return -1;
    snprintf(m->library, sizeof m->library, "%s", lname);
  }
  const char *text;
  if (cfg_has(c, key_of(key, sizeof key, path, "source"))) {
    if (cfg_get_string(c, key, NULL, &text, err)) return -1;
    snprintf(m->source, sizeof m->source, "%s", text);
  }
  if (cfg_has(c, key_of(key, sizeof key, path, "note")) &&
      cfg_get_string(c, key, NULL, &text, err))
    return -1;
  int kind;
  if (cfg_get_choice(c, key_of(key, sizeof key, path, "eos"), NULL, eos_kind_names, &kind, err))
    return -1;
  m->eos = (enum eos_kind)kind;
  int rc = -1;
  switch (m->eos) {
  case EOS_IDEAL_GAS: rc = read_ideal_gas(c, path, m, err); break;
  case EOS_MIE_GRUNEISEN: rc = read_mie_gruneisen(c, path, m, err); break;
  case EOS_TILLOTSON: rc = read_tillotson(c, path, m, err); break;
  case EOS_TABLE: rc = read_table(c, path, m, err); break;
  case EOS_KIND_COUNT: break;
  }
  if (rc || read_strength(c, path, m, err) || fracture_read(c, path, m, err) ||
      check_units(c, path, m, err)) {
    material_free(m);
    return -1;
  }
  return 0;
}

void material_free(struct material *m)
{
  if (m->eos == EOS_TABLE) eos_table_free(&m->eosp.tab);
}
