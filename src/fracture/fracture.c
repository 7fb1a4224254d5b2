/* fracture.c — see fracture.h. */
#include "fracture/fracture.h"

#include <math.h>

#include "particles/particles.h"
#include "strength/sym3.h"

double fracture_max_principal(double p, const double S[6])
{
  double sig[6] = {S[0] - p, S[1] - p, S[2] - p, S[3], S[4], S[5]}, lam[3];
  sym3_eigen(sig, lam, NULL);
  return lam[0];
}

int fracture_cracked(const struct fracture_params *fp, double damage)
{
  return fp->split == SPLIT_CRACK && damage >= 1.0 && damage < 2.0;
}

int fracture_keeps_stress(const struct fracture_params *fp, double damage)
{
  return damage < 1.0 || fp->friction > 0.0 || fp->split == SPLIT_NO_TENSION ||
         fracture_cracked(fp, damage);
}

int fracture_no_tension(const struct fracture_params *fp, double damage)
{
  return damage >= 1.0 && fp->split == SPLIT_NO_TENSION;
}

double fracture_yield(const struct fracture_params *fp, double damage, double Y, double p)
{
  if (damage < 1.0 || fp->split == SPLIT_NO_TENSION || fracture_cracked(fp, damage)) return Y;
  const double Yd = fp->friction * (p > 0.0 ? p : 0.0);
  return Yd < Y ? Yd : Y;
}

int fracture_project(double p, double T[6])
{
  double sig[6] = {T[0] - p, T[1] - p, T[2] - p, T[3], T[4], T[5]};
  if (!(sym3_max_bound(sig) > 0.0)) return 0;
  double lam[3], Q[9];
  sym3_eigen(sig, lam, Q);
  if (!(lam[0] > 0.0)) return 0;
  for (int k = 0; k < 3; k++) lam[k] = lam[k] > 0.0 ? 0.0 : lam[k];
  sym3_from_eigen(Q, lam, sig);
  for (int k = 0; k < 3; k++) T[k] = sig[k] + p;
  for (int k = 3; k < 6; k++) T[k] = sig[k];
  return 1;
}

double fracture_effective(double p, const double S[6], double Se[6])
{
  for (int k = 0; k < 6; k++) Se[k] = S[k];
  if (!fracture_project(p, Se)) return p;
  const double m = (Se[0] + Se[1] + Se[2]) / 3.0;   /* σ' = −(p − m) I + dev(Se) */
  for (int k = 0; k < 3; k++) Se[k] -= m;
  return p - m;
}

double fracture_plastic(const struct fracture_params *fp, double damage, double deps_p)
{
  if (fp->kind != FRACTURE_CUMULATIVE || fp->eps_f <= 0 || damage >= 1.0) return damage;
  damage += deps_p / fp->eps_f;
  return damage >= 1.0 ? 1.0 : damage;
}

double fracture_tension(const struct fracture_params *fp, double damage, double p,
                        const double S[6], double dt)
{
  if (damage >= 1.0 || fp->kind == FRACTURE_NONE) return damage;
  const double limit = -fp->sigma_c;   /* σ_c < 0: tension */
  const double sig[6] = {S[0] - p, S[1] - p, S[2] - p, S[3], S[4], S[5]};
  const int over = limit > 0 && sym3_max_bound(sig) > limit && fracture_max_principal(p, S) > limit;
  if (fp->kind == FRACTURE_TRESCA) return over ? 1.0 : damage;
  if (over) damage += fp->tau > 0 ? dt / fp->tau : 1.0;
  return damage >= 1.0 ? 1.0 : damage;
}

void fracture_crack_normal(double p, const double S[6], double n[3])
{
  double sig[6] = {S[0] - p, S[1] - p, S[2] - p, S[3], S[4], S[5]}, lam[3], Q[9];
  sym3_eigen(sig, lam, Q);
  /* the eigenvector of lam[0], the largest: Q's first column (sym3.h) */
  n[0] = Q[0];
  n[1] = Q[3];
  n[2] = Q[6];
  const double r = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (r > 0.0 && isfinite(r)) {
    for (int k = 0; k < 3; k++) n[k] /= r;
  } else {
    n[0] = 1.0;
    n[1] = n[2] = 0.0;
  }
}

void fracture_crack_rotate(double n[3], const double L[9], double dt)
{
  double m[3];
  for (int a = 0; a < 3; a++) {
    double w = 0.0;   /* (Ω n)_a = Σ_b ½(L_ab − L_ba) n_b */
    for (int b = 0; b < 3; b++) w += 0.5 * (L[3 * a + b] - L[3 * b + a]) * n[b];
    m[a] = n[a] + dt * w;
  }
  const double r = sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
  if (!(r > 0.0) || !isfinite(r)) return;
  for (int a = 0; a < 3; a++) n[a] = m[a] / r;
}

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

/* σ_nn = nᵀσn of σ = −pI + S: the normal stress on the plane of normal n */
static double normal_stress(double p, const double S[6], const double n[3])
{
  double Sn[3];
  sym3_apply(S, n, Sn);
  return -p + Sn[0] * n[0] + Sn[1] * n[1] + Sn[2] * n[2];
}

/* The deviator's change when the plane of normal n opens by a strain dw (the pressure's,
 * about K dw, follows from the EOS): S −= 2G dw dev(nnᵀ) */
static void open_by(double S[6], const double n[3], double G, double dw)
{
  const double nn[6] = {n[0] * n[0], n[1] * n[1], n[2] * n[2], n[0] * n[1], n[1] * n[2], n[0] * n[2]};
  for (int k = 0; k < 6; k++) S[k] -= 2.0 * G * dw * (nn[k] - (k < 3 ? 1.0 / 3.0 : 0.0));
}

double fracture_crack_return(const struct fracture_params *fp, double d0, double d, double p,
                             double K, double G, double eps_p, double S[6], double n[3],
                             double *eps_c, double *dp)
{
  *dp = 0.0;
  if (d < 1.0 || d >= 2.0) return d;
  if (d0 < 1.0) {   /* split in this step: the crack */
    fracture_crack_normal(p, S, n);
    *eps_c = 0.0;
  }
  /* the crack strain that returns σ_nn to 0 (not below ε_c = 0) */
  const double snn = normal_stress(p, S, n);
  const double M = K + 4.0 / 3.0 * G;
  double de = M > 0.0 ? snn / M : 0.0;
  if (*eps_c + de < 0.0) de = -*eps_c;
  if (de != 0.0) {
    *eps_c += de;
    open_by(S, n, G, de);
    *dp = K * de;
  }
  if (*eps_c > 0.0) {   /* open: no shear traction on the plane, t_s = Sn − (nᵀSn) n */
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
    for (int k = 0; k < 6; k++) S[k] = 0.0;   /* split again: fluid */
    n[0] = n[1] = n[2] = 0.0;
    *eps_c = 0.0;
    return 2.0;
  }
  return 1.0;
}

int fracture_opening(const struct fracture_params *fp, double damage)
{
  return fracture_cracked(fp, damage) || (fp->energy > 0.0 && damage > 0.0 && damage < 1.0);
}

double fracture_open_strain(const struct fracture_params *fp, double l)
{
  return 2.0 * fp->energy / (-fp->sigma_c * l);
}

double fracture_cohesive_return(const struct fracture_params *fp, double d0, double d, double p,
                                double K, double G, double l, double S[6], double n[3],
                                double *w, double *dp)
{
  *dp = 0.0;
  if (!(d0 > 0.0)) {
    if (d < 1.0) return d0;   /* intact, and stays so */
    fracture_crack_normal(p, S, n);   /* starts to open */
    *w = 0.0;
    d0 = 1e-12;
  }
  const double sc = -fp->sigma_c, wu = fracture_open_strain(fp, l);
  double wmax = d0 * wu;
  const double snn = normal_stress(p, S, n);
  const double M = K + 4.0 / 3.0 * G, T = sc * (1.0 - wmax / wu), soft = sc / wu;
  double dw = 0.0, s = snn;
  if (s > 0.0 && *w < wmax) {   /* a part closed before reopens without traction */
    dw = s / M < wmax - *w ? s / M : wmax - *w;
    s -= M * dw;
  }
  if (s > T) {   /* opens on along the softening line */
    double more = M > soft ? (s - T) / (M - soft) : wu - wmax;
    if (wmax + more > wu || !isfinite(more)) more = wu - wmax;
    dw += more;
    wmax += more;
  } else if (s < 0.0 && *w > 0.0) {   /* closes under compression, without traction */
    dw = s / M < -*w ? -*w : s / M;
  }
  if (dw != 0.0) {
    *w += dw;
    open_by(S, n, G, dw);
    *dp = K * dw;
  }
  if (!(wmax < wu)) {   /* opened through: split (the paper's rule) */
    n[0] = n[1] = n[2] = 0.0;
    *w = 0.0;
    return 1.0;
  }
  return wmax / wu > 1e-12 ? wmax / wu : 1e-12;
}
