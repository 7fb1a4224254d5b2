/* conserve.c — the conservation tests' stepping loop (conserve.h) */
#include "conserve.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "integrate/step.h"
#include "testlib.h"

double conserve_uniform(uint64_t *state)
{
  uint64_t s = *state;
  s ^= s >> 12;
  s ^= s << 25;
  s ^= s >> 27;
  *state = s;
  return (double)((s * 0x2545F4914F6CDD1Dull) >> 11) * 0x1.0p-53 - 0.5;
}

/* Σ m in id order (independent of the memory order of the particles). */
static double mass_by_id(const struct particles *p, double *m_by_id, size_t nid)
{
  for (size_t k = 0; k < nid; k++) m_by_id[k] = (double)NAN;
  for (size_t i = 0; i < p->n; i++)
    if (p->id[i] >= 0 && (size_t)p->id[i] < nid) m_by_id[p->id[i]] = p->m[i];
  double sum = 0.0;
  for (size_t k = 0; k < nid; k++) sum += m_by_id[k];
  return sum;
}

/* Σ m |v| over the particles: the scale of the momentum round-off. */
static double momentum_scale(const struct particles *p)
{
  double s = 0.0;
  for (size_t i = 0; i < p->n; i++)
    s +=
        p->m[i] * sqrt(p->v[0][i] * p->v[0][i] + p->v[1][i] * p->v[1][i] + p->v[2][i] * p->v[2][i]);
  return s;
}

void conserve_steps(struct sim *s, int nsteps, double momentum_max, double energy_max,
                    struct conserve_result *r)
{
  struct hv_error err;
  hv_error_clear(&err);
  const size_t n0 = s->p.n;
  double *m0 = malloc(n0 * sizeof *m0), *m1 = malloc(n0 * sizeof *m1);
  if (!m0 || !m1) {
    CHECK(0, "memory for %zu masses", n0);
    free(m0);
    free(m1);
    r->ok = 0;
    return;
  }
  const double mass0_id = mass_by_id(&s->p, m0, n0);
  struct totals *t0 = &r->t0, *t = &r->t;
  diag_totals(&s->p, t0);
  *t = *t0;
  printf("initial: n = %zu, mass = %.17g kg, p = (%.6e, %.6e, %.6e) kg m/s, "
         "sum m|v| = %.6e kg m/s, E = %.17g J (kinetic %.6e, internal %.6e)\n",
         n0, t0->mass, t0->mom[0], t0->mom[1], t0->mom[2], momentum_scale(&s->p), t0->e_total,
         t0->e_kin, t0->e_int);

  int ok = !step_init(s, &err);
  CHECK(ok, "step_init (%s)", ok ? "ok" : err.msg);
  double worst_dp = 0.0, worst_de = 0.0;
  int mass_diag_same = 1, mass_id_same = 1, masses_same = 1, count_same = 1;
  long worst_dp_step = 0;
  for (int k = 1; k <= nsteps && ok; k++) {
    ok = !step_advance(s, &err);
    if (!ok) break;
    diag_totals(&s->p, t);
    const double dp = sqrt((t->mom[0] - t0->mom[0]) * (t->mom[0] - t0->mom[0]) +
                           (t->mom[1] - t0->mom[1]) * (t->mom[1] - t0->mom[1]) +
                           (t->mom[2] - t0->mom[2]) * (t->mom[2] - t0->mom[2])) /
                      momentum_scale(&s->p);
    const double de = fabs(t->e_total - t0->e_total) / t0->e_total;
    if (dp > worst_dp) {
      worst_dp = dp;
      worst_dp_step = k;
    }
    if (de > worst_de) worst_de = de;
    count_same &= s->p.n == n0;
    mass_diag_same &= t->mass == t0->mass;
    mass_id_same &= mass_by_id(&s->p, m1, n0) == mass0_id;
    masses_same &= !memcmp(m0, m1, n0 * sizeof *m0);
    if (k % 10 == 0)
      printf("step %3d  t = %.6e s  dt = %.3e s  |dp|/sum m|v| = %.3e  (E - E0)/E0 = %+.3e  "
             "E_kin/E_kin0 = %.4f  E_int = %.4e J\n",
             k, s->t, s->dt, dp, (t->e_total - t0->e_total) / t0->e_total, t->e_kin / t0->e_kin,
             t->e_int);
  }
  CHECK(ok, "%d steps run (%s)", nsteps, ok ? "ok" : err.msg);
  CHECK(count_same, "particle count stays %zu", n0);
  CHECK(masses_same, "every particle's mass (by id) is bitwise unchanged");
  CHECK(mass_id_same, "total mass summed in id order is bitwise the initial %.17g kg", mass0_id);
  CHECK(mass_diag_same, "total mass from diag_totals is bitwise the initial %.17g kg (last %.17g)",
        t0->mass, t->mass);
  CHECK(worst_dp < momentum_max, "momentum: max |dp| / sum m|v| = %.3e (step %ld) < %.0e", worst_dp,
        worst_dp_step, momentum_max);
  CHECK(worst_de < energy_max,
        "energy: max |E - E0| / E0 = %.3e < %.0e (reported; "
        "the scheme is not exactly energy conserving)",
        worst_de, energy_max);
  r->ok = ok;
  free(m0);
  free(m1);
}
