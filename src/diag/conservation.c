/* conservation.c — see conservation.h. */
#include "diag/conservation.h"

#include <string.h>

void diag_totals(const struct particles *p, struct totals *t)
{
  memset(t, 0, sizeof *t);
  for (size_t i = 0; i < p->n; i++) {
    const double m = p->m[i];
    double v2 = 0.0;
    for (int k = 0; k < 3; k++) {
      t->mom[k] += m * p->v[k][i];
      v2 += p->v[k][i] * p->v[k][i];
    }
    t->mass += m;
    t->e_kin += 0.5 * m * v2;
    t->e_int += m * p->e[i];
  }
  t->e_total = t->e_kin + t->e_int;
}
