/* read.h — what the fracture rules' readers share (fracture_read.c), and each rule's
 * reader of its own keys (in the rule's file). fp is the mapping's key path
 * ("materials.NAME.fracture"). The key helpers (material_key, material_key_error,
 * material_get_q, material_not_used_here) are the materials' own, so that a fracture key
 * is read, and its error written, as any other material key's. */
#ifndef HV_FRACTURE_READ_RULES_H
#define HV_FRACTURE_READ_RULES_H

#include "fracture/fracture_read.h"
#include "material/material_read.h"

/* tresca.c: sigma_c (required; zero_off: 0 accepted, "no tensile criterion", with the
 * default def). */
int fracture_read_sigma_c(struct cfg *c, const char *fp, const double *def, int zero_off,
                          double *out, struct hv_error *err);
int fracture_read_tresca(struct cfg *c, const char *fp, struct material *m, struct hv_error *err);
/* cumulative.c: sigma_c (0 by default: off), eps_f, tau. */
int fracture_read_cumulative(struct cfg *c, const char *fp, struct material *m,
                             struct hv_error *err);
/* cohesive.c: energy (model tresca). */
int fracture_read_energy(struct cfg *c, const char *fp, struct material *m, struct hv_error *err);
/* split_fluid.c: friction (any model but none). */
int fracture_read_friction(struct cfg *c, const char *fp, struct material *m, struct hv_error *err);
/* crack.c: crack_eps_f (split: crack). */
int fracture_read_crack_eps_f(struct cfg *c, const char *fp, struct fracture_params *f,
                              struct hv_error *err);

#endif
