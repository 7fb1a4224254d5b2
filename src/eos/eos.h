/* eos.h — equations of state: p(ρ, e) and the sound speed, one dispatch.
 *
 * eos.c dispatches through the table of models (material.h, eos_models[m->eos]); each
 * EOS has its own file (ideal_gas.c, mie_gruneisen.c, tillotson.c, table.c) with its
 * equations and references in the file header, its reader, its listing and its row,
 * and docs/models.md gives them all.
 * Every function here is pure: values and a const parameter pointer in, values out.
 */
#ifndef HV_EOS_H
#define HV_EOS_H

#include <stddef.h>

#include "core/error.h"
#include "material/material.h"

struct eos_state {
  double p;  /* [Pa] pressure */
  double cs; /* [m/s] sound speed (floored where the EOS has a floor) */
};

/* Return codes of eos_evaluate / eos_energy_from_pressure. */
enum eos_status {
  EOS_OK = 0,
  EOS_ERR_INPUT = -1,         /* ρ <= 0 or a non-finite ρ or e */
  EOS_ERR_OUTSIDE_TABLE = -2, /* (ρ, e) outside a tabulated EOS */
  EOS_ERR_NO_SOLUTION = -3,   /* eos_energy_from_pressure: no energy gives that pressure */
  EOS_ERR_KIND = -4           /* unknown EOS kind (internal error) */
};

/* p and c at density rho [kg/m3] and specific internal energy e [J/kg].
 * Returns EOS_OK, or a negative enum eos_status (out is then left unchanged);
 * eos_describe() turns a failure (or, with EOS_OK, a result the caller found not finite)
 * into a message naming the material and the state. */
int eos_evaluate(const struct material *m, double rho, double e, struct eos_state *out);
/* Specific internal energy [J/kg] giving pressure p [Pa] at density rho (initial
 * conditions). Ideal gas and Mie–Grüneisen: exact; Tillotson: bracketing + bisection on
 * e >= 0; table: the piecewise-linear p(e) at that ρ, solved exactly. */
int eos_energy_from_pressure(const struct material *m, double rho, double p, double *e);
/* "material 'steel' (table 'x.txt'): rho = 1.2e4 kg/m3, e = 3e6 J/kg is outside the table
 * (rho 7000 to 9000 kg/m3, e 0 to 1e6 J/kg)" for a status returned by the functions above
 * (for EOS_ERR_NO_SOLUTION from eos_energy_from_pressure, pass the pressure as e). */
void eos_describe(const struct material *m, double rho, double e, int status, char *buf,
                  size_t len);

/* ---- per-EOS functions (pure; called through their models' rows, and by the tests) ---- */

void eos_ideal_gas_evaluate(const struct eos_ideal_gas *g, double rho, double e,
                            struct eos_state *out);

/* Mie–Grüneisen with the Murnaghan cold curve (mie_gruneisen.c). */
void eos_mg_evaluate(const struct eos_mie_gruneisen *g, double rho, double e,
                     struct eos_state *out);
double eos_mg_cold_pressure(const struct eos_mie_gruneisen *g, double rho); /* p_c [Pa] */
double eos_mg_cold_energy(const struct eos_mie_gruneisen *g, double rho);   /* E_c [J/kg] */
int eos_mg_energy_from_pressure(const struct eos_mie_gruneisen *g, double rho, double p, double *e);

/* Tillotson (tillotson.c). */
void eos_tillotson_evaluate(const struct eos_tillotson *t, double rho, double e,
                            struct eos_state *out);
int eos_tillotson_energy_from_pressure(const struct eos_tillotson *t, double rho, double p,
                                       double *e);

/* Tabulated p(ρ, e) (table.c). */
int eos_table_evaluate(const struct eos_table *t, double rho, double e, struct eos_state *out);
int eos_table_energy_from_pressure(const struct eos_table *t, double rho, double p, double *e);
/* Reads and validates a table file into t (arrays malloc'ed; eos_table_free releases them).
 * Errors name the file and line: "tab.txt:7: rho values must increase strictly (...)". */
int eos_table_load(const char *path, struct eos_table *t, struct hv_error *err);
void eos_table_free(struct eos_table *t);

#endif
