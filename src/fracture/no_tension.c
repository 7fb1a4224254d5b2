/* no_tension.c — split without tension (fracture.split: no-tension): a split particle
 * keeps its deviatoric stress and yield stress as if intact, but the principal tensions
 * of σ = −pI + S are removed (σ' = Q min(Λ, 0) Qᵀ) wherever the stress enters the forces
 * and the energy (sph_solid.c): cracks open under tension and close under compression
 * (the "directional" or orthotropic post-failure response of hydrocodes). A split wall
 * in radial compression and hoop tension keeps its radial compression and its shear.
 * The state (ρ, e, S) is not projected within a step — p stays the EOS's, S the updated
 * deviator — only the stress the forces and the heating use; at the end of the step S
 * takes the deviator of σ' (the elastic stress a crack releases). */
#include "fracture/rules.h"

#include "particles/particles.h"
#include "strength/sym3.h"

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
  const double m = (Se[0] + Se[1] + Se[2]) / 3.0; /* σ' = −(p − m) I + dev(Se) */
  for (int k = 0; k < 3; k++) Se[k] -= m;
  return p - m;
}

void fracture_no_tension_end(struct particles *p, size_t i)
{
  /* the pressure stays the EOS's; each step's forces remove its tension again */
  double S[6], Se[6];
  for (int k = 0; k < 6; k++) S[k] = p->S[k][i];
  fracture_effective(p->p[i], S, Se);
  for (int k = 0; k < 6; k++) p->S[k][i] = Se[k];
}
