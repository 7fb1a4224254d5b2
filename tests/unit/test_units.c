/* test_units.c — the unit parser: conversions to SI, dimension checks, junk rejected. */
#include "core/units.h"
#include "testlib.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define PI 3.14159265358979323846

/* Parses text as dim and checks the SI value to a relative tolerance of 1e-14. */
static void ok(const char *text, enum unit_dim dim, double expect)
{
  double v = -12345.0;
  char msg[256];
  int rc = units_parse(text, dim, &v, msg, sizeof msg);
  CHECK(rc == 0, "'%s' parses as %s (%s)", text, units_dim_name(dim), rc ? msg : "ok");
  CHECK_CLOSE(v, expect, 1e-14 * fabs(expect), text);
}

/* Expects a failure whose message contains every one of the (up to two) words. */
static void bad(const char *text, enum unit_dim dim, const char *w1, const char *w2)
{
  double v = 7.0;
  char msg[256] = "";
  int rc = units_parse(text, dim, &v, msg, sizeof msg);
  CHECK(rc == -1, "'%s' is rejected as %s", text, units_dim_name(dim));
  CHECK(v == 7.0, "'%s': output untouched on error", text);
  CHECK(w1 == NULL || strstr(msg, w1), "'%s': message '%s' mentions '%s'", text, msg, w1);
  CHECK(w2 == NULL || strstr(msg, w2), "'%s': message '%s' mentions '%s'", text, msg, w2);
}

static void test_header_examples(void)
{
  ok("6.2 km/s", UNIT_VELOCITY, 6200.0);
  ok("2.78 g/cm3", UNIT_DENSITY, 2780.0);
  ok("10.5 bar", UNIT_PRESSURE, 1.05e6);
  ok("0.2 kJ/g", UNIT_SPECIFIC_ENERGY, 2e5);
  ok("35 us", UNIT_TIME, 3.5e-5);
  ok("35 mks", UNIT_TIME, 3.5e-5);
  ok("1.5 mm", UNIT_LENGTH, 1.5e-3);
  ok("45 deg", UNIT_ANGLE, PI / 4.0);
  ok("2780 kg/m^3", UNIT_DENSITY, 2780.0);
  ok("9.81 m/s2", UNIT_ACCELERATION, 9.81);
  ok("9.81 m/s^2", UNIT_ACCELERATION, 9.81);
  ok("1 GPa", UNIT_PRESSURE, 1e9);
  ok("900 J/kg/K", UNIT_SPECIFIC_HEAT, 900.0);
  ok("5 N*m", UNIT_ENERGY, 5.0);
  ok("1e5 1/s", UNIT_RATE, 1e5);
  ok("3 s^-1", UNIT_RATE, 3.0);
}

static void test_exact_values(void)
{
  double v;
  /* Decimal prefixes convert without a stray last bit where the result is exact. */
  CHECK(units_parse("35 us", UNIT_TIME, &v, NULL, 0) == 0 && v == 3.5e-5,
        "35 us == 3.5e-5 exactly");
  CHECK(units_parse("6.2 km/s", UNIT_VELOCITY, &v, NULL, 0) == 0 && v == 6200.0,
        "6.2 km/s == 6200 exactly");
  /* wall-clock intervals (output.checkpoint_wall) */
  CHECK(units_parse("10 min", UNIT_TIME, &v, NULL, 0) == 0 && v == 600.0, "10 min == 600 s");
  CHECK(units_parse("1.5 h", UNIT_TIME, &v, NULL, 0) == 0 && v == 5400.0, "1.5 h == 5400 s");
  CHECK(units_parse("36 km/h", UNIT_VELOCITY, &v, NULL, 0) == 0 && fabs(v - 10.0) < 1e-12,
        "36 km/h == 10 m/s (got %.17g)", v);
  CHECK(units_parse("10 min", UNIT_LENGTH, &v, NULL, 0) != 0, "10 min is not a length");
  CHECK(units_parse("2 mh", UNIT_TIME, &v, NULL, 0) != 0, "'mh' (no prefix on h) is refused");
  CHECK(units_parse("2.78 g/cm3", UNIT_DENSITY, &v, NULL, 0) == 0 && v == 2780.0,
        "2.78 g/cm3 == 2780 exactly");
  CHECK(units_parse("1.5 mm", UNIT_LENGTH, &v, NULL, 0) == 0 && v == 1.5e-3, "1.5 mm == 1.5e-3");
}

static void test_atoms_and_prefixes(void)
{
  ok("1 m", UNIT_LENGTH, 1.0);
  ok("3 ms", UNIT_TIME, 3e-3);
  ok("2 mg", UNIT_MASS, 2e-6);
  ok("1 Mbar", UNIT_PRESSURE, 1e11);
  ok("20 kbar", UNIT_PRESSURE, 2e9);
  ok("70 MPa", UNIT_PRESSURE, 7e7);
  ok("101 kPa", UNIT_PRESSURE, 1.01e5);
  ok("1 Pa", UNIT_PRESSURE, 1.0);
  ok("1 atm", UNIT_PRESSURE, 101325.0);
  ok("2 MJ/kg", UNIT_SPECIFIC_ENERGY, 2e6);
  ok("4 kJ", UNIT_ENERGY, 4e3);
  ok("7.8 g/cc", UNIT_DENSITY, 7800.0);
  ok("3 um", UNIT_LENGTH, 3e-6);
  ok("3 \xc2\xb5s", UNIT_TIME, 3e-6);
  ok("5 ns", UNIT_TIME, 5e-9);
  ok("300 K", UNIT_TEMPERATURE, 300.0);
  ok("2 kg", UNIT_MASS, 2.0);
  ok("1 rad", UNIT_ANGLE, 1.0);
  ok("10 Hz", UNIT_RATE, 10.0);
  ok("1 kg*m/s2/m2", UNIT_PRESSURE, 1.0);
  ok("6.2km/s", UNIT_VELOCITY, 6200.0);
  ok("  2 cm  ", UNIT_LENGTH, 0.02);
  ok("1 kg / m3", UNIT_DENSITY, 1.0);
}

static void test_bare_numbers(void)
{
  ok("6200", UNIT_VELOCITY, 6200.0);
  ok("-3.5e2", UNIT_PRESSURE, -350.0);
  ok("0.5", UNIT_ANGLE, 0.5);
  ok("1.4", UNIT_NONE, 1.4);
  bad("1.4 m", UNIT_NONE, "bare number", NULL);
}

static void test_wrong_dimension(void)
{
  double v;
  char msg[256];
  CHECK(units_parse("5 kg", UNIT_VELOCITY, &v, msg, sizeof msg) == -1 &&
            !strcmp(msg, "unit 'kg' is a mass, expected a velocity (e.g. m/s)"),
        "exact message: %s", msg);
  bad("5 kg", UNIT_VELOCITY, "mass", "velocity");
  bad("5 kg", UNIT_VELOCITY, "'kg'", "m/s");
  bad("1 m/s", UNIT_LENGTH, "velocity", "length");
  bad("1 J", UNIT_SPECIFIC_ENERGY, "an energy", "J/kg");
  bad("1 kg*m", UNIT_DENSITY, "dimension", "density");
  bad("1 m/m", UNIT_LENGTH, "dimensionless", NULL);
  bad("45 deg", UNIT_LENGTH, "angle", NULL);
}

static void test_junk(void)
{
  bad("6.2 km/ss", UNIT_VELOCITY, "unknown unit 'ss'", NULL);
  bad("abc", UNIT_LENGTH, "not a number", NULL);
  bad("1.0.0", UNIT_LENGTH, NULL, NULL);
  bad("nan", UNIT_LENGTH, NULL, NULL);
  bad("inf", UNIT_LENGTH, NULL, NULL);
  bad("-infinity m", UNIT_LENGTH, NULL, NULL);
  bad("0x10", UNIT_LENGTH, NULL, NULL);
  bad("1e999", UNIT_LENGTH, "range", NULL);
  /* a number that is not zero must not become zero: too small for a double ... */
  bad("1e-400 m", UNIT_LENGTH, "range", NULL);
  bad("-2.5e-999", UNIT_PRESSURE, "range", NULL);
  /* ... or after the unit's factor */
  bad("1e-320 pm", UNIT_LENGTH, "range", NULL);
  ok("0e-999 m", UNIT_LENGTH, 0.0);
  ok("4.9406564584124654e-324", UNIT_LENGTH, 4.9406564584124654e-324); /* subnormal: kept */
  double z = 1.0;
  CHECK(units_parse("-0 mm", UNIT_LENGTH, &z, NULL, 0) == 0 && z == 0.0, "-0 mm is zero");
  bad("", UNIT_LENGTH, "empty", NULL);
  bad("   ", UNIT_LENGTH, "empty", NULL);
  bad("5 m s", UNIT_LENGTH, NULL, NULL);
  bad("5 m/", UNIT_LENGTH, NULL, NULL);
  bad("5 m^", UNIT_LENGTH, "power", NULL);
  bad("5 ks2x", UNIT_LENGTH, NULL, NULL);
  bad("5 kdeg", UNIT_ANGLE, "unknown unit", NULL);
  bad("5 hr", UNIT_TIME, "unknown unit", NULL);
  bad("5 %", UNIT_NONE, NULL, NULL);
}

static void test_names(void)
{
  CHECK(!strcmp(units_dim_name(UNIT_VELOCITY), "velocity"), "velocity name");
  CHECK(!strcmp(units_si_symbol(UNIT_VELOCITY), "m/s"), "velocity symbol");
  CHECK(!strcmp(units_si_symbol(UNIT_DENSITY), "kg/m3"), "density symbol");
  CHECK(!strcmp(units_si_symbol(UNIT_SPECIFIC_HEAT), "J/kg/K"), "specific heat symbol");
  CHECK(!strcmp(units_si_symbol(UNIT_NONE), ""), "dimensionless symbol is empty");
  int all = 1;
  for (int d = 0; d < UNIT_DIM_COUNT; d++) {
    const char *n = units_dim_name((enum unit_dim)d), *s = units_si_symbol((enum unit_dim)d);
    if (!n || !*n || !s) all = 0;
    /* Each SI symbol parses back to its own dimension with factor 1. */
    if (d != UNIT_NONE) {
      char text[64];
      double v = 0.0;
      snprintf(text, sizeof text, "2 %s", s);
      if (units_parse(text, (enum unit_dim)d, &v, NULL, 0) || v != 2.0) all = 0;
    }
  }
  CHECK(all, "every dimension has a name and a symbol that parses back");
}

int main(void)
{
  test_header_examples();
  test_exact_values();
  test_atoms_and_prefixes();
  test_bare_numbers();
  test_wrong_dimension();
  test_junk();
  test_names();
  return test_finish();
}
