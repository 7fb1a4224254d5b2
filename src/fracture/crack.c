/* crack.c — split along a crack (fracture.split: crack; a smeared crack). A particle
 * that splits cracks across the plane normal to its largest principal tension (the unit
 * normal n, stored per particle and turned with the material's spin, ṅ = Ωn: plane.c).
 * The crack opens by a strain ε_c >= 0 of its own (a distension, as porosity: the
 * material's density is ρ_m = ρ e^{ε_c}, and the EOS takes ρ_m), so that the open plane
 * carries no traction: at the end of each step the normal stress σ_nn = nᵀσn is returned
 * to 0 by Δε_c = σ_nn/M (M = K + 4G/3, the uniaxial-strain modulus; the material's stress
 * changes by −Δε_c (K I + 2G dev(nnᵀ))), bounded by ε_c >= 0 (a closed crack carries
 * compression), and while it is open the shear traction on the plane is released. Within
 * its plane the material keeps its stress, tension included, and its strength: a spalled
 * plate keeps its membrane tension. When the largest principal stress within the plane
 * exceeds |σ_c| the particle splits a second time and is split fluid; with
 * fracture.crack_eps_f it does so as well once its equivalent plastic strain ε_p reaches
 * ε_f = d1 + d2 exp(d3 σ*), σ* = σ_m/σ_eq the stress triaxiality (the Johnson–Cook
 * failure strain without its rate and temperature factors): a cracked membrane, in plane
 * stress below |σ_c|, tears by stretching. States: FRACTURE_SPLIT (cracked, D = 1),
 * FRACTURE_SPLIT_AGAIN (fluid, D = 2). */
#include "fracture/rules.h"

#include <math.h>

#include "fracture/read.h"
#include "particles/particles.h"
#include "strength/sym3.h"

double fracture_crack_eps_f(const struct fracture_params *fp, double p, const double S[6])
{
  if (!fp->crack_eps_f_on) return HUGE_VAL;
  /* σ* = σ_m/σ_eq, σ_m = −p, σ_eq = √(3J₂); ±1.5 without deviator */
  const double seq = sqrt(3.0 * sym3_j2(S));
  double tri = seq > 0.0 ? -p / seq : (p < 0.0 ? 1.5 : p > 0.0 ? -1.5 : 0.0);
  if (!(tri <= 1.5)) tri = 1.5;
  if (!(tri >= -1.5)) tri = -1.5;
  return fp->crack_d[0] + fp->crack_d[1] * exp(fp->crack_d[2] * tri);
}

int fracture_crack_return(const struct fracture_params *fp, int split_now, double p, double K,
                          double G, double eps_p, double S[6], double n[3], double *eps_c,
                          double *dp)
{
  *dp = 0.0;
  if (split_now) { /* the crack */
    fracture_crack_normal(p, S, n);
    *eps_c = 0.0;
  }
  /* the crack strain that returns σ_nn to 0 (not below ε_c = 0) */
  const double snn = fracture_normal_stress(p, S, n);
  const double M = K + 4.0 / 3.0 * G;
  double de = M > 0.0 ? snn / M : 0.0;
  if (*eps_c + de < 0.0) de = -*eps_c;
  if (de != 0.0) {
    *eps_c += de;
    fracture_open_by(S, n, G, de);
    *dp = K * de;
  }
  if (*eps_c > 0.0) { /* open: no shear traction on the plane, t_s = Sn − (nᵀSn) n */
    double t[3];
    sym3_apply(S, n, t);
    const double tn = t[0] * n[0] + t[1] * n[1] + t[2] * n[2];
    const double ts[3] = {t[0] - tn * n[0], t[1] - tn * n[1], t[2] - tn * n[2]};
    S[T_XX] -= 2.0 * ts[0] * n[0];
    S[T_YY] -= 2.0 * ts[1] * n[1];
    S[T_ZZ] -= 2.0 * ts[2] * n[2];
    S[T_XY] -= ts[0] * n[1] + n[0] * ts[1];
    S[T_YZ] -= ts[1] * n[2] + n[1] * ts[2];
    S[T_XZ] -= ts[0] * n[2] + n[0] * ts[2];
  }
  if ((fp->sigma_c < 0.0 && fracture_max_principal(p + *dp, S) > -fp->sigma_c) ||
      (fp->crack_eps_f_on && eps_p >= fracture_crack_eps_f(fp, p + *dp, S))) {
    for (int k = 0; k < 6; k++) S[k] = 0.0; /* split again: fluid */
    n[0] = n[1] = n[2] = 0.0;
    *eps_c = 0.0;
    return FRACTURE_SPLIT_AGAIN;
  }
  return FRACTURE_SPLIT;
}

int fracture_crack_end(struct particles *p, size_t i, const struct material *m, int split_now)
{
  if (p->fstate[i] != FRACTURE_SPLIT) return 0; /* split again: fluid, S = 0 for good */
  /* cracked now, the crack opened or closed to carry no normal stress, or split again;
     the pressure then moves, so the caller evaluates the EOS again */
  double S[6], n[3] = {p->crack[0][i], p->crack[1][i], p->crack[2][i]}, ec = p->eps_c[i], dp, K, G;
  for (int k = 0; k < 6; k++) S[k] = p->S[k][i];
  fracture_opening_moduli(p, i, m, &K, &G);
  const int st =
      fracture_crack_return(&m->frac, split_now, p->p[i], K, G, p->eps_p[i], S, n, &ec, &dp);
  p->fstate[i] = st;
  if (st == FRACTURE_SPLIT_AGAIN) p->damage[i] = 2.0;
  for (int k = 0; k < 3; k++) p->crack[k][i] = n[k];
  p->eps_c[i] = ec;
  for (int k = 0; k < 6; k++) p->S[k][i] = S[k];
  return dp != 0.0 || (st == FRACTURE_SPLIT_AGAIN && p->p[i] < 0.0);
}

/* ---- reading (fracture_read.c) ---------------------------------------------------- */

/* fracture.crack_eps_f: a number (a constant strain to failure of the cracked state) or
 * {d1, d2, d3} (ε_f = d1 + d2 exp(d3 σ*), the Johnson–Cook form). */
int fracture_read_crack_eps_f(struct cfg *c, const char *fp, struct fracture_params *f,
                              struct hv_error *err)
{
  char k[320];
  material_key(k, sizeof k, fp, "crack_eps_f");
  if (!cfg_has(c, k)) return 0;
  const double zero = 0.0;
  if (!cfg_is_map(c, k)) {
    if (cfg_get_quantity(c, k, UNIT_NONE, NULL, 0.0, HUGE_VAL, &f->crack_d[0], err)) return -1;
    if (!(f->crack_d[0] > 0.0))
      return material_key_error(c, k, err,
                                "the strain to failure must be > 0 (leave "
                                "crack_eps_f out for none)");
  } else {
    static const char *const dn[3] = {"d1", "d2", "d3"};
    for (int j = 0; j < 3; j++) {
      char kd[340];
      if (cfg_get_quantity(c, material_key(kd, sizeof kd, k, dn[j]), UNIT_NONE, j ? &zero : NULL,
                           -HUGE_VAL, HUGE_VAL, &f->crack_d[j], err))
        return -1;
    }
    /* positive over the triaxialities it is evaluated at, σ* in [−1.5, 1.5] */
    for (int e = -1; e <= 1; e += 2) {
      const double ef = f->crack_d[0] + f->crack_d[1] * exp(f->crack_d[2] * 1.5 * e);
      if (!(ef > 0.0))
        return material_key_error(c, k, err,
                                  "d1 + d2 exp(d3 sigma*) = %.6g at sigma* = %g: "
                                  "the strain to failure must be > 0 for sigma* in [-1.5, 1.5]",
                                  ef, 1.5 * e);
    }
  }
  f->crack_eps_f_on = 1;
  return 0;
}
