/* kernel.h — SPH interpolation kernels in 3D, support radius 2h.
 *
 * Cubic B-spline M4 (Monaghan & Lattanzio 1985; the paper's "second order
 * B-spline"):  W = σ/h³ · { 1 − 3/2 q² + 3/4 q³      0 ≤ q < 1
 *                          { 1/4 (2 − q)³            1 ≤ q < 2,   σ = 1/π
 * Wendland C2 (Wendland 1995; Dehnen & Aly 2012), written with support 2h:
 *   W = σ/h³ (1 − q/2)⁴ (2q + 1),  0 ≤ q < 2,   σ = 21/(16π)
 * Quadratic (Johnson, Stryk & Beissel 1996, CMAME 139:347; a reading of the paper's
 * "second order B-spline" as the degree-2 kernel of impact SPH):
 *   W = σ/h³ (3/16 q² − 3/4 q + 3/4),  0 ≤ q ≤ 2,   σ = 5/(4π)
 *   its slope dW/dq = σ/h³ (3/8 q − 3/4) grows in magnitude towards q = 0, so close
 *   pairs repel more strongly (no inflection point, unlike M4); (1/r) dW/dr diverges
 *   as 1/r there, the gradient (x (1/r) dW/dr) stays finite.
 * q = r/h. Pair interactions use the symmetric h_ij = (h_i + h_j)/2, so a pair
 * interacts when r < h_i + h_j.
 */
#ifndef HV_KERNEL_H
#define HV_KERNEL_H

#include <math.h>

enum kernel_kind { KERNEL_CUBIC_SPLINE = 0, KERNEL_WENDLAND_C2 = 1, KERNEL_QUADRATIC = 2 };

/* A kind with this bit set is the same kernel normalised in two dimensions (the
 * meridional plane of an axisymmetric run, domain.geometry: axisymmetric):
 * W₂ = σ₂/h² w(q) = W₃ · h σ₂/σ₃, with σ₂ = 10/(7π) (cubic spline), 7/(4π) (Wendland C2,
 * Dehnen & Aly 2012) and 2/π (quadratic, Johnson, Stryk & Beissel 1996): the 3D value
 * times h σ₂/σ₃, so that a 3D run computes exactly what it did (the same operations). */
#define KERNEL_2D      8
#define KERNEL_BASE(k) ((enum kernel_kind)((int)(k) & (KERNEL_2D - 1)))

/* h σ₂/σ₃ for kind k (KERNEL_2D set): the factor from the 3D to the 2D normalisation. */
static inline double kernel_to_2d(enum kernel_kind k, double h)
{
  const enum kernel_kind b = KERNEL_BASE(k);
  if (b == KERNEL_WENDLAND_C2) return h * (7.0 / 4.0) * (16.0 / 21.0);
  if (b == KERNEL_QUADRATIC) return h * 2.0 * (4.0 / 5.0);
  return h * (10.0 / 7.0);
}

#define HV_KERNEL_PI 3.14159265358979323846

/* W(r, h) [1/m³] */
static inline double kernel_w_3d(enum kernel_kind k, double r, double h)
{
  double q = r / h, h3 = h * h * h;
  if (q >= 2.0) return 0.0;
  if (k == KERNEL_WENDLAND_C2) {
    double t = 1.0 - 0.5 * q;
    return 21.0 / (16.0 * HV_KERNEL_PI) / h3 * t * t * t * t * (2.0 * q + 1.0);
  }
  if (k == KERNEL_QUADRATIC)
    return 5.0 / (4.0 * HV_KERNEL_PI) / h3 * (0.1875 * q * q - 0.75 * q + 0.75);
  if (q < 1.0) return (1.0 - 1.5 * q * q + 0.75 * q * q * q) / (HV_KERNEL_PI * h3);
  double t = 2.0 - q;
  return 0.25 * t * t * t / (HV_KERNEL_PI * h3);
}

/* h³ W(r, h) as a function of q = r/h: the kernel's shape, dimensionless (no division). */
static inline double kernel_w_h3_3d(enum kernel_kind k, double q)
{
  if (q >= 2.0) return 0.0;
  if (k == KERNEL_WENDLAND_C2) {
    double t = 1.0 - 0.5 * q;
    return 21.0 / (16.0 * HV_KERNEL_PI) * t * t * t * t * (2.0 * q + 1.0);
  }
  if (k == KERNEL_QUADRATIC) return 5.0 / (4.0 * HV_KERNEL_PI) * (0.1875 * q * q - 0.75 * q + 0.75);
  if (q < 1.0) return (1.0 - 1.5 * q * q + 0.75 * q * q * q) * (1.0 / HV_KERNEL_PI);
  double t = 2.0 - q;
  return 0.25 / HV_KERNEL_PI * t * t * t;
}

/* (1/r) dW/dr (r, h) [1/m⁵]: ∇ᵢWᵢⱼ = (xᵢ − xⱼ) · kernel_f(r, h). Finite at r = 0
 * (the quadratic kernel's is 0 there: see above).
 * One division, two in the outer shell 1 ≤ q < 2 (h/r); computing 1/h and 1/r
 * from one 1/(r h) was measured slower (docs/performance.md, "Where the time goes"). */
static inline double kernel_f_3d(enum kernel_kind k, double r, double h)
{
  const double ih = 1.0 / h, q = r * ih, ih2 = ih * ih, ih5 = ih2 * ih2 * ih;
  if (q >= 2.0) return 0.0;
  if (k == KERNEL_WENDLAND_C2) {
    /* dW/dq = σ/h³ · (−5 q)(1 − q/2)³ ; (1/r) dW/dr = dW/dq / (q h²) */
    const double t = 1.0 - 0.5 * q;
    return (-5.0 * 21.0 / (16.0 * HV_KERNEL_PI)) * ih5 * t * t * t;
  }
  if (k == KERNEL_QUADRATIC) {
    /* dW/dq = σ/h³ (3/8 q − 3/4); divided by q h²: σ/h⁵ (3/8 − 3/(4q)). A pair at
     * one point (q = 0) has no direction: no force (its x is 0 as well). */
    if (q < 1e-12) return 0.0;
    return 5.0 / (4.0 * HV_KERNEL_PI) * ih5 * (0.375 - 0.75 * h / r);
  }
  if (q < 1.0) return (-3.0 + 2.25 * q) * (1.0 / HV_KERNEL_PI) * ih5;
  /* −¾ (2 − q)²/q: with 1/q = h/r, r > h here */
  const double t = 2.0 - q;
  return (-0.75 / HV_KERNEL_PI) * t * t * ih5 * (h / r);
}

/* The kernels of kind k, in 3D or (KERNEL_2D set) in 2D. */
static inline double kernel_w(enum kernel_kind k, double r, double h)
{
  if (!((int)k & KERNEL_2D)) return kernel_w_3d(k, r, h);
  return kernel_w_3d(KERNEL_BASE(k), r, h) * kernel_to_2d(k, h);
}
/* h^d W as a function of q (d the kind's dimension). */
static inline double kernel_w_h3(enum kernel_kind k, double q)
{
  if (!((int)k & KERNEL_2D)) return kernel_w_h3_3d(k, q);
  return kernel_w_h3_3d(KERNEL_BASE(k), q) * kernel_to_2d(k, 1.0);
}
static inline double kernel_f(enum kernel_kind k, double r, double h)
{
  if (!((int)k & KERNEL_2D)) return kernel_f_3d(k, r, h);
  return kernel_f_3d(KERNEL_BASE(k), r, h) * kernel_to_2d(k, h);
}

const char *kernel_name(enum kernel_kind k);

#endif
