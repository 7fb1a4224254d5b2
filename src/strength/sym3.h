/* sym3.h — small helpers for symmetric 3×3 tensors stored as 6 components in VTK
 * order (xx, yy, zz, xy, yz, xz), and their eigen-decomposition (cyclic Jacobi). */
#ifndef HV_SYM3_H
#define HV_SYM3_H

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

/* Second invariant of a deviator: J2 = ½ S:S. */
static inline double sym3_j2(const double s[6])
{
  return 0.5 * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]) + s[3] * s[3] + s[4] * s[4] + s[5] * s[5];
}

#endif
