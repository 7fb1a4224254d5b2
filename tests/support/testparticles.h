/* testparticles.h — building particle sets by hand in the unit tests. */
#ifndef HV_TESTPARTICLES_H
#define HV_TESTPARTICLES_H

#include <stddef.h>

#include "particles/particles.h"

/* Appends one real particle at (x, y, z) with mass m [kg], smoothing length h [m] and
 * density rho [kg/m3], at rest, material 0, body `body`, id = its slot; every other
 * field zero. Returns the slot. */
size_t tp_add(struct particles *p, double x, double y, double z, double m, double h, double rho,
              int body);

#endif
