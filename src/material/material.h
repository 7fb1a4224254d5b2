/* material.h — a material: equation of state, strength and fracture parameters, and the
 * table of models that gives each EOS and yield model its operations.
 *
 * Materials are named in case files or taken from the library data/materials.yaml,
 * and chosen at run time; every physics function takes a `const struct material *`.
 * The EOS is named ("ideal-gas", "mie-gruneisen", "tillotson", "table"), never a
 * number. A material with no strength (G = 0 or Y = 0) is a fluid.
 *
 * Each model lives in one file (eos/<name>.c, strength/<name>.c) that reads its keys,
 * lists its parameters and holds its physics; material.c maps a name to the model's
 * row of operations (struct eos_model, struct yield_model). The parameter structs are
 * declared here only because struct material holds them by value in a union: no
 * allocation and no indirection for the step's loops. This header does not include
 * the config layer; reading a material from a case file is material/material_read.h.
 */
#ifndef HV_MATERIAL_H
#define HV_MATERIAL_H

#include <stdio.h>

struct cfg;
struct hv_error;
struct eos_state;
struct material;

enum eos_kind { EOS_IDEAL_GAS = 0, EOS_MIE_GRUNEISEN, EOS_TILLOTSON, EOS_TABLE, EOS_KIND_COUNT };

struct eos_ideal_gas {
  double gamma; /* [-] adiabatic exponent, > 1 */
};

/* Mie–Grüneisen with the Murnaghan cold curve (the paper's §2.1). */
struct eos_mie_gruneisen {
  double rho0;     /* [kg/m3] */
  double c0;       /* [m/s] bulk sound speed */
  double n;        /* [-] Murnaghan exponent, >= 1 (1: the limit, E_c with ln) */
  double Gamma;    /* [-] Grüneisen coefficient */
  double cs_floor; /* [m/s] smallest sound speed returned; default 0.1 c0 */
};

/* Tillotson (1962); notation of Melosh (1989), Impact Cratering, appendix II. */
struct eos_tillotson {
  double rho0;        /* [kg/m3] */
  double a, b;        /* [-] */
  double A, B;        /* [Pa] */
  double E0;          /* [J/kg] */
  double alpha, beta; /* [-] */
  double E_iv, E_cv;  /* [J/kg] incipient and complete vaporisation, E_cv > E_iv */
  double rho_iv;      /* [kg/m3] below this density the compressed-branch pressure used
                          for cold and hybrid expanded states carries no tension
                          (p_c <- max(p_c, 0)); 0 (default): no cut; see eos/tillotson.c */
  double cs_floor;    /* [m/s] smallest sound speed returned; default 0.01 sqrt(A/rho0) */
};

/* p(ρ, e) and c(ρ, e) on a rectangular grid, bilinear; see eos/table.c for the file. */
struct eos_table {
  int nrho, ne;
  double *rho;         /* [kg/m3] nrho, increasing */
  double *e;           /* [J/kg] ne, increasing */
  double *p;           /* [Pa] nrho*ne, p[i*ne + j] at (rho[i], e[j]) */
  double *cs;          /* [m/s] nrho*ne, or NULL: c from the derivatives of p */
  double cs_floor;     /* [m/s] smallest sound speed returned; default 0.01 cs_max */
  double cs_max;       /* [m/s] largest sound speed in the table (set when loaded) */
  char path[512];      /* the file, for messages */
  unsigned long crc32; /* CRC-32 (zlib's, as checkpoints) of the file's bytes as read */
};

enum yield_kind { YIELD_CONSTANT = 0, YIELD_LINEAR, YIELD_JOHNSON_COOK, YIELD_KIND_COUNT };

struct strength_params {
  int enabled; /* 0: fluid (no deviatoric stress) */
  double G;    /* [Pa] shear modulus (given, or from Poisson's ratio) */
  double nu;   /* [-] Poisson's ratio if given, else 0 */
  enum yield_kind yield;
  double Y0; /* [Pa] yield stress (constant, or initial for linear hardening) */
  double H;  /* [Pa] linear hardening modulus: Y = Y0 + H eps_p */
  /* Johnson–Cook: Y = (A + B eps_p^N)(1 + C ln(rate/rate0))(1 − T*^M) */
  double jc_A, jc_B, jc_N, jc_C, jc_M; /* [Pa], [Pa], [-], [-], [-] */
  double jc_rate0;                     /* [1/s] */
  double T_ref, T_melt;                /* [K] */
  double cv;                           /* [J/kg/K] heat capacity, T = T_ref + e/cv */
};

enum fracture_kind { FRACTURE_NONE = 0, FRACTURE_TRESCA, FRACTURE_CUMULATIVE, FRACTURE_KIND_COUNT };
/* What a split particle (D = 1) carries: FLUID, no deviatoric stress and no tension
   (the paper's rule as hvsph reads it); NO_TENSION, its stress as if intact with the
   principal tensions removed: cracks open under tension and close under compression,
   where the material keeps its yield stress; CRACK, one crack across the largest
   principal tension, which opens (a crack strain, not the material's) so that its plane
   carries no traction, while the material keeps its stress within the plane up to
   |sigma_c|, then fluid (damage 2; fracture.h). */
enum split_kind { SPLIT_FLUID = 0, SPLIT_NO_TENSION, SPLIT_CRACK, SPLIT_KIND_COUNT };

struct fracture_params {
  enum fracture_kind kind;
  double sigma_c; /* [Pa] < 0: ultimate tensile stress (tension negative, as the paper's tables) */
  /* cumulative: damage D grows with plastic strain, dD = d(eps_p)/eps_f, and with time
     under tension beyond |sigma_c|, dD = dt/tau; split at D = 1 */
  double eps_f; /* [-] plastic strain to failure (0: not used) */
  double tau;   /* [s] time under tension to failure (0: not used) */
  /* split particles (D = 1): 0 (the paper's rule) — no deviatoric stress; > 0 — the
     friction coefficient μ of the broken material, whose yield stress is then
     min(Y, μ max(p, 0)) (a cohesionless Drucker–Prager/Coulomb limit) */
  double friction; /* [-] */
  enum split_kind split;
  /* split: crack — strain to failure of the cracked state (fracture.crack_eps_f): a
     cracked particle splits again (fluid) once its equivalent plastic strain reaches
     eps_f = d1 + d2 exp(d3 sigma*), sigma* = sigma_m/sigma_eq its stress triaxiality
     (the Johnson–Cook form without its rate and temperature factors); off when
     crack_eps_f_on is 0 */
  int crack_eps_f_on;
  double crack_d[3]; /* d1, d2 [-], d3 [-] */
  /* fracture.energy (model tresca, split fluid): the fracture energy G_f [J/m2] of a
     cohesive opening before the split (fracture.h); 0: split at once (the paper's rule) */
  double energy;
};

struct material {
  char name[64];
  char source[256]; /* where the values come from (library entries) */
  char library[64]; /* the library entry it was read from ("" if none) */
  enum eos_kind eos;
  double rho0; /* [kg/m3] reference density (0 if none, e.g. a gas) */
  double K0;   /* [Pa] reference bulk modulus: rho0 c0^2 (Mie–Grüneisen), A
                          (Tillotson), 0 if none (gas, table); used for G from Poisson's ratio */
  union {
    struct eos_ideal_gas gas;
    struct eos_mie_gruneisen mg;
    struct eos_tillotson til;
    struct eos_table tab;
  } eosp;
  struct strength_params str;
  struct fracture_params frac;
};

#define HV_MAX_MATERIALS 32

/* The densities condensed materials span [kg/m3]: a bare number outside is a wrong unit
 * (cfg_check_typical; a material's rho0 and a body's density, docs/units.md). */
#define HV_RHO_CONDENSED_LO   50.0
#define HV_RHO_CONDENSED_HI   1e5
#define HV_RHO_CONDENSED_WHAT "densities of condensed materials"

/* Releases what material_read allocated (the arrays of a table EOS). */
void material_free(struct material *m);

/* ---- the table of models (material.c) ---- */

/* A key whose bare number far outside what real materials span is refused as a wrong
 * unit (a density in g/cm3; material.c, check_units). */
struct material_typical {
  const char *key;  /* under the material, e.g. "c0" */
  int dim;          /* enum unit_dim (core/units.h) */
  double lo, hi;    /* [SI] the span of real condensed materials */
  const char *what; /* "bulk sound speeds of condensed materials" */
};

/* An EOS model: its case-file name and its operations on a material whose `eos` is
 * its kind. read: reads the keys under `path` into m->eosp (and sets m->rho0, and m->K0
 * where the EOS has a bulk modulus at rest), through material_read.h's helpers; 0 or -1
 * with err set. print: every parameter with its unit (`hvsph materials NAME`).
 * evaluate, energy_from_pressure: the physics, pure (eos.h). typical: its keys' spans,
 * ended by {NULL}; NULL marks the EOS of a gas, whose keys are not checked. Optional
 * (NULL): release, what read allocated; describe_name and describe_outside, text
 * appended to the material's name in eos_describe's messages (" 'file'") and to its
 * "outside the table" message (" (rho 1 to 2 kg/m3, ...)"). */
struct eos_model {
  const char *name;
  int (*read)(struct cfg *c, const char *path, struct material *m, struct hv_error *err);
  void (*print)(FILE *f, const struct material *m);
  int (*evaluate)(const struct material *m, double rho, double e, struct eos_state *out);
  int (*energy_from_pressure)(const struct material *m, double rho, double p, double *e);
  const struct material_typical *typical;
  void (*release)(struct material *m);
  void (*describe_name)(const struct material *m, char *buf, size_t len);
  void (*describe_outside)(const struct material *m, char *buf, size_t len);
};

/* A yield model of the von Mises strength (strength.h): the yield stress Y(eps_p, rate,
 * e). read: its keys under `sp` (the material's strength mapping) into m->str, setting
 * Y0 to the initial yield stress; the shear modulus is read before it (material.c).
 * yield_max: a yield stress of the parameters that is 0 only when they give none: the
 * material is a solid when G > 0 and yield_max > 0, else a fluid. */
struct yield_model {
  const char *name;
  int (*read)(struct cfg *c, const char *sp, struct material *m, struct hv_error *err);
  void (*print)(FILE *f, const struct strength_params *s);
  double (*yield)(const struct strength_params *s, double eps_p, double rate, double e);
  double (*yield_max)(const struct strength_params *s);
};

/* Indexed by enum eos_kind and enum yield_kind: eos_models[m->eos]. */
extern const struct eos_model *const eos_models[EOS_KIND_COUNT];
extern const struct yield_model *const yield_models[YIELD_KIND_COUNT];

#endif
