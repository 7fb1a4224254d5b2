/* read.h — what the fracture rules' readers share (fracture_read.c), and each rule's
 * reader of its own keys (in the rule's file). fp is the mapping's key path
 * ("materials.NAME.fracture"). */
#ifndef HV_FRACTURE_READ_RULES_H
#define HV_FRACTURE_READ_RULES_H

#include "fracture/fracture_read.h"

/* "path.key" into buf. */
const char *fracture_key(char *buf, size_t len, const char *path, const char *key);
/* "file:line: key: message" (the line of the key, or of the deepest node present);
 * HV_EXIT_INPUT, returns -1. */
int fracture_key_error(struct cfg *c, const char *key, struct hv_error *err, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
/* A quantity path.key; def NULL: required. */
int fracture_get_q(struct cfg *c, const char *path, const char *key, enum unit_dim dim,
                   const double *def, double lo, double hi, double *out, struct hv_error *err);
/* A key the chosen model does not use: an error if the case wrote it. */
int fracture_not_used_here(struct cfg *c, const char *path, const char *key, const char *why,
                           struct hv_error *err);

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
