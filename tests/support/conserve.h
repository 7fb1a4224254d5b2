/* conserve.h — the stepping loop shared by the conservation tests
 * (tests/consistency/test_conservation.c, test_conservation_solid.c): step a set-up
 * simulation through the library and check, at every step, that the particle count
 * and every particle's mass (by id) stay bit for bit, that the total mass does too
 * (summed in id order and by diag_totals, so the sum does not depend on the memory
 * order the cell sort gives the particles), that the linear momentum is conserved to
 * momentum_max of Σ m|v|, and that the total energy drifts by less than energy_max.
 */
#ifndef HV_CONSERVE_H
#define HV_CONSERVE_H

#include <stdint.h>

#include "diag/conservation.h"
#include "sim/sim.h"

/* xorshift64*: the same numbers on every platform (unlike rand()); [-0.5, 0.5). */
double conserve_uniform(uint64_t *state);

struct conserve_result {
  int ok;              /* every step ran */
  struct totals t0, t; /* before the first step and after the last */
};

/* step_init, then nsteps × step_advance on s, with the checks above as CHECKs (their
 * thresholds in the messages); prints the totals before and every tenth step. */
void conserve_steps(struct sim *s, int nsteps, double momentum_max, double energy_max,
                    struct conserve_result *r);

#endif
