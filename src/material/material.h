/* material.h — a material: its equation of state and (later) strength and fracture.
 *
 * Materials are named in case files and chosen at run time; every physics function
 * takes a `const struct material *`. The EOS is named ("ideal-gas", ...), never a number.
 */
#ifndef HV_MATERIAL_H
#define HV_MATERIAL_H

#include "config/config.h"

enum eos_kind { EOS_IDEAL_GAS = 0 };

struct eos_ideal_gas {
  double gamma;        /* [-] adiabatic exponent, > 1 */
};

struct material {
  char name[64];
  enum eos_kind eos;
  double rho0;         /* [kg/m3] reference density (0 if none, e.g. a gas) */
  union {
    struct eos_ideal_gas gas;
  } eosp;
};

#define HV_MAX_MATERIALS 32

/* Reads the material defined at `path` (a mapping, e.g. "materials.air") from the case. */
int material_read(struct cfg *c, const char *path, const char *name, struct material *m,
                  struct hv_error *err);
/* Names of the EOS kinds, in enum order (NULL-terminated). */
extern const char *const eos_kind_names[];

#endif
