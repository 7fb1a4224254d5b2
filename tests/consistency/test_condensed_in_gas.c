/* test_condensed_in_gas.c — a fragment of solid flying through a gas keeps its density
 * (docs/models.md, "Condensed material in a gas"), stepped through the library.
 *
 * One aluminium particle (al-alloy, a 0.3 mm cube: the size of the vessel case's wall
 * debris) at 4 km/s enters nitrogen at 10.5 bar (ρ = 13.125 kg/m³, the vessel's gas) on
 * a 3 mm lattice, and flies 16 mm into it in 5 µs. It has no condensed neighbour, so
 * its density rate, summed over condensed neighbours only, is zero: ρ must stay at
 * ρ₀ = 2780 kg/m³ to rounding at every step. Summed over the gas particles as well (the
 * rule before 6037ca8, 2026-11-23), whose volumes mⱼ/ρⱼ are a thousand times its own, it was
 * compressed to 2.4 ρ₀ (350 GPa) and its step fell to half. The gas still acts on it
 * through the pressure and viscous forces: it must slow down, and the total energy
 * (kinetic + internal, rigid walls all round) must stay within 1e-8 of its start
 * (measured −6.77e-10 over the 830 steps; the bound was 1e-3 before). The
 * work of a gas–condensed pair goes to the gas particle (the condensed one's density
 * does not see the gas, so neither does its energy): the particle's internal energy
 * stays exactly 0, where the even split before 001e252 (2026-11-23) gave it 3.2·10⁵ J/kg (1 GPa).
 *
 * A plate at rest against the gas at rest (al-alloy 1.5 mm on a 0.3 mm lattice, the
 * nitrogen at 1.05 MPa on a 3 mm lattice filling the rest of the box, vacuum behind the
 * plate), 5 µs: the gas pushes the plate back, a = p/(ρ₀ t), −1.26 m/s by 5 µs; the gas
 * follows it and stays at its density. A pair of a gas and a condensed particle pushes
 * with the gas's pressure weighed by volume, 2 p̂_gas/(ρᵢρⱼ); with the mass-weighted
 * pᵢ/ρᵢ² + pⱼ/ρⱼ² (before 001e252) the gas next to the plate was blown off at up to
 * 312 m/s (Mach 0.93) and compressed to 1.41 ρ₁, and the plate moved at −7.0 m/s; now
 * the gas moves below 0.1 c (5 m/s) and the plate within 30 % of p t/(ρ₀ L) (−1.15).
 */
#include <math.h>
#include <stdio.h>

#include "config/config.h"
#include "diag/conservation.h"
#include "integrate/step.h"
#include "sim/sim.h"
#include "particles/particles.h"
#include "simtext.h"
#include "testlib.h"

static const char *const CASE =
    "name: condensed-in-gas\n"
    "domain:\n"
    "  min: [-6 mm, 0, 0]\n"
    "  max: [24 mm, 12 mm, 12 mm]\n"
    "  boundary: {x_min: wall, x_max: wall, y: wall, z: wall}\n"
    "bodies:\n"
    "  - name: bit\n"
    "    material: al-alloy\n"
    "    shape: {type: box, min: [-3.3 mm, 5.7 mm, 5.7 mm], max: [-3 mm, 6 mm, 6 mm]}\n"
    "    spacing: 0.3 mm\n"
    "    velocity: [4 km/s, 0, 0]\n"
    "  - name: gas\n"
    "    material: nitrogen\n"
    "    shape: {type: box, min: [0, 0, 0], max: [24 mm, 12 mm, 12 mm]}\n"
    "    spacing: 3 mm\n"
    "    density: 13.125 kg/m3\n"
    "    energy: 0.2 kJ/g\n"
    "sph:\n"
    "  viscosity: {alpha: 1.0, beta: 2.0, reconstruct: true}\n"
    "time: {end: 5 us}\n";

/* %s: the plate's density line ("" or "    density: ...\n") */
static const char *const REST =
    "name: plate-gas-rest\n"
    "domain:\n"
    "  min: [-3 mm, 0, 0]\n"
    "  max: [31.5 mm, 12 mm, 12 mm]\n"
    "  boundary: {x_min: open, x_max: wall, y: wall, z: wall}\n"
    "bodies:\n"
    "  - name: plate\n"
    "    material: al-alloy\n"
    "    shape: {type: box, min: [0, 0, 0], max: [1.5 mm, 12 mm, 12 mm]}\n"
    "    spacing: 0.3 mm\n"
    "%s"
    "  - name: gas\n"
    "    material: nitrogen\n"
    "    shape: {type: box, min: [1.5 mm, 0, 0], max: [31.5 mm, 12 mm, 12 mm]}\n"
    "    spacing: 3 mm\n"
    "    density: 13.125 kg/m3\n"
    "    energy: 0.2 kJ/g\n"
    "sph:\n"
    "  viscosity: {alpha: 1.0, beta: 2.0, reconstruct: true}\n"
    "time: {end: 5 us}\n";

/* Sets REST up with the plate's density line, records the gas's initial pressure and
 * sound speed, runs to the end. Returns 0 (then free s and c), -1 when it did not set up
 * (sim_from_text has then failed its check). */
static int run_rest(const char *density, const char *name, struct sim *s, struct cfg **c,
                    double *p1, double *cs1)
{
  struct hv_error err = {0};
  char text[2048];
  snprintf(text, sizeof text, REST, density);
  if (sim_from_text(text, name, s, c)) return -1;
  int ok = !step_init(s, &err);
  for (size_t i = 0; i < s->p.n; i++)
    if (s->p.body[i] == 1) {
      *p1 = s->p.p[i];
      *cs1 = s->p.cs[i];
    }
  while (ok && s->t < s->tp.end * (1 - 1e-12)) ok = !step_advance(s, &err);
  CHECK(ok, "%s runs to 5 us (%s)", name, ok ? "ok" : err.msg);
  return 0;
}

static void test_plate_at_rest(void)
{
  struct sim s;
  struct cfg *c;
  double p1 = 0.0, cs1 = 0.0;
  if (run_rest("", "plate_gas_rest.yaml", &s, &c, &p1, &cs1)) return;
  const double rho1 = 13.125, rho0 = 2780.0;
  double vgas = 0.0, rgas = 0.0, vplate = 0.0, xv = 0.0;
  size_t nplate = 0;
  for (size_t i = 0; i < s.p.n; i++) {
    const double v =
        sqrt(s.p.v[0][i] * s.p.v[0][i] + s.p.v[1][i] * s.p.v[1][i] + s.p.v[2][i] * s.p.v[2][i]);
    if (s.p.body[i] == 1) {
      if (v > vgas) xv = s.p.x[0][i];
      vgas = fmax(vgas, v);
      rgas = fmax(rgas, s.p.rho[i] / rho1);
    } else {
      vplate += s.p.v[0][i];
      nplate++;
    }
  }
  vplate /= (double)nplate;
  const double expect = -p1 * s.t / (rho0 * 1.5e-3);
  printf("gas p = %.4g Pa; after %.3g s: gas |v| <= %.3g m/s (at x = %.2f mm), rho/rho1 <= "
         "%.4f; plate vx %.4g m/s (p t / (rho0 L) = %.4g)\n",
         p1, s.t, vgas, 1e3 * xv, rgas, vplate, expect);
  CHECK(rgas < 1.01, "the gas next to the plate is not compressed: rho/rho1 <= %.4f", rgas);
  /* what is left is a sound pulse from the start (5 m/s; with (p̂ᵢ + p̂ⱼ)/(ρᵢρⱼ), 16 m/s,
     which ran into the gas at the sound speed without growing: 17.8 m/s at 11.8 mm by
     40 us) */
  CHECK(vgas < 0.1 * cs1,
        "the gas is not blown off the plate: |v| <= %.3g m/s, below "
        "0.1 c = %.3g m/s",
        vgas, 0.1 * cs1);
  CHECK(fabs(vplate / expect - 1.0) < 0.3,
        "the plate is pushed back at %.3g m/s, p t/(rho0 L) "
        "= %.3g m/s within 30 %%",
        vplate, expect);
  sim_free(&s);
  cfg_free(c);
}

/* The same plate, compressed by 0.1 % at the start (ρ = 1.001 ρ₀, p = 88 MPa) between
 * the rigid side walls: it relaxes through its faces toward in-plane compression, but
 * at an SPH free surface slowly — after 5 µs p is still 34 MPa and σ_xx −12.5 MPa at its
 * faces, where the traction is the gas's 1 MPa. The gas must not be driven by the
 * plate's stress: the pair force takes the gas's pressure as the interface pressure,
 * and the plate acts through its motion (a face at 5 m/s raises the gas's pressure by
 * ρ c v ≈ 22 kPa). After 5 µs the gas moves below 0.1 c (5 m/s). With (p̂ᵢ + p̂ⱼ)/(ρᵢρⱼ)
 * it reached 420 m/s at 2.5 µs (315 m/s at 5 µs), and with the normal stresses along
 * the pair's line, p − ê·S·ê, the same. */
static void test_plate_in_plane(void)
{
  struct sim s;
  struct cfg *c;
  double p1 = 0.0, cs1 = 0.0;
  if (run_rest("    density: 2782.78 kg/m3\n", "plate_gas_in_plane.yaml", &s, &c, &p1, &cs1))
    return;
  double vgas = 0.0, pmax = 0.0, sxx = 0.0;
  for (size_t i = 0; i < s.p.n; i++) {
    if (s.p.body[i] == 1)
      vgas = fmax(vgas, sqrt(s.p.v[0][i] * s.p.v[0][i] + s.p.v[1][i] * s.p.v[1][i] +
                             s.p.v[2][i] * s.p.v[2][i]));
    else if (s.p.p[i] > pmax) {
      pmax = s.p.p[i];
      sxx = s.p.S[T_XX][i] - s.p.p[i];
    }
  }
  printf("compressed plate: its pressure up to %.3g MPa (sigma_xx there %.3g MPa); gas |v| <= "
         "%.3g m/s\n",
         pmax / 1e6, sxx / 1e6, vgas);
  CHECK(pmax > 10e6, "the plate stays compressed in its plane: p up to %.3g MPa (> 10 MPa)",
        pmax / 1e6);
  CHECK(vgas < 0.1 * cs1,
        "the gas is not pushed by the plate's in-plane pressure: |v| <= %.3g "
        "m/s, below 0.1 c = %.3g m/s",
        vgas, 0.1 * cs1);
  sim_free(&s);
  cfg_free(c);
}

/* A lone steel particle (steel-bumper, a 0.3 mm cube) at 4 km/s crosses sprayed debris
 * of another body: steel-projectile particles on a 1.5 mm lattice at ρ₀/50 (154 kg/m³,
 * split: damage 1, so p = 0 and no strength), each 2 500 times the bit's mass (in §2.4's
 * cloud a projectile particle is 11 times a bumper particle, and its spray sits at 1-3 %
 * of ρ₀). The bit's line runs 1.06 mm (0.75 mm in y and in z) from the nearest row of
 * spray particles, inside the pairs' support 2hᵢⱼ = 2.16 mm. Its density rate weighs a
 * neighbour of another body by at most twice that neighbour's reference volume,
 * 2mⱼ/ρ₀ⱼ: passing a spray particle it swings by a few per cent and returns, and its
 * density must stay below SPRAY_RHO_MAX ρ₀ at every step. With the spray's own volume
 * mⱼ/ρⱼ (25 times the cap; before a033786, 2026-11-25) it was compressed to 2.53 ρ₀ (with the
 * cap: 1.038 ρ₀) — the mechanism that held §2.4's step at 0.5 ns (a bumper particle at
 * 4.05 ρ₀ among spray at 37-73 times its reference volume). SPRAY_RHO_MAX = 1.08: twice
 * the measured 3.8 % swing (1.0382 ρ₀; the bound was 1.2 before). */
#define SPRAY_RHO_MAX 1.08
static const char *const SPRAY =
    "name: spray\n"
    "domain:\n"
    "  min: [-6 mm, 0, 0]\n"
    "  max: [24 mm, 12 mm, 12 mm]\n"
    "  boundary: {x_min: open, x_max: open, y: open, z: open}\n"
    "bodies:\n"
    "  - name: bit\n"
    "    material: steel-bumper\n"
    "    shape: {type: box, min: [-3.3 mm, 5.85 mm, 5.85 mm], max: [-3 mm, 6.15 mm, 6.15 mm]}\n"
    "    spacing: 0.3 mm\n"
    "    velocity: [4 km/s, 0, 0]\n"
    "  - name: spray\n"
    "    material: steel-projectile\n"
    "    shape: {type: box, min: [0, 0, 0], max: [18 mm, 12 mm, 12 mm]}\n"
    "    spacing: 1.5 mm\n"
    "    density: 154 kg/m3\n"
    "    damage: 1\n"
    "sph:\n"
    "  viscosity: {alpha: 1.0, beta: 2.0, reconstruct: true}\n"
    "time: {end: 5 us}\n";

static void test_through_spray(void)
{
  struct sim s;
  struct cfg *c;
  struct hv_error err = {0};
  if (sim_from_text(SPRAY, "spray.yaml", &s, &c)) return;
  int ok = !step_init(&s, &err);
  size_t bit = s.p.n;
  for (size_t i = 0; i < s.p.n; i++)
    if (s.p.body[i] == 0) bit = i;
  CHECK(bit < s.p.n, "the bit is set up (%zu particles in all)", s.p.n);
  if (bit >= s.p.n) ok = 0;
  const double rho0 = ok ? s.mat[s.p.mat[bit]].rho0 : 1.0;
  double rmax = 0.0, x = 0.0;
  while (ok && s.t < s.tp.end * (1 - 1e-12)) {
    ok = !step_advance(&s, &err);
    for (size_t i = 0; i < s.p.n; i++) /* steps reorder the particles */
      if (s.p.body[i] == 0) bit = i;
    rmax = fmax(rmax, s.p.rho[bit] / rho0);
    x = s.p.x[0][bit];
  }
  CHECK(ok, "the bit crosses the spray (%s)", ok ? "ok" : err.msg);
  printf("bit through spray: rho/rho0 up to %.4f, at x = %.2f mm after %.3g s\n", rmax, 1e3 * x,
         s.t);
  CHECK(x > 10e-3, "the bit is through the spray's first 10 mm: x = %.2f mm", 1e3 * x);
  CHECK(rmax < SPRAY_RHO_MAX,
        "the bit's density stays below %.2f rho0 among the spray: "
        "up to %.4f",
        SPRAY_RHO_MAX, rmax);
  sim_free(&s);
  cfg_free(c);
}

int main(void)
{
  test_through_spray();
  test_plate_at_rest();
  test_plate_in_plane();
  struct sim s;
  struct cfg *c;
  struct hv_error err = {0};
  if (sim_from_text(CASE, "condensed_in_gas.yaml", &s, &c)) {
    CHECK(0, "case set up");
    return test_finish();
  }
  size_t bit = s.p.n;
  for (size_t i = 0; i < s.p.n; i++)
    if (s.p.body[i] == 0) bit = (bit == s.p.n) ? i : s.p.n + 1;
  CHECK(bit < s.p.n, "one aluminium particle (%zu particles in all)", s.p.n);
  if (bit >= s.p.n) return test_finish();
  const double rho0 = s.p.rho[bit];
  struct totals t0, t1;
  diag_totals(&s.p, &t0);
  int ok = !step_init(&s, &err);
  double dev = 0.0, xmax = -INFINITY;
  long steps = 0;
  while (ok && s.t < s.tp.end * (1 - 1e-12)) {
    ok = !step_advance(&s, &err);
    steps++;
    for (size_t i = 0; i < s.p.n; i++) /* the arrays are reordered as particles move */
      if (s.p.body[i] == 0) bit = i;
    dev = fmax(dev, fabs(s.p.rho[bit] / rho0 - 1.0));
    xmax = fmax(xmax, s.p.x[0][bit]);
  }
  CHECK(ok, "runs to 5 us (%s)", ok ? "ok" : err.msg);
  diag_totals(&s.p, &t1);
  printf("%ld steps; the particle at x = %.2f mm, vx = %.1f m/s, rho/rho0 - 1 at most %.3g, "
         "e = %.4g J/kg, p = %.4g Pa; total energy %.6g -> %.6g J\n",
         steps, 1e3 * s.p.x[0][bit], s.p.v[0][bit], dev, s.p.e[bit], s.p.p[bit], t0.e_total,
         t1.e_total);
  CHECK(xmax > 10e-3, "it flew into the gas: x = %.2f mm", 1e3 * xmax);
  CHECK(dev < 1e-12, "its density stays at rho0 = %.0f kg/m3 (largest relative change %.3g)", rho0,
        dev);
  CHECK(s.p.v[0][bit] < 4000.0 - 1.0, "the gas slows it: vx = %.1f m/s", s.p.v[0][bit]);
  CHECK(s.p.e[bit] == 0.0,
        "the drag's heat goes to the gas: the particle's e = %.3g J/kg "
        "(it took half, 3.2e5 J/kg, before 001e252)",
        s.p.e[bit]);
  /* measured -6.77e-10 (was 1e-3) */
  CHECK(fabs(t1.e_total / t0.e_total - 1.0) < 1e-8, "total energy within 1e-8: %.3g",
        t1.e_total / t0.e_total - 1.0);
  sim_free(&s);
  cfg_free(c);
  return test_finish();
}
