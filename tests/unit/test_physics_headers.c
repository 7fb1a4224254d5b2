/* test_physics_headers.c — the physics headers do not pull in the config layer, and the
 * table of models (material.c) is complete.
 *
 * The physics (EOS, strength, fracture, kernels, particles, neighbours, the pair loops,
 * boundaries) takes parameters already read; reading a case file is the config layer's,
 * reached through material/material_read.h and the like from .c files only
 * (docs/design.md). The simulation (sim/sim.h) and the integrator (integrate/step.h) hold
 * the case file only as an opaque struct cfg. A physics header that included
 * config/config.h, directly or through another header, would define its guard here. */
#include <string.h>

#include "boundary/boundary.h"
#include "eos/eos.h"
#include "fracture/fracture.h"
#include "fracture/rules.h"
#include "integrate/step.h"
#include "kernel/kernel.h"
#include "material/material.h"
#include "neighbours/grid.h"
#include "particles/particles.h"
#include "sim/sim.h"
#include "sph/avswitch.h"
#include "sph/nsearch.h"
#include "sph/pair.h"
#include "sph/partner.h"
#include "sph/recon.h"
#include "sph/rest.h"
#include "sph/sph.h"
#include "strength/strength.h"
#include "strength/sym3.h"

#ifdef HV_CONFIG_H
static const int config_included = 1;
#else
static const int config_included = 0;
#endif

#include "testlib.h"

/* Every row names its model and has the operations every material calls (the optional
 * ones are release and the describe pair); no two rows share a name, which would make
 * the second unreachable from a case file. */
static void test_table(void)
{
  for (int k = 0; k < EOS_KIND_COUNT; k++) {
    const struct eos_model *e = eos_models[k];
    CHECK(e && e->name && e->read && e->print && e->evaluate && e->energy_from_pressure,
          "EOS row %d is complete", k);
    if (!e || !e->name) continue;
    for (int j = 0; j < k; j++)
      CHECK(strcmp(e->name, eos_models[j]->name), "EOS rows %d and %d share the name '%s'", j, k,
            e->name);
    for (const struct material_typical *t = e->typical; t && t->key; t++)
      CHECK(t->lo > 0.0 && t->hi > t->lo && t->what, "EOS '%s': the span of '%s'", e->name, t->key);
  }
  CHECK(eos_models[EOS_IDEAL_GAS]->typical == NULL, "ideal-gas is the gas (no condensed spans)");
  for (int k = 0; k < YIELD_KIND_COUNT; k++) {
    const struct yield_model *y = yield_models[k];
    CHECK(y && y->name && y->read && y->print && y->yield && y->yield_max,
          "yield row %d is complete", k);
    if (!y || !y->name) continue;
    for (int j = 0; j < k; j++)
      CHECK(strcmp(y->name, yield_models[j]->name), "yield rows %d and %d share the name '%s'", j,
            k, y->name);
  }
}

int main(void)
{
  CHECK(!config_included,
        "a physics header includes config/config.h (directly or through "
        "another header): move the reading function to a *_read.h included by .c files");
  test_table();
  return test_finish();
}
