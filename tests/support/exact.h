/* exact.h — exact solutions for the verification tests.
 *
 * Riemann problem for an ideal gas: the exact solver of Toro (2009), "Riemann
 * Solvers and Numerical Methods for Fluid Dynamics", 3rd ed., ch. 4 (pressure
 * function, Newton iteration for p*, sampling of the self-similar solution at
 * ξ = x/t). No vacuum generation (p* > 0 is assumed).
 * Noh (1987), J. Comput. Phys. 72:78: the 3D implosion of a cold gas at unit inward
 * speed; ρ = ρ₀ ((γ+1)/(γ−1))³ inside r_s = (γ−1) t / 2 (γ = 5/3: 64 inside t/3),
 * ρ = ρ₀ (1 + t/r)² outside.
 * Sedov–Taylor point blast in 3D (Sedov 1959, ch. IV): r_s = ξ₀ (E t²/ρ₀)^(1/5).
 * The full self-similar profile is found by integrating the similarity ODEs from
 * the strong-shock state at λ = r/r_s = 1 inwards (RK4); ξ₀ follows from the energy
 * integral (1.1517 for γ = 5/3, 1.0328 for γ = 1.4).
 */
#ifndef HV_EXACT_H
#define HV_EXACT_H

struct gas_state {
  double rho, u, p; /* density, velocity (radial for Noh/Sedov), pressure */
};

/* Solution at ξ = x/t of the Riemann problem L | R (interface at x = 0). */
void exact_riemann(struct gas_state L, struct gas_state R, double gamma, double xi,
                   struct gas_state *out);
/* Star-region pressure and velocity. */
void exact_riemann_star(struct gas_state L, struct gas_state R, double gamma, double *pstar,
                        double *ustar);

/* Noh: density at radius r and time t for initial density rho0 and inflow speed 1. */
double exact_noh_density(double r, double t, double gamma, double rho0);
/* Noh: shock radius (γ − 1) t / 2. */
double exact_noh_shock_radius(double t, double gamma);

/* Sedov–Taylor shock radius. */
double exact_sedov_radius(double xi0, double E, double rho0, double t);

/* The Sedov–Taylor self-similar solution for one γ (spherical, uniform ρ₀).
 * u = (r/t) V(λ), ρ = ρ₀ G(λ), c² = (r/t)² Z(λ) on a table over λ = r/r_s ∈ [0, 1]. */
#define EXACT_SEDOV_N 4001
struct sedov_solution {
  double gamma;
  double xi0;                /* r_s = xi0 (E t²/ρ₀)^(1/5) */
  double lam[EXACT_SEDOV_N]; /* λ, increasing, lam[N-1] = 1 */
  double G[EXACT_SEDOV_N], V[EXACT_SEDOV_N], Z[EXACT_SEDOV_N];
};
/* Integrates the similarity ODEs for gamma (1 < γ ≤ 3) and finds ξ₀. */
void exact_sedov_solve(double gamma, struct sedov_solution *s);
/* State at radius r and time t of a blast of energy E in gas of density rho0
 * (ahead of the shock: rho0 at rest, p = 0). */
void exact_sedov(const struct sedov_solution *s, double E, double rho0, double t, double r,
                 struct gas_state *out);

#endif
