/* exact.h — exact solutions for the verification tests.
 *
 * Riemann problem for an ideal gas: the exact solver of Toro (2009), "Riemann
 * Solvers and Numerical Methods for Fluid Dynamics", ch. 4 (pressure function,
 * Newton iteration for p*, sampling of the self-similar solution at ξ = x/t).
 * Noh (1987): the 3D implosion, ρ = ((γ+1)/(γ−1))³ inside r_s = t/3 (γ = 5/3:
 * 64), ρ = ρ₀ (1 + t/r)² outside. Sedov–Taylor: r_s = ξ₀ (E t²/ρ₀)^(1/5).
 */
#ifndef HV_EXACT_H
#define HV_EXACT_H

struct gas_state {
  double rho, u, p;
};

/* Solution at ξ = x/t of the Riemann problem L | R (interface at x = 0). */
void exact_riemann(struct gas_state L, struct gas_state R, double gamma, double xi,
                   struct gas_state *out);
/* Star-region pressure and velocity. */
void exact_riemann_star(struct gas_state L, struct gas_state R, double gamma, double *pstar,
                        double *ustar);

/* Noh: density at radius r and time t for initial density rho0 and inflow speed 1. */
double exact_noh_density(double r, double t, double gamma, double rho0);

/* Sedov–Taylor shock radius. */
double exact_sedov_radius(double xi0, double E, double rho0, double t);

#endif
