/* test_recon.c — the limited reconstruction of a pair's approach speed
 * (sph.viscosity.reconstruct, src/sph/recon.h) against hand results. This is the test
 * that isolates the slope limiter: test_reconstruct (a whole block stepped once) passes
 * with Φ = 1 as well, here the ratio-10 pair below gets 0 instead of 40.5/11·g. */
#include <math.h>

#include "sph/recon.h"
#include "testlib.h"

/* gₖ = r·Gₖ r for G = s·I (isotropic slope s) and r = (d, 0, 0): s d². */
static void iso(double s, double G[9])
{
  for (int k = 0; k < 9; k++) G[k] = 0.0;
  G[0] = G[4] = G[8] = s;
}

int main(void)
{
  const double d = 1e-3, edot = -1e4; /* spacing [m], compressive slope [1/s] */
  const double g = edot * d * d;      /* r·G r of a unit slope pair */
  double Gi[9], Gj[9];

  /* a linear field: both slopes equal, the pair's approach speed is exactly g */
  iso(edot, Gi);
  iso(edot, Gj);
  CHECK(fabs(sph_recon_approach(g, Gi, Gj, d, 0, 0)) <= 1e-15 * fabs(g),
        "linear field: no approach speed left (%.3e of g)",
        sph_recon_approach(g, Gi, Gj, d, 0, 0) / g);
  /* the same along a diagonal pair (r = (d, d, d)/√3, |r| = d) */
  const double e = d / sqrt(3.0);
  CHECK(fabs(sph_recon_approach(g, Gi, Gj, e, e, e)) <= 1e-15 * fabs(g),
        "linear field, diagonal pair: no approach speed left");

  /* slopes of ratio 10, both compressive, the pair approaching at their mean:
   * Φ = 4·10/11² = 40/121, left = 5.5 g − ½ Φ 11 g = 40.5/11 g (Φ = 1 would leave 0) */
  iso(edot, Gi);
  iso(10 * edot, Gj);
  const double want = 40.5 / 11.0 * g;
  CHECK_CLOSE(sph_recon_approach(5.5 * g, Gi, Gj, d, 0, 0), want, 1e-12 * fabs(want),
              "slopes 1:10: the limiter keeps 40.5/11 g");
  /* symmetric: i and j swapped (r → −r, the approach speed unchanged) */
  CHECK_CLOSE(sph_recon_approach(5.5 * g, Gj, Gi, -d, 0, 0), want, 1e-12 * fabs(want),
              "slopes 1:10, i and j swapped: the same");

  /* slopes of opposite sign (compression beside expansion) or one of them 0: Φ = 0 */
  iso(-edot, Gj);
  CHECK(sph_recon_approach(g, Gi, Gj, d, 0, 0) == g, "slopes of opposite sign: whole jump");
  iso(0.0, Gj);
  CHECK(sph_recon_approach(g, Gi, Gj, d, 0, 0) == g, "one slope 0 (a kink): whole jump");
  /* a rotation has no slope along any pair */
  for (int k = 0; k < 9; k++) Gi[k] = Gj[k] = 0.0;
  Gi[1] = Gj[1] = 1e4;
  Gi[3] = Gj[3] = -1e4;
  CHECK(sph_recon_approach(g, Gi, Gj, e, e, 0) == g, "rotation: whole jump");

  /* the clamp: it only removes viscosity, never adds or reverses it */
  iso(edot, Gi);
  iso(edot, Gj);
  CHECK(sph_recon_approach(0.5 * g, Gi, Gj, d, 0, 0) == 0.0,
        "slopes steeper than the pair's difference: 0, not a reversed approach");
  iso(-edot, Gi);
  iso(-edot, Gj);
  CHECK(sph_recon_approach(g, Gi, Gj, d, 0, 0) == g,
        "both slopes expanding while the pair approaches: the whole jump, no more");
  return test_finish();
}
