/* conservation.c — see conservation.h. The sums run over the particles in the order
 * of their ids, so they do not depend on how the store happens to be ordered (the
 * solver reorders particles by cell for memory locality): a conserved total is
 * reproduced bit for bit. */
#include "diag/conservation.h"

#include <stdlib.h>
#include <string.h>

#include "core/error.h"

struct id_slot {
  int64_t id;
  size_t slot;
};

static int by_id(const void *a, const void *b)
{
  int64_t x = ((const struct id_slot *)a)->id, y = ((const struct id_slot *)b)->id;
  return (x > y) - (x < y);
}

void diag_totals(const struct particles *p, struct totals *t)
{
  memset(t, 0, sizeof *t);
  struct id_slot *ord = hv_malloc((p->n + 1) * sizeof *ord, "totals order");
  for (size_t k = 0; k < p->n; k++) ord[k] = (struct id_slot){p->id[k], k};
  qsort(ord, p->n, sizeof *ord, by_id);
  for (size_t k = 0; k < p->n; k++) {
    const size_t i = ord[k].slot;
    const double m = p->m[i];
    double v2 = 0.0;
    for (int d = 0; d < 3; d++) {
      t->mom[d] += m * p->v[d][i];
      v2 += p->v[d][i] * p->v[d][i];
    }
    t->mass += m;
    t->e_kin += 0.5 * m * v2;
    t->e_int += m * p->e[i];
  }
  t->e_total = t->e_kin + t->e_int;
  free(ord);
}
