/* plane.c — the plane a crack (split: crack) or a cohesive opening (fracture.energy)
 * opens across: its normal, which turns with the material, the normal stress on it, and
 * the stress an opening releases. See fracture.h and rules.h. */
#include "fracture/rules.h"

#include <math.h>

#include "particles/particles.h"
#include "strength/sym3.h"

double fracture_max_principal(double p, const double S[6])
{
  double sig[6] = {S[0] - p, S[1] - p, S[2] - p, S[3], S[4], S[5]}, lam[3];
  sym3_eigen(sig, lam, NULL);
  return lam[0];
}

void fracture_crack_normal(double p, const double S[6], double n[3])
{
  double sig[6] = {S[0] - p, S[1] - p, S[2] - p, S[3], S[4], S[5]}, lam[3], Q[9];
  sym3_eigen(sig, lam, Q);
  /* the eigenvector of lam[0], the largest: Q's first column (sym3.h) */
  n[0] = Q[0];
  n[1] = Q[3];
  n[2] = Q[6];
  const double r = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (r > 0.0 && isfinite(r)) {
    for (int k = 0; k < 3; k++) n[k] /= r;
  } else {
    n[0] = 1.0;
    n[1] = n[2] = 0.0;
  }
}

void fracture_crack_rotate(double n[3], const double L[9], double dt)
{
  double m[3];
  for (int a = 0; a < 3; a++) {
    double w = 0.0; /* (Ω n)_a = Σ_b ½(L_ab − L_ba) n_b */
    for (int b = 0; b < 3; b++) w += 0.5 * (L[3 * a + b] - L[3 * b + a]) * n[b];
    m[a] = n[a] + dt * w;
  }
  const double r = sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
  if (!(r > 0.0) || !isfinite(r)) return;
  for (int a = 0; a < 3; a++) n[a] = m[a] / r;
}

double fracture_normal_stress(double p, const double S[6], const double n[3])
{
  double Sn[3];
  sym3_apply(S, n, Sn);
  return -p + Sn[0] * n[0] + Sn[1] * n[1] + Sn[2] * n[2];
}

void fracture_open_by(double S[6], const double n[3], double G, double dw)
{
  const double nn[6] = {n[0] * n[0], n[1] * n[1], n[2] * n[2],
                        n[0] * n[1], n[1] * n[2], n[0] * n[2]};
  for (int k = 0; k < 6; k++) S[k] -= 2.0 * G * dw * (nn[k] - (k < 3 ? 1.0 / 3.0 : 0.0));
}

void fracture_opening_moduli(const struct particles *p, size_t i, const struct material *m,
                             double *K, double *G)
{
  const double rho_m = p->rho[i] * exp(p->eps_c[i]);
  const double M = rho_m * p->cs[i] * p->cs[i];
  *G = m->str.G;
  *K = fmax(M - 4.0 / 3.0 * *G, 0.0);
}
