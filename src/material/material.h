/* material.h — a material: equation of state, strength and fracture parameters.
 *
 * Materials are named in case files or taken from the library data/materials.yaml,
 * and chosen at run time; every physics function takes a `const struct material *`.
 * The EOS is named ("ideal-gas", "mie-gruneisen", "tillotson", "table"), never a
 * number. A material with no strength (G = 0 or Y = 0) is a fluid.
 */
#ifndef HV_MATERIAL_H
#define HV_MATERIAL_H

#include "config/config.h"

enum eos_kind { EOS_IDEAL_GAS = 0, EOS_MIE_GRUNEISEN, EOS_TILLOTSON, EOS_TABLE, EOS_KIND_COUNT };

struct eos_ideal_gas {
  double gamma;        /* [-] adiabatic exponent, > 1 */
};

/* Mie–Grüneisen with the Murnaghan cold curve (the paper's §2.1). */
struct eos_mie_gruneisen {
  double rho0;         /* [kg/m3] */
  double c0;           /* [m/s] bulk sound speed */
  double n;            /* [-] Murnaghan exponent, > 1 */
  double Gamma;        /* [-] Grüneisen coefficient */
  double cs_floor;     /* [m/s] smallest sound speed returned */
};

/* Tillotson (1962); notation of Melosh (1989), Impact Cratering, appendix II. */
struct eos_tillotson {
  double rho0;         /* [kg/m3] */
  double a, b;         /* [-] */
  double A, B;         /* [Pa] */
  double E0;           /* [J/kg] */
  double alpha, beta;  /* [-] */
  double E_iv, E_cv;   /* [J/kg] incipient and complete vaporisation, E_cv > E_iv */
  double rho_iv;       /* [kg/m3] below this density (and E < E_cv) the cold expanded
                          state is cut off (p = 0 in tension); default 0.8 rho0? see eos */
  double cs_floor;     /* [m/s] */
};

/* p(ρ, e) and c(ρ, e) on a rectangular grid, bilinear; see eos/table.c for the file. */
struct eos_table {
  int nrho, ne;
  double *rho;         /* [kg/m3] nrho, increasing */
  double *e;           /* [J/kg] ne, increasing */
  double *p;           /* [Pa] nrho*ne, p[i*ne + j] at (rho[i], e[j]) */
  double *cs;          /* [m/s] nrho*ne */
  char path[512];      /* the file, for messages */
};

enum yield_kind { YIELD_CONSTANT = 0, YIELD_LINEAR, YIELD_JOHNSON_COOK, YIELD_KIND_COUNT };

struct strength_params {
  int enabled;         /* 0: fluid (no deviatoric stress) */
  double G;            /* [Pa] shear modulus (given, or from Poisson's ratio) */
  double nu;           /* [-] Poisson's ratio if given, else 0 */
  enum yield_kind yield;
  double Y0;           /* [Pa] yield stress (constant, or initial for linear hardening) */
  double H;            /* [Pa] linear hardening modulus: Y = Y0 + H eps_p */
  /* Johnson–Cook: Y = (A + B eps_p^N)(1 + C ln(rate/rate0))(1 − T*^M) */
  double jc_A, jc_B, jc_N, jc_C, jc_M;   /* [Pa], [Pa], [-], [-], [-] */
  double jc_rate0;     /* [1/s] */
  double T_ref, T_melt;/* [K] */
  double cv;           /* [J/kg/K] heat capacity, T = T_ref + e/cv */
};

enum fracture_kind { FRACTURE_NONE = 0, FRACTURE_TRESCA, FRACTURE_CUMULATIVE, FRACTURE_KIND_COUNT };

struct fracture_params {
  enum fracture_kind kind;
  double sigma_c;      /* [Pa] < 0: ultimate tensile stress (tension negative, as the paper's tables) */
  /* cumulative: damage D grows with plastic strain, dD = d(eps_p)/eps_f, and with time
     under tension beyond |sigma_c|, dD = dt/tau; split at D = 1 */
  double eps_f;        /* [-] plastic strain to failure (0: not used) */
  double tau;          /* [s] time under tension to failure (0: not used) */
};

struct material {
  char name[64];
  char source[256];    /* where the values come from (library entries) */
  enum eos_kind eos;
  double rho0;         /* [kg/m3] reference density (0 if none, e.g. a gas) */
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

/* Reads the material defined at `path` (a mapping, e.g. "materials.steel") from the
 * case, after grafting the library entry it names (`library: NAME`) under it. */
int material_read(struct cfg *c, const char *path, const char *name, struct material *m,
                  struct hv_error *err);
void material_free(struct material *m);
/* Names of the EOS kinds, in enum order (NULL-terminated). */
extern const char *const eos_kind_names[];

#endif
