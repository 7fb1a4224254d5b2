/* test_materials.c — materials from case files and the library data/materials.yaml:
 * the paper's values exactly, library overrides (config grafts), G from Poisson's ratio,
 * input errors with file and line, bodies naming library materials, `hvsph materials`. */
#include "config/config.h"
#include "eos/eos.h"
#include "material/material_read.h"
#include "strength/strength.h"
#include "testlib.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static void use_library(const char *dir)
{
  static char data[4200];
  if (dir)
    snprintf(data, sizeof data, "%s", dir);
  else
    snprintf(data, sizeof data, "%s/data", test_source_dir());
  setenv("HVSPH_DATA", data, 1);
}

/* Reads materials.NAME of a case given as text; returns 0 or -1 (err filled). */
static int read_case_material(const char *yaml, const char *name, struct material *m,
                              struct cfg **cp, struct hv_error *err)
{
  struct cfg *c = cfg_load_string(yaml, "case.yaml", err);
  if (cp) *cp = c;
  if (!c) return -1;
  char path[128];
  snprintf(path, sizeof path, "materials.%s", name);
  int rc = material_read(c, path, name, m, err);
  if (!cp) cfg_free(c);
  return rc;
}

static void expect_error(const char *yaml, const char *name, const char *expect)
{
  struct material m;
  struct hv_error err = {0};
  int rc = read_case_material(yaml, name, &m, NULL, &err);
  int same = strstr(err.msg, expect) != NULL;
  CHECK(rc == -1 && err.code == HV_EXIT_INPUT && same, "error '%s'%s%s", err.msg,
        same ? "" : "\n        wanted (part): ", same ? "" : expect);
  if (!rc) material_free(&m);
}

/* ---------------------------------------------------------------- the paper's values */

struct paper_mg {
  const char *name;
  double rho0, c0, n, Gamma, G, nu, Y, sigma_c; /* SI; G = 0 where the table gives ν */
};

/* ../shared/reference/paper_tables.yaml (Tables 2, 5, 8), in SI, written out by hand. */
static const struct paper_mg paper[] = {
    {"tungsten-alloy", 17780.0, 4612.0, 3.54, 1.66, 126.615e9, 0.0, 0.983e9, -0.983e9},
    {"steel-target", 7810.0, 4900.0, 4.5, 1.8, 95e9, 0.0, 0.39e9, -0.39e9},
    {"steel-projectile", 7700.0, 4760.0, 4.0, 1.38, 0.0, 0.3, 1.55e9, -2.66e9},
    {"steel-bumper", 7850.0, 4406.0, 4.0, 1.38, 0.0, 0.275, 0.35e9, -0.47e9},
    {"al-alloy", 2780.0, 5612.0, 3.54, 1.176, 0.0, 0.362, 0.383e9, -0.59e9},
    {"al-projectile", 2701.0, 5240.0, 3.54, 0.97, 0.0, 0.33, 0.075e9, -0.1e9},
};

/* ---------------------------------------------------------------- beyond the paper */

/* steel-target-jc: Table 2's steel (EOS, G) with Johnson & Cook's (1983) 4340 strength:
 * the same EOS and shear modulus as steel-target, the published A, B, N, C, M, T_melt,
 * and the yield the model gives from them: A + B at eps_p = 1 (1.302 GPa), A + B 0.5^0.26
 * at eps_p = 0.5, nothing at the melting temperature. */
/* The shielding materials (issue 75): each reads, with the values of its source
 * (shared/reference/shielding.md §4; Murnaghan n = 4 s - 1 from the Hugoniot slope s),
 * Johnson-Cook strength, a Tresca spall stress, and a source naming what was read and
 * what is from memory ([read: ...], [mem]). */
static void test_shield_library(struct cfg *lib)
{
  static const struct {
    const char *name;
    double rho0, c0, s, Gamma, G, A, B, T_melt, cv, sigma_c;
  } want[] = {
      {"al-6061-t6", 2703, 5240, 1.40, 1.97, 27.6e9, 324e6, 114e6, 925, 885, -1.2e9},
      {"al-2024-t3", 2785, 5328, 1.338, 2.00, 28.6e9, 369e6, 684e6, 775, 863, -1.3e9},
      {"al-7075-t6", 2803, 5200, 1.36, 2.20, 26.7e9, 546e6, 678e6, 893, 848, -1.4e9},
      {"ti-6al-4v", 4419, 5130, 1.028, 1.23, 41.9e9, 1098e6, 1092e6, 1878, 525, -4e9},
      {"copper-ofhc", 8930, 3940, 1.489, 2.02, 47.7e9, 90e6, 292e6, 1356, 383, -1.3e9},
      {"steel-4340", 7830, 4569, 1.49, 2.17, 81.8e9, 792e6, 510e6, 1793, 477, -3.5e9},
      {"tungsten-wha", 18167, 4030, 1.237, 1.67, 145e9, 1506e6, 177e6, 1723, 143, -3.5e9},
      {"tungsten-wha-rod", 17340, 4030, 1.237, 1.67, 145e9, 1506e6, 177e6, 1723, 143, -3.5e9},
  };
  for (size_t k = 0; k < sizeof want / sizeof want[0]; k++) {
    struct hv_error err = {0};
    struct material m;
    const int rc = material_read(lib, want[k].name, want[k].name, &m, &err);
    CHECK(rc == 0, "%s read (%s)", want[k].name, rc ? err.msg : "ok");
    if (rc) continue;
    const struct eos_mie_gruneisen *mg = &m.eosp.mg;
    CHECK(m.eos == EOS_MIE_GRUNEISEN && mg->rho0 == want[k].rho0 && mg->c0 == want[k].c0 &&
              fabs(mg->n - (4 * want[k].s - 1)) < 1e-12 && mg->Gamma == want[k].Gamma &&
              m.str.G == want[k].G,
          "%s: rho0, c0, n = 4 s - 1, Gamma, G of its source", want[k].name);
    CHECK(m.str.yield == YIELD_JOHNSON_COOK && m.str.jc_A == want[k].A && m.str.jc_B == want[k].B &&
              m.str.T_melt == want[k].T_melt && m.str.cv == want[k].cv && m.str.jc_rate0 == 1.0 &&
              m.frac.kind == FRACTURE_TRESCA && m.frac.sigma_c == want[k].sigma_c,
          "%s: Johnson-Cook A, B, T_melt, cv, rate0 1/s; spall sigma_c", want[k].name);
    CHECK(strstr(m.source, "[read") && strstr(m.source, "[mem"),
          "%s: source tags what was "
          "read and what is from memory: %s",
          want[k].name, m.source);
    material_free(&m);
  }
}

/* The sourced set of the rods (issue 74): tungsten-wha-rod against steel-4340.
 * - The rod's density is the rods' own: m / (pi r^2 l) from Table 1 (paper_tables.yaml,
 *   written out by hand) within 0.1 % for each of the six rods. The data's last digits
 *   (0.01 g in 46 g, 0.0001 cm in r: 0.01 % and 0.08 % in r^2) allow about that; Table
 *   2's 17.78 g/cm3 is 2.5 % off.
 * - The target's flow stress is near the 1.1 GPa that Tate's balance asks for rod 1929
 *   (a target resistance of about 6 GPa; Tate 1986: R_t = Y (2/3 + ln(0.57 E/Y))): the
 *   Johnson-Cook yield at 1e5 1/s after 5 % plastic strain lies in [1.0, 1.3] GPa and
 *   the R_t it gives in [5.5, 7] GPa (E = 2 G (1 + nu), nu = 0.29 of ShearBands). */
static void test_sourced_rod_set(struct cfg *lib)
{
  static const double rods[6][3] = {/* l, r [cm], m [g] */
                                    {15.575, 0.3433, 100},   {15.575, 0.3380, 96.96},
                                    {15.575, 0.3376, 96.73}, {12.18, 0.2638, 46.20},
                                    {12.18, 0.2633, 46.02},  {12.18, 0.2615, 45.41}};
  struct hv_error err = {0};
  struct material rod, target;
  if (material_read(lib, "tungsten-wha-rod", "rod", &rod, &err)) {
    CHECK(0, "tungsten-wha-rod read (%s)", err.msg);
    return;
  }
  for (int k = 0; k < 6; k++) {
    const double rho = rods[k][2] / (3.14159265358979323846 * rods[k][1] * rods[k][1] * rods[k][0]);
    CHECK(fabs(rho * 1000.0 / rod.eosp.mg.rho0 - 1.0) < 1e-3,
          "tungsten-wha-rod: rho0 %g kg/m3 is Table 1's rod %d: %.5g g/cm3", rod.eosp.mg.rho0, k,
          rho);
  }
  material_free(&rod);
  if (material_read(lib, "steel-4340", "target", &target, &err)) {
    CHECK(0, "steel-4340 read (%s)", err.msg);
    return;
  }
  const double Y = strength_yield(&target.str, 0.05, 1e5, 0.0);
  const double E = 2.0 * target.str.G * 1.29, Rt = Y * (2.0 / 3.0 + log(0.57 * E / Y));
  CHECK(Y > 1.0e9 && Y < 1.3e9 && Rt > 5.5e9 && Rt < 7e9,
        "steel-4340: flow stress %.4g GPa at eps_p 0.05, 1e5 1/s; Tate's R_t %.3g GPa", Y * 1e-9,
        Rt * 1e-9);
  material_free(&target);
}

static void test_jc_library(struct cfg *lib)
{
  struct hv_error err = {0};
  struct material m[2];
  int rc = material_read(lib, "steel-target-jc", "jc", &m[0], &err);
  if (rc == 0 && material_read(lib, "steel-target", "t2", &m[1], &err)) {
    material_free(&m[0]);
    rc = 1;
  }
  CHECK(rc == 0, "steel-target-jc read (%s)", rc ? err.msg : "ok");
  if (rc) return;
  const struct strength_params *s = &m[0].str;
  CHECK(m[0].eos == m[1].eos && m[0].eosp.mg.rho0 == m[1].eosp.mg.rho0 &&
            m[0].eosp.mg.c0 == m[1].eosp.mg.c0 && m[0].eosp.mg.n == m[1].eosp.mg.n &&
            m[0].eosp.mg.Gamma == m[1].eosp.mg.Gamma && s->G == m[1].str.G,
        "steel-target-jc: Table 2's EOS and shear modulus");
  CHECK(s->yield == YIELD_JOHNSON_COOK && s->jc_A == 0.792e9 && s->jc_B == 0.510e9 &&
            s->jc_N == 0.26 && s->jc_C == 0.014 && s->jc_M == 1.03 && s->T_melt == 1793.0 &&
            s->cv == 477.0 && s->jc_rate0 == 1.0 && m[0].frac.sigma_c == -0.792e9,
        "steel-target-jc: Johnson & Cook's 4340 constants");
  const double y1 = strength_yield(s, 1.0, 1.0, 0.0), yh = strength_yield(s, 0.5, 1.0, 0.0);
  const double ym = strength_yield(s, 1.0, 1.0, 477.0 * (1793.0 - 293.15));
  CHECK(fabs(y1 - 1.302e9) < 1e3 && fabs(yh - (0.792e9 + 0.510e9 * pow(0.5, 0.26))) < 1e3 &&
            ym == 0.0,
        "steel-target-jc: Y(eps_p 1) = %.6g, Y(0.5) = %.6g Pa, Y at melting = %g", y1, yh, ym);
  for (int k = 0; k < 2; k++) material_free(&m[k]);
}

static void test_paper_values(void)
{
  struct cfg *lib;
  struct hv_error err = {0};
  if (material_library_load(NULL, &lib, &err)) {
    CHECK(0, "library loads: %s", err.msg);
    return;
  }
  for (size_t k = 0; k < sizeof paper / sizeof paper[0]; k++) {
    const struct paper_mg *w = &paper[k];
    struct material m;
    int rc = material_read(lib, w->name, w->name, &m, &err);
    CHECK(rc == 0, "%s reads (%s)", w->name, rc ? err.msg : "ok");
    if (rc) continue;
    const struct eos_mie_gruneisen *g = &m.eosp.mg;
    /* exact equality: the library's decimal values with units convert to the nearest double */
    CHECK(m.eos == EOS_MIE_GRUNEISEN && g->rho0 == w->rho0 && m.rho0 == w->rho0 && g->c0 == w->c0 &&
              g->n == w->n && g->Gamma == w->Gamma,
          "%s: EOS rho0 %.17g c0 %.17g n %.17g Gamma %.17g", w->name, g->rho0, g->c0, g->n,
          g->Gamma);
    CHECK(m.str.enabled && m.str.yield == YIELD_CONSTANT && m.str.Y0 == w->Y, "%s: yield %.17g Pa",
          w->name, m.str.Y0);
    if (w->G > 0) {
      CHECK(m.str.G == w->G, "%s: G = %.17g Pa (table)", w->name, m.str.G);
    } else {
      const double K = w->rho0 * w->c0 * w->c0, G = 3 * K * (1 - 2 * w->nu) / (2 * (1 + w->nu));
      CHECK(m.str.nu == w->nu && fabs(m.str.G - G) <= 1e-15 * G,
            "%s: nu %.17g -> G = %.17g Pa (3K(1-2nu)/(2(1+nu)) = %.17g, K = rho0 c0^2)", w->name,
            m.str.nu, m.str.G, G);
    }
    CHECK(m.frac.kind == FRACTURE_TRESCA && m.frac.sigma_c == w->sigma_c,
          "%s: tresca, sigma_c = %.17g Pa", w->name, m.frac.sigma_c);
    CHECK(strstr(m.source, "seed paper, Table") != NULL, "%s: source '%s'", w->name, m.source);
    material_free(&m);
  }
  struct material m;
  int rc = material_read(lib, "nitrogen", "nitrogen", &m, &err);
  CHECK(rc == 0 && m.eos == EOS_IDEAL_GAS && m.eosp.gas.gamma == 1.4 && m.rho0 == 13.125 &&
            !m.str.enabled && m.frac.kind == FRACTURE_NONE,
        "nitrogen: ideal gas, gamma 1.4, rho0 13.125 kg/m3 (%s)", rc ? err.msg : "ok");
  /* and p = 10.5 bar at e = 0.2 kJ/g (section 3) */
  struct eos_state st;
  eos_evaluate(&m, 13.125, 200.0e3, &st);
  CHECK(fabs(st.p - 10.5e5) <= 1e-9 * 10.5e5, "nitrogen: p = %.10g Pa (10.5 bar)", st.p);

  /* Tillotson sets and the verification materials */
  rc = material_read(lib, "aluminium-tillotson", "al", &m, &err);
  const struct eos_tillotson *t = &m.eosp.til;
  CHECK(rc == 0 && m.eos == EOS_TILLOTSON && t->rho0 == 2700 && t->A == 75.2e9 && t->B == 65e9 &&
            t->E0 == 5e6 && t->a == 0.5 && t->b == 1.63 && t->alpha == 5 && t->beta == 5 &&
            t->E_iv == 3e6 && t->E_cv == 13.9e6 && m.K0 == 75.2e9,
        "aluminium-tillotson: Melosh (1989) values");
  rc = material_read(lib, "iron-tillotson", "fe", &m, &err);
  CHECK(rc == 0 && t->rho0 == 7800 && t->A == 128e9 && t->B == 105e9 && t->E0 == 9.5e6 &&
            t->b == 1.5 && t->E_iv == 2.4e6 && t->E_cv == 8.67e6,
        "iron-tillotson: Melosh (1989) values");
  rc = material_read(lib, "copper", "copper", &m, &err);
  CHECK(rc == 0 && m.rho0 == 8930 && m.eosp.mg.c0 == 3940 && m.str.yield == YIELD_LINEAR &&
            m.str.Y0 == 400e6 && m.str.H == 100e6 && m.str.nu == 0.35 &&
            fabs(m.str.G - 117e9 / 2.7) <= 1e-15 * 43.4e9,
        "copper: G = E/(2(1 + nu)) = %.17g Pa, Y 400 MPa, H 100 MPa", m.str.G);
  rc = material_read(lib, "rubber-ring", "rubber", &m, &err);
  CHECK(rc == 0 && m.eosp.mg.n == 1 && m.eosp.mg.Gamma == 0 && m.str.G == 0.22 && m.str.enabled,
        "rubber-ring: n = 1, Gamma = 0, G = 0.22");
  eos_evaluate(&m, 1.1, 0.0, &st);
  CHECK(fabs(st.p - 0.1) <= 1e-15, "rubber-ring: p = c0^2 (rho - rho0) = %.17g at rho = 1.1", st.p);
  test_jc_library(lib);
  test_shield_library(lib);
  test_sourced_rod_set(lib);
  /* every entry reads and no key is left unread */
  CHECK(cfg_check_unused(lib, &err) == 0, "no unknown key in the library (%s)",
        err.code ? err.msg : "ok");
  cfg_free(lib);
}

/* ---------------------------------------------------------------- overrides */

static void test_overrides(void)
{
  static const char *yaml =
      "materials:\n" /* 1 */
      "  target: {library: steel-target, strength: {yield: 0.5 GPa}, fracture: {friction: 0.4}}\n"
      "  rod: {library: tungsten-alloy, strength: {poisson: 0.28}}\n"
      "  plate:\n" /* 4 */
      "    library: al-alloy\n"
      "    c0: 5 km/s\n"
      "    fracture: {model: none}\n"
      "  hard: {library: steel-target, strength: {model: linear, hardening: 1 GPa}}\n";
  struct hv_error err = {0};
  struct cfg *c = cfg_load_string(yaml, "case.yaml", &err);
  struct material m[4];
  int rc = material_read(c, "materials.target", "target", &m[0], &err) ||
           material_read(c, "materials.rod", "rod", &m[1], &err) ||
           material_read(c, "materials.plate", "plate", &m[2], &err) ||
           material_read(c, "materials.hard", "hard", &m[3], &err);
  CHECK(rc == 0, "overrides read (%s)", rc ? err.msg : "ok");
  if (rc) {
    cfg_free(c);
    return;
  }
  CHECK(m[0].str.Y0 == 0.5e9 && m[0].str.G == 95e9 && m[0].eosp.mg.c0 == 4900 &&
            m[0].frac.sigma_c == -0.39e9 && !strcmp(m[0].library, "steel-target") &&
            strstr(m[0].source, "Table 2") && m[0].frac.friction == 0.4 &&
            m[0].frac.kind == FRACTURE_TRESCA && m[1].frac.friction == 0.0,
        "target: yield overridden to 0.5 GPa, friction 0.4 added, the rest from steel-target; "
        "rod: no friction (the default)");
  const double K = 17780.0 * 4612.0 * 4612.0;
  CHECK(m[1].str.nu == 0.28 && fabs(m[1].str.G - 3 * K * 0.44 / 2.56) <= 1e-14 * m[1].str.G &&
            m[1].str.Y0 == 0.983e9,
        "rod: the case's poisson replaces the library's shear_modulus (G = %.17g)", m[1].str.G);
  const double K2 = 2780.0 * 5000.0 * 5000.0;
  CHECK(m[2].eosp.mg.c0 == 5000 && m[2].K0 == K2 && m[2].eosp.mg.n == 3.54 &&
            fabs(m[2].str.G - 3 * K2 * (1 - 0.724) / (2 * 1.362)) <= 1e-14 * m[2].str.G &&
            m[2].frac.kind == FRACTURE_NONE,
        "plate: c0 5 km/s changes K and G; fracture none");
  CHECK(m[3].str.yield == YIELD_LINEAR && m[3].str.H == 1e9, "hard: linear hardening");
  /* values from the library carry its file and line in messages */
  char where[512];
  cfg_where(c, "materials.target.c0", where, sizeof where);
  CHECK(strstr(where, "data/materials.yaml:") != NULL, "library value located at '%s'", where);
  cfg_where(c, "materials.target.strength.yield", where, sizeof where);
  CHECK(!strcmp(where, "case.yaml:2"), "case value located at '%s'", where);
  /* the library's unused keys (al-alloy's sigma_c under model none) are not "unknown" */
  CHECK(cfg_check_unused(c, &err) == 0, "no unknown keys (%s)", err.code ? err.msg : "ok");
  /* used_parameters.yaml records the values taken from the library */
  char path[4200], text[8192] = "";
  snprintf(path, sizeof path, "%s/used_materials.yaml", test_tmpdir());
  rc = cfg_write_used(c, path, "test", &err);
  FILE *f = fopen(path, "r");
  size_t n = f ? fread(text, 1, sizeof text - 1, f) : 0;
  text[n] = '\0';
  if (f) fclose(f);
  CHECK(rc == 0 && strstr(text, "c0: 4900  # m/s") && strstr(text, "yield: 5e+08  # Pa") &&
            strstr(text, "library: \"steel-target\""),
        "used parameters record library values");
  for (int k = 0; k < 4; k++) material_free(&m[k]);
  cfg_free(c);
}

/* A library material's tensile criterion switched off: sigma_c: 0 with cumulative damage
 * leaves a pure plastic-strain (deformation) criterion; with tresca it stays an error. */
static void test_sigma_c_off(void)
{
  struct material m;
  struct hv_error err = {0};
  int rc = read_case_material("materials:\n  x: {library: steel-bumper, fracture: {model: "
                              "cumulative, sigma_c: 0, eps_f: 0.8}}\n",
                              "x", &m, NULL, &err);
  CHECK(rc == 0 && m.frac.kind == FRACTURE_CUMULATIVE && m.frac.sigma_c == 0.0 &&
            m.frac.eps_f == 0.8,
        "cumulative, sigma_c: 0 over steel-bumper's -0.47 GPa: strain criterion only (%s)",
        rc ? err.msg : "ok");
  if (!rc) material_free(&m);
  rc = read_case_material("materials:\n  x: {library: steel-bumper, fracture: {model: "
                          "cumulative, eps_f: 0.8}}\n",
                          "x", &m, NULL, &err);
  CHECK(rc == 0 && m.frac.sigma_c == -0.47e9, "without sigma_c the library's -0.47 GPa stays (%s)",
        rc ? err.msg : "ok");
  if (!rc) material_free(&m);
  expect_error("materials:\n  x: {library: steel-bumper, fracture: {model: cumulative, "
               "sigma_c: 0}}\n",
               "x",
               "case.yaml:2: materials.x.fracture.model: cumulative "
               "damage needs eps_f > 0");
  expect_error("materials:\n  x: {library: steel-bumper, fracture: {model: cumulative, "
               "sigma_c: 0.1 GPa, eps_f: 1}}\n",
               "x",
               "must be negative (tension is negative, "
               "as in the paper's tables); 0 switches the tensile criterion off");
  expect_error("materials:\n  x: {library: steel-bumper, fracture: {sigma_c: 0}}\n", "x",
               "case.yaml:2: materials.x.fracture.sigma_c: sigma_c = 0 Pa must be negative "
               "(tension is negative, as in the paper's tables)");
}

/* ---------------------------------------------------------------- errors */

static void test_errors(void)
{
  expect_error("materials:\n  x:\n    eos: mie-gruneisen\n    rho0: 7.8 g/cm3\n    c0: 5 km/s\n"
               "    n: 4\n    gamma: 2\n    strength: {poisson: 0.5, yield: 1 GPa}\n",
               "x",
               "case.yaml:8: materials.x.strength.poisson: Poisson's ratio 0.5 is outside "
               "(-1, 0.5)");
  expect_error(
      "materials:\n  x: {library: steel-bumper, strength: {poisson: -1}}\n", "x",
      "case.yaml:2: materials.x.strength.poisson: Poisson's ratio -1 is outside (-1, 0.5)");
  expect_error("materials:\n  x:\n    library: aluminium-tillotson\n    E_cv: 2 MJ/kg\n", "x",
               "case.yaml:4: materials.x.E_cv: E_cv = 2000000 J/kg must be greater than E_iv = "
               "3000000 J/kg");
  expect_error("materials:\n  x: {eos: murnaghan, rho0: 1000}\n", "x",
               "case.yaml:2: materials.x.eos: 'murnaghan' is not one of 'ideal-gas', "
               "'mie-gruneisen', 'tillotson', 'table'");
  expect_error("materials:\n  x: {library: steel-targte}\n", "x",
               "case.yaml:2: materials.x.library: unknown library material 'steel-targte' (");
  expect_error("materials:\n  x: {library: steel-targte}\n", "x",
               "has: tungsten-alloy, steel-target, steel-projectile");
  expect_error("materials:\n  x:\n    eos: mie-gruneisen\n    rho0: 7.8 g/cm3\n    n: 4\n"
               "    gamma: 2\n",
               "x", "case.yaml:2: missing required key 'materials.x.c0'");
  expect_error("materials:\n  x: {library: steel-target, fracture: {sigma_c: 0.39 GPa}}\n", "x",
               "case.yaml:2: materials.x.fracture.sigma_c: sigma_c = 390000000 Pa must be "
               "negative");
  expect_error("materials:\n  x: {library: steel-target, c0: 5 kg}\n", "x",
               "case.yaml:2: materials.x.c0: unit 'kg' is a mass, expected a velocity");
  expect_error("materials:\n  x: {library: steel-target, strength: {poisson: 0.3, shear_modulus: "
               "80 GPa}}\n",
               "x",
               "materials.x.strength.poisson: give shear_modulus or poisson, "
               "not both");
  expect_error("materials:\n  x: {library: tungsten-alloy, strength: {hardening: 1 GPa}}\n", "x",
               "case.yaml:2: materials.x.strength.hardening: hardening applies to model: linear "
               "only");
  expect_error("materials:\n  x: {library: aluminium-tillotson, strength: {poisson: 0.3, yield: "
               "1 GPa}, fracture: {model: tresca}}\n",
               "x", "missing required key 'materials.x.fracture.sigma_c'");
  expect_error("materials:\n  x: {library: nitrogen, strength: {poisson: 0.3, yield: 1 GPa}}\n",
               "x", "materials.x.strength.poisson: G from Poisson's ratio needs the bulk modulus");
  expect_error("materials:\n  x: {library: steel-target, strength: {model: johnson-cook, B: 1 GPa, "
               "N: 0.3, cv: 450, T_melt: 200 K}}\n",
               "x", "materials.x.strength.T_melt: T_melt = 200 K must be above T_ref = 293.15 K");
  expect_error("materials:\n  x: 5\n", "x",
               "case.yaml:2: materials.x: material 'x' must be a "
               "mapping");
  expect_error("materials:\n  x: {library: steel-target, fracture: {model: none, friction: 0.5}}\n",
               "x",
               "case.yaml:2: materials.x.fracture.friction: friction applies to split "
               "material: model tresca or cumulative");
  expect_error("materials:\n  x: {library: steel-target, fracture: {friction: -0.1}}\n", "x",
               "materials.x.fracture.friction");
  expect_error("materials:\n  x: {library: steel-target, strength: {yield: 0}, fracture: "
               "{friction: 0.5}}\n",
               "x",
               "materials.x.fracture.friction: friction limits the "
               "deviatoric stress of split material, but the material has no strength");
  expect_error("materials:\n  x: {library: steel-target, fracture: {split: brittle}}\n", "x",
               "case.yaml:2: materials.x.fracture.split");
  expect_error("materials:\n  x: {library: steel-target, fracture: {model: none, split: "
               "no-tension}}\n",
               "x",
               "case.yaml:2: materials.x.fracture.split: split applies "
               "to split material");
  expect_error("materials:\n  x: {library: steel-target, strength: {yield: 0}, fracture: "
               "{split: no-tension}}\n",
               "x",
               "materials.x.fracture.split: split: no-tension "
               "keeps the deviatoric stress of split material, but the material has no strength");
  expect_error("materials:\n  x: {library: steel-target, fracture: {split: no-tension, friction: "
               "0.5}}\n",
               "x",
               "materials.x.fracture.split: split: no-tension keeps the yield "
               "stress of split material; friction");
  /* crack_eps_f: the cracked state's strain to failure, with split: crack only */
  expect_error("materials:\n  x: {library: al-alloy, fracture: {crack_eps_f: 0.2}}\n", "x",
               "case.yaml:2: materials.x.fracture.crack_eps_f: crack_eps_f is the strain to "
               "failure of a cracked particle: it applies to split: crack only");
  expect_error("materials:\n  x: {library: al-alloy, fracture: {model: none, crack_eps_f: "
               "0.2}}\n",
               "x", "materials.x.fracture.crack_eps_f: crack_eps_f applies to split: crack");
  /* energy: a cohesive opening before the paper's split (model tresca, split fluid) */
  expect_error("materials:\n  x: {library: al-alloy, fracture: {energy: 10 kJ/m2, split: crack}}\n",
               "x",
               "materials.x.fracture.energy: energy (a cohesive opening before the split) ends "
               "in the paper's split (split: fluid); with split: crack leave it out");
  expect_error("materials:\n  x: {library: al-alloy, fracture: {model: cumulative, eps_f: 1, "
               "energy: 10 kJ/m2}}\n",
               "x",
               "materials.x.fracture.energy: energy (a cohesive "
               "opening before the split) applies to model: tresca only");
  expect_error(
      "materials:\n  x: {eos: ideal-gas, gamma: 1.4, strength: {shear_modulus: 10 GPa, "
      "yield: 1 GPa}, fracture: {model: tresca, sigma_c: -1 GPa, energy: 10 kJ/m2}}\n",
      "x",
      "materials.x.fracture.energy: the cohesive opening (energy > 0) takes each particle's "
      "spacing from its mass and the material's rho0");
  expect_error("materials:\n  x: {library: al-alloy, fracture: {energy: 10 kJ}}\n", "x",
               "materials.x.fracture.energy");
  expect_error("materials:\n  x: {library: al-alloy, fracture: {energy: -1 J/m2}}\n", "x",
               "materials.x.fracture.energy");
  expect_error("materials:\n  x: {eos: mie-gruneisen, rho0: 2.7 g/cm3, c0: 5.2 km/s, n: 4, "
               "gamma: 2, fracture: {model: tresca, sigma_c: -1 GPa, energy: 10 kJ/m2}}\n",
               "x",
               "materials.x.fracture.energy: the cohesive opening (energy > 0) acts on the stress "
               "of a solid, but the material has no strength");
  expect_error("materials:\n  x: {library: al-alloy, fracture: {split: crack, crack_eps_f: 0}}\n",
               "x", "materials.x.fracture.crack_eps_f: the strain to failure must be > 0");
  expect_error("materials:\n  x: {library: al-alloy, fracture: {split: crack, crack_eps_f: "
               "{d2: 0.1}}}\n",
               "x", "materials.x.fracture.crack_eps_f.d1");
  expect_error("materials:\n  x: {library: al-alloy, fracture: {split: crack, crack_eps_f: "
               "{d1: -2.2, d2: 5.43, d3: -2}}}\n",
               "x",
               "materials.x.fracture.crack_eps_f: "
               "d1 + d2 exp(d3 sigma*) = ");
  {
    struct material m;
    struct hv_error err = {0};
    int rc = read_case_material("materials:\n  x: {library: al-alloy, fracture: {split: crack, "
                                "crack_eps_f: {d1: 0.13, d2: 0.13, d3: -1.5}}}\n",
                                "x", &m, NULL, &err);
    CHECK(rc == 0 && m.frac.crack_eps_f_on && m.frac.crack_d[0] == 0.13 &&
              m.frac.crack_d[1] == 0.13 && m.frac.crack_d[2] == -1.5,
          "crack_eps_f {d1, d2, d3} read (%s)", rc ? err.msg : "ok");
    if (!rc) material_free(&m);
    rc = read_case_material("materials:\n  x: {library: al-alloy, fracture: {split: crack, "
                            "crack_eps_f: 0.3}}\n",
                            "x", &m, NULL, &err);
    CHECK(rc == 0 && m.frac.crack_eps_f_on && m.frac.crack_d[0] == 0.3 && m.frac.crack_d[1] == 0.0,
          "crack_eps_f as a number: a constant strain to failure (%s)", rc ? err.msg : "ok");
    if (!rc) material_free(&m);
    rc = read_case_material("materials:\n  x: {library: al-alloy, fracture: {split: crack}}\n", "x",
                            &m, NULL, &err);
    CHECK(rc == 0 && !m.frac.crack_eps_f_on, "split: crack without crack_eps_f: none");
    if (!rc) material_free(&m);
    rc = read_case_material("materials:\n  x: {library: steel-projectile, fracture: {energy: "
                            "11 kJ/m2}}\n",
                            "x", &m, NULL, &err);
    CHECK(rc == 0 && fabs(m.frac.energy - 11e3) < 1e-9 && m.frac.sigma_c == -2.66e9,
          "fracture.energy 11 kJ/m2 read as %g J/m2 over the library's sigma_c (%s)",
          rc ? 0.0 : m.frac.energy, rc ? err.msg : "ok");
    if (!rc) material_free(&m);
  }
}

/* An error in a library value names the library file and line. */
/* ---------------------------------------------------------------- wrong units */

/* A condensed material's parameter written as a bare number (SI) far outside what real
 * materials span is refused, naming the file, line and key, with the unit it was likely
 * written in; with its unit, 0, a library's value or a gas's, it is taken. */
static void test_wrong_units(void)
{
#define MG                                                                                         \
  "materials:\n  x:\n    eos: mie-gruneisen\n    rho0: %s\n    c0: %s\n    n: 4\n"                 \
  "    gamma: 2\n"
  char y[512];
  snprintf(y, sizeof y, MG, "2780", "5.35");
  expect_error(y, "x",
               "case.yaml:5: materials.x.c0: the bare number 5.35 is read as 5.35 m/s "
               "(a number without a unit is SI), outside the bulk sound speeds of condensed "
               "materials, 100 to 50000 m/s; was it 5.35 km/s? Write the value with its unit "
               "('5.35 m/s' keeps this one)");
  snprintf(y, sizeof y, MG, "2.78", "5350");
  expect_error(y, "x",
               "case.yaml:4: materials.x.rho0: the bare number 2.78 is read as 2.78 "
               "kg/m3 (a number without a unit is SI), outside the densities of condensed "
               "materials, 50 to 100000 kg/m3; was it 2.78 g/cm3?");
  snprintf(y, sizeof y, MG, "2780", "1e6"); /* no likely unit: the range and the way out */
  expect_error(y, "x", "50000 m/s; write the value with its unit ('1e6 m/s' keeps this one)");
  expect_error("materials:\n  x: {library: steel-target, strength: {yield: 0.39}}\n", "x",
               "case.yaml:2: materials.x.strength.yield: the bare number 0.39 is read as 0.39 Pa");
  expect_error("materials:\n  x: {library: steel-target, strength: {yield: 0.39}}\n", "x",
               "was it 0.39 GPa?");
  expect_error("materials:\n  x: {library: steel-target, strength: {yield: 300}}\n", "x",
               "was it 300 MPa?");
  expect_error("materials:\n  x: {library: steel-target, strength: {shear_modulus: 95}}\n", "x",
               "materials.x.strength.shear_modulus: the bare number 95 is read as 95 Pa");
  expect_error("materials:\n  x: {library: steel-target, fracture: {sigma_c: -0.39}}\n", "x",
               "materials.x.fracture.sigma_c: the bare number -0.39 is read as -0.39 Pa");
  expect_error("materials:\n  x: {library: steel-target-jc, strength: {B: 510}}\n", "x",
               "materials.x.strength.B: the bare number 510 is read as 510 Pa");
  expect_error("materials:\n  x: {library: aluminium-tillotson, E0: 5}\n", "x",
               "materials.x.E0: the bare number 5 is read as 5 J/kg");
  expect_error("materials:\n  x: {library: aluminium-tillotson, E0: 5}\n", "x", "was it 5 MJ/kg?");
  /* taken: the same values with their units, in range, 0, a gas in scaled units */
  static const char *const ok[] = {
      "materials:\n  x:\n    eos: mie-gruneisen\n    rho0: 2780\n    c0: 5.35 m/s\n"
      "    n: 4\n    gamma: 2\n",
      "materials:\n  x:\n    eos: mie-gruneisen\n    rho0: 2.78 kg/m3\n    c0: 5350\n"
      "    n: 4\n    gamma: 2\n",
      "materials:\n  x: {library: steel-target, strength: {yield: 0.39 Pa}}\n",
      "materials:\n  x: {library: steel-target, strength: {yield: 390e6}}\n",
      "materials:\n  x: {library: steel-target, strength: {yield: 0}}\n",
      "materials:\n  x: {eos: ideal-gas, gamma: 1.4, rho0: 1}\n",
  };
  for (size_t k = 0; k < sizeof ok / sizeof ok[0]; k++) {
    struct material m;
    struct hv_error err = {0};
    const int rc = read_case_material(ok[k], "x", &m, NULL, &err);
    CHECK(rc == 0, "taken (%s): %s", rc ? err.msg : "ok", ok[k]);
    if (!rc) material_free(&m);
  }
#undef MG
}

static void test_library_errors(void)
{
  char dir[4200];
  snprintf(dir, sizeof dir, "%s/badlib", test_tmpdir());
  if (mkdir(dir, 0755) && errno != EEXIST) {
    CHECK(0, "mkdir %s", dir);
    return;
  }
  char file[4300];
  snprintf(file, sizeof file, "%s/materials.yaml", dir);
  FILE *f = fopen(file, "w");
  if (!f) return;
  fputs("# a library with a mistake\n"         /* 1 */
        "good: {eos: ideal-gas, gamma: 1.4}\n" /* 2 */
        "bad:\n"                               /* 3 */
        "  eos: mie-gruneisen\n"               /* 4 */
        "  rho0: 7.8 g/cm3\n"                  /* 5 */
        "  c0: 5 kg\n"                         /* 6 */
        "  n: 4\n"
        "  gamma: 2\n"
        "chain: {library: good}\n",
        f);
  fclose(f);
  use_library(dir);
  expect_error("materials:\n  x: {library: bad}\n", "x",
               "badlib/materials.yaml:6: materials.x.c0: unit 'kg' is a mass, expected a velocity");
  expect_error("materials:\n  x: {library: chain}\n", "x",
               "badlib/materials.yaml:9: chain.library: a library entry cannot name another");
  struct material m;
  struct hv_error err = {0};
  int rc = read_case_material("materials:\n  x: {library: good}\n", "x", &m, NULL, &err);
  CHECK(rc == 0 && m.eosp.gas.gamma == 1.4, "HVSPH_DATA chooses the library (%s)",
        rc ? err.msg : "ok");
  setenv("HVSPH_DATA", "/nonexistent-hvsph-data", 1);
  expect_error("materials:\n  x: {library: good}\n", "x",
               "case.yaml:2: materials.x.library: HVSPH_DATA=/nonexistent-hvsph-data: no readable "
               "materials.yaml there");
  use_library(NULL);
}

/* ---------------------------------------------------------------- table EOS in a case */

static void test_table_material(void)
{
  test_write_file("tab_eos.txt", "rho_count 2 e_count 2\n1000 2000\n0 1e6\n0 4e8\n0 8e8\n");
  const char *casefile =
      test_write_file("tab_case.yaml", "materials:\n"
                                       "  t: {eos: table, file: tab_eos.txt, rho0: 1000}\n"
                                       "  u: {eos: table, file: missing.txt}\n");
  struct hv_error err = {0};
  struct cfg *c = cfg_load(casefile, &err);
  if (!c) {
    CHECK(0, "case loads: %s", err.msg);
    return;
  }
  struct material m;
  int rc = material_read(c, "materials.t", "t", &m, &err);
  CHECK(rc == 0 && m.eos == EOS_TABLE && m.rho0 == 1000 && m.eosp.tab.nrho == 2,
        "table relative to the case's folder (%s)", rc ? err.msg : "ok");
  if (!rc) {
    struct eos_state st;
    eos_evaluate(&m, 1500, 5e5, &st);
    CHECK(fabs(st.p - 3e8) <= 1e-6, "table p = %.17g (3e8)", st.p);
    double e;
    CHECK(eos_energy_from_pressure(&m, 1500, 3e8, &e) == 0 && fabs(e - 5e5) <= 1e-6,
          "table: e from p round trip (%.17g)", e);
    material_free(&m);
  }
  rc = material_read(c, "materials.u", "u", &m, &err);
  char want[8400];
  snprintf(want, sizeof want,
           "%s:3: materials.u.file: cannot open EOS table '%s/missing.txt': "
           "No such file or directory",
           casefile, test_tmpdir());
  CHECK(rc == -1 && !strcmp(err.msg, want), "missing table: '%s'", err.msg);
  cfg_free(c);
}

/* ---------------------------------------------------------------- grafts and lookups */

static void test_graft(void)
{
  struct hv_error err = {0};
  struct cfg *d = cfg_load_string("a:\n  x: 1\n  m: {p: 2}\n", "dst.yaml", &err);
  struct cfg *s = cfg_load_string("e:\n  x: 9\n  y: 8\n  m: {p: 7, q: 6}\n", "src.yaml", &err);
  int rc = cfg_graft(d, "a", s, "e", &err) || cfg_graft(d, "new.b", s, "e", &err);
  cfg_free(s); /* the grafted nodes do not depend on src */
  CHECK(rc == 0, "grafts (%s)", rc ? err.msg : "ok");
  double v[6] = {0};
  rc = cfg_get_quantity(d, "a.x", UNIT_NONE, NULL, -HUGE_VAL, HUGE_VAL, &v[0], &err) ||
       cfg_get_quantity(d, "a.y", UNIT_NONE, NULL, -HUGE_VAL, HUGE_VAL, &v[1], &err) ||
       cfg_get_quantity(d, "a.m.p", UNIT_NONE, NULL, -HUGE_VAL, HUGE_VAL, &v[2], &err) ||
       cfg_get_quantity(d, "a.m.q", UNIT_NONE, NULL, -HUGE_VAL, HUGE_VAL, &v[3], &err) ||
       cfg_get_quantity(d, "new.b.x", UNIT_NONE, NULL, -HUGE_VAL, HUGE_VAL, &v[4], &err);
  CHECK(rc == 0 && v[0] == 1 && v[1] == 8 && v[2] == 2 && v[3] == 6 && v[4] == 9,
        "merge: dst keys win, src fills the rest, mappings merge (%g %g %g %g %g)", v[0], v[1],
        v[2], v[3], v[4]);
  char w[256];
  CHECK(!strcmp(cfg_where(d, "a.y", w, sizeof w), "src.yaml:3"), "grafted line: %s", w);
  CHECK(!strcmp(cfg_where(d, "a.m.q", w, sizeof w), "src.yaml:4"), "grafted nested line: %s", w);
  CHECK(!strcmp(cfg_where(d, "a.x", w, sizeof w), "dst.yaml:2"), "own line: %s", w);
  CHECK(!strcmp(cfg_node_file(d, "a.y"), "src.yaml") &&
            !strcmp(cfg_node_file(d, "a.x"), "dst.yaml") &&
            !strcmp(cfg_node_file(d, "nothing"), "dst.yaml"),
        "cfg_node_file");
  rc = cfg_get_quantity(d, "a.y", UNIT_NONE, NULL, 100.0, 200.0, &v[5], &err);
  CHECK(rc == -1 && !strncmp(err.msg, "src.yaml:3: a.y: ", 17),
        "value error in a grafted key: "
        "'%s'",
        err.msg);
  /* grafted keys never read are not "unknown" (the reader decides what applies) */
  CHECK(cfg_check_unused(d, &err) == 0, "unused grafted keys are not errors (%s)",
        err.code ? err.msg : "ok");
  s = cfg_load_string("e: 5\n", "src.yaml", &err);
  rc = cfg_graft(d, "a", s, "e", &err);
  CHECK(rc == -1 && strstr(err.msg, "src.yaml:1: 'e' must be a mapping"), "graft of a scalar: '%s'",
        err.msg);
  rc = cfg_graft(d, "a.x", s, "", &err);
  CHECK(rc == -1 && strstr(err.msg, "dst.yaml:2: a.x: expected a mapping"),
        "graft onto a scalar: "
        "'%s'",
        err.msg);
  cfg_free(s);
  cfg_free(d);
}

static void test_find_or_load(void)
{
  static const char *yaml = "materials:\n"
                            "  a: {library: steel-target}\n"
                            "bodies:\n"
                            "  - {material: copper}\n"
                            "  - {material: a}\n"
                            "  - {material: copper}\n"
                            "  - {material: nope}\n";
  struct hv_error err = {0};
  struct cfg *c = cfg_load_string(yaml, "case.yaml", &err);
  struct material mats[4];
  int n = 0;
  int i0 = material_find_or_load(c, "bodies[0].material", "copper", mats, &n, 4, &err);
  int i1 = material_find_or_load(c, "bodies[1].material", "a", mats, &n, 4, &err);
  int i2 = material_find_or_load(c, "bodies[2].material", "copper", mats, &n, 4, &err);
  CHECK(i0 == 0 && i1 == 1 && i2 == 0 && n == 2 && mats[0].eosp.mg.c0 == 3940 &&
            mats[1].str.G == 95e9 && !strcmp(mats[0].library, "copper"),
        "library material by name, case material, reuse (%d %d %d, n %d)", i0, i1, i2, n);
  CHECK(cfg_has(c, "materials.copper.c0"), "the library entry is grafted into the case");
  int i3 = material_find_or_load(c, "bodies[3].material", "nope", mats, &n, 4, &err);
  CHECK(i3 == -1 &&
            strstr(err.msg, "case.yaml:7: bodies[3].material: unknown material 'nope' "
                            "(the case defines: a, copper; the library ") &&
            strstr(err.msg, "has: tungsten-alloy, steel-target"),
        "unknown material: '%s'", err.msg);
  CHECK(cfg_check_unused(c, &err) != 0, "bodies' other keys are still unread (sanity)");
  for (int k = 0; k < n; k++) material_free(&mats[k]);
  cfg_free(c);
}

/* ---------------------------------------------------------------- hvsph materials */

static void test_cli(void)
{
  char cmd[8400], out[16384];
  snprintf(cmd, sizeof cmd, "'%s' materials", test_bin());
  int st = test_run(cmd, out, sizeof out);
  CHECK(st == 0 && strstr(out, "tungsten-alloy") && strstr(out, "nitrogen") &&
            strstr(out, "iron-tillotson") && strstr(out, "17780"),
        "hvsph materials lists the library (status %d)", st);
  snprintf(cmd, sizeof cmd, "'%s' materials al-alloy", test_bin());
  st = test_run(cmd, out, sizeof out);
  CHECK(st == 0 && strstr(out, "poisson") && strstr(out, "0.362") && strstr(out, "sigma_c") &&
            strstr(out, "-590000000") && strstr(out, "kg/m3") && strstr(out, "(5.612 km/s)"),
        "hvsph materials al-alloy: every parameter with units (status %d)%s%s", st, st ? "\n" : "",
        st ? out : "");
  snprintf(cmd, sizeof cmd, "'%s' materials steel-targte", test_bin());
  st = test_run(cmd, out, sizeof out);
  CHECK(st == 2 && strstr(out, "unknown material 'steel-targte'") && strstr(out, "steel-target"),
        "unknown name: exit 2 naming the known ones (status %d): %s", st, out);
}

int main(void)
{
  use_library(NULL);
  test_paper_values();
  test_overrides();
  test_sigma_c_off();
  test_errors();
  test_wrong_units();
  test_library_errors();
  test_table_material();
  test_graft();
  test_find_or_load();
  test_cli();
  return test_finish();
}
