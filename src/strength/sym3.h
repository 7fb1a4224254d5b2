/* sym3.h — small helpers for symmetric 3×3 tensors stored as 6 components in VTK
 * order (xx, yy, zz, xy, yz, xz), and their eigen-decomposition (cyclic Jacobi). */
#ifndef HV_SYM3_H
#define HV_SYM3_H

#include <math.h>

/* Eigenvalues lam[3] (descending) and, if Q is not NULL, the eigenvectors as the
 * columns of Q (row-major 3×3): A = Q diag(lam) Qᵀ. */
void sym3_eigen(const double a[6], double lam[3], double Q[9]);
/* B = Q diag(d) Qᵀ, as 6 components. */
void sym3_from_eigen(const double Q[9], const double d[3], double b[6]);
/* Full 3×3 (row-major) from 6 components. */
static inline void sym3_full(const double a[6], double m[9])
{
  m[0] = a[0];
  m[4] = a[1];
  m[8] = a[2];
  m[1] = m[3] = a[3];
  m[5] = m[7] = a[4];
  m[2] = m[6] = a[5];
}
/* An upper bound of the largest eigenvalue (Gershgorin discs): cheap test before an
 * eigen-decomposition. */
/* out = A v for a symmetric A given as 6 components (VTK order xx, yy, zz, xy, yz, xz). */
static inline void sym3_apply(const double a[6], const double v[3], double out[3])
{
  out[0] = a[0] * v[0] + a[3] * v[1] + a[5] * v[2];
  out[1] = a[3] * v[0] + a[1] * v[1] + a[4] * v[2];
  out[2] = a[5] * v[0] + a[4] * v[1] + a[2] * v[2];
}

static inline double sym3_max_bound(const double a[6])
{
  const double r0 = a[0] + (a[3] < 0 ? -a[3] : a[3]) + (a[5] < 0 ? -a[5] : a[5]);
  const double r1 = a[1] + (a[3] < 0 ? -a[3] : a[3]) + (a[4] < 0 ? -a[4] : a[4]);
  const double r2 = a[2] + (a[4] < 0 ? -a[4] : a[4]) + (a[5] < 0 ? -a[5] : a[5]);
  return r0 > r1 ? (r0 > r2 ? r0 : r2) : (r1 > r2 ? r1 : r2);
}

/* Whether every eigenvalue of a is certainly negative (a negative definite): the leading
 * minors of −a positive (Sylvester's criterion), each by a margin of 10⁻¹² of its scale
 * (s, s², s³ with s the largest |aᵢⱼ|), far beyond their rounding errors (~10⁻¹⁵):
 * then det(−a) > 10⁻¹² s³ puts the largest eigenvalue below −10⁻¹³ s, where the Jacobi
 * rotations (sym3_eigen, errors ~10⁻¹⁶ s) find it negative too. A cheap test (about 20
 * operations) that spares the eigen-decomposition of compressed material; 0 when in
 * doubt (a zero matrix, NaN). */
static inline int sym3_negative_definite(const double a[6])
{
  const double b0 = -a[0], b1 = -a[1], b2 = -a[2], b3 = -a[3], b4 = -a[4], b5 = -a[5];
  double s = 0.0;
  for (int k = 0; k < 6; k++) s = fabs(a[k]) > s ? fabs(a[k]) : s;
  const double eps = 1e-12;
  const double m2 = b0 * b1 - b3 * b3;
  const double m3 = b0 * (b1 * b2 - b4 * b4) - b3 * (b3 * b2 - b4 * b5) + b5 * (b3 * b4 - b1 * b5);
  return b0 > eps * s && m2 > eps * s * s && m3 > eps * s * s * s;
}

/* Second invariant of a deviator: J2 = ½ S:S. */
static inline double sym3_j2(const double s[6])
{
  return 0.5 * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]) + s[3] * s[3] + s[4] * s[4] + s[5] * s[5];
}

#endif
