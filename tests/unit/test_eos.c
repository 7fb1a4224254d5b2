/* test_eos.c — the equations of state: Mie–Grüneisen/Murnaghan (the paper's §2.1),
 * Tillotson, tabulated; their limits, continuity, sound speeds, inverse, and the table
 * reader's errors. Thresholds are written at each check. */
#define _XOPEN_SOURCE 700 /* realpath */
#include "config/config.h"
#include "eos/eos.h"
#include "material/material.h"
#include "testlib.h"

#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

/* ---------------------------------------------------------------- materials */

static struct material mg_material(const char *name, double rho0, double c0, double n, double G)
{
  struct material m;
  memset(&m, 0, sizeof m);
  snprintf(m.name, sizeof m.name, "%s", name);
  m.eos = EOS_MIE_GRUNEISEN;
  m.rho0 = rho0;
  m.eosp.mg = (struct eos_mie_gruneisen){rho0, c0, n, G, 0.1 * c0};
  m.K0 = rho0 * c0 * c0;
  return m;
}

/* Tillotson sets of Melosh (1989) Table AII.3, as in data/materials.yaml. */
static struct material till_material(const char *name, int iron)
{
  struct material m;
  memset(&m, 0, sizeof m);
  snprintf(m.name, sizeof m.name, "%s", name);
  m.eos = EOS_TILLOTSON;
  struct eos_tillotson *t = &m.eosp.til;
  if (iron)
    *t = (struct eos_tillotson){7800, 0.5, 1.5, 128e9, 105e9, 9.5e6, 5, 5, 2.4e6, 8.67e6, 0, 0};
  else
    *t = (struct eos_tillotson){2700, 0.5, 1.63, 75.2e9, 65e9, 5e6, 5, 5, 3e6, 13.9e6, 0, 0};
  t->cs_floor = 0.01 * sqrt(t->A / t->rho0);
  m.rho0 = t->rho0;
  m.K0 = t->A;
  return m;
}

/* The paper's six metals (Tables 2, 5, 8), the copper and the rubber of the library. */
#define NMG 8
static struct material mg_all[NMG];
static struct material till_all[2];

static void make_materials(void)
{
  mg_all[0] = mg_material("tungsten-alloy", 17780, 4612, 3.54, 1.66);
  mg_all[1] = mg_material("steel-target", 7810, 4900, 4.5, 1.8);
  mg_all[2] = mg_material("steel-projectile", 7700, 4760, 4, 1.38);
  mg_all[3] = mg_material("steel-bumper", 7850, 4406, 4, 1.38);
  mg_all[4] = mg_material("al-alloy", 2780, 5612, 3.54, 1.176);
  mg_all[5] = mg_material("al-projectile", 2701, 5240, 3.54, 0.97);
  mg_all[6] = mg_material("copper", 8930, 3940, 4.96, 2.0);
  mg_all[7] = mg_material("rubber-ring", 1, 1, 1, 0);
  till_all[0] = till_material("aluminium-tillotson", 0);
  till_all[1] = till_material("iron-tillotson", 1);
}

static double pressure(const struct material *m, double rho, double e)
{
  struct eos_state st = {(double)NAN, (double)NAN};
  int rc = eos_evaluate(m, rho, e, &st);
  return rc == EOS_OK ? st.p : (double)NAN;
}

/* ---------------------------------------------------------------- Mie–Grüneisen */

static void test_mg_reference_state(void)
{
  for (int k = 0; k < NMG; k++) {
    const struct material *m = &mg_all[k];
    struct eos_state st;
    int rc = eos_evaluate(m, m->rho0, 0.0, &st);
    /* threshold: |p| <= 1e-9 Pa (exactly 0 in exact arithmetic; expm1(n ln 1) = 0) */
    CHECK(rc == 0 && fabs(st.p) <= 1e-9, "%s: p(rho0, 0) = %g Pa", m->name, st.p);
    /* at the reference state c = c0 (threshold 1e-12 relative) */
    CHECK(fabs(st.cs - m->eosp.mg.c0) <= 1e-12 * m->eosp.mg.c0, "%s: c(rho0, 0) = %.17g, c0 %g",
          m->name, st.cs, m->eosp.mg.c0);
    CHECK(eos_mg_cold_energy(&m->eosp.mg, m->rho0) == 0.0, "%s: E_c(rho0) = 0", m->name);
  }
}

/* dE_c/dρ = p_c/ρ² holds exactly for the paper's formulas (see mie_gruneisen.c):
 * central differences, step 1e-4 ρ, relative 1e-6. */
static void test_mg_cold_identity(void)
{
  static const double xs[] = {0.5, 0.7, 0.9, 0.97, 1.03, 1.2, 1.5, 2.0, 3.0};
  double worst = 0.0;
  for (int k = 0; k < NMG; k++) {
    const struct eos_mie_gruneisen *g = &mg_all[k].eosp.mg;
    for (size_t i = 0; i < sizeof xs / sizeof xs[0]; i++) {
      const double rho = xs[i] * g->rho0, h = 1e-4 * rho;
      const double fd = (eos_mg_cold_energy(g, rho + h) - eos_mg_cold_energy(g, rho - h)) / (2 * h);
      const double exact = eos_mg_cold_pressure(g, rho) / (rho * rho);
      const double rel = fabs(fd - exact) / fabs(exact);
      if (rel > worst) worst = rel;
      CHECK(rel <= 1e-6, "%s: dE_c/drho = %.12g vs p_c/rho^2 = %.12g at rho/rho0 = %g (rel %.2g)",
            mg_all[k].name, fd, exact, xs[i], rel);
    }
  }
  printf("  dE_c/drho = p_c/rho^2: worst relative difference %.2g (threshold 1e-6)\n", worst);
}

/* steel-target (Table 2) at ρ = 1.2ρ₀ = 9372 kg/m3, E = 1 MJ/kg, computed by hand with
 * 50-digit decimals: x^4.5 = 1.2^4 √1.2, x^3.5 = 1.2^3 √1.2;
 * p_c = ρ₀c₀²/n (x^4.5 − 1) = 52 984 905 586.076657 Pa,
 * E_c = c₀²/n ((x^3.5 − 1)/3.5 − 1 + 1/1.2) = 471 961.636 061 113 86 J/kg,
 * p = p_c + Γρ(E − E_c) = 61 892 701 570.380 090 Pa, c = 6 936.176 357 010 241 m/s. */
static void test_mg_hand_point(void)
{
  const struct material *m = &mg_all[1];
  struct eos_state st;
  int rc = eos_evaluate(m, 1.2 * 7810.0, 1e6, &st);
  const double p = 61892701570.380090490500747, c = 6936.1763570102413300977595;
  CHECK(rc == 0 && fabs(st.p - p) <= 1e-12 * p,
        "steel-target p(1.2 rho0, 1 MJ/kg) = %.17g Pa, "
        "hand %.17g (rel %.2g, threshold 1e-12)",
        st.p, p, fabs(st.p - p) / p);
  CHECK(fabs(st.cs - c) <= 1e-12 * c, "steel-target c = %.17g m/s, hand %.17g", st.cs, c);
  CHECK(fabs(eos_mg_cold_pressure(&m->eosp.mg, 9372.0) - 52984905586.076656892) <= 1e-12 * 5.3e10,
        "p_c hand value");
  CHECK(fabs(eos_mg_cold_energy(&m->eosp.mg, 9372.0) - 471961.63606111386172) <= 1e-12 * 4.8e5,
        "E_c hand value");
}

/* ---------------------------------------------------------------- sound speeds */

/* c² = ∂p/∂ρ|_e + p/ρ² ∂p/∂e|_ρ by central differences; relative steps 1e-6. */
static double c2_numeric(const struct material *m, double rho, double e, double escale)
{
  const double hr = 1e-6 * rho, he = 1e-6 * escale;
  const double dpdr = (pressure(m, rho + hr, e) - pressure(m, rho - hr, e)) / (2 * hr);
  const double dpde = (pressure(m, rho, e + he) - pressure(m, rho, e - he)) / (2 * he);
  return dpdr + pressure(m, rho, e) / (rho * rho) * dpde;
}

/* The analytic sound speeds against numerical derivatives of p (relative 1e-5), where the
 * floor is not active and not at a region boundary. */
static void test_sound_speed_consistency(void)
{
  static const double xs[] = {0.6, 0.85, 0.97, 1.05, 1.3, 2.0, 2.9};
  static const double es[] = {0.0, 0.4e6, 2.0e6, 5.5e6, 9.0e6, 16e6};
  int n = 0;
  double worst = 0.0;
  for (int k = 0; k < NMG + 2; k++) {
    const struct material *m = k < NMG ? &mg_all[k] : &till_all[k - NMG];
    if (k == NMG - 1) continue; /* rubber: dimensionless, energies do not apply */
    const double floor = k < NMG ? m->eosp.mg.cs_floor : m->eosp.til.cs_floor;
    for (size_t i = 0; i < sizeof xs / sizeof xs[0]; i++)
      for (size_t j = 0; j < sizeof es / sizeof es[0]; j++) {
        double e = es[j];
        if (k >= NMG && e == 0.0) e = 1e4; /* Tillotson clamps e < 0: stay inside */
        if (k >= NMG) {
          const struct eos_tillotson *t = &m->eosp.til;
          if (fabs(e - t->E_iv) < 1e4 || fabs(e - t->E_cv) < 1e4) continue;
        }
        struct eos_state st;
        eos_evaluate(m, xs[i] * m->rho0, e, &st);
        const double c2n = c2_numeric(m, xs[i] * m->rho0, e, 1e6);
        if (!(c2n > 1.01 * floor * floor)) continue;
        const double rel = fabs(st.cs * st.cs - c2n) / c2n;
        if (rel > worst) worst = rel;
        n++;
        CHECK(rel <= 1e-5, "%s: c^2 = %.10g vs numerical %.10g at rho/rho0 = %g, e = %g J/kg",
              m->name, st.cs * st.cs, c2n, xs[i], e);
      }
  }
  printf("  sound speed vs numerical dp: %d states, worst relative difference %.2g (threshold "
         "1e-5)\n",
         n, worst);
}

/* c² > 0 (a finite c ≥ floor > 0) over 0.5–3 ρ₀ and 0–20 MJ/kg for every library solid;
 * and in compression (ρ ≥ ρ₀, E ≥ 0) the floor is never needed. */
static void test_sound_speed_positive(void)
{
  for (int k = 0; k < NMG + 2; k++) {
    const struct material *m = k < NMG ? &mg_all[k] : &till_all[k - NMG];
    int bad = 0, floored_in_compression = 0, floored = 0, total = 0;
    for (int i = 0; i <= 50; i++)
      for (int j = 0; j <= 40; j++) {
        const double x = 0.5 + 2.5 * i / 50.0, e = 20e6 * j / 40.0;
        struct eos_state st;
        const int rc = eos_evaluate(m, x * m->rho0, e, &st);
        const double floor = k < NMG ? m->eosp.mg.cs_floor : m->eosp.til.cs_floor;
        total++;
        if (rc || !(st.cs > 0.0) || !isfinite(st.cs) || !isfinite(st.p)) bad++;
        if (st.cs <= floor) {
          floored++;
          if (x >= 1.0) floored_in_compression++;
        }
      }
    CHECK(bad == 0, "%s: c > 0 and finite over 0.5-3 rho0 x 0-20 MJ/kg (%d bad of %d)", m->name,
          bad, total);
    CHECK(floored_in_compression == 0, "%s: no floored sound speed for rho >= rho0 (%d)", m->name,
          floored_in_compression);
    printf("  %-20s c > 0 on %d states; floor active on %d (all with rho < rho0)\n", m->name, total,
           floored);
  }
}

/* ---------------------------------------------------------------- Tillotson */

static void test_tillotson_reference(void)
{
  for (int k = 0; k < 2; k++) {
    const struct material *m = &till_all[k];
    struct eos_state st;
    eos_evaluate(m, m->rho0, 0.0, &st);
    /* threshold |p| <= 1e-9 Pa; c = √(A/ρ₀) there to 1e-12 */
    CHECK(fabs(st.p) <= 1e-9, "%s: p(rho0, 0) = %g", m->name, st.p);
    const double c0 = sqrt(m->eosp.til.A / m->rho0);
    CHECK(fabs(st.cs - c0) <= 1e-12 * c0, "%s: c(rho0, 0) = %.15g, sqrt(A/rho0) = %.15g", m->name,
          st.cs, c0);
    /* compressed, cold: p = Aμ + Bμ² exactly */
    const double mu = 0.1, pc = m->eosp.til.A * mu + m->eosp.til.B * mu * mu;
    CHECK(fabs(pressure(m, 1.1 * m->rho0, 0.0) - pc) <= 1e-12 * pc,
          "%s: p(1.1 rho0, 0) = A mu + "
          "B mu^2",
          m->name);
  }
}

/* In expansion, p is continuous at E_iv and E_cv: approaching from both sides within
 * 1e-13 E (so that the smooth change ∂p/∂E·2δ is ~1e-13 of p), the relative jump
 * |p+ − p−|/|p| stays below 1e-9. Also continuous in ρ at ρ₀. */
static void test_tillotson_continuity(void)
{
  static const double xs[] = {0.95, 0.8, 0.6, 0.4, 0.2};
  double worst = 0.0;
  for (int k = 0; k < 2; k++) {
    const struct material *m = &till_all[k];
    const struct eos_tillotson *t = &m->eosp.til;
    for (size_t i = 0; i < sizeof xs / sizeof xs[0]; i++) {
      const double E[2] = {t->E_iv, t->E_cv}, rho = xs[i] * t->rho0;
      for (int b = 0; b < 2; b++) {
        const double d = 1e-13 * E[b];
        const double pm = pressure(m, rho, E[b] - d), pp = pressure(m, rho, E[b] + d);
        const double p0 = pressure(m, rho, E[b]);
        const double jump = fabs(pp - pm) / fabs(p0);
        if (jump > worst) worst = jump;
        CHECK(jump < 1e-9, "%s: jump at %s, rho/rho0 = %g: p- = %.15g, p+ = %.15g (rel %.2g)",
              m->name, b ? "E_cv" : "E_iv", xs[i], pm, pp, jump);
      }
    }
    /* across ρ₀ at energies in every region */
    const double es[] = {1e6, 0.5 * (t->E_iv + t->E_cv), 2.0 * t->E_cv};
    for (int j = 0; j < 3; j++) {
      const double pm = pressure(m, t->rho0 * (1 - 1e-12), es[j]);
      const double pp = pressure(m, t->rho0 * (1 + 1e-12), es[j]);
      CHECK(fabs(pp - pm) <= 1e-9 * fabs(pp),
            "%s: continuous across rho0 at e = %g (%.15g, "
            "%.15g)",
            m->name, es[j], pm, pp);
    }
  }
  printf("  Tillotson: worst relative jump at E_iv/E_cv %.2g (threshold 1e-9)\n", worst);
}

/* The hybrid region is the linear interpolation in E of the two branches. */
static void test_tillotson_hybrid(void)
{
  const struct material *m = &till_all[0];
  const struct eos_tillotson *t = &m->eosp.til;
  const double rho = 0.7 * t->rho0, Em = 0.25 * t->E_iv + 0.75 * t->E_cv;
  const double pc = pressure(m, rho, t->E_iv), pe = pressure(m, rho, t->E_cv);
  /* at fixed ρ the branches depend on E too: check against the formulas directly */
  const double eta = 0.7, mu = eta - 1, z = 1 / eta - 1, w = Em / (t->E0 * eta * eta) + 1;
  const double Pc = (t->a + t->b / w) * rho * Em + t->A * mu + t->B * mu * mu;
  const double Pe = t->a * rho * Em +
                    (t->b * rho * Em / w + t->A * mu * exp(-t->beta * z)) * exp(-t->alpha * z * z);
  const double want = 0.75 * Pe + 0.25 * Pc;
  CHECK(fabs(pressure(m, rho, Em) - want) <= 1e-12 * fabs(want),
        "hybrid p = %.15g, formula "
        "%.15g",
        pressure(m, rho, Em), want);
  CHECK(pc != pe, "branches differ at rho = 0.7 rho0 (%.6g, %.6g)", pc, pe);
}

static void test_tillotson_rho_iv(void)
{
  struct material m = till_all[0];
  m.eosp.til.rho_iv = 0.8 * m.rho0;
  /* cold, below ρ_iv: no tension; above: the usual tension */
  CHECK(pressure(&m, 0.7 * m.rho0, 0.0) == 0.0, "rho < rho_iv, cold: p = 0 (%g)",
        pressure(&m, 0.7 * m.rho0, 0.0));
  CHECK(pressure(&m, 0.9 * m.rho0, 0.0) < 0.0, "rho_iv < rho < rho0, cold: tension");
  CHECK(pressure(&till_all[0], 0.7 * m.rho0, 0.0) < 0.0, "without rho_iv: tension at 0.7 rho0");
}

/* ---------------------------------------------------------------- tables */

static const double tab_gamma = 1.4, tab_A = 2e9, tab_r0 = 1000.0;

/* p(ρ, e) = (γ − 1)ρe + A((ρ/ρ₀)³ − 1): bilinear error bound Δρ²/8 max|p_ρρ| (p_ee = 0). */
static double tab_f(double rho, double e, int cubic)
{
  const double x = rho / tab_r0;
  return (tab_gamma - 1) * rho * e + (cubic ? tab_A * (x * x * x - 1) : 0.0);
}

/* Writes an N × M table of tab_f (with c rows if with_c) and returns its path. */
static const char *write_table(const char *name, int N, int M, int cubic, int with_c)
{
  size_t cap = 64 + 40 * (size_t)(N + M + 2 * N * M), k = 0;
  char *s = malloc(cap);
  k += (size_t)snprintf(s + k, cap - k, "# analytic test table\nrho_count %d e_count %d\n", N, M);
  for (int i = 0; i < N; i++)
    k += (size_t)snprintf(s + k, cap - k, "%.17g ", 500.0 + 1500.0 * i / (N - 1));
  k += (size_t)snprintf(s + k, cap - k, "\n");
  for (int j = 0; j < M; j++) k += (size_t)snprintf(s + k, cap - k, "%.17g ", 1e6 * j / (M - 1));
  k += (size_t)snprintf(s + k, cap - k, "\n");
  for (int pass = 0; pass < 1 + with_c; pass++)
    for (int i = 0; i < N; i++) {
      const double rho = 500.0 + 1500.0 * i / (N - 1);
      for (int j = 0; j < M; j++) {
        const double e = 1e6 * j / (M - 1);
        const double v = pass ? sqrt(tab_gamma * (tab_gamma - 1) * e + 1.0) : tab_f(rho, e, cubic);
        k += (size_t)snprintf(s + k, cap - k, "%.17g ", v);
      }
      k += (size_t)snprintf(s + k, cap - k, "\n");
    }
  const char *path = test_write_file(name, s);
  free(s);
  return path;
}

static struct material table_material(const char *path, struct hv_error *err, int *rc)
{
  struct material m;
  memset(&m, 0, sizeof m);
  snprintf(m.name, sizeof m.name, "tab");
  m.eos = EOS_TABLE;
  *rc = eos_table_load(path, &m.eosp.tab, err);
  return m;
}

static void test_table_interpolation(void)
{
  struct hv_error err = {0};
  int rc;
  /* ideal gas: p = (γ−1)ρe is bilinear, so the interpolation is exact (to 1e-12 relative),
   * and so is c² = ∂p/∂ρ + p/ρ² ∂p/∂e = γ(γ−1)e from the cell's derivatives */
  struct material m = table_material(write_table("gas.txt", 7, 9, 0, 0), &err, &rc);
  CHECK(rc == 0, "ideal-gas table loads (%s)", rc ? err.msg : "ok");
  if (rc) return;
  double worst = 0.0;
  srand(12345);
  for (int k = 0; k < 2000; k++) {
    const double rho = 500.0 + 1500.0 * rand() / (double)RAND_MAX;
    const double e = 1e3 + (1e6 - 1e3) * rand() / (double)RAND_MAX;
    struct eos_state st;
    eos_evaluate(&m, rho, e, &st);
    const double p = tab_f(rho, e, 0), c = sqrt(tab_gamma * (tab_gamma - 1) * e);
    const double rel = fmax(fabs(st.p - p) / p, fabs(st.cs - c) / c);
    if (rel > worst) worst = rel;
  }
  CHECK(worst <= 1e-12, "ideal-gas table exact: worst relative error %.2g (threshold 1e-12)",
        worst);
  /* energy from pressure on the table: round trip to 1e-12 */
  double e = 0.0;
  const double p = tab_f(1234.5, 4.2e5, 0);
  rc = eos_energy_from_pressure(&m, 1234.5, p, &e);
  CHECK(rc == 0 && fabs(e - 4.2e5) <= 1e-12 * 4.2e5, "table: e from p = %.15g (4.2e5)", e);
  /* outside: an error naming the material and the state */
  struct eos_state st = {0, 0};
  rc = eos_evaluate(&m, 2500.0, 1e5, &st);
  char msg[512];
  eos_describe(&m, 2500.0, 1e5, rc, msg, sizeof msg);
  CHECK(rc == EOS_ERR_OUTSIDE_TABLE && strstr(msg, "material 'tab'") && strstr(msg, "rho = 2500") &&
            strstr(msg, "e = 100000") && strstr(msg, "outside the table"),
        "outside the table: rc %d, '%s'", rc, msg);
  CHECK(eos_evaluate(&m, 1000.0, -1.0, &st) == EOS_ERR_OUTSIDE_TABLE, "e below the table");
  CHECK(eos_energy_from_pressure(&m, 3000.0, 1e5, &e) == EOS_ERR_OUTSIDE_TABLE,
        "energy_from_pressure outside");
  material_free(&m);

  /* a non-bilinear p: the error stays within Δρ²/8 max|p_ρρ| = Δρ²/8 · 6Aρ_max/ρ₀³ */
  const int N = 16;
  m = table_material(write_table("cubic.txt", N, 5, 1, 1), &err, &rc);
  CHECK(rc == 0, "cubic table loads (%s)", rc ? err.msg : "ok");
  if (rc) return;
  const double dr = 1500.0 / (N - 1);
  const double bound = dr * dr / 8.0 * 6.0 * tab_A * 2000.0 / (tab_r0 * tab_r0 * tab_r0);
  double emax = 0.0;
  for (int k = 0; k < 4000; k++) {
    const double rho = 500.0 + 1500.0 * rand() / (double)RAND_MAX;
    const double en = 1e6 * rand() / (double)RAND_MAX;
    struct eos_state s2;
    eos_evaluate(&m, rho, en, &s2);
    const double err_abs = fabs(s2.p - tab_f(rho, en, 1));
    if (err_abs > emax) emax = err_abs;
  }
  CHECK(emax <= bound * (1 + 1e-9), "bilinear error %.4g Pa within the bound %.4g Pa", emax, bound);
  CHECK(emax >= 0.05 * bound, "the test table is not trivially exact (error %.3g, bound %.3g)",
        emax, bound);
  printf("  table: bilinear error %.4g Pa, bound dr^2/8 max|p_rr| = %.4g Pa\n", emax, bound);
  /* c rows: interpolated (at a node: exact) */
  struct eos_state s3;
  eos_evaluate(&m, 500.0, 1e6, &s3);
  CHECK(fabs(s3.cs - sqrt(tab_gamma * (tab_gamma - 1) * 1e6 + 1.0)) <= 1e-9,
        "c from the c rows "
        "at a node (%.12g)",
        s3.cs);
  material_free(&m);
}

/* Bad files: each message names the file and the line. */
static void test_table_errors(void)
{
  static const struct {
    const char *name, *text, *expect;
  } cases[] = {
      {"unsorted_rho.txt", "rho_count 3 e_count 2\n1 3 2\n0 1\n1 2\n3 4\n5 6\n",
       "unsorted_rho.txt:2: rho values must increase strictly (rho[3] = 2 after 3)"},
      {"unsorted_e.txt", "rho_count 2 e_count 3\n1 2\n# e\n0 2 2\n1 2 3\n4 5 6\n",
       "unsorted_e.txt:4: e values must increase strictly (e[3] = 2 after 2)"},
      {"hole.txt", "rho_count 2 e_count 3\n1 2\n0 1 2\n1 2 3\n4 6\n",
       "hole.txt:5: pressure row 2 (rho = 2 kg/m3) has 2 values, expected 3 (e_count)"},
      {"nan.txt", "rho_count 2 e_count 2\n1 2\n0 1\n1 nan\n3 4\n",
       "nan.txt:4: pressure row 1 value 2: 'nan' is not a finite number (holes are not allowed)"},
      {"short.txt", "rho_count 3 e_count 2\n1 2 3\n0 1\n1 2\n3 4\n",
       "short.txt:5: expected 3 pressure rows of 2 values, found 2 (the file ends)"},
      {"axis.txt", "rho_count 3 e_count 2\n1 2\n",
       "axis.txt:2: expected 3 rho values, found 2 (the file ends)"},
      {"axis_e.txt", "rho_count 2 e_count 2\n1 2\n0\n",
       "axis_e.txt:3: expected 2 e values, found 1 (the file ends)"},
      {"header.txt", "# no header\nrho 3 e 2\n",
       "header.txt:2: expected the header 'rho_count N e_count M'"},
      {"count.txt", "rho_count 1 e_count 2\n",
       "count.txt:1: rho_count must be an integer >= 2 (got 1)"},
      {"extra.txt", "rho_count 2 e_count 2\n1 2\n0 1\n1 2\n3 4\n5 6\n7 8\n9 9\n",
       "extra.txt:8: unexpected values after the 2 sound-speed rows"},
      {"cneg.txt", "rho_count 2 e_count 2\n1 2\n0 1\n1 2\n3 4\n5 6\n7 -8\n",
       "cneg.txt:7: sound-speed row 2 value 2 = -8 must be > 0"},
      {"word.txt", "rho_count 2 e_count 2\n1 2\n0 x1\n", "word.txt:3: e[2]: 'x1' is not a number"},
      /* a sound speed past light's (found by fuzzing: 9.2e18 m/s set a step of order 1e-22 s, a
         run that never ends) */
      {"clight.txt", "rho_count 2 e_count 2\n1 2\n0 1\n1 2\n3 4\n5 9.2e18\n7 8\n",
       "clight.txt:6: sound-speed row 1 value 2 = 9.2e+18 m/s is faster than light "
       "(2.99792e+08 m/s): the table is in SI units"},
  };
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
    const char *path = test_write_file(cases[k].name, cases[k].text);
    struct eos_table t;
    struct hv_error err = {0};
    int rc = eos_table_load(path, &t, &err);
    char want[600];
    snprintf(want, sizeof want, "%s/%s", test_tmpdir(), cases[k].expect);
    const int same = !strcmp(err.msg, want);
    CHECK(rc == -1 && err.code == HV_EXIT_INPUT && same, "%s: '%s'%s%s", cases[k].name, err.msg,
          same ? "" : "\n        wanted: ", same ? "" : want);
  }
  struct eos_table t;
  struct hv_error err = {0};
  int rc = eos_table_load("/nonexistent/eos.txt", &t, &err);
  CHECK(rc == -1 && strstr(err.msg, "cannot open EOS table '/nonexistent/eos.txt'"),
        "missing file: '%s'", err.msg);
  /* comments, blank lines, axes over several lines */
  const char *ok = test_write_file("ok.txt", "# header\n\nrho_count 2 e_count 2  # sizes\n1\n2\n"
                                             "0 1\n\n1 2  # row 1\n3 4\n");
  rc = eos_table_load(ok, &t, &err);
  CHECK(rc == 0 && t.nrho == 2 && t.ne == 2 && t.p[3] == 4.0 && !t.cs,
        "comments and blank "
        "lines (%s)",
        rc ? err.msg : "ok");
  if (!rc) eos_table_free(&t);
  /* the example of docs/models.md */
  const char *doc = test_write_file(
      "doc.txt",
      "# comments start with '#' and run to the end of the line; blank lines are ignored\n"
      "rho_count 3 e_count 4          # header: N, M >= 2\n"
      "2000 2700 3500                 # N densities [kg/m3], > 0, strictly increasing\n"
      "0 1e5 1e6 1e7                  # M specific energies [J/kg], strictly increasing\n"
      "-1e9  -9e8  0     9e9          # N pressure rows [Pa], one line per density,\n"
      " 0     2e8  2e9   2e10         #   M values each\n"
      " 2e10  2e10 2.3e10 4e10\n"
      "5000 5010 5100 6000            # optional: N sound-speed rows [m/s], > 0\n"
      "5300 5310 5400 6300\n"
      "5600 5610 5700 6600\n");
  rc = eos_table_load(doc, &t, &err);
  CHECK(rc == 0 && t.nrho == 3 && t.ne == 4 && t.cs && t.cs[11] == 6600 && t.cs_max == 6600,
        "the docs/models.md example loads (%s)", rc ? err.msg : "ok");
  if (!rc) eos_table_free(&t);
}

/* ---------------------------------------------------------------- the table's file */

/* The value of `key: "..."` in a used_parameters.yaml text ("" if absent). */
static const char *used_value(const char *text, const char *key, char *buf, size_t len)
{
  buf[0] = '\0';
  const char *q = text ? strstr(text, key) : NULL;
  if (!q || !(q = strchr(q, '"'))) return buf;
  const size_t n = strcspn(q + 1, "\"");
  snprintf(buf, len, "%.*s", (int)(n < len ? n : len - 1), q + 1);
  return buf;
}

/* Exactly one error line in the output. */
static int one_error(const char *s)
{
  const char *e = strstr(s, "hvsph: error: ");
  return e && !strstr(e + 1, "hvsph: error: ");
}

/* A table named by a relative path in a case file: the run's used_parameters.yaml
 * records the resolved absolute path and the file's CRC-32 (file_crc32), so that
 * `hvsph restart` from another working folder and a rerun of used_parameters.yaml find
 * the table (both failed with "cannot open EOS table 'num/T2/wide.txt'", the path taken
 * relative to the run folder); a table changed since is refused by both, naming the
 * file, and the run folder stays as it was. A FIFO as the table is refused (alarm: a
 * regression blocks in open() and must fail, not hang). */
static void test_table_file(void)
{
  char dir[4200], cmd[12000], out[8192], path[4400];
  snprintf(dir, sizeof dir, "%s/proj", test_tmpdir());
  snprintf(cmd, sizeof cmd, "rm -rf '%s' && mkdir -p '%s/num/T2'", dir, dir);
  CHECK(test_run(cmd, NULL, 0) == 0, "prepared %s", dir);
  /* p = p(ρ, e) linear in each: any state of the gas-like slab below lies inside */
  const char *table = "rho_count 4 e_count 3\n500 1000 1500 2000\n0 1e5 1e6\n"
                      "-4.99e7 -2.99e7 1.501e8\n1e5 4.01e7 4.001e8\n5.01e7 1.101e8 6.501e8\n"
                      "1.001e8 1.801e8 9.001e8\n";
  snprintf(path, sizeof path, "%s/num/T2/wide.txt", dir);
  FILE *f = fopen(path, "w");
  if (f) {
    fputs(table, f);
    fclose(f);
  }
  snprintf(path, sizeof path, "%s/case.yaml", dir);
  f = fopen(path, "w");
  if (f) {
    fputs("name: tab\n"
          "materials:\n"
          "  w: {eos: table, file: num/T2/wide.txt, rho0: 1000}\n"
          "domain: {min: [0, 0, 0], max: [0.1, 0.05, 0.05],\n"
          "         boundary: {x: wall, y: periodic, z: periodic}}\n"
          "bodies:\n"
          "  - {name: slab, material: w,\n"
          "     shape: {type: box, min: [0, 0, 0], max: [0.1, 0.05, 0.05]},\n"
          "     spacing: 6.25 mm, density: 1000, energy: 5e5}\n"
          "time: {end: 1e-5}\n"
          "output: {every: 5e-6}\n",
          f);
    fclose(f);
  }
  snprintf(cmd, sizeof cmd, "cd '%s' && '%s' run case.yaml -o out/tab -q 2>&1", dir, test_bin());
  int rc = test_run(cmd, out, sizeof out);
  CHECK(rc == 0, "run with the table at num/T2/wide.txt: exit %d (%s)", rc, out);
  char used[4400], rec[4200], want[4400];
  snprintf(used, sizeof used, "%s/out/tab/used_parameters.yaml", dir);
  char *text = test_slurp(used, NULL);
  char *real = realpath(dir, NULL);
  snprintf(want, sizeof want, "%s/num/T2/wide.txt", real ? real : dir);
  free(real);
  used_value(text, "    file:", rec, sizeof rec);
  CHECK(!strcmp(rec, want), "used_parameters.yaml records the resolved path '%s' (got '%s')", want,
        rec);
  char crc[16];
  snprintf(crc, sizeof crc, "%08lx",
           crc32(crc32(0L, Z_NULL, 0), (const Bytef *)table, (uInt)strlen(table)) & 0xffffffffUL);
  used_value(text, "file_crc32:", rec, sizeof rec);
  CHECK(!strcmp(rec, crc), "and the table's CRC-32 %s (got '%s')", crc, rec);
  free(text);

  /* restart from another working folder; rerun used_parameters.yaml from the run folder */
  snprintf(cmd, sizeof cmd, "cd / && '%s' restart '%s/out/tab' --set time.end=2e-5 -q 2>&1",
           test_bin(), dir);
  rc = test_run(cmd, out, sizeof out);
  CHECK(rc == 0, "restart from /: exit %d (%s)", rc, out);
  snprintf(cmd, sizeof cmd,
           "cd '%s/out/tab' && '%s' run used_parameters.yaml -o ../rerun -q "
           "2>&1",
           dir, test_bin());
  rc = test_run(cmd, out, sizeof out);
  CHECK(rc == 0, "rerun of used_parameters.yaml from the run folder: exit %d (%s)", rc, out);

  /* the table changed (one comment line added): both refused, naming the file */
  snprintf(path, sizeof path, "%s/num/T2/wide.txt", dir);
  f = fopen(path, "a");
  if (f) {
    fputs("# edited\n", f);
    fclose(f);
  }
  char sum[4400];
  snprintf(sum, sizeof sum, "%s/out/tab/summary.csv", dir);
  char *before = test_slurp(sum, NULL);
  snprintf(cmd, sizeof cmd, "cd / && '%s' restart '%s/out/tab' --set time.end=3e-5 -q 2>&1",
           test_bin(), dir);
  rc = test_run(cmd, out, sizeof out);
  CHECK(rc == 2 && strstr(out, want) && strstr(out, "file_crc32") && strstr(out, crc) &&
            one_error(out),
        "restart with the table changed: exit %d (want 2), one line "
        "naming the table and its recorded CRC: %s",
        rc, out);
  char *after = test_slurp(sum, NULL);
  CHECK(before && after && !strcmp(before, after), "the run's summary.csv is untouched");
  free(before);
  free(after);
  snprintf(cmd, sizeof cmd,
           "cd '%s/out/tab' && '%s' run used_parameters.yaml -o ../rerun2 -q "
           "2>&1",
           dir, test_bin());
  rc = test_run(cmd, out, sizeof out);
  CHECK(rc == 2 && strstr(out, want) && strstr(out, "used_parameters.yaml:") &&
            strstr(out, "file_crc32"),
        "rerun with the table changed: exit %d (want 2): %s", rc, out);
  snprintf(cmd, sizeof cmd,
           "cd '%s' && '%s' run case.yaml --set materials.w.file_crc32=1234 "
           "-o out/bad -q 2>&1",
           dir, test_bin());
  rc = test_run(cmd, out, sizeof out);
  CHECK(rc == 2 && strstr(out, "materials.w.file_crc32") && strstr(out, "'1234' is not a CRC-32"),
        "a malformed file_crc32: exit %d (want 2): %s", rc, out);

  /* eos_table_load's CRC is that of the file's bytes */
  struct eos_table t;
  struct hv_error err = {0};
  rc = eos_table_load(path, &t, &err);
  char *bytes = test_slurp(path, NULL);
  CHECK(rc == 0 && bytes &&
            t.crc32 == (crc32(crc32(0L, Z_NULL, 0), (const Bytef *)bytes, (uInt)strlen(bytes)) &
                        0xffffffffUL),
        "eos_table_load's crc32 is zlib's of the file (%s)", rc ? err.msg : "ok");
  free(bytes);
  if (!rc) eos_table_free(&t);

  /* a FIFO or a device as the table */
  snprintf(path, sizeof path, "%s/fifo.txt", dir);
  CHECK(mkfifo(path, 0600) == 0, "made the FIFO %s", path);
  alarm(30);
  rc = eos_table_load(path, &t, &err);
  alarm(0);
  CHECK(rc == -1 && err.code == HV_EXIT_INPUT && strstr(err.msg, path) && strstr(err.msg, "FIFO"),
        "a FIFO as the table refused: '%s'", err.msg);
  rc = eos_table_load("/dev/zero", &t, &err);
  CHECK(rc == -1 && strstr(err.msg, "'/dev/zero' is a character device"),
        "/dev/zero as the table refused: '%s'", err.msg);
}

/* ---------------------------------------------------------------- extreme densities */

/* ρ → 0: the pressure has a finite limit, and the code must return it, not −inf or NaN
 * (a non-finite p ends the run; the state is a valid one of the EOS).
 * Mie–Grüneisen: E_c ≈ c₀²ρ₀/(nρ) overflows below ρ ≈ 1e-297 kg/m3, while ρE_c stays
 * finite: p → p_c(0) − Γρ₀c₀²/n·(1 + ρ/((n − 1)ρ₀) …) = −(1 + Γ)ρ₀c₀²/n (relative 1e-12;
 * the neglected terms are below 1e-290), c → floor (c² → −∞). With Γ = 0 (rubber)
 * p = c₀²(ρ − ρ₀) = −1 and c = c₀ = 1 (n = 1).
 * Tillotson: η² = (ρ/ρ₀)² underflows to 0 below ρ ≈ 1e-165, where the cold state
 * (E = 0, or E < 0 evaluated as 0) has ω = 0/0 + 1; its limit is p = Aμ + Bμ² = B − A.
 * In the expanded branch (E ≥ E_cv) p → aρE and c² = ∂p/∂ρ + (p/ρ²)∂p/∂E → a(a + 1)E (the
 * terms with e^(−αz²) and e^(−βz) vanish faster than any power of ρ), which the code gives
 * down to ρ ≈ 1e-150; below, 0·∞ in the derivatives floored c at 1% of √(A/ρ₀). */
static void test_low_density(void)
{
  for (int k = 0; k < NMG - 1; k++) {
    const struct material *m = &mg_all[k];
    const struct eos_mie_gruneisen *g = &m->eosp.mg;
    const double want = -(1.0 + g->Gamma) * g->rho0 * g->c0 * g->c0 / g->n;
    const double rhos[] = {1e-100, 1e-300, 1e-310};
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++) {
        const double e = j == 0 ? 0.0 : j == 1 ? -1e6 : 1e7;
        struct eos_state st = {(double)NAN, (double)NAN};
        const int rc = eos_evaluate(m, rhos[i], e, &st);
        CHECK(rc == 0 && fabs(st.p - want) <= 1e-12 * fabs(want) && st.cs == g->cs_floor,
              "%s: p(%g kg/m3, %g J/kg) = %.15g Pa, limit %.15g; c = %g (floor %g)", m->name,
              rhos[i], e, st.p, want, st.cs, g->cs_floor);
      }
  }
  {
    struct eos_state st = {(double)NAN, (double)NAN};
    const int rc = eos_evaluate(&mg_all[7], 1e-310, 0.0, &st);
    CHECK(rc == 0 && st.p == -1.0 && st.cs == 1.0,
          "rubber (Gamma = 0): p(1e-310) = %.17g, want c0^2 (rho - rho0) = -1; c = %g, want "
          "c0 = 1",
          st.p, st.cs);
  }
  for (int k = 0; k < 2; k++) {
    const struct material *m = &till_all[k];
    const struct eos_tillotson *t = &m->eosp.til;
    const double rhos[] = {1e-100, 1e-200, 1e-310};
    for (int i = 0; i < 3; i++) {
      const double want = t->B - t->A;
      for (int j = 0; j < 2; j++) {
        const double e = j ? -1e3 : 0.0;
        const double p = pressure(m, rhos[i], e);
        CHECK(fabs(p - want) <= 1e-12 * fabs(want),
              "%s: cold p(%g kg/m3, %g J/kg) = %.15g, "
              "limit B - A = %.15g",
              m->name, rhos[i], e, p, want);
      }
      const double e = 2.0 * t->E_cv, c = sqrt(t->a * (t->a + 1.0) * e);
      struct eos_state st = {(double)NAN, (double)NAN};
      const int rc = eos_evaluate(m, rhos[i], e, &st);
      CHECK(rc == 0 && isfinite(st.p) && fabs(st.p) <= 1e-12 && fabs(st.cs - c) <= 1e-9 * c,
            "%s: expanded at %g kg/m3, e = %g: p = %g (a rho e), c = %.15g, want sqrt(a(a+1)e) = "
            "%.15g",
            m->name, rhos[i], e, st.p, st.cs, c);
    }
  }
}

/* ---------------------------------------------------------------- inverse */

static void test_energy_from_pressure(void)
{
  double e = 0.0;
  /* ideal gas */
  struct material g;
  memset(&g, 0, sizeof g);
  g.eos = EOS_IDEAL_GAS;
  g.eosp.gas.gamma = 1.4;
  CHECK(eos_energy_from_pressure(&g, 13.125, 10.5e5, &e) == 0 && fabs(e - 2e5) <= 1e-9 * 2e5,
        "nitrogen: 10.5 bar at 13.125 kg/m3 -> e = %.15g (0.2 kJ/g)", e);
  /* Mie–Grüneisen: linear in E, round trip to 1e-12 of the larger of |p| and |p_c(ρ)|
   * (p = p_c + Γρ(E − E_c) cancels p_c: its round-off is that of p_c) */
  double worst = 0.0;
  for (int k = 0; k < NMG - 1; k++) {
    const struct material *m = &mg_all[k];
    const double xs[] = {0.9, 1.0, 1.1, 1.5}, ps[] = {0.0, 1e5, 1e9, 3e10};
    for (int i = 0; i < 4; i++)
      for (int j = 0; j < 4; j++) {
        const double rho = xs[i] * m->rho0;
        int rc = eos_energy_from_pressure(m, rho, ps[j], &e);
        const double p = pressure(m, rho, e);
        const double pc = eos_mg_cold_pressure(&m->eosp.mg, rho);
        const double rel = fabs(p - ps[j]) / (fabs(ps[j]) + fabs(pc) + 1.0);
        if (rel > worst) worst = rel;
        CHECK(rc == 0 && rel <= 1e-12, "%s: p(rho, e(p)) = %.15g for p = %g at %g rho0", m->name, p,
              ps[j], xs[i]);
      }
  }
  printf("  energy_from_pressure (Mie-Gruneisen): worst relative residual %.2g\n", worst);
  /* Γ = 0 (rubber): only p = p_c(ρ) is reachable */
  CHECK(eos_energy_from_pressure(&mg_all[7], 1.0, 0.0, &e) == 0 && e == 0.0,
        "rubber: p = 0 at rho0");
  CHECK(eos_energy_from_pressure(&mg_all[7], 1.0, 0.5, &e) == EOS_ERR_NO_SOLUTION,
        "rubber: p = 0.5 at rho0 has no energy");
  /* Tillotson: bisection, round trip to 1e-10 relative, in compression and expansion */
  for (int k = 0; k < 2; k++) {
    const struct material *m = &till_all[k];
    const double xs[] = {0.5, 0.8, 0.99, 1.0, 1.2, 2.0};
    for (int i = 0; i < 6; i++) {
      const double rho = xs[i] * m->rho0;
      const double p0 = pressure(m, rho, 0.0);
      const double targets[] = {p0 + 1e8, p0 + 5e9, p0 + 5e10};
      for (int j = 0; j < 3; j++) {
        int rc = eos_energy_from_pressure(m, rho, targets[j], &e);
        const double p = pressure(m, rho, e);
        CHECK(rc == 0 && e > 0 && fabs(p - targets[j]) <= 1e-10 * fabs(targets[j]),
              "%s: p(e(p)) = %.15g for p = %.15g at %g rho0 (e = %g)", m->name, p, targets[j],
              xs[i], e);
      }
    }
    CHECK(eos_energy_from_pressure(m, m->rho0, 0.0, &e) == 0 && e == 0.0,
          "%s: p = 0 at rho0 -> "
          "e = 0",
          m->name);
    CHECK(eos_energy_from_pressure(m, 1.2 * m->rho0, 0.0, &e) == EOS_ERR_NO_SOLUTION,
          "%s: p = 0 in compression needs e < 0: no solution", m->name);
  }
  /* bad input */
  CHECK(eos_evaluate(&mg_all[1], 0.0, 0.0, &(struct eos_state){0, 0}) == EOS_ERR_INPUT, "rho = 0");
  CHECK(eos_evaluate(&mg_all[1], 7000.0, NAN, &(struct eos_state){0, 0}) == EOS_ERR_INPUT,
        "e = NaN");
  char msg[256];
  eos_describe(&mg_all[1], -1.0, 0.0, EOS_ERR_INPUT, msg, sizeof msg);
  CHECK(strstr(msg, "material 'steel-target' (mie-gruneisen)") && strstr(msg, "rho = -1"),
        "describe: '%s'", msg);
}

int main(void)
{
  make_materials();
  test_mg_reference_state();
  test_mg_cold_identity();
  test_mg_hand_point();
  test_sound_speed_consistency();
  test_sound_speed_positive();
  test_tillotson_reference();
  test_tillotson_continuity();
  test_tillotson_hybrid();
  test_tillotson_rho_iv();
  test_table_interpolation();
  test_table_errors();
  test_table_file();
  test_energy_from_pressure();
  test_low_density();
  return test_finish();
}
