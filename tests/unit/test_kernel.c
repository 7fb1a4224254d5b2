/* test_kernel.c — the SPH kernels of src/kernel/kernel.h (cubic spline M4, Wendland C2,
 * Johnson's quadratic) against what a kernel must satisfy:
 *   - normalisation ∫W dV = 1 (radial quadrature, 20 000 Simpson intervals on [0, 2h]);
 *   - the value at the centre against the closed form (1/π, 21/(16π), 15/(16π) over h³),
 *     and W = 0 from q = 2 on;
 *   - kernel_w_h3(q) = h³ W(qh, h);
 *   - the gradient: (1/r) dW/dr against a central difference of W, at q from 0.05 to 1.95;
 *   - the quadratic kernel's defining property, a slope that grows in magnitude towards
 *     the centre (no inflection point), and the cubic spline's zero slope there;
 *   - second moment: on a simple cubic lattice of spacing Δ with h = 1.2Δ the sum
 *     Σⱼ Vⱼ (xⱼ − xᵢ) ⊗ ∇ᵢWᵢⱼ = I (the matrix A of the gradient correction, whose
 *     closeness to I the uncorrected velocity gradient relies on) and Σⱼ Vⱼ Wᵢⱼ = 1:
 *     within 2 % for the cubic spline and Wendland C2 (measured: A = 0.982 I and 0.985 I,
 *     ΣVW = 1.001 and 1.018), within 5 % for the quadratic kernel (A = 0.959 I, ΣVW =
 *     1.030: the degree-2 kernel is the least accurate of the three on a lattice at this h).
 * A wrong constant, a wrong derivative or a sign error fails one of these. */
#include <math.h>
#include <string.h>

#include "kernel/kernel.h"
#include "testlib.h"

static const char *const NAMES[] = {"cubic-spline", "wendland-c2", "quadratic"};

int main(void)
{
  const double h = 1.7e-3;
  const enum kernel_kind kinds[] = {KERNEL_CUBIC_SPLINE, KERNEL_WENDLAND_C2, KERNEL_QUADRATIC};
  const double tol_lattice[] = {0.02, 0.02, 0.05};
  const double w0[] = {1.0 / HV_KERNEL_PI, 21.0 / (16.0 * HV_KERNEL_PI),
                       15.0 / (16.0 * HV_KERNEL_PI)};

  for (int n = 0; n < 3; n++) {
    const enum kernel_kind k = kinds[n];
    CHECK(!strcmp(kernel_name(k), NAMES[n]), "kernel %d is named %s (got %s)", n, NAMES[n],
          kernel_name(k));

    /* ∫ 4π r² W dr over [0, 2h], Simpson */
    const int M = 20000;
    const double a = 2.0 * h / M;
    double s = 0.0;
    for (int i = 0; i <= M; i++) {
      const double r = i * a, f = 4.0 * HV_KERNEL_PI * r * r * kernel_w(k, r, h);
      s += (i == 0 || i == M) ? f : (i % 2 ? 4.0 * f : 2.0 * f);
    }
    s *= a / 3.0;
    CHECK(fabs(s - 1.0) < 1e-10, "%s: integral of W = 1 (got %.12f)", NAMES[n], s);

    CHECK(fabs(kernel_w(k, 0.0, h) * h * h * h - w0[n]) < 1e-14, "%s: h^3 W(0) = %.12f (got %.12f)",
          NAMES[n], w0[n], kernel_w(k, 0.0, h) * h * h * h);
    CHECK(kernel_w(k, 2.0 * h, h) == 0.0 && kernel_w(k, 2.5 * h, h) == 0.0 &&
              kernel_f(k, 2.0 * h, h) == 0.0,
          "%s: W and its gradient vanish from q = 2 on", NAMES[n]);

    double worst_h3 = 0.0, worst_f = 0.0;
    for (int i = 1; i < 40; i++) {
      const double q = 0.05 * i, r = q * h;
      const double rel =
          fabs(kernel_w_h3(k, q) - h * h * h * kernel_w(k, r, h)) / kernel_w_h3(k, q);
      if (rel > worst_h3) worst_h3 = rel;
      const double d = 1e-6 * h;
      const double dwdr = (kernel_w(k, r + d, h) - kernel_w(k, r - d, h)) / (2.0 * d);
      const double scale = kernel_w(k, 0.0, h) / h; /* a slope of order W(0)/h */
      const double err = fabs(kernel_f(k, r, h) * r - dwdr) / scale;
      if (err > worst_f) worst_f = err;
    }
    CHECK(worst_h3 < 1e-13, "%s: kernel_w_h3 = h^3 W (worst relative %.2e)", NAMES[n], worst_h3);
    CHECK(worst_f < 1e-6,
          "%s: (1/r) dW/dr against a central difference of W (worst %.2e of W(0)/h)", NAMES[n],
          worst_f);

    /* Σ_j V_j (x_j − x_i) ⊗ ∇_i W_ij = I and Σ_j V_j W_ij = 1 on a cubic lattice, h = 1.2 Δ */
    const double D = h / 1.2, V = D * D * D;
    double A[9] = {0}, S = V * kernel_w(k, 0.0, h);
    for (int ix = -3; ix <= 3; ix++)
      for (int iy = -3; iy <= 3; iy++)
        for (int iz = -3; iz <= 3; iz++) {
          if (!ix && !iy && !iz) continue;
          const double x[3] = {ix * D, iy * D, iz * D}; /* x_j − x_i */
          const double r = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
          const double f = kernel_f(k, r, h); /* ∇_i W = (x_i − x_j) f */
          S += V * kernel_w(k, r, h);
          for (int p = 0; p < 3; p++)
            for (int q = 0; q < 3; q++) A[3 * p + q] += V * x[p] * (-x[q]) * f;
        }
    double off = 0.0;
    for (int p = 0; p < 3; p++)
      for (int q = 0; q < 3; q++)
        if (p != q) off = fmax(off, fabs(A[3 * p + q]));
    const double tl = tol_lattice[n];
    CHECK(fabs(A[0] - 1.0) < tl && fabs(A[4] - 1.0) < tl && fabs(A[8] - 1.0) < tl && off < 1e-12,
          "%s: lattice sum of V (xj - xi) x grad W = I within %.0f %% (diagonal %.4f %.4f %.4f, "
          "off-diagonal %.1e)",
          NAMES[n], 100 * tl, A[0], A[4], A[8], off);
    CHECK(fabs(S - 1.0) < tl, "%s: lattice sum of V W = 1 within %.0f %% (got %.4f)", NAMES[n],
          100 * tl, S);
  }

  /* the quadratic kernel: |dW/dr| grows monotonically towards the centre, where it is
   * 3/4 σ/h⁴; the cubic spline's slope vanishes there (its inflection at q = 2/3) */
  double prev = INFINITY;
  int mono = 1;
  for (int i = 1; i < 40; i++) {
    const double r = 0.05 * i * h, slope = fabs(kernel_f(KERNEL_QUADRATIC, r, h) * r);
    if (!(slope < prev)) mono = 0;
    prev = slope;
  }
  CHECK(mono, "quadratic: |dW/dr| falls monotonically from the centre outwards");
  const double r_small = 1e-6 * h;
  CHECK_CLOSE(kernel_f(KERNEL_QUADRATIC, r_small, h) * r_small * h * h * h * h,
              -0.75 * 5.0 / (4.0 * HV_KERNEL_PI), 1e-5,
              "quadratic: dW/dr at the centre = -3/4 sigma/h^4");
  CHECK(fabs(kernel_f(KERNEL_CUBIC_SPLINE, r_small, h) * r_small) * h * h * h * h < 1e-5,
        "cubic spline: dW/dr vanishes at the centre");
  CHECK(kernel_f(KERNEL_QUADRATIC, 0.0, h) == 0.0, "quadratic: a pair at one point has no force");
  return test_finish();
}
