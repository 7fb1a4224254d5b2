/* exact.c — see exact.h. */
#include "exact.h"

#include <math.h>

/* Toro eq. 4.6–4.7: f_K(p) and its derivative. */
static void pressure_fn(double p, struct gas_state K, double g, double *f, double *df)
{
  double c = sqrt(g * K.p / K.rho);
  if (p > K.p) { /* shock */
    double A = 2.0 / ((g + 1.0) * K.rho), B = (g - 1.0) / (g + 1.0) * K.p;
    double s = sqrt(A / (p + B));
    *f = (p - K.p) * s;
    *df = s * (1.0 - 0.5 * (p - K.p) / (B + p));
  } else { /* rarefaction */
    double e = (g - 1.0) / (2.0 * g);
    *f = 2.0 * c / (g - 1.0) * (pow(p / K.p, e) - 1.0);
    *df = 1.0 / (K.rho * c) * pow(p / K.p, -(g + 1.0) / (2.0 * g));
  }
}

void exact_riemann_star(struct gas_state L, struct gas_state R, double g, double *pstar,
                        double *ustar)
{
  double p = 0.5 * (L.p + R.p), du = R.u - L.u;
  for (int it = 0; it < 100; it++) {
    double fL, dfL, fR, dfR;
    pressure_fn(p, L, g, &fL, &dfL);
    pressure_fn(p, R, g, &fR, &dfR);
    double pn = p - (fL + fR + du) / (dfL + dfR);
    if (pn < 1e-12 * p) pn = 1e-12 * p;
    double change = fabs(pn - p) / (0.5 * (pn + p));
    p = pn;
    if (change < 1e-14) break;
  }
  double fL, dfL, fR, dfR;
  pressure_fn(p, L, g, &fL, &dfL);
  pressure_fn(p, R, g, &fR, &dfR);
  *pstar = p;
  *ustar = 0.5 * (L.u + R.u) + 0.5 * (fR - fL);
}

/* Toro §4.5: sampling. */
void exact_riemann(struct gas_state L, struct gas_state R, double g, double S,
                   struct gas_state *o)
{
  double ps, us;
  exact_riemann_star(L, R, g, &ps, &us);
  double gm = (g - 1.0) / (g + 1.0);
  if (S <= us) { /* left of the contact */
    double cL = sqrt(g * L.p / L.rho);
    if (ps > L.p) {
      double SL = L.u - cL * sqrt((g + 1.0) / (2.0 * g) * ps / L.p + (g - 1.0) / (2.0 * g));
      if (S <= SL) *o = L;
      else *o = (struct gas_state){L.rho * (ps / L.p + gm) / (gm * ps / L.p + 1.0), us, ps};
    } else {
      double SH = L.u - cL, cs = cL * pow(ps / L.p, (g - 1.0) / (2.0 * g)), ST = us - cs;
      if (S <= SH) *o = L;
      else if (S > ST) *o = (struct gas_state){L.rho * pow(ps / L.p, 1.0 / g), us, ps};
      else {
        double f = 2.0 / (g + 1.0) + gm / cL * (L.u - S);
        double c = f * cL;
        *o = (struct gas_state){L.rho * pow(f, 2.0 / (g - 1.0)),
                                2.0 / (g + 1.0) * (cL + (g - 1.0) / 2.0 * L.u + S),
                                L.p * pow(c / cL, 2.0 * g / (g - 1.0))};
      }
    }
  } else { /* right of the contact */
    double cR = sqrt(g * R.p / R.rho);
    if (ps > R.p) {
      double SR = R.u + cR * sqrt((g + 1.0) / (2.0 * g) * ps / R.p + (g - 1.0) / (2.0 * g));
      if (S >= SR) *o = R;
      else *o = (struct gas_state){R.rho * (ps / R.p + gm) / (gm * ps / R.p + 1.0), us, ps};
    } else {
      double SH = R.u + cR, cs = cR * pow(ps / R.p, (g - 1.0) / (2.0 * g)), ST = us + cs;
      if (S >= SH) *o = R;
      else if (S < ST) *o = (struct gas_state){R.rho * pow(ps / R.p, 1.0 / g), us, ps};
      else {
        double f = 2.0 / (g + 1.0) - gm / cR * (R.u - S);
        double c = f * cR;
        *o = (struct gas_state){R.rho * pow(f, 2.0 / (g - 1.0)),
                                2.0 / (g + 1.0) * (-cR + (g - 1.0) / 2.0 * R.u + S),
                                R.p * pow(c / cR, 2.0 * g / (g - 1.0))};
      }
    }
  }
}

double exact_noh_density(double r, double t, double g, double rho0)
{
  double rs = 0.5 * (g - 1.0) * t;   /* shock speed (γ−1)/2 for unit inflow: 1/3 at γ = 5/3 */
  if (r < rs) return rho0 * pow((g + 1.0) / (g - 1.0), 3.0);
  return rho0 * (1.0 + t / r) * (1.0 + t / r);
}

double exact_sedov_radius(double xi0, double E, double rho0, double t)
{
  return xi0 * pow(E * t * t / rho0, 0.2);
}
