/* test_strength.c — the pure strength and fracture functions against hand results:
 * eigen-decomposition, Jaumann rate, radial return, yield models, fracture. */
#include <math.h>
#include <string.h>

#include "fracture/fracture.h"
#include "fracture/rules.h"
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

/* sym3_negative_definite: never says yes where sym3_eigen finds an eigenvalue ≥ 0 (so
 * the artificial stress that it gates keeps its bits), and says yes for clearly
 * negative definite tensors (so that it spares the decomposition). Random rotations of
 * diagonals whose largest entry runs from clearly negative through ±10⁻¹⁸ of the
 * scale to positive. */
static void test_negative_definite(void)
{
  unsigned long long x = 88172645463325252ull;
  int wrong = 0, missed = 0, said = 0;
  for (int n = 0; n < 20000; n++) {
    double u[4];
    for (int k = 0; k < 4; k++) { /* xorshift64: fixed, portable */
      x ^= x << 13;
      x ^= x >> 7;
      x ^= x << 17;
      u[k] = (double)(x >> 11) * (1.0 / 9007199254740992.0);
    }
    const double scale = pow(10.0, 12.0 * u[0] - 3.0);
    const double e[7] = {-0.5, -1e-3, -1e-9, -1e-18, 0.0, 1e-18, 1e-6};
    const double lmax = e[n % 7] * scale;
    const double d[3] = {lmax, -scale * (0.2 + u[1]), -scale * (0.1 + u[2])};
    /* a rotation about a random axis by a random angle (Rodrigues) */
    const double th = 6.283185307179586 * u[3], c = cos(th), s = sin(th);
    const double ax[3] = {u[1] - 0.5, u[2] - 0.5, 0.3};
    const double nn = sqrt(ax[0] * ax[0] + ax[1] * ax[1] + ax[2] * ax[2]);
    const double k0 = ax[0] / nn, k1 = ax[1] / nn, k2 = ax[2] / nn;
    const double Q[9] = {
        c + k0 * k0 * (1 - c),      k0 * k1 * (1 - c) - k2 * s, k0 * k2 * (1 - c) + k1 * s,
        k1 * k0 * (1 - c) + k2 * s, c + k1 * k1 * (1 - c),      k1 * k2 * (1 - c) - k0 * s,
        k2 * k0 * (1 - c) - k1 * s, k2 * k1 * (1 - c) + k0 * s, c + k2 * k2 * (1 - c)};
    double a[6], lam[3];
    sym3_from_eigen(Q, d, a);
    sym3_eigen(a, lam, NULL);
    const int nd = sym3_negative_definite(a);
    said += nd;
    if (nd && !(lam[0] < 0.0)) wrong++;
    if (!nd && lmax <= -1e-3 * scale) missed++;
  }
  CHECK(wrong == 0, "negative definite only where the largest eigenvalue is negative (%d wrong)",
        wrong);
  CHECK(missed == 0, "clearly negative definite tensors recognised (%d missed)", missed);
  CHECK(said > 5000, "the test says yes often (%d of 20000)", said);
  const double zero[6] = {0, 0, 0, 0, 0, 0}, nan6[6] = {NAN, 0, 0, 0, 0, 0};
  CHECK(!sym3_negative_definite(zero) && !sym3_negative_definite(nan6),
        "no for a zero tensor and for NaN");
}

static void test_rate(void)
{
  const double G = 80e9, gd = 1e3, S0[6] = {0};
  double L[9] = {0, gd, 0, 0, 0, 0, 0, 0, 0}, dS[6]; /* simple shear v_x = γ̇ y */
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
  double sds =
      S[0] * dS[0] + S[1] * dS[1] + S[2] * dS[2] + 2 * (S[3] * dS[3] + S[4] * dS[4] + S[5] * dS[5]);
  CHECK(fabs(sds) < 1e-6 * sym3_j2(S) * 5, "rotation leaves J2 unchanged (S:dS = %.3g)", sds);
  CHECK_CLOSE(dS[0] + dS[1] + dS[2], 0.0, 1e-3, "rotation keeps S traceless");
  /* a pure rotation by Ω = [[0,-w],[w,0]] turns S_xx - S_yy into S_xy: dS_xy = w (S_xx - S_yy) */
  CHECK_CLOSE(dS[T_XY], 5 * (S[0] - S[1]), 1e-3, "Jaumann: dS_xy = ω (S_xx − S_yy)");
}

static void test_return(void)
{
  const double G = 26e9, Y = 300e6;
  double S[6] = {2 * Y / 3, -Y / 3, -Y / 3, 0, 0, 0}; /* uniaxial: √(3J2) = Y */
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
  sp.jc_A = 90e6;
  sp.jc_B = 292e6;
  sp.jc_N = 0.31;
  sp.jc_C = 0.025;
  sp.jc_M = 1.09;
  sp.jc_rate0 = 1.0;
  sp.T_ref = 294;
  sp.T_melt = 1356;
  sp.cv = 383;
  double yjc = strength_yield(&sp, 0.1, 1.0, 0.0);
  CHECK_CLOSE(yjc, 90e6 + 292e6 * pow(0.1, 0.31), 1.0, "Johnson-Cook at reference rate and T");
  CHECK_CLOSE(strength_yield(&sp, 0.1, 1e3, 0.0) / yjc, 1 + 0.025 * log(1e3), 1e-12,
              "JC rate factor");
  CHECK(strength_yield(&sp, 0.1, 1.0, 383.0 * (1356 - 294) + 1) == 0.0,
        "JC: no strength above melt");
  /* thermal softening below melt: e = c_v (T_melt − T_ref)/2 gives T = 825 K, T* = 531/1062
     = 0.5 exactly; at the reference rate (rate factor 1) and ε_p = 0.1 the reference yield
     is yjc (checked above), so Y = yjc (1 − 0.5^M) exactly (today: equal to round-off; a
     linear softening, M = 1, would be off by 6 %, T* taken as T/T_melt by 21 %) */
  const double yhalf = strength_yield(&sp, 0.1, 1.0, 383.0 * (1356 - 294) / 2);
  const double yhalf_want = yjc * (1 - pow(0.5, 1.09));
  CHECK_CLOSE(yhalf, yhalf_want, 1e-12 * yhalf_want,
              "JC thermal softening at T* = 0.5: "
              "Y = Y_ref (1 - 0.5^M)");
}

/* split: no-tension — σ = Q diag(2, −1, −3)·10⁸ Qᵀ (Pa, Q a rotation about (1, 2, 2)/3
 * by 0.7 rad) with p = 0.5·10⁸ Pa carried apart from T: the projection must give
 * Q diag(0, −1, −3)·10⁸ Qᵀ, keep compression untouched, and free hydrostatic tension
 * entirely. */
static void test_no_tension(void)
{
  struct fracture_params nt = {
      .kind = FRACTURE_TRESCA, .sigma_c = -0.39e9, .split = SPLIT_NO_TENSION};
  CHECK(fracture_keeps_stress(&nt, FRACTURE_SPLIT) && fracture_no_tension(&nt, FRACTURE_SPLIT) &&
            !fracture_no_tension(&nt, FRACTURE_INTACT),
        "no-tension: split particles keep a stress");
  CHECK(fracture_yield(&nt, FRACTURE_SPLIT, 0.383e9, -1e8) == 0.383e9, "no-tension: split keeps Y");
  const double ax[3] = {1.0 / 3, 2.0 / 3, 2.0 / 3}, c = cos(0.7), s = sin(0.7);
  double Q[9]; /* Rodrigues: Q = c I + s [a]x + (1 − c) a aᵀ */
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) Q[3 * a + b] = (a == b ? c : 0.0) + (1 - c) * ax[a] * ax[b];
  Q[1] -= s * ax[2];
  Q[2] += s * ax[1];
  Q[3] += s * ax[2];
  Q[5] -= s * ax[0];
  Q[6] -= s * ax[1];
  Q[7] += s * ax[0];
  const double lam[3] = {2e8, -1e8, -3e8}, lam_p[3] = {0.0, -1e8, -3e8}, p = 0.5e8;
  double sig[6], want[6], T[6];
  sym3_from_eigen(Q, lam, sig);
  sym3_from_eigen(Q, lam_p, want);
  for (int k = 0; k < 6; k++) T[k] = sig[k] + (k < 3 ? p : 0.0); /* σ = −pI + T */
  CHECK(fracture_project(p, T) == 1, "no-tension: a principal tension is removed");
  double err = 0.0;
  for (int k = 0; k < 6; k++) err = fmax(err, fabs(T[k] - (k < 3 ? p : 0.0) - want[k]));
  CHECK(err < 1e-6 * 3e8, "no-tension: σ' = Q diag(0, -1, -3) Qᵀ (largest error %g Pa)", err);
  double lam2[3], out[6]; /* the projected stress itself, σ' = −pI + T */
  for (int k = 0; k < 6; k++) out[k] = T[k] - (k < 3 ? p : 0.0);
  sym3_eigen(out, lam2, NULL);
  CHECK(fabs(lam2[0]) < 1e-6 * 3e8, "no-tension: σ' has no tension (σ1 = %g Pa)", lam2[0]);
  double C[6], C0[6]; /* all principal stresses compressive: unchanged, to the bit */
  const double lc[3] = {-0.5e8, -1e8, -3e8};
  sym3_from_eigen(Q, lc, C);
  for (int k = 0; k < 6; k++) C0[k] = C[k];
  CHECK(fracture_project(1e8, C) == 0, "no-tension: compression is not touched");
  int same = 1;
  for (int k = 0; k < 6; k++) same &= C[k] == C0[k];
  CHECK(same, "no-tension: compressive stress unchanged");
  double H[6] = {0, 0, 0, 0, 0, 0}; /* hydrostatic tension p = −1e8: σ' = 0 */
  CHECK(fracture_project(-1e8, H) == 1 && fabs(H[0] + 1e8) < 1e-6 * 1e8 &&
            fabs(H[1] + 1e8) < 1e-6 * 1e8 && fabs(H[2] + 1e8) < 1e-6 * 1e8 && fabs(H[3]) < 1.0,
        "no-tension: hydrostatic tension released entirely (T = pI, σ' = 0)");
  /* the same σ split into p' and a traceless S' (σ' = −p'I + S'): p' = −tr σ'/3 = 4/3·10⁸ */
  double S0d[6], Se[6];
  for (int k = 0; k < 6; k++) S0d[k] = sig[k] + (k < 3 ? p : 0.0);
  const double pe = fracture_effective(p, S0d, Se);
  double err2 = fabs(Se[0] + Se[1] + Se[2]);
  for (int k = 0; k < 6; k++) err2 = fmax(err2, fabs(Se[k] - (k < 3 ? pe : 0.0) - want[k]));
  CHECK(fabs(pe - 4e8 / 3) < 1e-6 * 3e8 && err2 < 1e-6 * 3e8,
        "no-tension: p' = %.6g Pa "
        "(4/3e8), S' traceless and -p'I + S' = σ' (largest error %g Pa)",
        pe, err2);
  double Cc[6]; /* no tension: p and S returned as they are */
  CHECK(fracture_effective(1e8, C0, Cc) == 1e8 && !memcmp(Cc, C0, sizeof Cc),
        "no-tension: p and S unchanged without tension");
}

/* split: crack — the smeared crack's return (fracture.h). Moduli K, G of al-alloy's
 * order; M = K + 4G/3. */
static double sig_nn(double p, const double S[6], const double n[3])
{
  double t[3];
  sym3_apply(S, n, t);
  return -p + t[0] * n[0] + t[1] * n[1] + t[2] * n[2];
}

static void test_crack(void)
{
  const double S0c[6] = {0, 0, 0, 0, 0, 0};
  struct fracture_params cr = {.kind = FRACTURE_TRESCA, .sigma_c = -0.39e9, .split = SPLIT_CRACK};
  CHECK(fracture_cracked(&cr, FRACTURE_SPLIT) && !fracture_cracked(&cr, FRACTURE_INTACT) &&
            !fracture_cracked(&cr, FRACTURE_SPLIT_AGAIN),
        "crack: cracked at D = 1, intact below, fluid at D = 2");
  CHECK(fracture_keeps_stress(&cr, FRACTURE_SPLIT) &&
            !fracture_keeps_stress(&cr, FRACTURE_SPLIT_AGAIN),
        "crack: a cracked particle keeps its stress, a twice-split one none");
  CHECK(fracture_yield(&cr, FRACTURE_SPLIT, 0.383e9, -1e8) == 0.383e9 &&
            fracture_yield(&cr, FRACTURE_SPLIT_AGAIN, 0.383e9, 1e9) == 0.0,
        "crack: cracked keeps Y, fluid has none");
  CHECK(!fracture_no_tension(&cr, FRACTURE_SPLIT), "crack is not no-tension");
  const double K = 76e9, G = 26e9, M = K + 4.0 / 3.0 * G;
  /* uniaxial strain ε along y (elastic): p = −Kε, S = 2Gε dev(e_y e_y), σ_yy = Mε =
     0.5 GPa: it cracks across y, and the crack's opening ε_c = ε takes the whole
     strain: σ = 0 after (dp = Kε) */
  const double eps = 0.5e9 / M;
  double S[6] = {-2 * G * eps / 3, 4 * G * eps / 3, -2 * G * eps / 3, 0, 0, 0}, n[3] = {0, 0, 0};
  double ec = 0.0, dp = 0.0, p = -K * eps;
  int st = fracture_crack_return(&cr, fracture_tension(&cr, 0.0, p, S, 1e-9) >= 1.0, p, K, G, 0.0,
                                 S, n, &ec, &dp);
  double smax = 0.0;
  for (int k = 0; k < 6; k++) smax = fmax(smax, fabs(S[k]));
  CHECK(st == FRACTURE_SPLIT && fabs(fabs(n[1]) - 1.0) < 1e-12,
        "crack: uniaxial strain in y cracks across y "
        "(state %d, n = (%g, %g, %g))",
        st, n[0], n[1], n[2]);
  CHECK(fabs(ec - eps) < 1e-12 * eps && smax < 1e-6 * 0.5e9 && fabs(p + dp) < 1e-6 * 0.5e9,
        "crack: the opening takes the whole uniaxial strain (ε_c/ε = %.12f, |S| %g Pa, p + dp "
        "= %g Pa)",
        ec / eps, smax, p + dp);
  /* in-plane tension with the crack's plane traction-free (plane stress, σ_xx = 0 across
     a crack normal to x): carried, nothing moves, below |σ_c| */
  const double T = 0.3e9; /* σ = diag(0, T, T) = −pI + S */
  double Sm[6] = {-2 * T / 3, T / 3, T / 3, 0, 0, 0}, nx[3] = {1, 0, 0}, S0[6];
  for (int k = 0; k < 6; k++) S0[k] = Sm[k];
  ec = 0.0;
  st = fracture_crack_return(&cr, 0, -2 * T / 3, K, G, 0.0, Sm, nx, &ec, &dp);
  CHECK(st == FRACTURE_SPLIT && ec == 0.0 && dp == 0.0 && !memcmp(Sm, S0, sizeof Sm),
        "crack: 0.3 GPa of membrane tension within the plane is carried, unchanged");
  const double T2 = 0.45e9;
  double Sm2[6] = {-2 * T2 / 3, T2 / 3, T2 / 3, 0, 0, 0}, nx2[3] = {1, 0, 0};
  ec = 0.0;
  st = fracture_crack_return(&cr, 0, -2 * T2 / 3, K, G, 0.0, Sm2, nx2, &ec, &dp);
  CHECK(st == FRACTURE_SPLIT_AGAIN && Sm2[1] == 0.0 && nx2[0] == 0.0 && ec == 0.0,
        "crack: 0.45 GPa within the plane splits it again (state %d): S = 0, n = 0, ε_c = 0", st);
  /* hydrostatic tension T: the crack opens by T/M and the plane keeps T·2G/M */
  double Sh[6] = {0, 0, 0, 0, 0, 0}, nh[3] = {1, 0, 0};
  ec = 0.0;
  st = fracture_crack_return(&cr, 0, -T, K, G, 0.0, Sh, nh, &ec, &dp);
  const double syy = -(-T + dp) + Sh[T_YY], sxx = -(-T + dp) + Sh[T_XX];
  CHECK(st == FRACTURE_SPLIT && fabs(ec - T / M) < 1e-12 * T / M && fabs(sxx) < 1e-6 * T &&
            fabs(syy - T * 2 * G / M) < 1e-6 * T,
        "crack: hydrostatic tension T opens it by T/M = "
        "%.4g and leaves σ_xx = %g Pa, σ_yy = %.5g GPa (T·2G/M = %.5g)",
        ec, sxx, syy * 1e-9, T * 2 * G / M * 1e-9);
  /* an open crack closes under compression, down to ε_c = 0, and then carries the rest */
  double Sc[6] = {0, 0, 0, 0, 0, 0}, nc[3] = {1, 0, 0};
  ec = 1e-3;
  const double pc = 0.0; /* σ_xx = −2e-3 M (as if compressed by 2e-3 in x) */
  for (int k = 0; k < 6; k++) Sc[k] = 0.0;
  Sc[T_XX] = -2e-3 * 4 * G / 3;
  Sc[T_YY] = Sc[T_ZZ] = 2e-3 * 2 * G / 3;
  const double pcl = 2e-3 * K;
  st = fracture_crack_return(&cr, 0, pcl + pc, K, G, 0.0, Sc, nc, &ec, &dp);
  CHECK(st == FRACTURE_SPLIT && ec == 0.0 &&
            fabs(sig_nn(pcl + dp, Sc, nc) + 1e-3 * M) < 1e-6 * M * 1e-3,
        "crack: closes by 1e-3 of its 2e-3 compression and carries σ_nn = %.5g GPa (−1e-3 M "
        "= %.5g)",
        sig_nn(pcl + dp, Sc, nc) * 1e-9, -1e-3 * M * 1e-9);
  /* open, with shear on its plane: the shear traction is released, in-plane shear kept */
  const double ax[3] = {1.0 / 3, 2.0 / 3, 2.0 / 3}, c = cos(0.7), s = sin(0.7);
  double Q[9]; /* Rodrigues, as test_no_tension: the crack's frame turned */
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) Q[3 * a + b] = (a == b ? c : 0.0) + (1 - c) * ax[a] * ax[b];
  Q[1] -= s * ax[2];
  Q[2] += s * ax[1];
  Q[3] += s * ax[2];
  Q[5] -= s * ax[0];
  Q[6] -= s * ax[1];
  Q[7] += s * ax[0];
  double nq[3] = {Q[0], Q[3], Q[6]};
  /* σ₀ in the crack's frame (e₁ = n): normal 0.1 GPa, shear 0.05 and −0.03 on the plane,
     in-plane 0.2, −0.1 and 0.04 GPa */
  const double s0[3][3] = {{1e8, 5e7, -3e7}, {5e7, 2e8, 4e7}, {-3e7, 4e7, -1e8}};
  double m3[3][3] = {{0}};
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++)
      for (int k = 0; k < 3; k++)
        for (int l = 0; l < 3; l++) m3[i][j] += Q[3 * i + k] * s0[k][l] * Q[3 * j + l];
  const double ps = -(m3[0][0] + m3[1][1] + m3[2][2]) / 3;
  double Sq[6] = {m3[0][0] + ps, m3[1][1] + ps, m3[2][2] + ps, m3[0][1], m3[1][2], m3[0][2]};
  ec = 0.0;
  st = fracture_crack_return(&cr, 0, ps, K, G, 0.0, Sq, nq, &ec, &dp);
  double t[3] = {0, 0, 0}; /* the traction on the plane after: (σ n) */
  const double sg[3][3] = {{Sq[T_XX] - ps - dp, Sq[T_XY], Sq[T_XZ]},
                           {Sq[T_XY], Sq[T_YY] - ps - dp, Sq[T_YZ]},
                           {Sq[T_XZ], Sq[T_YZ], Sq[T_ZZ] - ps - dp}};
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) t[a] += sg[a][b] * nq[b];
  const double tt = sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
  /* the in-plane shear (e₂, e₃ turned) is kept: e₂ᵀ σ e₃ = 0.04 GPa */
  const double e2[3] = {Q[1], Q[4], Q[7]}, e3[3] = {Q[2], Q[5], Q[8]};
  double s23 = 0.0;
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) s23 += e2[a] * sg[a][b] * e3[b];
  CHECK(st == FRACTURE_SPLIT && ec > 0.0 && tt < 1e-6 * 1e8 && fabs(s23 - 4e7) < 1e-6 * 1e8,
        "crack, open in a turned frame: no traction on the plane (|σn| = %g Pa), in-plane "
        "shear kept (%.6g GPa, 0.04)",
        tt, s23 * 1e-9);
  /* the normal of the largest principal tension */
  const double lam[3] = {3e8, 1e8, -2e8};
  double d6[6], nn[3];
  sym3_from_eigen(Q, lam, d6);
  for (int k = 0; k < 6; k++) S[k] = d6[k] + (k < 3 ? -(2e8 / 3) : 0.0); /* p = −tr/3 */
  fracture_crack_normal(-(2e8 / 3), S, nn);
  const double dot = nn[0] * nq[0] + nn[1] * nq[1] + nn[2] * nq[2];
  CHECK(fabs(fabs(dot) - 1.0) < 1e-12,
        "crack normal along the largest principal stress "
        "(|n·e| = %.15f)",
        fabs(dot));
  /* the spin turns n: rigid rotation about z at ω, 0.5 rad in 1000 steps; a stretch does not */
  const double w = 5e5, dt = 1e-9;
  const double Lr[9] = {0, -w, 0, w, 0, 0, 0, 0, 0}; /* L[3a+b] = ∂v_a/∂x_b, v = ω × x */
  double r[3] = {1, 0, 0};
  for (int k = 0; k < 1000; k++) fracture_crack_rotate(r, Lr, dt);
  CHECK(fabs(r[0] - cos(0.5)) < 1e-3 && fabs(r[1] - sin(0.5)) < 1e-3 && r[2] == 0.0,
        "crack: turned by the spin to (%.5f, %.5f, %g), want (cos 0.5, sin 0.5, 0)", r[0], r[1],
        r[2]);
  const double Ls[9] = {1e5, 0, 0, 0, -1e5, 0, 0, 0, 0};
  double q[3] = {0.6, 0.8, 0};
  for (int k = 0; k < 100; k++) fracture_crack_rotate(q, Ls, dt);
  CHECK(q[0] == 0.6 && q[1] == 0.8, "crack: a pure stretch does not turn it");

  /* crack_eps_f: the cracked state's strain to failure, ε_f = d1 + d2 exp(d3 σ*) (2024-T351's
     Johnson–Cook d1..d3). Equibiaxial membrane tension T within a plane cracked across x,
     σ = diag(0, T, T): σ_m = 2T/3, σ_eq = T, σ* = 2/3 → ε_f = 0.13 + 0.13 e^{−1} = 0.17782;
     uniaxial tension σ* = 1/3 → 0.13 + 0.13 e^{−0.5} = 0.20885; pure shear σ* = 0 → 0.26 */
  struct fracture_params cf = cr;
  cf.crack_eps_f_on = 1;
  cf.crack_d[0] = 0.13;
  cf.crack_d[1] = 0.13;
  cf.crack_d[2] = -1.5;
  const double Tm = 0.3e9;
  const double Sb[6] = {-2 * Tm / 3, Tm / 3, Tm / 3, 0, 0, 0};
  const double Su[6] = {2 * Tm / 3, -Tm / 3, -Tm / 3, 0, 0, 0}; /* σ = diag(T, 0, 0) */
  const double Sp[6] = {0, 0, 0, Tm, 0, 0};                     /* pure shear */
  const double ef_b = fracture_crack_eps_f(&cf, -2 * Tm / 3, Sb);
  const double ef_u = fracture_crack_eps_f(&cf, -Tm / 3, Su);
  const double ef_s = fracture_crack_eps_f(&cf, 0.0, Sp);
  CHECK(fabs(ef_b - (0.13 + 0.13 * exp(-1.0))) < 1e-12 &&
            fabs(ef_u - (0.13 + 0.13 * exp(-0.5))) < 1e-12 && fabs(ef_s - 0.26) < 1e-12,
        "crack_eps_f: ε_f = %.5f (equibiaxial, want 0.17782), %.5f "
        "(uniaxial, 0.20885), %.5f (shear, 0.26)",
        ef_b, ef_u, ef_s);
  CHECK(fracture_crack_eps_f(&cf, -1e8, S0c) == 0.13 + 0.13 * exp(-2.25) &&
            fracture_crack_eps_f(&cf, 1e8, S0c) == 0.13 + 0.13 * exp(2.25) &&
            fracture_crack_eps_f(&cr, -1e8, S0c) == HUGE_VAL,
        "crack_eps_f: σ* clamped to ±1.5 without a deviator; none without crack_eps_f");
  const double Ssm[6] = {0, 0, 0, 1e6, 0, 0}; /* σ_eq = √3 MPa under 0.1 GPa: σ* = ±57.7 */
  CHECK(fracture_crack_eps_f(&cf, -1e8, Ssm) == 0.13 + 0.13 * exp(-2.25) &&
            fracture_crack_eps_f(&cf, 1e8, Ssm) == 0.13 + 0.13 * exp(2.25),
        "crack_eps_f: σ* = ±57.7 (a small deviator) clamped to ±1.5");
  /* the membrane of 0.3 GPa (carried above, below |σ_c|) tears once ε_p reaches ε_f */
  double Sa[6], na[3] = {1, 0, 0};
  for (int k = 0; k < 6; k++) Sa[k] = Sb[k];
  ec = 0.0;
  st = fracture_crack_return(&cf, 0, -2 * Tm / 3, K, G, 0.99 * ef_b, Sa, na, &ec, &dp);
  CHECK(st == FRACTURE_SPLIT && !memcmp(Sa, Sb, sizeof Sa),
        "crack_eps_f: carried at ε_p = 0.99 ε_f");
  st = fracture_crack_return(&cf, 0, -2 * Tm / 3, K, G, ef_b, Sa, na, &ec, &dp);
  CHECK(st == FRACTURE_SPLIT_AGAIN && Sa[1] == 0.0 && na[0] == 0.0,
        "crack_eps_f: split again (state %d) at ε_p = ε_f", st);
  /* under compression (σ* = −1: ε_f = 0.13 + 0.13 e^{1.5} = 0.7126) the same strain is
     carried */
  const double Pc = 2e8;
  /* pure shear τ: σ_eq = √3 τ; with p = 2e8 and τ = p/√3, σ* = −p/σ_eq = −1 */
  double Sk[6] = {0, 0, 0, Pc / sqrt(3.0), 0, 0}, nk[3] = {1, 0, 0};
  CHECK(fabs(fracture_crack_eps_f(&cf, Pc, Sk) - (0.13 + 0.13 * exp(1.5))) < 1e-12,
        "crack_eps_f: σ* = −1 gives 0.7126");
  ec = 0.0;
  st = fracture_crack_return(&cf, 0, Pc, K, G, 0.5, Sk, nk, &ec, &dp);
  CHECK(st == FRACTURE_SPLIT,
        "crack_eps_f: ε_p = 0.5 carried under compression (σ* = −1), state %d", st);
}

/* fracture.energy: a material point in uniaxial strain along y, stretched in small steps
 * (elastic: p = −K ε_e, S = 2G ε_e dev(e_y e_y), ε_e = ε − w), with the cohesive return at
 * each step. The work σ_yy dε done on it until it splits is the triangle ½|σ_c| w_u: G_f
 * per unit area of a particle of spacing l. */
static double cohesive_state(double K, double G, double ee, double S[6])
{
  S[T_XX] = S[T_ZZ] = -2.0 * G * ee / 3.0;
  S[T_YY] = 4.0 * G * ee / 3.0;
  S[T_XY] = S[T_YZ] = S[T_XZ] = 0.0;
  return -K * ee;
}

static void test_cohesive(void)
{
  const double K = 160e9, G = 80e9, M = K + 4.0 / 3.0 * G, sc = 2.66e9, Gf = 11e3, l = 0.2e-3;
  struct fracture_params co = {.kind = FRACTURE_TRESCA, .sigma_c = -sc, .energy = Gf};
  const double wu = fracture_open_strain(&co, l);
  CHECK(fabs(wu - 2 * Gf / (sc * l)) < 1e-14 * wu, "cohesive: w_u = 2 G_f/(|σ_c| l) = %.5f", wu);
  CHECK(!fracture_opening(&co, FRACTURE_INTACT) && fracture_opening(&co, FRACTURE_OPENING) &&
            !fracture_opening(&co, FRACTURE_SPLIT),
        "cohesive: opening for 0 < D < 1 only");
  CHECK(fracture_keeps_stress(&co, FRACTURE_OPENING) &&
            fracture_yield(&co, FRACTURE_OPENING, 1.55e9, 0.0) == 1.55e9,
        "cohesive: an opening particle keeps its deviator and its yield stress");
  /* monotonic stretching to the split */
  double eps = 0.0, w = 0.0, D = 0.0, S[6], n[3] = {0, 0, 0}, work = 0.0, peak = 0.0;
  double sig_old = 0.0, eps_at_split = -1.0, sig_at_01 = -1.0;
  const double de = wu / 20000.0;
  int steps = 0;
  while (D < 1.0 && steps < 100000) {
    eps += de;
    steps++;
    double p = cohesive_state(K, G, eps - w, S), dp = 0.0;
    const double d = fracture_tension(&co, D, p, S, 1e-9);
    D = fracture_cohesive_return(&co, D, d, p, K, G, l, S, n, &w, &dp);
    const double sig = D >= 1.0 ? 0.0 : -(p + dp) + S[T_YY];
    work += 0.5 * (sig + sig_old) * de;
    sig_old = sig;
    peak = fmax(peak, sig);
    if (D >= 1.0) eps_at_split = eps;
    if (sig_at_01 < 0 && D >= 0.1 && D < 1.0) sig_at_01 = sig;
  }
  CHECK(D == 1.0 && n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0 && w == 0.0,
        "cohesive: split (D = %g) clears the normal and w", D);
  CHECK(fabs(peak - sc) < 1e-3 * sc, "cohesive: the stress peaks at |σ_c| (%.5g GPa)", peak * 1e-9);
  CHECK(fabs(sig_at_01 - 0.9 * sc) < 2e-3 * sc,
        "cohesive: at D = 0.1 the plane carries 0.9|σ_c| "
        "(%.5g GPa)",
        sig_at_01 * 1e-9);
  CHECK(fabs(eps_at_split - wu) < 2e-4 * wu,
        "cohesive: it splits when the strain reaches w_u "
        "(ε/w_u = %.6f)",
        eps_at_split / wu);
  CHECK(fabs(work * l / Gf - 1.0) < 1e-3,
        "cohesive: the work to split it, times l, is G_f: "
        "%.2f J/m2 (%.0f), %d steps",
        work * l, Gf, steps);
  /* a short pulse: stretched to 0.3 w_u and back to compression — it does not split, the
     opening closes, and on reloading the plane carries (1 − D)|σ_c| at most */
  eps = w = D = 0.0;
  n[0] = n[1] = n[2] = 0.0;
  double Dpulse = 0.0, peak2 = 0.0;
  for (int phase = 0; phase < 3; phase++) {
    const double target = phase == 0 ? 0.3 * wu : phase == 1 ? -0.01 : 0.6 * wu;
    const double step = (target - eps) / 20000.0;
    for (int k = 0; k < 20000; k++) {
      eps += step;
      double p = cohesive_state(K, G, eps - w, S), dp = 0.0;
      D = fracture_cohesive_return(&co, D, fracture_tension(&co, D, p, S, 1e-9), p, K, G, l, S, n,
                                   &w, &dp);
      if (phase == 2) peak2 = fmax(peak2, -(p + dp) + S[T_YY]);
    }
    if (phase == 0) Dpulse = D;
    /* on the softening line ε = D w_u + (1 − D)|σ_c|/M: D = (ε/w_u − r)/(1 − r), r = |σ_c|/(M w_u) */
    const double r = sc / (M * wu);
    if (phase == 0)
      CHECK(fabs(D - (0.3 - r) / (1 - r)) < 1e-3,
            "cohesive: stretched to 0.3 w_u, "
            "D = %.4f ((0.3 − r)/(1 − r) = %.4f)",
            D, (0.3 - r) / (1 - r));
    if (phase == 1)
      CHECK(w == 0.0 && D == Dpulse,
            "cohesive: compressed after the pulse, the "
            "opening has closed (w = %g) and D = %.4f stays",
            w, D);
    if (phase == 2)
      CHECK(fabs(D - (0.6 - r) / (1 - r)) < 1e-3,
            "cohesive: reloaded to 0.6 w_u, "
            "the opening went on: D = %.4f (%.4f)",
            D, (0.6 - r) / (1 - r));
  }
  CHECK(fabs(peak2 - (1.0 - Dpulse) * sc) < 2e-3 * sc,
        "cohesive: reloaded, the plane carries (1 − D)|σ_c| = %.4g GPa at most (%.4g)",
        (1.0 - Dpulse) * sc * 1e-9, peak2 * 1e-9);
  /* a tiny G_f: the paper's rule (split at once, where the softening line is steeper than M) */
  struct fracture_params co0 = {.kind = FRACTURE_TRESCA, .sigma_c = -sc, .energy = 1e-9};
  double p = cohesive_state(K, G, 1.01 * sc / M, S), dp, w0 = 0.0, n0[3];
  D = fracture_cohesive_return(&co0, 0.0, fracture_tension(&co0, 0.0, p, S, 1e-9), p, K, G, l, S,
                               n0, &w0, &dp);
  CHECK(D == 1.0, "cohesive: G_f -> 0 splits at once (D = %g), as the paper's rule", D);
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
  struct fracture_params cu = {
      .kind = FRACTURE_CUMULATIVE, .sigma_c = -1e8, .eps_f = 0.5, .tau = 1e-6};
  double Dc = 0.0;
  int32_t sc = FRACTURE_INTACT;
  fracture_plastic(&cu, 0.1, &Dc, &sc);
  CHECK_CLOSE(Dc, 0.2, 1e-15, "cumulative: dD = deps/eps_f");
  CHECK(sc == FRACTURE_INTACT, "cumulative: intact below D = 1");
  fracture_plastic(&cu, 0.45, &Dc, &sc);
  CHECK(Dc == 1.0 && sc == FRACTURE_SPLIT,
        "cumulative: plastic strain to D = 1 splits it (D = "
        "%g, state %d)",
        Dc, (int)sc);
  CHECK_CLOSE(fracture_tension(&cu, 0.2, -2e8, S0, 2e-7), 0.4, 1e-12,
              "cumulative: dD = dt/tau in tension");
  CHECK(fracture_tension(&cu, 0.9, -2e8, S0, 2e-7) == 1.0, "cumulative: split at D = 1");
  /* split material: no deviatoric stress (the paper's rule), or min(Y, μ max(p, 0)) */
  CHECK(fracture_keeps_stress(&tr, FRACTURE_INTACT) && !fracture_keeps_stress(&tr, FRACTURE_SPLIT),
        "without friction only intact particles keep a deviatoric stress");
  CHECK(fracture_yield(&tr, FRACTURE_SPLIT, 0.383e9, 1e9) == 0.0, "split, no friction: Y = 0");
  struct fracture_params fr = {.kind = FRACTURE_TRESCA, .sigma_c = -0.39e9, .friction = 0.3};
  CHECK(fracture_keeps_stress(&fr, FRACTURE_SPLIT),
        "with friction split particles keep a deviatoric stress");
  CHECK(fracture_yield(&fr, FRACTURE_INTACT, 0.383e9, 1e9) == 0.383e9,
        "not yet split: the intact Y");
  CHECK_CLOSE(fracture_yield(&fr, FRACTURE_SPLIT, 0.383e9, 1e9), 0.3e9, 1e-15,
              "split: Y = μp below Y0");
  CHECK(fracture_yield(&fr, FRACTURE_SPLIT, 0.383e9, 2e9) == 0.383e9, "split: Y = Y0 when μp > Y0");
  CHECK(fracture_yield(&fr, FRACTURE_SPLIT, 0.383e9, -1e8) == 0.0,
        "split: no strength without pressure");
  test_no_tension();
  test_crack();
  test_cohesive();
}

/* The explicit fracture state (fracture.h): where a body's damage starts it, the check a
 * restart makes of a checkpoint's states, and the end of a step moving an intact
 * particle in tension beyond |σ_c| to split (damage 1, S dropped, its pressure to be
 * evaluated again). */
static void test_states(void)
{
  struct material mat[3];
  memset(mat, 0, sizeof mat);
  mat[0].frac = (struct fracture_params){.kind = FRACTURE_TRESCA, .sigma_c = -0.39e9};
  mat[1].frac =
      (struct fracture_params){.kind = FRACTURE_TRESCA, .sigma_c = -0.39e9, .split = SPLIT_CRACK};
  mat[2].frac =
      (struct fracture_params){.kind = FRACTURE_TRESCA, .sigma_c = -0.39e9, .energy = 1e4};
  double d;
  int32_t st;
  fracture_start(&mat[0].frac, 1.0, &d, &st);
  CHECK(d == 1.0 && st == FRACTURE_SPLIT, "start: damage 1 is split (D = %g, state %d)", d,
        (int)st);
  fracture_start(&mat[1].frac, 1.0, &d, &st);
  CHECK(d == 2.0 && st == FRACTURE_SPLIT_AGAIN,
        "start: split: crack starts split again, no "
        "crack known (D = %g, state %d)",
        d, (int)st);
  fracture_start(&mat[2].frac, 0.3, &d, &st);
  CHECK(d == 0.3 && st == FRACTURE_OPENING, "start: energy and 0 < D < 1 is opening (state %d)",
        (int)st);
  fracture_start(&mat[0].frac, 0.3, &d, &st);
  CHECK(d == 0.3 && st == FRACTURE_INTACT, "start: D < 1 is intact (state %d)", (int)st);

  struct particles p;
  particles_init(&p);
  particles_enable_solid(&p);
  particles_add(&p, 3);
  p.n = 3;
  const double dmg[3] = {1.0, 2.0, 0.5};
  const int32_t sts[3] = {FRACTURE_SPLIT, FRACTURE_SPLIT_AGAIN, FRACTURE_OPENING};
  for (size_t i = 0; i < 3; i++) {
    p.mat[i] = (int32_t)i;
    p.damage[i] = dmg[i];
    p.fstate[i] = sts[i];
  }
  CHECK(fracture_check_states(&p, mat) == (size_t)-1, "check: states that agree pass");
  const struct {
    size_t i;
    int32_t st;
    double d;
    const char *what;
  } bad[] = {{0, FRACTURE_SPLIT_AGAIN, 2.0, "split again without split: crack"},
             {0, FRACTURE_OPENING, 0.5, "opening without fracture.energy"},
             {1, FRACTURE_SPLIT, 0.5, "split with D = 0.5"},
             {2, FRACTURE_INTACT, 0.5, "intact with an opening's D under fracture.energy"},
             {2, 7, 0.5, "a state out of range"},
             {2, -1, 0.5, "a negative state"}};
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
    const int32_t s0 = p.fstate[bad[k].i];
    const double d0 = p.damage[bad[k].i];
    p.fstate[bad[k].i] = bad[k].st;
    p.damage[bad[k].i] = bad[k].d;
    CHECK(fracture_check_states(&p, mat) == bad[k].i, "check: %s is refused", bad[k].what);
    p.fstate[bad[k].i] = s0;
    p.damage[bad[k].i] = d0;
  }

  /* the end of a step: intact particle 0 in hydrostatic tension 0.5 GPa > |σ_c| splits */
  p.fstate[0] = FRACTURE_INTACT;
  p.damage[0] = 0.0;
  p.p[0] = -0.5e9;
  for (int k = 0; k < 6; k++) p.S[k][0] = k < 3 ? 1e7 * (k - 1) : 0.0;
  p.n = 1;
  const long again = fracture_end_step(&p, mat, 1e-9);
  double smax = 0.0;
  for (int k = 0; k < 6; k++) smax = fmax(smax, fabs(p.S[k][0]));
  CHECK(p.fstate[0] == FRACTURE_SPLIT && p.damage[0] == 1.0 && smax == 0.0 && again == 1,
        "end of step: tension beyond |σ_c| splits (state %d, D = %g, |S| %g, %ld to evaluate "
        "again)",
        (int)p.fstate[0], p.damage[0], smax, again);
  p.p[0] = -0.3e9; /* split, below |σ_c|: stays split, still in tension */
  CHECK(fracture_end_step(&p, mat, 1e-9) == 1 && p.fstate[0] == FRACTURE_SPLIT,
        "end of step: a split particle stays split");
  particles_free(&p);
}

int main(void)
{
  test_eigen();
  test_negative_definite();
  test_rate();
  test_return();
  test_fracture();
  test_states();
  return test_finish();
}
