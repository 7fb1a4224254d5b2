/* conservation.h — global sums: mass, momentum, energies (serial, so the sums are
 * the same whatever the number of threads). */
#ifndef HV_CONSERVATION_H
#define HV_CONSERVATION_H

#include "particles/particles.h"

struct totals {
  double mass;    /* [kg] */
  double mom[3];  /* [kg m/s] */
  double e_kin;   /* [J] */
  double e_int;   /* [J] */
  double e_total; /* [J] */
};

void diag_totals(const struct particles *p, struct totals *t);

#endif
