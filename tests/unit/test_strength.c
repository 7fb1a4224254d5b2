/* test_strength.c — the pure strength and fracture functions against hand results:
 * eigen-decomposition, Jaumann rate, radial return, yield models, fracture. */
#include <math.h>
#include <string.h>

#include "fracture/fracture.h"
#include "particles/particles.h"
#include "strength/strength.h"
#include "strength/sym3.h"
#include "testlib.h"

static void test_eigen(void)
{
  /* A = Q diag(3, 1, -2) Qᵀ with Q a rotation by 30° about z */
  const double c = cos(0.52359877559829887), s = sin(0.52359877559829887);
  const double Q[9] = {c, -s, 0, s, c, 0, 0, 0, 1}, d[3] = {3, 1, -2};
  double a[6], lam[3], V[9], back[6];
  sym3_from_eigen(Q, d, a);
  CHECK_CLOSE(a[T_XY], (3 - 1) * c * s, 1e-14, "A_xy of the rotated diagonal");
  sym3_eigen(a, lam, V);
  CHECK_CLOSE(lam[0], 3, 1e-13, "largest eigenvalue");
  CHECK_CLOSE(lam[1], 1, 1e-13, "middle eigenvalue");
  CHECK_CLOSE(lam[2], -2, 1e-13, "smallest eigenvalue");
  sym3_from_eigen(V, lam, back);
  double e = 0;
  for (int k = 0; k < 6; k++) e = fmax(e, fabs(back[k] - a[k]));
  CHECK(e < 1e-13, "Q diag Qᵀ reproduces A (max error %.2e)", e);
  const double g[6] = {1, 2, 3, 0.5, -0.7, 0.2};
  sym3_eigen(g, lam, V);
  CHECK_CLOSE(lam[0] + lam[1] + lam[2], 6.0, 1e-13, "trace = sum of eigenvalues");
}

static void test_rate(void)
{
  const double G = 80e9, gd = 1e3, S0[6] = {0};
  double L[9] = {0, gd, 0, 0, 0, 0, 0, 0, 0}, dS[6];  /* simple shear v_x = γ̇ y */
  strength_rate(G, S0, L, dS);
  CHECK_CLOSE(dS[T_XY], G * gd, 1e-6 * G * gd, "simple shear: dS_xy/dt = G γ̇");
  CHECK(dS[T_XX] == 0 && dS[T_YY] == 0 && dS[T_ZZ] == 0, "simple shear from rest: no normal rate");
  /* uniaxial strain rate ε̇_xx: dS_xx = 4/3 G ε̇, dS_yy = dS_zz = −2/3 G ε̇ */
  double Lx[9] = {gd, 0, 0, 0, 0, 0, 0, 0, 0};
  strength_rate(G, S0, Lx, dS);
  CHECK_CLOSE(dS[T_XX], 4.0 / 3.0 * G * gd, 1e-12 * G * gd, "uniaxial: dS_xx = 4/3 G ε̇");
  CHECK_CLOSE(dS[T_YY], -2.0 / 3.0 * G * gd, 1e-12 * G * gd, "uniaxial: dS_yy = -2/3 G ε̇");
  /* pure rotation (Ω only) keeps J2 and the trace: dJ2/dt = S:dS = 0 */
  const double S[6] = {2e8, -1e8, -1e8, 3e7, 0, 1e7};
  double W[9] = {0, -5, 0, 5, 0, 0, 0, 0, 0};
  strength_rate(G, S, W, dS);
  double sds = S[0] * dS[0] + S[1] * dS[1] + S[2] * dS[2] +
               2 * (S[3] * dS[3] + S[4] * dS[4] + S[5] * dS[5]);
  CHECK(fabs(sds) < 1e-6 * sym3_j2(S) * 5, "rotation leaves J2 unchanged (S:dS = %.3g)", sds);
  CHECK_CLOSE(dS[0] + dS[1] + dS[2], 0.0, 1e-3, "rotation keeps S traceless");
  /* a pure rotation by Ω = [[0,-w],[w,0]] turns S_xx - S_yy into S_xy: dS_xy = w (S_xx - S_yy) */
  CHECK_CLOSE(dS[T_XY], 5 * (S[0] - S[1]), 1e-3, "Jaumann: dS_xy = ω (S_xx − S_yy)");
}

static void test_return(void)
{
  const double G = 26e9, Y = 300e6;
  double S[6] = {2 * Y / 3, -Y / 3, -Y / 3, 0, 0, 0};  /* uniaxial: √(3J2) = Y */
  CHECK_CLOSE(sqrt(3 * sym3_j2(S)), Y, 1e-6, "uniaxial deviator has von Mises stress σ");
  double deps = strength_return(G, Y, S);
  CHECK(deps == 0.0, "on the yield surface: no plastic strain");
  for (int k = 0; k < 6; k++) S[k] *= 2.0;
  deps = strength_return(G, Y, S);
  CHECK_CLOSE(sqrt(3 * sym3_j2(S)), Y, 1e-6, "returned onto the surface");
  CHECK_CLOSE(deps, Y / (3 * G), 1e-15, "plastic strain (2Y − Y)/3G");
  struct strength_params sp = {.enabled = 1, .G = G, .yield = YIELD_LINEAR, .Y0 = Y, .H = 1e8};
  CHECK_CLOSE(strength_yield(&sp, 0.5, 0, 0), Y + 0.5e8, 1e-6, "linear hardening");
  sp.yield = YIELD_JOHNSON_COOK;
  sp.jc_A = 90e6; sp.jc_B = 292e6; sp.jc_N = 0.31; sp.jc_C = 0.025; sp.jc_M = 1.09;
  sp.jc_rate0 = 1.0; sp.T_ref = 294; sp.T_melt = 1356; sp.cv = 383;
  double yjc = strength_yield(&sp, 0.1, 1.0, 0.0);
  CHECK_CLOSE(yjc, 90e6 + 292e6 * pow(0.1, 0.31), 1.0, "Johnson-Cook at reference rate and T");
  CHECK_CLOSE(strength_yield(&sp, 0.1, 1e3, 0.0) / yjc, 1 + 0.025 * log(1e3), 1e-12, "JC rate factor");
  CHECK(strength_yield(&sp, 0.1, 1.0, 383.0 * (1356 - 294) + 1) == 0.0, "JC: no strength above melt");
}

/* split: no-tension — σ = Q diag(2, −1, −3)·10⁸ Qᵀ (Pa, Q a rotation about (1, 2, 2)/3
 * by 0.7 rad) with p = 0.5·10⁸ Pa carried apart from T: the projection must give
 * Q diag(0, −1, −3)·10⁸ Qᵀ, keep compression untouched, and free hydrostatic tension
 * entirely. */
static void test_no_tension(void)
{
  struct fracture_params nt = {.kind = FRACTURE_TRESCA, .sigma_c = -0.39e9, .split = SPLIT_NO_TENSION};
  CHECK(fracture_keeps_stress(&nt, 1.0) && fracture_no_tension(&nt, 1.0) &&
        !fracture_no_tension(&nt, 0.99), "no-tension: split particles keep a stress");
  CHECK(fracture_yield(&nt, 1.0, 0.383e9, -1e8) == 0.383e9, "no-tension: split keeps Y");
  const double ax[3] = {1.0 / 3, 2.0 / 3, 2.0 / 3}, c = cos(0.7), s = sin(0.7);
  double Q[9];   /* Rodrigues: Q = c I + s [a]x + (1 − c) a aᵀ */
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) Q[3 * a + b] = (a == b ? c : 0.0) + (1 - c) * ax[a] * ax[b];
  Q[1] -= s * ax[2]; Q[2] += s * ax[1]; Q[3] += s * ax[2];
  Q[5] -= s * ax[0]; Q[6] -= s * ax[1]; Q[7] += s * ax[0];
  const double lam[3] = {2e8, -1e8, -3e8}, lam_p[3] = {0.0, -1e8, -3e8}, p = 0.5e8;
  double sig[6], want[6], T[6];
  sym3_from_eigen(Q, lam, sig);
  sym3_from_eigen(Q, lam_p, want);
  for (int k = 0; k < 6; k++) T[k] = sig[k] + (k < 3 ? p : 0.0);   /* σ = −pI + T */
  CHECK(fracture_project(p, T) == 1, "no-tension: a principal tension is removed");
  double err = 0.0;
  for (int k = 0; k < 6; k++) err = fmax(err, fabs(T[k] - (k < 3 ? p : 0.0) - want[k]));
  CHECK(err < 1e-6 * 3e8, "no-tension: σ' = Q diag(0, -1, -3) Qᵀ (largest error %g Pa)", err);
  double lam2[3], out[6];   /* the projected stress itself, σ' = −pI + T */
  for (int k = 0; k < 6; k++) out[k] = T[k] - (k < 3 ? p : 0.0);
  sym3_eigen(out, lam2, NULL);
  CHECK(fabs(lam2[0]) < 1e-6 * 3e8, "no-tension: σ' has no tension (σ1 = %g Pa)", lam2[0]);
  double C[6], C0[6];   /* all principal stresses compressive: unchanged, to the bit */
  const double lc[3] = {-0.5e8, -1e8, -3e8};
  sym3_from_eigen(Q, lc, C);
  for (int k = 0; k < 6; k++) C0[k] = C[k];
  CHECK(fracture_project(1e8, C) == 0, "no-tension: compression is not touched");
  int same = 1;
  for (int k = 0; k < 6; k++) same &= C[k] == C0[k];
  CHECK(same, "no-tension: compressive stress unchanged");
  double H[6] = {0, 0, 0, 0, 0, 0};   /* hydrostatic tension p = −1e8: σ' = 0 */
  CHECK(fracture_project(-1e8, H) == 1 && fabs(H[0] + 1e8) < 1e-6 * 1e8 &&
        fabs(H[1] + 1e8) < 1e-6 * 1e8 && fabs(H[2] + 1e8) < 1e-6 * 1e8 && fabs(H[3]) < 1.0,
        "no-tension: hydrostatic tension released entirely (T = pI, σ' = 0)");
  /* the same σ split into p' and a traceless S' (σ' = −p'I + S'): p' = −tr σ'/3 = 4/3·10⁸ */
  double S0d[6], Se[6];
  for (int k = 0; k < 6; k++) S0d[k] = sig[k] + (k < 3 ? p : 0.0);
  const double pe = fracture_effective(p, S0d, Se);
  double err2 = fabs(Se[0] + Se[1] + Se[2]);
  for (int k = 0; k < 6; k++) err2 = fmax(err2, fabs(Se[k] - (k < 3 ? pe : 0.0) - want[k]));
  CHECK(fabs(pe - 4e8 / 3) < 1e-6 * 3e8 && err2 < 1e-6 * 3e8, "no-tension: p' = %.6g Pa "
        "(4/3e8), S' traceless and -p'I + S' = σ' (largest error %g Pa)", pe, err2);
  double Cc[6];   /* no tension: p and S returned as they are */
  CHECK(fracture_effective(1e8, C0, Cc) == 1e8 && !memcmp(Cc, C0, sizeof Cc),
        "no-tension: p and S unchanged without tension");
}

static void test_fracture(void)
{
  const double S0[6] = {0};
  CHECK_CLOSE(fracture_max_principal(-1e8, S0), 1e8, 1e-6, "hydrostatic tension: σ1 = -p");
  const double S[6] = {2e8, -1e8, -1e8, 0, 0, 0};
  CHECK_CLOSE(fracture_max_principal(0.0, S), 2e8, 1e-6, "σ1 from the deviator");
  struct fracture_params tr = {.kind = FRACTURE_TRESCA, .sigma_c = -0.39e9};
  CHECK(fracture_tension(&tr, 0, -0.38e9, S0, 1e-9) == 0.0, "below |σc|: no split");
  CHECK(fracture_tension(&tr, 0, -0.40e9, S0, 1e-9) == 1.0, "beyond |σc|: split");
  CHECK(fracture_tension(&tr, 0, 1e9, S, 1e-9) == 0.0, "compression: no split");
  struct fracture_params cu = {.kind = FRACTURE_CUMULATIVE, .sigma_c = -1e8, .eps_f = 0.5, .tau = 1e-6};
  CHECK_CLOSE(fracture_plastic(&cu, 0.0, 0.1), 0.2, 1e-15, "cumulative: dD = deps/eps_f");
  CHECK_CLOSE(fracture_tension(&cu, 0.2, -2e8, S0, 2e-7), 0.4, 1e-12, "cumulative: dD = dt/tau in tension");
  CHECK(fracture_tension(&cu, 0.9, -2e8, S0, 2e-7) == 1.0, "cumulative: split at D = 1");
  /* split material: no deviatoric stress (the paper's rule), or min(Y, μ max(p, 0)) */
  CHECK(fracture_keeps_stress(&tr, 0.5) && !fracture_keeps_stress(&tr, 1.0),
        "without friction only intact particles keep a deviatoric stress");
  CHECK(fracture_yield(&tr, 1.0, 0.383e9, 1e9) == 0.0, "split, no friction: Y = 0");
  struct fracture_params fr = {.kind = FRACTURE_TRESCA, .sigma_c = -0.39e9, .friction = 0.3};
  CHECK(fracture_keeps_stress(&fr, 1.0), "with friction split particles keep a deviatoric stress");
  CHECK(fracture_yield(&fr, 0.99, 0.383e9, 1e9) == 0.383e9, "not yet split: the intact Y");
  CHECK_CLOSE(fracture_yield(&fr, 1.0, 0.383e9, 1e9), 0.3e9, 1e-15, "split: Y = μp below Y0");
  CHECK(fracture_yield(&fr, 1.0, 0.383e9, 2e9) == 0.383e9, "split: Y = Y0 when μp > Y0");
  CHECK(fracture_yield(&fr, 1.0, 0.383e9, -1e8) == 0.0, "split: no strength without pressure");
  test_no_tension();
}

int main(void)
{
  test_eigen();
  test_rate();
  test_return();
  test_fracture();
  return test_finish();
}
