/* test_taylor.c — the copper Taylor bar (issue 3, item 6; examples/verification/taylor_bar.yaml).
 *
 * A copper bar, L₀ = 32.4 mm, R₀ = 3.2 mm, hits a rigid frictionless wall at 227 m/s
 * (ρ = 8930 kg/m³, E = 117 GPa, ν = 0.35, Y = 400 MPa + 100 MPa ε_p); 80 µs. A quarter
 * of the bar is simulated (symmetry planes y = 0 and z = 0).
 *
 * Reference: the published finite-element results for this benchmark, final length
 * 21.4–21.5 mm and impact-face ("mushroom") radius 7.0–7.1 mm (the ranges given with the
 * task; the problem itself is that of the ANSYS Technology Demonstration Guide, ch. 17
 * "Impact Analysis of a Metal Bar", whose set-up was checked; its table of reference
 * values could not be retrieved here). The test compares with the middle of each
 * range, L_REF and R_REF (docs/verification-solids.md).
 *
 * Measured at 80 µs, from the particle positions:
 *   final length  L = x_max − x_min + Δ (the bar's ends lie half a spacing Δ beyond
 *                 the outermost particle centres; the same estimator gives exactly
 *                 L₀ = 32.4 mm on the initial lattice);
 *   face radius   R = max √(y² + z²) over the particles of the impact face — those
 *                 that started in the lattice layer next to the wall (followed by id) —
 *                 + Δ/2. (A band in x next to the wall is fragile: one particle pushed
 *                 towards the wall narrows it. This estimator gives 3.35 mm instead of
 *                 3.2 mm on the initial lattice: the particle picture of a surface is
 *                 uncertain by about ±Δ/2 = ±0.27 mm, ±4% of R.)
 * Thresholds: L within 3% of L_REF (LENGTH_TOL, the brief's criterion: 0.64 mm, a bit
 * more than one spacing), R within 8% of R_REF (RADIUS_TOL: the ±4% of the particle
 * surface above, plus the spread of the published radii, 7.0–7.15 mm, and of the
 * mushroom's sensitivity to how the artificial viscosity and stress resist the radial
 * flow at this resolution; see the measured numbers in the docs).
 * Also checked: the bar has come to rest (the mean axial velocity is below 5% of
 * the impact speed: the plastic deformation is over), and the rear end is not
 * deformed (the radius of the last layer is the initial one within half a spacing).
 *
 * The case halves the artificial viscosity (α = 0.5, β = 1; see the case file): with
 * the shock defaults (α = 1, β = 2) the viscous pressure dominates the flow stress at
 * this resolution and the bar comes out too stiff (measured: L = 22.81 mm, +6.3%;
 * R = 6.29 mm, −10.8%; 2026-12-07: 22.84 mm, +6.5 %, and 6.25 mm, −11.3 %). Measured with
 * the case as given at the time of writing: L = 22.04 mm (+2.7%), R = 6.90 mm (−2.2%);
 * 2026-12-07: R = 6.907 mm (−2.02 %).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "solidcase.h"
#include "testlib.h"

#define L0         32.4e-3  /* [m] initial length (the case) */
#define V0         227.0    /* [m/s] impact speed (the case) */
#define L_REF      21.45e-3 /* [m] published final length 21.4–21.5 mm: the middle */
#define R_REF      7.05e-3  /* [m] published mushroom radius 7.0–7.1 mm: the middle */
#define LENGTH_TOL 0.03     /* the brief: final length within 3% */
#define RADIUS_TOL 0.08     /* the brief: radius within 8% (justified above) */
#define REST_TOL   0.05     /* mean |v_x| at the end below 5% of V0 */

struct shape {
  double L, R, Rrear, vx, epsmax;
};

/* face[id] / rear[id]: the particle started in the first / last lattice layer. */
static void measure(const struct particles *p, double dx, const unsigned char *face,
                    const unsigned char *rear, struct shape *s)
{
  double xmin = HUGE_VAL, xmax = -HUGE_VAL, m = 0, mv = 0, rface = 0, rrear = 0;
  s->epsmax = 0;
  for (size_t i = 0; i < p->n; i++) {
    const double r = hypot(p->x[1][i], p->x[2][i]);
    xmin = fmin(xmin, p->x[0][i]);
    xmax = fmax(xmax, p->x[0][i]);
    m += p->m[i];
    mv += p->m[i] * p->v[0][i];
    s->epsmax = fmax(s->epsmax, p->eps_p[i]);
    if (face[p->id[i]]) rface = fmax(rface, r);
    if (rear[p->id[i]]) rrear = fmax(rrear, r);
  }
  s->L = xmax - xmin + dx;
  s->R = rface + 0.5 * dx;
  s->Rrear = rrear + 0.5 * dx;
  s->vx = mv / m;
}

int main(void)
{
  double secs;
  int rc = sc_run("taylor_bar", "taylor_bar", NULL, &secs);
  CHECK(rc == 0, "taylor_bar.yaml runs (exit status %d, %.1f s)", rc, secs);
  if (rc) return test_finish();
  const char *dir = sc_outdir("taylor_bar");
  const int nsnap = sc_count_snapshots(dir);
  CHECK(nsnap >= 2, "%d snapshots", nsnap);
  if (nsnap < 2) return test_finish();

  struct particles p;
  double t;
  struct shape s0, s;
  if (sc_read(dir, 0, &p, &t)) return CHECK(0, "snapshot 0 readable"), test_finish();
  const double dx = cbrt(p.m[0] / p.rho[0]); /* m = ρ Δ³ on the cubic lattice */
  const size_t nid = p.n;
  unsigned char *face = calloc(nid, 1), *rear = calloc(nid, 1);
  double x0min = HUGE_VAL, x0max = -HUGE_VAL;
  for (size_t i = 0; i < p.n; i++) {
    x0min = fmin(x0min, p.x[0][i]);
    x0max = fmax(x0max, p.x[0][i]);
  }
  for (size_t i = 0; i < p.n; i++) {
    if (p.id[i] < 0 || (size_t)p.id[i] >= nid) continue;
    face[p.id[i]] = p.x[0][i] < x0min + 0.5 * dx;
    rear[p.id[i]] = p.x[0][i] > x0max - 0.5 * dx;
  }
  measure(&p, dx, face, rear, &s0);
  printf("initial: %zu particles (quarter bar), spacing %.4f mm; estimators: L = %.3f mm, "
         "R = %.3f mm (true 32.4, 3.2)\n",
         p.n, dx * 1e3, s0.L * 1e3, s0.R * 1e3);
  particles_free(&p);
  for (int k = 1; k < nsnap; k++) {
    if (sc_read(dir, k, &p, &t)) {
      free(face);
      free(rear);
      return CHECK(0, "snapshot %d readable", k), test_finish();
    }
    measure(&p, dx, face, rear, &s);
    printf("  t = %5.1f us: L = %.3f mm, R = %.3f mm, rear radius %.3f mm, mean v_x = %+.2f m/s, "
           "max plastic strain %.3f\n",
           t * 1e6, s.L * 1e3, s.R * 1e3, s.Rrear * 1e3, s.vx, s.epsmax);
    particles_free(&p);
  }
  printf("at %.0f us: final length %.3f mm vs %.2f mm (%+.2f%%), mushroom radius %.3f mm vs "
         "%.2f mm (%+.2f%%), L/L0 = %.4f\n",
         t * 1e6, s.L * 1e3, L_REF * 1e3, 100 * (s.L / L_REF - 1), s.R * 1e3, R_REF * 1e3,
         100 * (s.R / R_REF - 1), s.L / L0);
  CHECK(fabs(t - 80e-6) < 1e-9, "the run reaches 80 us (t = %.3f us)", t * 1e6);
  CHECK(fabs(s.vx) < REST_TOL * V0,
        "the bar has stopped: mean v_x = %+.2f m/s (< %.0f%% of "
        "%.0f m/s)",
        s.vx, 100 * REST_TOL, V0);
  CHECK(fabs(s.Rrear - s0.R) <= 0.5 * dx,
        "the rear end keeps its radius: %.3f mm (initially "
        "%.3f mm)",
        s.Rrear * 1e3, s0.R * 1e3);
  CHECK(fabs(s.L / L_REF - 1) < LENGTH_TOL, "final length %.3f mm within %.0f%% of %.2f mm",
        s.L * 1e3, 100 * LENGTH_TOL, L_REF * 1e3);
  CHECK(fabs(s.R / R_REF - 1) < RADIUS_TOL, "mushroom radius %.3f mm within %.0f%% of %.2f mm",
        s.R * 1e3, 100 * RADIUS_TOL, R_REF * 1e3);
  free(face);
  free(rear);
  return test_finish();
}
