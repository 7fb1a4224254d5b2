/* test_taylor_rz.c — the copper Taylor bar in axisymmetric (RZ) geometry
 * (examples/verification/taylor_bar_rz.yaml; issue 74, item 3), against the same
 * published results as the 3D quarter model (test_taylor.c).
 *
 * A copper bar, L₀ = 32.4 mm, R₀ = 3.2 mm, hits a rigid frictionless wall at 227 m/s
 * (ρ = 8930 kg/m³, E = 117 GPa, ν = 0.35, Y = 400 MPa + 100 MPa ε_p); 80 µs; 1 440 rings
 * at 0.27 mm. Reference (as test_taylor.c): final length 21.4–21.5 mm and impact-face
 * radius 7.0–7.1 mm, the middles L_REF and R_REF.
 * Measured at 80 µs as test_taylor.c does, with r the ring's radius:
 *   final length  L = x_max − x_min + Δ;
 *   face radius   R = the largest r of the rings that started in the layer next to the
 *                 wall, + Δ/2 (Δ = twice the first row's radius, the lattice's spacing).
 * Thresholds as in 3D (the brief's): L within 3 %, R within 8 %, the bar at rest (mean
 * |v_x| < 5 % of V0), its rear end undeformed (radius within Δ/2); and the energy of
 * summary.csv kept within 0.5 % (ENERGY_TOL: the η-form with the pair forces' own
 * deviatoric work keeps it to round-off and time integration; the first version's area
 * weights gained 5 %).
 * Measured (2026-12-07, cdd7dd4, 1 thread, 21 s of CPU): L = 21.84 mm (+1.8 %),
 * R = 6.64 mm (−5.8 %), mean v_x +5.9 m/s (2.6 %), energy +8e-6; the 3D quarter model at
 * 0.54 mm: 22.04 mm (+2.7 %), 6.90 mm (−2.2 %). At 0.54 mm in RZ: 22.33 mm (+4.1 %),
 * 6.18 mm (−12.4 %); with the artificial stress (ε = 0.3, as in 3D): 22.92 mm (+6.8 %),
 * 5.37 mm (−23.9 %): both fail.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "solidcase.h"
#include "testlib.h"

#define V0         227.0
#define L_REF      21.45e-3
#define R_REF      7.05e-3
#define LENGTH_TOL 0.03
#define RADIUS_TOL 0.08
#define REST_TOL   0.05
#define ENERGY_TOL 0.005

struct shape {
  double L, R, Rrear, vx;
};

static void measure(const struct particles *p, double dx, const unsigned char *face,
                    const unsigned char *rear, size_t nid, struct shape *s)
{
  double xmin = HUGE_VAL, xmax = -HUGE_VAL, m = 0, mv = 0, rface = 0, rrear = 0;
  for (size_t i = 0; i < p->n; i++) {
    xmin = fmin(xmin, p->x[0][i]);
    xmax = fmax(xmax, p->x[0][i]);
    m += p->m[i];
    mv += p->m[i] * p->v[0][i];
    if (p->id[i] < 0 || (size_t)p->id[i] >= nid) continue;
    if (face[p->id[i]]) rface = fmax(rface, p->x[1][i]);
    if (rear[p->id[i]]) rrear = fmax(rrear, p->x[1][i]);
  }
  s->L = xmax - xmin + dx;
  s->R = rface + 0.5 * dx;
  s->Rrear = rrear + 0.5 * dx;
  s->vx = mv / m;
}

int main(void)
{
  double secs;
  int rc = sc_run("taylor_bar_rz", "taylor_bar_rz", NULL, &secs);
  CHECK(rc == 0, "taylor_bar_rz.yaml runs (exit status %d, %.1f s)", rc, secs);
  if (rc) return test_finish();
  const char *dir = sc_outdir("taylor_bar_rz");
  const int nsnap = sc_count_snapshots(dir);
  CHECK(nsnap >= 2, "%d snapshots", nsnap);
  if (nsnap < 2) return test_finish();
  struct particles p;
  double t;
  if (sc_read(dir, 0, &p, &t)) return CHECK(0, "snapshot 0 readable"), test_finish();
  double rmin = HUGE_VAL, x0min = HUGE_VAL, x0max = -HUGE_VAL;
  for (size_t i = 0; i < p.n; i++) {
    rmin = fmin(rmin, p.x[1][i]);
    x0min = fmin(x0min, p.x[0][i]);
    x0max = fmax(x0max, p.x[0][i]);
  }
  const double dx = 2.0 * rmin; /* the first row stands at Δ/2 */
  const size_t nid = p.n;
  unsigned char *face = calloc(nid, 1), *rear = calloc(nid, 1);
  for (size_t i = 0; i < p.n; i++) {
    if (p.id[i] < 0 || (size_t)p.id[i] >= nid) continue;
    face[p.id[i]] = p.x[0][i] < x0min + 0.5 * dx;
    rear[p.id[i]] = p.x[0][i] > x0max - 0.5 * dx;
  }
  struct shape s0, s;
  measure(&p, dx, face, rear, nid, &s0);
  printf("initial: %zu rings, spacing %.4f mm; estimators: L = %.3f mm, R = %.3f mm (true "
         "32.4, 3.2)\n",
         p.n, dx * 1e3, s0.L * 1e3, s0.R * 1e3);
  particles_free(&p);
  for (int k = 1; k < nsnap; k++) {
    if (sc_read(dir, k, &p, &t)) {
      free(face);
      free(rear);
      return CHECK(0, "snapshot %d readable", k), test_finish();
    }
    measure(&p, dx, face, rear, nid, &s);
    printf("  t = %5.1f us: L = %.3f mm, R = %.3f mm, rear radius %.3f mm, mean v_x = %+.2f m/s\n",
           t * 1e6, s.L * 1e3, s.R * 1e3, s.Rrear * 1e3, s.vx);
    particles_free(&p);
  }
  double e0 = 0, e1 = 0;
  const int erc = test_summary_energy_span(dir, &e0, &e1);
  printf("at %.0f us: final length %.3f mm vs %.2f mm (%+.2f%%), mushroom radius %.3f mm vs "
         "%.2f mm (%+.2f%%); energy %+.2e\n",
         t * 1e6, s.L * 1e3, L_REF * 1e3, 100 * (s.L / L_REF - 1), s.R * 1e3, R_REF * 1e3,
         100 * (s.R / R_REF - 1), e1 / e0 - 1);
  CHECK(fabs(t - 80e-6) < 1e-9, "the run reaches 80 us (t = %.3f us)", t * 1e6);
  CHECK(fabs(s.vx) < REST_TOL * V0,
        "the bar has stopped: mean v_x = %+.2f m/s (< %.0f%% of %.0f m/s)", s.vx, 100 * REST_TOL,
        V0);
  CHECK(fabs(s.Rrear - s0.R) <= 0.5 * dx,
        "the rear end keeps its radius: %.3f mm (initially %.3f mm)", s.Rrear * 1e3, s0.R * 1e3);
  CHECK(fabs(s.L / L_REF - 1) < LENGTH_TOL, "final length %.3f mm within %.0f%% of %.2f mm",
        s.L * 1e3, 100 * LENGTH_TOL, L_REF * 1e3);
  CHECK(fabs(s.R / R_REF - 1) < RADIUS_TOL, "mushroom radius %.3f mm within %.0f%% of %.2f mm",
        s.R * 1e3, 100 * RADIUS_TOL, R_REF * 1e3);
  CHECK(erc == 0 && fabs(e1 / e0 - 1) < ENERGY_TOL, "energy kept within %.1f%% (%+.2e)",
        100 * ENERGY_TOL, e1 / e0 - 1);
  free(face);
  free(rear);
  return test_finish();
}
