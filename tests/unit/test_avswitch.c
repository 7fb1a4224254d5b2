/* test_avswitch.c — the viscosity switch's per-particle update (sph.viscosity.switch:
 * cullen-dehnen, src/sph/avswitch.h) against hand results: the limiter ξ for the flows
 * it must tell apart, the rise to α_loc, the exponential decay over τ = 2h/(2ℓc), the
 * floor and the ceiling, and the corrected gradient (L = G·A for a linear field and a
 * skewed neighbourhood gives G back).
 * Each check would fail for a wrong model: ξ = 1 for a plane shock (no limiter) or for a
 * shear (a limiter on the curl alone, which lets a stagnation flow through), a decay
 * with the wrong time constant, a switch that rises on steady compression. */
#include <math.h>

#include "sph/avswitch.h"
#include "testlib.h"

static void diag3(double a, double b, double c, double G[9])
{
  for (int k = 0; k < 9; k++) G[k] = 0.0;
  G[0] = a;
  G[4] = b;
  G[8] = c;
}

int main(void)
{
  const double k = 1e4; /* [1/s] */
  double G[9];

  /* ξ = (2d)²/((2d)² + S:S), S the trace-free symmetric part of G */
  diag3(-k, -k, -k, G);
  CHECK_CLOSE(avsw_xi(G), 1.0, 1e-15, "isotropic compression: xi = 1");
  diag3(-k, 0, 0, G); /* plane shock: d = −k, S:S = 2k²/3 → 4/(4 + 2/3) = 6/7 */
  CHECK_CLOSE(avsw_xi(G), 6.0 / 7.0, 1e-15, "plane compression: xi = 6/7");
  diag3(-k, k / 2, k / 2, G); /* volume-keeping stagnation flow: d = 0 */
  CHECK(avsw_xi(G) == 0.0, "axisymmetric stagnation flow (div v = 0): xi = 0 (got %g)", avsw_xi(G));
  diag3(0, 0, 0, G);
  G[1] = k; /* simple shear: ∂vx/∂y = k */
  CHECK(avsw_xi(G) == 0.0, "simple shear: xi = 0 (got %g)", avsw_xi(G));
  diag3(-0.01 * k, -0.01 * k, -0.01 * k, G); /* 1 % compression in a strong shear */
  G[1] = k;
  /* d = −0.03k, S:S = 2 (k/2)² (the diagonal is isotropic): ξ = 0.0036/(0.0036 + 0.5) */
  CHECK_CLOSE(avsw_xi(G), 0.0036 / 0.5036, 1e-15,
              "weak compression in a strong shear: xi = 0.0071");

  struct sph_params sp = {.alpha = 1.0, .beta = 2.0, .av_min = 0.0, .av_decay = 0.05};
  const double h = 1e-3, c = 5000.0, dt = 1e-8, H = 2.0 * h;
  const double I[9] = {-1, 0, 0, 0, -1, 0, 0, 0, -1}; /* A = −I: L = −G gives G (A⁻¹) */
  double L[9], dnew;

  /* steady compression (d' = d): no rise, however strong */
  diag3(k, k, k, L); /* L = −G for G = −k I: d = −3k */
  double a = avsw_update(&sp, L, I, 0.0, -3.0 * k, h, c, dt, &dnew);
  CHECK(a == 0.0, "steady isotropic compression: alpha stays 0 (got %g)", a);
  CHECK_CLOSE(dnew, -3.0 * k, 1e-9 * k, "the divergence is stored (-3k)");

  /* compression growing: ḋ = −3k/dt, ξ = 1 → α_loc = H²A/(H²A + c²) */
  diag3(k, k, k, L);
  a = avsw_update(&sp, L, I, 0.0, 0.0, h, c, dt, &dnew);
  const double A = 3.0 * k / dt, want = H * H * A / (H * H * A + c * c);
  CHECK(fabs(a - want) <= 1e-12, "growing compression: alpha = alpha_loc = %.6f (got %.6f)", want,
        a);
  /* expanding: no rise */
  diag3(-k, -k, -k, L);
  a = avsw_update(&sp, L, I, 0.0, 0.0, h, c, dt, &dnew);
  CHECK(a == 0.0, "growing expansion: alpha stays 0 (got %g)", a);

  /* decay with no source: α e^(−dt/τ), τ = H/(2ℓc) */
  diag3(0, 0, 0, L);
  const double tau = H / (2.0 * sp.av_decay * c), big = 50.0 * dt;
  a = avsw_update(&sp, L, I, 0.8, 0.0, h, c, big, &dnew);
  CHECK(fabs(a - 0.8 * exp(-big / tau)) <= 1e-14,
        "decay: 0.8 exp(-dt/tau), tau = %.3e s (got %.6f)", tau, a);
  /* the floor and the ceiling */
  sp.av_min = 0.1;
  a = avsw_update(&sp, L, I, 0.05, 0.0, h, c, big, &dnew);
  CHECK_CLOSE(a, 0.1, 0.0, "alpha_min holds the floor");
  diag3(1e9, 1e9, 1e9, L);
  a = avsw_update(&sp, L, I, 0.0, 0.0, h, c, dt, &dnew);
  CHECK(a <= sp.alpha && a > 0.999, "a very strong shock: alpha up to, not past, alpha (got %.6f)",
        a);

  /* the gradient correction: L = G·A for a skewed neighbourhood gives G back */
  const double Gt[9] = {1, 2, 0, -1, 3, 0.5, 0, 0.25, -2};
  const double As[9] = {0.9, 0.1, 0.0, 0.05, 1.1, 0.02, 0.0, 0.03, 0.95};
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) {
      L[3 * i + j] = 0.0;
      for (int m = 0; m < 3; m++) L[3 * i + j] += Gt[3 * i + m] * As[3 * m + j];
    }
  sph_correct_gradient(L, As);
  double err = 0.0;
  for (int t = 0; t < 9; t++) err = fmax(err, fabs(L[t] - Gt[t]));
  CHECK(err < 1e-13, "corrected gradient recovers G (max error %.2e)", err);
  return test_finish();
}
