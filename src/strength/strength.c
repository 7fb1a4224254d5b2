/* strength.c — see strength.h for the equations and references. */
#include "strength/strength.h"

#include <math.h>

#include "particles/particles.h"
#include "strength/sym3.h"

void strength_rate(double G, const double S[6], const double L[9], double dS[6])
{
  double e[9], w[9], s[9], r[9];
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) {
      e[3 * a + b] = 0.5 * (L[3 * a + b] + L[3 * b + a]);
      w[3 * a + b] = 0.5 * (L[3 * a + b] - L[3 * b + a]);
    }
  const double tr3 = (e[0] + e[4] + e[8]) / 3.0;
  sym3_full(S, s);
  /* r = S Ωᵀ + Ω S = Ω S − S Ω (Ω antisymmetric) */
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) {
      double t = 0.0;
      for (int c = 0; c < 3; c++) t += w[3 * a + c] * s[3 * c + b] - s[3 * a + c] * w[3 * c + b];
      r[3 * a + b] = t;
    }
  dS[T_XX] = 2.0 * G * (e[0] - tr3) + r[0];
  dS[T_YY] = 2.0 * G * (e[4] - tr3) + r[4];
  dS[T_ZZ] = 2.0 * G * (e[8] - tr3) + r[8];
  dS[T_XY] = 2.0 * G * e[1] + r[1];
  dS[T_YZ] = 2.0 * G * e[5] + r[5];
  dS[T_XZ] = 2.0 * G * e[2] + r[2];
}

double strength_equivalent_rate(const double L[9])
{
  double e[9];
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) e[3 * a + b] = 0.5 * (L[3 * a + b] + L[3 * b + a]);
  const double tr3 = (e[0] + e[4] + e[8]) / 3.0;
  e[0] -= tr3;
  e[4] -= tr3;
  e[8] -= tr3;
  double s = 0.0;
  for (int k = 0; k < 9; k++) s += e[k] * e[k];
  return sqrt(2.0 / 3.0 * s);
}

double strength_yield(const struct strength_params *sp, double eps_p, double rate, double e)
{
  switch (sp->yield) {
  case YIELD_CONSTANT: return sp->Y0;
  case YIELD_LINEAR: return sp->Y0 + sp->H * eps_p;
  case YIELD_JOHNSON_COOK: {
    double Y = sp->jc_A + sp->jc_B * (eps_p > 0 ? pow(eps_p, sp->jc_N) : 0.0);
    if (sp->jc_C > 0 && sp->jc_rate0 > 0 && rate > sp->jc_rate0) Y *= 1.0 + sp->jc_C * log(rate / sp->jc_rate0);
    if (sp->cv > 0 && sp->T_melt > sp->T_ref) {
      double T = sp->T_ref + (e > 0 ? e : 0.0) / sp->cv;
      double Ts = (T - sp->T_ref) / (sp->T_melt - sp->T_ref);
      if (Ts >= 1.0) return 0.0;
      if (Ts > 0.0) Y *= 1.0 - pow(Ts, sp->jc_M);
    }
    return Y;
  }
  case YIELD_KIND_COUNT: break;
  }
  return sp->Y0;
}

double strength_return(double G, double Y, double S[6])
{
  const double q = sqrt(3.0 * sym3_j2(S));  /* von Mises equivalent stress */
  if (q <= Y || q == 0.0) return 0.0;
  const double f = Y / q;
  for (int k = 0; k < 6; k++) S[k] *= f;
  return G > 0 ? (q - Y) / (3.0 * G) : 0.0;
}
