/* fracture_read.h — reading a material's fracture mapping from a case file (or the
 * library): material_read calls fracture_read. Apart from fracture.h so that the physics
 * does not include the config layer. */
#ifndef HV_FRACTURE_READ_H
#define HV_FRACTURE_READ_H

#include "config/config.h"
#include "material/material.h"

/* path.fracture of material m (whose strength and rho0 are read already) into m->frac
 * (all 0 when absent): model none | tresca | cumulative, split fluid | no-tension |
 * crack, and each rule's keys (docs/models.md, "Fracture"). A key the chosen model or
 * split does not use is an error when the case wrote it (the library's is ignored). */
int fracture_read(struct cfg *c, const char *path, struct material *m, struct hv_error *err);

#endif
