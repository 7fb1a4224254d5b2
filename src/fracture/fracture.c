/* fracture.c — the fracture state and the end of a step; see fracture.h. */
#include "fracture/fracture.h"

#include <math.h>

#include "fracture/rules.h"
#include "particles/particles.h"

int fracture_cracked(const struct fracture_params *fp, int state)
{
  return fp->split == SPLIT_CRACK && state == FRACTURE_SPLIT;
}

int fracture_keeps_stress(const struct fracture_params *fp, int state)
{
  return state < FRACTURE_SPLIT || fp->friction > 0.0 || fp->split == SPLIT_NO_TENSION ||
         fracture_cracked(fp, state);
}

int fracture_no_tension(const struct fracture_params *fp, int state)
{
  return state >= FRACTURE_SPLIT && fp->split == SPLIT_NO_TENSION;
}

double fracture_yield(const struct fracture_params *fp, int state, double Y, double p)
{
  if (state < FRACTURE_SPLIT || fp->split == SPLIT_NO_TENSION || fracture_cracked(fp, state))
    return Y;
  return fracture_fluid_yield(fp, Y, p);
}

int fracture_opening(const struct fracture_params *fp, int state)
{
  return fracture_cracked(fp, state) || state == FRACTURE_OPENING;
}

double fracture_eos_density(const struct particles *p, size_t i, const struct fracture_params *fp)
{
  return p->cracks && fracture_opening(fp, p->fstate[i]) ? p->rho[i] * exp(p->eps_c[i]) : p->rho[i];
}

double fracture_pressure(const struct fracture_params *fp, int state, double pe)
{
  if (state >= FRACTURE_SPLIT && pe < 0.0 && fp->split != SPLIT_NO_TENSION &&
      !fracture_cracked(fp, state))
    return 0.0;
  return pe;
}

void fracture_start(const struct fracture_params *fp, double d0, double *damage, int32_t *state)
{
  *damage = d0;
  if (d0 >= 1.0 && fp->split == SPLIT_CRACK) {
    *damage = 2.0;
    *state = FRACTURE_SPLIT_AGAIN;
  } else if (d0 >= 1.0) {
    *state = FRACTURE_SPLIT;
  } else {
    *state = fp->energy > 0.0 && d0 > 0.0 ? FRACTURE_OPENING : FRACTURE_INTACT;
  }
}

void fracture_states_from_damage(struct particles *p, const struct material *mat)
{
  for (size_t i = 0; i < p->n; i++) {
    const double d = p->damage[i];
    p->fstate[i] = d >= 2.0                                      ? FRACTURE_SPLIT_AGAIN
                   : d >= 1.0                                    ? FRACTURE_SPLIT
                   : mat[p->mat[i]].frac.energy > 0.0 && d > 0.0 ? FRACTURE_OPENING
                                                                 : FRACTURE_INTACT;
  }
}

/* Particle i: the tensile test on σ = −pI + S (S its end-of-step deviator), then the
 * return of its rule. The tensile test runs before the rule and only on particles not
 * yet split (fracture_tension leaves D >= 1 alone): the order of the paper's step. */
static int end_particle(struct particles *p, size_t i, const struct material *m, double dt)
{
  const struct fracture_params *fp = &m->frac;
  const int st0 = p->fstate[i];
  double S[6];
  for (int k = 0; k < 6; k++) S[k] = p->S[k][i];
  const double d =
      st0 < FRACTURE_SPLIT ? fracture_tension(fp, p->damage[i], p->p[i], S, dt) : p->damage[i];
  if (fp->energy > 0.0 && st0 < FRACTURE_SPLIT) return fracture_cohesive_end(p, i, m, d);
  p->damage[i] = d;
  const int split_now = st0 < FRACTURE_SPLIT && d >= 1.0;
  if (split_now) p->fstate[i] = FRACTURE_SPLIT;
  const int st = p->fstate[i];
  if (st < FRACTURE_SPLIT) return 0;
  if (fp->split == SPLIT_CRACK) return fracture_crack_end(p, i, m, split_now);
  if (fp->split == SPLIT_NO_TENSION) {
    fracture_no_tension_end(p, i);
    return 0;
  }
  return fracture_fluid_end(p, i, fp, split_now);
}

long fracture_end_step(struct particles *p, const struct material *mat, double dt)
{
  long again = 0;
#pragma omp parallel for schedule(static) reduction(+ : again)
  for (size_t i = 0; i < p->n; i++) {
    const struct material *m = &mat[p->mat[i]];
    if (m->frac.kind != FRACTURE_NONE) again += end_particle(p, i, m, dt);
  }
  return again;
}

int fracture_end_particle(struct particles *p, size_t i, const struct material *mat, double dt)
{
  const struct material *m = &mat[p->mat[i]];
  return m->frac.kind != FRACTURE_NONE ? end_particle(p, i, m, dt) : 0;
}

size_t fracture_check_states(const struct particles *p, const struct material *mat)
{
  for (size_t i = 0; i < p->n; i++) {
    const struct fracture_params *fp = &mat[p->mat[i]].frac;
    const int32_t st = p->fstate[i];
    const double d = p->damage[i];
    int ok;
    switch (st) {
    case FRACTURE_INTACT: ok = d >= 0.0 && d < 1.0 && !(fp->energy > 0.0 && d > 0.0); break;
    case FRACTURE_OPENING: ok = fp->energy > 0.0 && d > 0.0 && d < 1.0; break;
    case FRACTURE_SPLIT: ok = fp->kind != FRACTURE_NONE && d == 1.0; break;
    case FRACTURE_SPLIT_AGAIN: ok = fp->split == SPLIT_CRACK && d == 2.0; break;
    default: ok = 0; break;
    }
    if (!ok) return i;
  }
  return (size_t)-1;
}
