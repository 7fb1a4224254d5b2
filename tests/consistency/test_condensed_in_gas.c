/* test_condensed_in_gas.c — a fragment of solid flying through a gas keeps its density
 * (docs/models.md, "Condensed material in a gas"), stepped through the library.
 *
 * One aluminium particle (al-alloy, a 0.3 mm cube: the size of the vessel case's wall
 * debris) at 4 km/s enters nitrogen at 10.5 bar (ρ = 13.125 kg/m³, the vessel's gas) on
 * a 3 mm lattice, and flies 16 mm into it in 5 µs. It has no condensed neighbour, so
 * its density rate, summed over condensed neighbours only, is zero: ρ must stay at
 * ρ₀ = 2780 kg/m³ to rounding at every step. Summed over the gas particles as well (the
 * rule before session 12), whose volumes mⱼ/ρⱼ are a thousand times its own, it was
 * compressed to 2.4 ρ₀ (350 GPa) and its step fell to half. The gas still acts on it
 * through the pressure and viscous forces: it must slow down, and the total energy
 * (kinetic + internal, rigid walls all round) must stay within 1e-3 of its start.
 */
#include <math.h>
#include <stdio.h>

#include "config/config.h"
#include "diag/conservation.h"
#include "integrate/step.h"
#include "run/sim.h"
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

int main(void)
{
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
    for (size_t i = 0; i < s.p.n; i++)   /* the arrays are reordered as particles move */
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
  CHECK(dev < 1e-12, "its density stays at rho0 = %.0f kg/m3 (largest relative change %.3g)",
        rho0, dev);
  CHECK(s.p.v[0][bit] < 4000.0 - 1.0, "the gas slows it: vx = %.1f m/s", s.p.v[0][bit]);
  CHECK(fabs(t1.e_total / t0.e_total - 1.0) < 1e-3, "total energy within 1e-3: %.3g",
        t1.e_total / t0.e_total - 1.0);
  sim_free(&s);
  cfg_free(c);
  return test_finish();
}
