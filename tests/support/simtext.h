/* simtext.h — a case set up through the library from YAML text (consistency tests that
 * step a struct sim themselves: test_conservation, test_conservation_solid,
 * test_reconstruct). */
#ifndef HV_SIMTEXT_H
#define HV_SIMTEXT_H

#include "config/config.h"
#include "sim/sim.h"

/* Loads `text` as the case file `name`, sets *s up (run_setup) and checks that every key
 * was used; a failed CHECK names the error. Returns 0, or -1 with *c freed (NULL). */
int sim_from_text(const char *text, const char *name, struct sim *s, struct cfg **c);

#endif
