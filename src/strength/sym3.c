/* sym3.c — cyclic Jacobi rotations for symmetric 3×3 matrices (Golub & Van Loan,
 * Matrix Computations, §8.5): converges quadratically, a handful of sweeps. */
#include "strength/sym3.h"

#include <math.h>

void sym3_eigen(const double a[6], double lam[3], double Q[9])
{
  double A[9], V[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  sym3_full(a, A);
  for (int sweep = 0; sweep < 30; sweep++) {
    double off = A[1] * A[1] + A[2] * A[2] + A[5] * A[5];
    double scale = A[0] * A[0] + A[4] * A[4] + A[8] * A[8] + off;
    if (off <= 1e-30 * scale || off == 0.0) break;
    for (int p = 0; p < 2; p++)
      for (int q = p + 1; q < 3; q++) {
        double apq = A[3 * p + q];
        if (apq == 0.0) continue;
        double theta = (A[3 * q + q] - A[3 * p + p]) / (2.0 * apq);
        double t = (theta >= 0 ? 1.0 : -1.0) / (fabs(theta) + sqrt(theta * theta + 1.0));
        double c = 1.0 / sqrt(t * t + 1.0), s = t * c;
        for (int k = 0; k < 3; k++) { /* A ← Jᵀ A J */
          double akp = A[3 * k + p], akq = A[3 * k + q];
          A[3 * k + p] = c * akp - s * akq;
          A[3 * k + q] = s * akp + c * akq;
        }
        for (int k = 0; k < 3; k++) {
          double apk = A[3 * p + k], aqk = A[3 * q + k];
          A[3 * p + k] = c * apk - s * aqk;
          A[3 * q + k] = s * apk + c * aqk;
        }
        for (int k = 0; k < 3; k++) {
          double vkp = V[3 * k + p], vkq = V[3 * k + q];
          V[3 * k + p] = c * vkp - s * vkq;
          V[3 * k + q] = s * vkp + c * vkq;
        }
      }
  }
  int idx[3] = {0, 1, 2};
  double d[3] = {A[0], A[4], A[8]};
  for (int i = 0; i < 2; i++) /* sort descending */
    for (int j = i + 1; j < 3; j++)
      if (d[idx[j]] > d[idx[i]]) {
        int t = idx[i];
        idx[i] = idx[j];
        idx[j] = t;
      }
  for (int k = 0; k < 3; k++) {
    lam[k] = d[idx[k]];
    if (Q)
      for (int r = 0; r < 3; r++) Q[3 * r + k] = V[3 * r + idx[k]];
  }
}

void sym3_from_eigen(const double Q[9], const double d[3], double b[6])
{
  double m[9];
  for (int r = 0; r < 3; r++)
    for (int c = 0; c < 3; c++)
      m[3 * r + c] = Q[3 * r] * d[0] * Q[3 * c] + Q[3 * r + 1] * d[1] * Q[3 * c + 1] +
                     Q[3 * r + 2] * d[2] * Q[3 * c + 2];
  b[0] = m[0];
  b[1] = m[4];
  b[2] = m[8];
  b[3] = m[1];
  b[4] = m[5];
  b[5] = m[2];
}
