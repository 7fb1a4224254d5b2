/* eos.h — equations of state: p(ρ, e) and the sound speed, one dispatch.
 *
 * eos.c is the only place that switches on the EOS kind; each EOS has its own file.
 */
#ifndef HV_EOS_H
#define HV_EOS_H

#include "material/material.h"

struct eos_state {
  double p;    /* [Pa] pressure */
  double cs;   /* [m/s] sound speed */
};

/* Returns 0, or -1 if the state cannot be evaluated (non-finite input). */
int eos_evaluate(const struct material *m, double rho, double e, struct eos_state *out);
/* Specific internal energy giving pressure p at density rho (initial conditions). */
int eos_energy_from_pressure(const struct material *m, double rho, double p, double *e);

/* Per-EOS functions (pure). */
void eos_ideal_gas_evaluate(const struct eos_ideal_gas *g, double rho, double e,
                            struct eos_state *out);

#endif
