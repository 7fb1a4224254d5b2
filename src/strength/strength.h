/* strength.h — elastic–plastic deviatoric stress (pure functions).
 *
 * Jaumann rate (Libersky & Petschek 1991; Gray, Monaghan & Swift 2001, eq. 4):
 *   dS/dt = 2G (ε̇ − ⅓ tr ε̇ I) + S Ωᵀ + Ω S,
 *   ε̇ = ½(L + Lᵀ), Ω = ½(L − Lᵀ), L_ab = ∂v_a/∂x_b.
 * von Mises yield with radial return (Wilkins 1964): if √(3J₂) > Y then
 *   S ← S · Y/√(3J₂), and the equivalent plastic strain grows by (√(3J₂) − Y)/(3G).
 * Yield, one model per file with its keys and its listing (a row of the table of
 * models, material.h): constant Y₀ and linear hardening Y = Y₀ + H ε_p (von_mises.c);
 * Johnson–Cook (1983) Y = (A + B ε_pᴺ)(1 + C ln(ε̇_eq / ε̇₀))(1 − T*ᴹ),
 *   T* = (T − T_ref)/(T_melt − T_ref), T = T_ref + e/c_v (johnson_cook.c).
 */
#ifndef HV_STRENGTH_H
#define HV_STRENGTH_H

#include "material/material.h"

/* dS/dt [Pa/s] from S [Pa] and the velocity gradient L [1/s] (row-major 3×3). */
void strength_rate(double G, const double S[6], const double L[9], double dS[6]);
/* Yield stress [Pa] at plastic strain eps_p, equivalent strain rate [1/s] and
 * specific internal energy e [J/kg]. */
double strength_yield(const struct strength_params *sp, double eps_p, double rate, double e);
/* Radial return of S onto the yield surface; returns the plastic strain increment. */
double strength_return(double G, double Y, double S[6]);
/* Equivalent strain rate √(⅔ ε̇':ε̇') [1/s]. */
double strength_equivalent_rate(const double L[9]);

#endif
