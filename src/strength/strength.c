/* strength.c — the elastic–plastic stress update shared by every yield model: the
 * Jaumann rate, the radial return and the dispatch to the yield model's row
 * (material.h, yield_models[]); the yield models are von_mises.c (constant, linear)
 * and johnson_cook.c. See strength.h for the equations and references. */
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
  if ((unsigned)sp->yield >= YIELD_KIND_COUNT) return sp->Y0;
  return yield_models[sp->yield]->yield(sp, eps_p, rate, e);
}

double strength_return(double G, double Y, double S[6])
{
  const double q = sqrt(3.0 * sym3_j2(S)); /* von Mises equivalent stress */
  if (q <= Y || q == 0.0) return 0.0;
  const double f = Y / q;
  for (int k = 0; k < 6; k++) S[k] *= f;
  return G > 0 ? (q - Y) / (3.0 * G) : 0.0;
}
