/* cohesive.c — a cohesive opening before the split (fracture.energy = G_f > 0, model
 * tresca, split fluid; a crack band, Bažant & Oh 1983, Mater. Struct. 16:155). Where the
 * paper's rule would split the particle, it starts to open across the plane normal to
 * its largest principal tension (n, as split: crack; plane.c) by a strain w >= 0 of its
 * own (the EOS takes ρ e^{w}); the traction the opening plane carries falls linearly
 * from |σ_c| to 0 as the largest opening w_max reached grows to w_u = 2 G_f/(|σ_c| l),
 * l = (m/ρ₀)^{1/3} the particle's spacing, so that a particle opened through has taken
 * G_f per unit area of its cross-section, ½|σ_c| w_u l = G_f, whatever its size. State
 * FRACTURE_OPENING with D = max(w_max/w_u, 10⁻¹²) while it opens (it keeps its
 * deviatoric stress and yield stress); at w_u it splits (FRACTURE_SPLIT, D = 1, the
 * paper's rule). G_f → 0 is the paper's rule. The opening runs only while the tension
 * is there: a short tensile pulse leaves it opening, D < 1. */
#include "fracture/rules.h"

#include <math.h>

#include "fracture/read.h"
#include "particles/particles.h"

double fracture_open_strain(const struct fracture_params *fp, double l)
{
  return 2.0 * fp->energy / (-fp->sigma_c * l);
}

double fracture_cohesive_return(const struct fracture_params *fp, double d0, double d, double p,
                                double K, double G, double l, double S[6], double n[3], double *w,
                                double *dp)
{
  *dp = 0.0;
  if (!(d0 > 0.0)) {
    if (d < 1.0) return d0;         /* intact, and stays so */
    fracture_crack_normal(p, S, n); /* starts to open */
    *w = 0.0;
    d0 = 1e-12;
  }
  const double sc = -fp->sigma_c, wu = fracture_open_strain(fp, l);
  double wmax = d0 * wu;
  const double snn = fracture_normal_stress(p, S, n);
  const double M = K + 4.0 / 3.0 * G, T = sc * (1.0 - wmax / wu), soft = sc / wu;
  double dw = 0.0, s = snn;
  if (s > 0.0 && *w < wmax) { /* a part closed before reopens without traction */
    dw = s / M < wmax - *w ? s / M : wmax - *w;
    s -= M * dw;
  }
  if (s > T) { /* opens on along the softening line */
    double more = M > soft ? (s - T) / (M - soft) : wu - wmax;
    if (wmax + more > wu || !isfinite(more)) more = wu - wmax;
    dw += more;
    wmax += more;
  } else if (s < 0.0 && *w > 0.0) { /* closes under compression, without traction */
    dw = s / M < -*w ? -*w : s / M;
  }
  if (dw != 0.0) {
    *w += dw;
    fracture_open_by(S, n, G, dw);
    *dp = K * dw;
  }
  if (!(wmax < wu)) { /* opened through: split (the paper's rule) */
    n[0] = n[1] = n[2] = 0.0;
    *w = 0.0;
    return 1.0;
  }
  return wmax / wu > 1e-12 ? wmax / wu : 1e-12;
}

int fracture_cohesive_end(struct particles *p, size_t i, const struct material *m, double d)
{
  /* starts where the paper's rule would split, opens on under tension, splits when
     opened through; the pressure then moves, so the caller evaluates the EOS again */
  double S[6], n[3] = {p->crack[0][i], p->crack[1][i], p->crack[2][i]}, w = p->eps_c[i], dp, K, G;
  for (int k = 0; k < 6; k++) S[k] = p->S[k][i];
  fracture_opening_moduli(p, i, m, &K, &G);
  const double l = cbrt(p->m[i] / m->rho0);
  const double D =
      fracture_cohesive_return(&m->frac, p->damage[i], d, p->p[i], K, G, l, S, n, &w, &dp);
  p->damage[i] = D;
  p->fstate[i] = D >= 1.0 ? FRACTURE_SPLIT : D > 0.0 ? FRACTURE_OPENING : FRACTURE_INTACT;
  for (int k = 0; k < 3; k++) p->crack[k][i] = n[k];
  p->eps_c[i] = w;
  if (D >= 1.0) {
    for (int k = 0; k < 6; k++) p->S[k][i] = 0.0; /* split: the paper's rule */
    return 1;
  }
  for (int k = 0; k < 6; k++) p->S[k][i] = S[k];
  return dp != 0.0;
}

/* ---- reading (fracture_read.c) ---------------------------------------------------- */

int fracture_read_energy(struct cfg *c, const char *fp, struct material *m, struct hv_error *err)
{
  struct fracture_params *f = &m->frac;
  const double zero = 0.0;
  char k[320];
  if (material_get_q(c, fp, "energy", UNIT_FRACTURE_ENERGY, &zero, 0.0, HUGE_VAL, &f->energy, err))
    return -1;
  if (f->energy > 0.0 && !m->str.enabled)
    return material_key_error(c, material_key(k, sizeof k, fp, "energy"), err,
                              "the cohesive opening (energy > 0) acts on the stress of a "
                              "solid, but the material has no strength (give strength with "
                              "shear modulus and yield > 0)");
  if (f->energy > 0.0 && !(m->rho0 > 0.0))
    return material_key_error(c, material_key(k, sizeof k, fp, "energy"), err,
                              "the cohesive opening (energy > 0) takes each particle's "
                              "spacing from its mass and the material's rho0, which this "
                              "material does not give");
  return 0;
}
