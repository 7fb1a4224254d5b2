/* units.c — parsing "number [unit]" into SI.
 *
 * A quantity is a C number (strtod syntax, finite, no hex) followed by an optional
 * unit expression: atoms joined by '/' or '*', read left to right; every atom after
 * a '/' is in the denominator ("J/kg/K" = J kg^-1 K^-1). An atom is a unit symbol
 * (m, g, s, K, Pa, bar, atm, J, N, W, Hz, rad, deg, cc, us, mks) with an optional SI
 * prefix (G M k c m u µ n p) and an optional integer power ("cm3", "m^3", "s^-1").
 * A leading "1" stands for a dimensionless numerator ("1/s").
 *
 * Whole symbols are matched before prefix + symbol, so "Pa" is pascal, "mks" is the
 * microsecond of the paper, "m" is metre and "mm" millimetre.
 *
 * Dimensions are tracked as integer exponents of (mass, length, time, temperature,
 * angle) and compared with the dimension the caller asks for. The conversion factor
 * is kept as (factor × 10^decade) so that decimal prefixes convert exactly where
 * the result is representable ("35 us" gives the double nearest 3.5e-5).
 */
#include "core/units.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define UNITS_PI 3.14159265358979323846

enum { DIM_M, DIM_L, DIM_T, DIM_K, DIM_A, NDIM };

/* A unit (or a product of units): value_SI = x * factor * 10^decade. */
struct unit_val {
  double factor; /* non-decimal part of the conversion to SI */
  int decade;    /* power of ten of the conversion to SI */
  int e[NDIM];   /* exponents of kg, m, s, K, rad */
};

struct unit_atom {
  const char *sym;
  double factor;
  int decade;
  int e[NDIM];    /* kg, m, s, K, rad */
  int prefixable; /* may take an SI prefix */
};

static const struct unit_atom atoms[] = {
    {"m", 1.0, 0, {0, 1, 0, 0, 0}, 1},
    {"g", 1.0, -3, {1, 0, 0, 0, 0}, 1},
    {"s", 1.0, 0, {0, 0, 1, 0, 0}, 1},
    {"K", 1.0, 0, {0, 0, 0, 1, 0}, 1},
    {"Pa", 1.0, 0, {1, -1, -2, 0, 0}, 1},
    {"bar", 1.0, 5, {1, -1, -2, 0, 0}, 1},
    {"atm", 101325.0, 0, {1, -1, -2, 0, 0}, 0},
    {"J", 1.0, 0, {1, 2, -2, 0, 0}, 1},
    {"N", 1.0, 0, {1, 1, -2, 0, 0}, 1},
    {"W", 1.0, 0, {1, 2, -3, 0, 0}, 1},
    {"Hz", 1.0, 0, {0, 0, -1, 0, 0}, 1},
    {"rad", 1.0, 0, {0, 0, 0, 0, 1}, 1},
    {"deg", UNITS_PI / 180.0, 0, {0, 0, 0, 0, 1}, 0},
    {"cc", 1.0, -6, {0, 3, 0, 0, 0}, 0},
    {"us", 1.0, -6, {0, 0, 1, 0, 0}, 0},
    {"mks", 1.0, -6, {0, 0, 1, 0, 0}, 0},
    {"min", 60.0, 0, {0, 0, 1, 0, 0}, 0},
    {"h", 3600.0, 0, {0, 0, 1, 0, 0}, 0},
};
#define NATOMS ((int)(sizeof atoms / sizeof atoms[0]))

struct unit_prefix {
  const char *sym; /* one ASCII letter, or µ in UTF-8 */
  int decade;
};

static const struct unit_prefix prefixes[] = {
    {"G", 9},  {"M", 6},         {"k", 3},  {"c", -2},  {"m", -3},
    {"u", -6}, {"\xc2\xb5", -6}, {"n", -9}, {"p", -12},
};
#define NPREFIXES ((int)(sizeof prefixes / sizeof prefixes[0]))

/* What each enum unit_dim means, in exponents of kg, m, s, K, rad. */
static const struct {
  const char *name, *article, *symbol;
  int e[NDIM];
} dims[UNIT_DIM_COUNT] = {
    [UNIT_NONE] = {"dimensionless number", "a", "", {0, 0, 0, 0, 0}},
    [UNIT_LENGTH] = {"length", "a", "m", {0, 1, 0, 0, 0}},
    [UNIT_TIME] = {"time", "a", "s", {0, 0, 1, 0, 0}},
    [UNIT_MASS] = {"mass", "a", "kg", {1, 0, 0, 0, 0}},
    [UNIT_VELOCITY] = {"velocity", "a", "m/s", {0, 1, -1, 0, 0}},
    [UNIT_ACCELERATION] = {"acceleration", "an", "m/s2", {0, 1, -2, 0, 0}},
    [UNIT_DENSITY] = {"density", "a", "kg/m3", {1, -3, 0, 0, 0}},
    [UNIT_PRESSURE] = {"pressure", "a", "Pa", {1, -1, -2, 0, 0}},
    [UNIT_ENERGY] = {"energy", "an", "J", {1, 2, -2, 0, 0}},
    [UNIT_SPECIFIC_ENERGY] = {"specific energy", "a", "J/kg", {0, 2, -2, 0, 0}},
    [UNIT_SPECIFIC_HEAT] = {"specific heat", "a", "J/kg/K", {0, 2, -2, -1, 0}},
    [UNIT_TEMPERATURE] = {"temperature", "a", "K", {0, 0, 0, 1, 0}},
    [UNIT_ANGLE] = {"angle", "an", "rad", {0, 0, 0, 0, 1}},
    [UNIT_RATE] = {"rate", "a", "1/s", {0, 0, -1, 0, 0}},
    [UNIT_FRACTURE_ENERGY] = {"fracture energy", "a", "J/m2", {1, 0, -2, 0, 0}},
};

const char *units_dim_name(enum unit_dim dim)
{
  if ((int)dim < 0 || dim >= UNIT_DIM_COUNT) return "unknown dimension";
  return dims[dim].name;
}

const char *units_si_symbol(enum unit_dim dim)
{
  if ((int)dim < 0 || dim >= UNIT_DIM_COUNT) return "?";
  return dims[dim].symbol;
}

static int fail(char *msg, size_t msglen, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

static int fail(char *msg, size_t msglen, const char *fmt, ...)
{
  if (msg && msglen) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, msglen, fmt, ap);
    va_end(ap);
  }
  return -1;
}

/* Finds an atom by whole name (len bytes of s); NULL if none. */
static const struct unit_atom *find_atom(const char *s, size_t len)
{
  for (int i = 0; i < NATOMS; i++)
    if (strlen(atoms[i].sym) == len && !memcmp(atoms[i].sym, s, len)) return &atoms[i];
  return NULL;
}

/* Resolves a unit name: whole symbol first, then prefix + prefixable symbol. */
static int lookup_name(const char *s, size_t len, struct unit_val *u)
{
  const struct unit_atom *a = find_atom(s, len);
  int decade = 0;
  if (!a) {
    for (int i = 0; i < NPREFIXES && !a; i++) {
      size_t pl = strlen(prefixes[i].sym);
      if (len <= pl || memcmp(prefixes[i].sym, s, pl)) continue;
      const struct unit_atom *b = find_atom(s + pl, len - pl);
      if (b && b->prefixable) {
        a = b;
        decade = prefixes[i].decade;
      }
    }
  }
  if (!a) return -1;
  u->factor = a->factor;
  u->decade = a->decade + decade;
  memcpy(u->e, a->e, sizeof u->e);
  return 0;
}

/* Reads an optional power after an atom: "3", "^3", "^-1", "-1". */
static int read_power(const char **pp, int *power)
{
  const char *p = *pp;
  int caret = (*p == '^');
  if (caret) p++;
  int sign = 1;
  if (*p == '-' || *p == '+') {
    sign = (*p == '-') ? -1 : 1;
    p++;
  } else if (!caret && !isdigit((unsigned char)*p)) {
    *power = 1;
    return 0;
  }
  if (!isdigit((unsigned char)*p)) return -1;
  int v = 0;
  while (isdigit((unsigned char)*p)) {
    v = 10 * v + (*p - '0');
    if (v > 99) return -1;
    p++;
  }
  *power = sign * v;
  *pp = p;
  return 0;
}

static int is_name_char(const char *p)
{
  return isalpha((unsigned char)*p) || (p[0] == '\xc2' && p[1] == '\xb5');
}

static void unit_mul(struct unit_val *acc, const struct unit_val *a, int power)
{
  acc->factor *= pow(a->factor, power);
  acc->decade += a->decade * power;
  for (int k = 0; k < NDIM; k++) acc->e[k] += a->e[k] * power;
}

/* Parses a unit expression (whole string) into u. */
static int parse_unit_expr(const char *s, struct unit_val *u, char *msg, size_t msglen)
{
  *u = (struct unit_val){.factor = 1.0};
  const char *p = s;
  int sign = 1; /* +1 numerator, -1 after a '/' */
  int first = 1;
  for (;;) {
    while (*p == ' ' || *p == '\t') p++;
    if (first && p[0] == '1' && !isdigit((unsigned char)p[1])) {
      p++; /* "1/s": dimensionless numerator */
    } else {
      const char *name = p;
      while (is_name_char(p)) p += (*p == '\xc2') ? 2 : 1;
      size_t len = (size_t)(p - name);
      if (!len)
        return fail(msg, msglen, "expected a unit name at '%s' in '%s'", *p ? p : "(end)", s);
      struct unit_val a;
      if (lookup_name(name, len, &a))
        return fail(msg, msglen, "unknown unit '%.*s' in '%s'", (int)len, name, s);
      int power;
      if (read_power(&p, &power))
        return fail(msg, msglen, "bad power after '%.*s' in '%s'", (int)len, name, s);
      unit_mul(u, &a, sign * power);
    }
    first = 0;
    while (*p == ' ' || *p == '\t') p++;
    if (!*p) return 0;
    if (*p == '/')
      sign = -1;
    else if (*p != '*')
      return fail(msg, msglen, "unexpected '%c' in unit '%s' (join units with '/' or '*')", *p, s);
    p++;
  }
}

/* Names the dimension of exponents e if it matches an enum value (UNIT_DIM_COUNT if not). */
static enum unit_dim classify(const int e[NDIM])
{
  for (int d = 1; d < UNIT_DIM_COUNT; d++)
    if (!memcmp(dims[d].e, e, sizeof dims[d].e)) return (enum unit_dim)d;
  return UNIT_DIM_COUNT;
}

/* Describes exponents e: "a mass", or "of dimension kg^1 m^-1" if unnamed. */
static void describe(const int e[NDIM], char *buf, size_t len)
{
  static const char *base[NDIM] = {"kg", "m", "s", "K", "rad"};
  enum unit_dim d = classify(e);
  if (d != UNIT_DIM_COUNT) {
    snprintf(buf, len, "%s %s", dims[d].article, dims[d].name);
    return;
  }
  int k = snprintf(buf, len, "of dimension");
  for (int i = 0; i < NDIM; i++)
    if (e[i] && k > 0 && (size_t)k < len)
      k += snprintf(buf + k, len - (size_t)k, " %s^%d", base[i], e[i]);
}

static int mismatch(const char *unit, const struct unit_val *u, enum unit_dim dim, char *msg,
                    size_t msglen)
{
  char what[128];
  int zero[NDIM] = {0};
  if (!memcmp(u->e, zero, sizeof zero))
    snprintf(what, sizeof what, "dimensionless");
  else
    describe(u->e, what, sizeof what);
  return fail(msg, msglen, "unit '%s' is %s, expected %s %s (e.g. %s)", unit, what,
              dims[dim].article, dims[dim].name, dims[dim].symbol);
}

/* Multiplies x by 10^decade, exactly rounded where the power of ten is exact. */
static double scale_decade(double x, int decade)
{
  static const double p10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                               1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                               1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  if (decade >= 0 && decade <= 22) return x * p10[decade];
  if (decade < 0 && decade >= -22) return x / p10[-decade];
  return x * pow(10.0, decade);
}

/* Reads the number at the start of text; *end after it. */
static int parse_number(const char *text, double *x, const char **end, char *msg, size_t msglen)
{
  const char *p = text;
  while (isspace((unsigned char)*p)) p++;
  if (!*p) return fail(msg, msglen, "empty value (expected a number)");
  char *q;
  errno = 0;
  double v = strtod(p, &q);
  if (q == p) return fail(msg, msglen, "'%s' is not a number", text);
  for (const char *c = p; c < q; c++) /* no hex floats, "inf" or "nan" */
    if (!isdigit((unsigned char)*c) && !strchr(".+-eE", *c))
      return fail(msg, msglen, "'%s' is not a finite decimal number", text);
  /* ERANGE: too large, or too small (a subnormal is kept; a number rounded to 0 is not) */
  if (errno == ERANGE && (fabs(v) > 1.0 || v == 0.0))
    return fail(msg, msglen, "'%s' is out of range", text);
  if (!isfinite(v)) return fail(msg, msglen, "'%s' is not a finite number", text);
  *x = v;
  *end = q;
  return 0;
}

int units_parse(const char *text, enum unit_dim dim, double *si, char *msg, size_t msglen)
{
  if (msg && msglen) msg[0] = '\0';
  if (!text) return fail(msg, msglen, "no value");
  if ((int)dim < 0 || dim >= UNIT_DIM_COUNT) return fail(msg, msglen, "bad dimension %d", (int)dim);
  double x = 0.0;
  const char *p = text;
  if (parse_number(text, &x, &p, msg, msglen)) return -1;
  while (isspace((unsigned char)*p)) p++;
  if (!*p) {
    *si = x; /* bare numbers are SI (angles in rad) */
    return 0;
  }
  char unit[256] = "";
  size_t n = strlen(p);
  while (n && isspace((unsigned char)p[n - 1])) n--;
  if (n >= sizeof unit) return fail(msg, msglen, "unit too long in '%s'", text);
  memcpy(unit, p, n);
  unit[n] = '\0';
  if (dim == UNIT_NONE)
    return fail(msg, msglen, "'%s': expected a bare number without a unit", text);
  struct unit_val u;
  if (parse_unit_expr(unit, &u, msg, msglen)) return -1;
  if (memcmp(u.e, dims[dim].e, sizeof u.e)) return mismatch(unit, &u, dim, msg, msglen);
  double v = scale_decade(x * u.factor, u.decade);
  if (!isfinite(v) || (v == 0.0 && x != 0.0))
    return fail(msg, msglen, "'%s' is out of range in SI", text);
  *si = v;
  return 0;
}
