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
void exact_riemann(struct gas_state L, struct gas_state R, double g, double S, struct gas_state *o)
{
  double ps, us;
  exact_riemann_star(L, R, g, &ps, &us);
  double gm = (g - 1.0) / (g + 1.0);
  if (S <= us) { /* left of the contact */
    double cL = sqrt(g * L.p / L.rho);
    if (ps > L.p) {
      double SL = L.u - cL * sqrt((g + 1.0) / (2.0 * g) * ps / L.p + (g - 1.0) / (2.0 * g));
      if (S <= SL)
        *o = L;
      else
        *o = (struct gas_state){L.rho * (ps / L.p + gm) / (gm * ps / L.p + 1.0), us, ps};
    } else {
      double SH = L.u - cL, cs = cL * pow(ps / L.p, (g - 1.0) / (2.0 * g)), ST = us - cs;
      if (S <= SH)
        *o = L;
      else if (S > ST)
        *o = (struct gas_state){L.rho * pow(ps / L.p, 1.0 / g), us, ps};
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
      if (S >= SR)
        *o = R;
      else
        *o = (struct gas_state){R.rho * (ps / R.p + gm) / (gm * ps / R.p + 1.0), us, ps};
    } else {
      double SH = R.u + cR, cs = cR * pow(ps / R.p, (g - 1.0) / (2.0 * g)), ST = us + cs;
      if (S >= SH)
        *o = R;
      else if (S < ST)
        *o = (struct gas_state){R.rho * pow(ps / R.p, 1.0 / g), us, ps};
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
  double rs = 0.5 * (g - 1.0) * t; /* shock speed (γ−1)/2 for unit inflow: 1/3 at γ = 5/3 */
  if (r < rs) return rho0 * pow((g + 1.0) / (g - 1.0), 3.0);
  return rho0 * (1.0 + t / r) * (1.0 + t / r);
}

double exact_sedov_radius(double xi0, double E, double rho0, double t)
{
  return xi0 * pow(E * t * t / rho0, 0.2);
}

double exact_noh_shock_radius(double t, double g) { return 0.5 * (g - 1.0) * t; }

/* Sedov similarity ODEs in ξ = ln λ, with u = (r/t)V, ρ = ρ₀G, c² = (r/t)²Z and
 * r_s ∝ t^δ, δ = 2/5. Continuity, momentum and entropy (p ρ^−γ constant along
 * particle paths) give, with g = G'/G, z = Z'/Z and W = V − δ:
 *   g  = [3VW − V(V − 1) − 2(1 − δ)Z/(γW)] / (Z − W²)
 *   V' = −3V − W g
 *   z  = 2(1 − δ)/W − 2 − (1 − γ) g                                          */
static void sedov_rhs(double g, const double y[3], double d[3])
{
  const double delta = 0.4, V = y[0], G = y[1], Z = y[2], W = V - delta;
  double gg = (3.0 * V * W - V * (V - 1.0) - 2.0 * (1.0 - delta) * Z / (g * W)) / (Z - W * W);
  double zz = 2.0 * (1.0 - delta) / W - 2.0 - (1.0 - g) * gg;
  d[0] = -3.0 * V - W * gg;
  d[1] = G * gg;
  d[2] = Z * zz;
}

void exact_sedov_solve(double g, struct sedov_solution *s)
{
  const int N = EXACT_SEDOV_N;
  const double delta = 0.4, lmin = 1e-6;
  /* strong-shock (Rankine–Hugoniot) state at λ = 1, shock speed D = δ r_s/t */
  double y[3] = {2.0 * delta / (g + 1.0), (g + 1.0) / (g - 1.0),
                 2.0 * g * (g - 1.0) * delta * delta / ((g + 1.0) * (g + 1.0))};
  s->gamma = g;
  /* steps uniform in ξ = ln λ from 0 down to ln(lmin), stored at decreasing λ */
  const double h = log(lmin) / (double)(N - 2);
  s->lam[N - 1] = 1.0;
  s->V[N - 1] = y[0];
  s->G[N - 1] = y[1];
  s->Z[N - 1] = y[2];
  for (int k = N - 2; k >= 1; k--) {
    double k1[3], k2[3], k3[3], k4[3], t[3];
    sedov_rhs(g, y, k1);
    for (int c = 0; c < 3; c++) t[c] = y[c] + 0.5 * h * k1[c];
    sedov_rhs(g, t, k2);
    for (int c = 0; c < 3; c++) t[c] = y[c] + 0.5 * h * k2[c];
    sedov_rhs(g, t, k3);
    for (int c = 0; c < 3; c++) t[c] = y[c] + h * k3[c];
    sedov_rhs(g, t, k4);
    for (int c = 0; c < 3; c++) y[c] += h / 6.0 * (k1[c] + 2.0 * k2[c] + 2.0 * k3[c] + k4[c]);
    s->lam[k] = exp(h * (double)(N - 1 - k));
    s->V[k] = y[0];
    s->G[k] = y[1];
    s->Z[k] = y[2];
  }
  s->lam[0] = 0.0; /* the centre: G → 0, V → δ/γ, G·Z·λ² (the pressure) finite */
  s->V[0] = delta / g;
  s->G[0] = 0.0;
  s->Z[0] = s->Z[1];
  /* energy E = 4π ρ₀ r_s⁵/t² ∫ G (V²/2 + Z/(γ(γ−1))) λ⁴ dλ (trapezoid in λ) */
  double I = 0.0;
  for (int k = 1; k < N; k++) {
    double f0 = s->G[k - 1] * (0.5 * s->V[k - 1] * s->V[k - 1] + s->Z[k - 1] / (g * (g - 1.0))) *
                pow(s->lam[k - 1], 4.0);
    double f1 =
        s->G[k] * (0.5 * s->V[k] * s->V[k] + s->Z[k] / (g * (g - 1.0))) * pow(s->lam[k], 4.0);
    I += 0.5 * (f0 + f1) * (s->lam[k] - s->lam[k - 1]);
  }
  s->xi0 = pow(4.0 * 3.14159265358979323846 * I, -0.2);
}

void exact_sedov(const struct sedov_solution *s, double E, double rho0, double t, double r,
                 struct gas_state *o)
{
  const double rs = exact_sedov_radius(s->xi0, E, rho0, t), lam = r / rs, g = s->gamma;
  if (lam >= 1.0) {
    *o = (struct gas_state){rho0, 0.0, 0.0};
    return;
  }
  /* bisection on the increasing λ table, linear interpolation */
  int lo = 0, hi = EXACT_SEDOV_N - 1;
  while (hi - lo > 1) {
    int mid = (lo + hi) / 2;
    if (s->lam[mid] <= lam)
      lo = mid;
    else
      hi = mid;
  }
  double w = (lam - s->lam[lo]) / (s->lam[hi] - s->lam[lo]);
  double G = s->G[lo] + w * (s->G[hi] - s->G[lo]), V = s->V[lo] + w * (s->V[hi] - s->V[lo]);
  /* pressure p = ρ₀ G Z r²/(γ t²): interpolate G·Z·λ², which stays finite at the centre */
  double P0 = s->G[lo] * s->Z[lo] * s->lam[lo] * s->lam[lo];
  double P1 = s->G[hi] * s->Z[hi] * s->lam[hi] * s->lam[hi];
  if (lo == 0) P0 = P1;
  double P = P0 + w * (P1 - P0);
  o->rho = rho0 * G;
  o->u = r / t * V;
  o->p = rho0 * P * rs * rs / (g * t * t);
}
