/* fracture.c — see fracture.h. */
#include "fracture/fracture.h"

#include "strength/sym3.h"

double fracture_max_principal(double p, const double S[6])
{
  double sig[6] = {S[0] - p, S[1] - p, S[2] - p, S[3], S[4], S[5]}, lam[3];
  sym3_eigen(sig, lam, NULL);
  return lam[0];
}

int fracture_keeps_stress(const struct fracture_params *fp, double damage)
{
  return damage < 1.0 || fp->friction > 0.0 || fp->split == SPLIT_NO_TENSION;
}

int fracture_no_tension(const struct fracture_params *fp, double damage)
{
  return damage >= 1.0 && fp->split == SPLIT_NO_TENSION;
}

double fracture_yield(const struct fracture_params *fp, double damage, double Y, double p)
{
  if (damage < 1.0 || fp->split == SPLIT_NO_TENSION) return Y;
  const double Yd = fp->friction * (p > 0.0 ? p : 0.0);
  return Yd < Y ? Yd : Y;
}

int fracture_project(double p, double T[6])
{
  double sig[6] = {T[0] - p, T[1] - p, T[2] - p, T[3], T[4], T[5]};
  if (!(sym3_max_bound(sig) > 0.0)) return 0;
  double lam[3], Q[9];
  sym3_eigen(sig, lam, Q);
  if (!(lam[0] > 0.0)) return 0;
  for (int k = 0; k < 3; k++) lam[k] = lam[k] > 0.0 ? 0.0 : lam[k];
  sym3_from_eigen(Q, lam, sig);
  for (int k = 0; k < 3; k++) T[k] = sig[k] + p;
  for (int k = 3; k < 6; k++) T[k] = sig[k];
  return 1;
}

double fracture_effective(double p, const double S[6], double Se[6])
{
  for (int k = 0; k < 6; k++) Se[k] = S[k];
  if (!fracture_project(p, Se)) return p;
  const double m = (Se[0] + Se[1] + Se[2]) / 3.0;   /* σ' = −(p − m) I + dev(Se) */
  for (int k = 0; k < 3; k++) Se[k] -= m;
  return p - m;
}

double fracture_plastic(const struct fracture_params *fp, double damage, double deps_p)
{
  if (fp->kind != FRACTURE_CUMULATIVE || fp->eps_f <= 0 || damage >= 1.0) return damage;
  damage += deps_p / fp->eps_f;
  return damage >= 1.0 ? 1.0 : damage;
}

double fracture_tension(const struct fracture_params *fp, double damage, double p,
                        const double S[6], double dt)
{
  if (damage >= 1.0 || fp->kind == FRACTURE_NONE) return damage;
  const double limit = -fp->sigma_c;   /* σ_c < 0: tension */
  const double sig[6] = {S[0] - p, S[1] - p, S[2] - p, S[3], S[4], S[5]};
  const int over = limit > 0 && sym3_max_bound(sig) > limit && fracture_max_principal(p, S) > limit;
  if (fp->kind == FRACTURE_TRESCA) return over ? 1.0 : damage;
  if (over) damage += fp->tau > 0 ? dt / fp->tau : 1.0;
  return damage >= 1.0 ? 1.0 : damage;
}
