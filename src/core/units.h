/* units.h — physical quantities written with units in case files.
 *
 * "6.2 km/s", "1.5 mm", "2.78 g/cm3", "10.5 bar", "0.2 kJ/g", "35 us", "45 deg".
 * A bare number is SI. A unit expression is a product/quotient of unit atoms, each
 * with an optional SI prefix and an integer power: "kg/m^3", "g/cm3", "m/s2",
 * "J/kg/K", "N*m", "1/s". Internally everything is SI (m, kg, s, K, rad).
 */
#ifndef HV_UNITS_H
#define HV_UNITS_H

#include <stddef.h>

/* Expected dimension of a quantity (what the reader asks for). */
enum unit_dim {
  UNIT_NONE = 0,        /* dimensionless: bare numbers only (or "%"?: no) */
  UNIT_LENGTH,          /* m   */
  UNIT_TIME,            /* s   */
  UNIT_MASS,            /* kg  */
  UNIT_VELOCITY,        /* m/s */
  UNIT_ACCELERATION,    /* m/s2 */
  UNIT_DENSITY,         /* kg/m3 */
  UNIT_PRESSURE,        /* Pa (also stress, elastic moduli) */
  UNIT_ENERGY,          /* J   */
  UNIT_SPECIFIC_ENERGY, /* J/kg (= m2/s2) */
  UNIT_SPECIFIC_HEAT,   /* J/kg/K */
  UNIT_TEMPERATURE,     /* K   */
  UNIT_ANGLE,           /* rad (deg accepted) */
  UNIT_RATE,            /* 1/s */
  UNIT_FRACTURE_ENERGY, /* J/m2 (= N/m, kg/s2): energy per unit crack area */
  UNIT_DIM_COUNT
};

/* Name of a dimension and its SI unit, for messages and used_parameters.yaml. */
const char *units_dim_name(enum unit_dim dim);  /* "velocity" */
const char *units_si_symbol(enum unit_dim dim); /* "m/s" */

/* Parses "number [unit]" into SI. Returns 0, or -1 with a message in msg
 * ("unit 'kg' is a mass, expected a velocity (e.g. m/s)"). */
int units_parse(const char *text, enum unit_dim dim, double *si, char *msg, size_t msglen);

#endif
