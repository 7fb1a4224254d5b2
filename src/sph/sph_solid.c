/* sph_solid.c — the two neighbour passes with stress: elastic–plastic solids,
 * fracture and contact between bodies.
 *
 * First pass, per particle i:
 *   dρᵢ/dt = ρᵢ Σⱼ (mⱼ/ρⱼ) vᵢⱼ·∇ᵢWᵢⱼ        (all neighbours; a condensed particle's
 *                                              over condensed ones only, not gas)
 *   Lᵢ = Σⱼ (mⱼ/ρⱼ) (vⱼ − vᵢ) ⊗ ∇ᵢWᵢⱼ                       (same body only)
 *   Ṡᵢ from Lᵢ (Jaumann, strength.h); S* = return(Sⁿ + ½Δt Ṡ), S¹ = return(Sⁿ + Δt Ṡ)
 *   deviatoric heating S*:ε̇/ρ.
 * Second pass, with σ = −pI + S (its principal tensions removed for split particles
 * without tension, fracture.h):
 *   dvᵢ/dt = Σⱼ mⱼ (σᵢ/ρᵢ² + σⱼ/ρⱼ² − Πᵢⱼ I + (Rᵢ + Rⱼ) fᵢⱼⁿ)·∇ᵢWᵢⱼ
 *   deᵢ/dt += Σⱼ mⱼ (pᵢ/ρᵢ² + Πᵢⱼ/2) vᵢⱼ·∇ᵢWᵢⱼ
 * with fᵢⱼ = W(rᵢⱼ)/W(Δp) and Δp = hᵢⱼ/η the particle spacing (Gray, Monaghan & Swift
 * 2001, CMAME 190:6641, eqs. 22–24).
 * Contact: a pair of particles of different bodies exchanges only compressive
 * pressure (max(p, 0)) and viscosity, and while it separates it can unload a
 * compressed particle to its reference density but not stretch it further: bodies
 * push but never pull each other. (Wall ghosts belong to their source's body: a wall
 * is a mirror, exact for compression; it can hold a body that rebounds from it.)
 * Tensors are 6-component, VTK order (particles.h).
 *
 * Layout: each pass is a loop over cells (resting cells left to rest.c) calling a
 * per-particle function, which copies the particle's neighbours from the records of
 * partner.c into a structure-of-arrays tile (the contact rules worked out per pair where
 * they do not depend on the pair's motion: density_tile_fill, force_tile_fill) and sums
 * the pair physics in one vector loop (density_tile_sums, force_tile_sums): pair.h's
 * geometry and viscosity (shared with the gas loops, sph.c) with their branches as
 * selects.
 */
#include <math.h>
#include <stdlib.h>

#include "core/error.h"
#include "eos/eos.h"
#include "fracture/fracture.h"
#include "sph/avswitch.h"
#include "sph/nsearch.h"
#include "sph/pair.h"
#include "sph/partner.h"
#include "sph/recon.h"
#include "sph/rest.h"
#include "sph/rz.h"
#include "sph/sph.h"
#include "strength/strength.h"
#include "strength/sym3.h"

/* The piece of body b (bodies[i].part_of; every body its own without a table). */
/* Whether particle i carries a deviatoric stress: a material with strength, intact or
 * split with friction (fracture.friction). */
static int has_strength(const struct material *m, int fstate)
{
  return m->str.enabled && fracture_keeps_stress(&m->frac, fstate);
}

/* Stress update of particle i from its velocity gradient L. */
static void update_stress(struct particles *p, size_t i, const struct material *m,
                          const double L[9], double dt)
{
  double S0[6], dS[6], Sm[6], S1[6];
  for (int k = 0; k < 6; k++) S0[k] = p->S[k][i];
  const double G = m->str.G;
  const double Y = fracture_yield(
      &m->frac, p->fstate[i],
      strength_yield(&m->str, p->eps_p[i], strength_equivalent_rate(L), p->e[i]), p->p[i]);
  strength_rate(G, S0, L, dS);
  for (int k = 0; k < 6; k++) {
    Sm[k] = S0[k] + 0.5 * dt * dS[k];
    S1[k] = S0[k] + dt * dS[k];
  }
  strength_return(G, Y, Sm);
  const double deps = strength_return(G, Y, S1);
  p->eps_p[i] += deps;
  fracture_plastic(&m->frac, deps, &p->damage[i], &p->fstate[i]);
  /* split without tension: the forces see the deviator S' of σ' (σ = −p I + Sm with its
     principal tensions removed, p the mid-step pressure: the EOS at the mid-step
     density and energy, as step.c finds it after this pass — the same operations, the
     same bits), so the heating takes S':ε̇ (and the pressure force's pdV work p').
     Sm itself is kept. (If the EOS fails here, update_eos reports it.) */
  if (p->cracks &&
      fracture_opening(&m->frac, p->fstate[i])) { /* the crack turns with the material */
    double n[3] = {p->crack[0][i], p->crack[1][i], p->crack[2][i]};
    fracture_crack_rotate(n, L, dt);
    for (int k = 0; k < 3; k++) p->crack[k][i] = n[k];
  }
  double Se[6];
  const double *Sh = Sm;
  if (fracture_no_tension(&m->frac, p->fstate[i])) {
    struct eos_state st;
    if (!eos_evaluate(m, p->rho[i] + 0.5 * dt * p->drho[i], p->e[i], &st)) {
      fracture_effective(st.p, Sm, Se);
      Sh = Se;
    }
  }
  /* S*:ε̇ with ε̇ the symmetric part of L */
  const double exx = L[0], eyy = L[4], ezz = L[8];
  const double exy = 0.5 * (L[1] + L[3]), eyz = 0.5 * (L[5] + L[7]), exz = 0.5 * (L[2] + L[6]);
  const double power = Sh[T_XX] * exx + Sh[T_YY] * eyy + Sh[T_ZZ] * ezz +
                       2.0 * (Sh[T_XY] * exy + Sh[T_YZ] * eyz + Sh[T_XZ] * exz);
  p->de[i] = power / p->rho[i];
  for (int k = 0; k < 6; k++) {
    p->S[k][i] = Sm[k];
    p->S1[k][i] = S1[k];
  }
}

/* The first pass's inputs, set once per call. */
struct density_pass {
  struct particles *p;
  const struct sph_params *sp;
  const struct material *mat;
  double *gradv; /* sph.viscosity.reconstruct: L of every real (else NULL) */
  double dt;
  const double *drec; /* the density records (partner.h) */
};

/* Particle i's side of its first-pass sums, the same for all its pairs. */
struct density_i {
  double x, y, z, h, vx, vy, vz;
  const struct material *m;
  int32_t piece;
  int cond;   /* a condensed material (any EOS but the ideal gas) */
  int strong; /* carries a deviatoric stress: sums L (and A with corr) */
  int corr;   /* sums the correction matrix A */
  int sw;     /* the viscosity switch's gradient, every neighbour */
  int dd;     /* density diffusion, with neighbours at ρ ≥ dd_rho */
  double dd_rho;
};

/* The first pass's sums of particle i over its neighbours. */
struct density_sums {
  double sum, ddiff, L[9], A[9], Lsw[9], Asw[9];
};

/* The neighbours of one particle as structure-of-arrays tiles: field f of the k-th
 * selected neighbour at a[f·cap + k], each field 64-byte aligned, the count padded to
 * TILE_W with neutral lanes (tile_pad). The pair loops gather their partners' data
 * here once (scalar copies: gathers are slow on the AVX-512 machines, and the partner
 * record is read whole anyway), then run the pair physics as one branch-free
 * `#pragma omp simd` loop over the tile: every branch of the scalar physics (viscosity
 * for approaching pairs only, the contact rules, the artificial stress, the kernel's
 * pieces) is computed on every lane and chosen by a select. Each lane's partial sums
 * are added in a fixed order set by the compiled code, never by the threads, so the
 * results stay independent of the thread count (docs/design.md, "Neighbour search");
 * they differ from a scalar loop's by rounding only. */
enum { TILE_W = 8 }; /* lanes: one AVX-512 vector of doubles */

struct tile {
  size_t cap; /* lanes per field, a multiple of TILE_W */
  double *a;
  int as; /* force tile: some pair carries the artificial stress */
};

static void tile_reserve(struct tile *t, size_t n, int nfield)
{
  const size_t need = (n + TILE_W - 1) / TILE_W * TILE_W;
  if (need <= t->cap && t->a) return;
  free(t->a);
  t->cap = need + TILE_W; /* (a small tile: all its fields stay in L1) */
  t->a = aligned_alloc(64, t->cap * (size_t)nfield * sizeof *t->a);
  if (!t->a)
    HV_FATAL("out of memory: %zu bytes for a neighbour tile",
             t->cap * (size_t)nfield * sizeof *t->a);
}

static void tile_free(struct tile *t)
{
  free(t->a);
  t->a = NULL;
  t->cap = 0;
}

/* The count n padded to whole vectors. */
static inline size_t tile_round(size_t n) { return (n + TILE_W - 1) / TILE_W * TILE_W; }

/* kernel_f (kernel.h) with its pieces as selects, for a constant k, without the
 * branches that stop vectorisation; 1/h and h/r from one division 1/(r h) (r = 0 taken as
 * h there: no outer shell at q = 0). Division is the vector loops' scarcest unit (an
 * AVX-512 division of 8 doubles takes as long as about 30 multiplications), so this
 * saves; in the scalar loops it did not (kernel.h). The same values to rounding. */
static inline __attribute__((always_inline)) double tile_kernel_f(enum kernel_kind k, double r,
                                                                  double h)
{
  const double rs = r > 0.0 ? r : h, inv = 1.0 / (rs * h);
  const double ih = rs * inv, hr = h * h * inv; /* 1/h, h/r */
  const double q = r * ih, ih2 = ih * ih, ih5 = ih2 * ih2 * ih;
  const enum kernel_kind b = KERNEL_BASE(k);
  double f;
  if (b == KERNEL_WENDLAND_C2) {
    const double t = 1.0 - 0.5 * q;
    f = (-5.0 * 21.0 / (16.0 * HV_KERNEL_PI)) * ih5 * t * t * t;
  } else if (b == KERNEL_QUADRATIC) {
    const double fq = 5.0 / (4.0 * HV_KERNEL_PI) * ih5 * (0.375 - 0.75 * hr);
    f = q < 1e-12 ? 0.0 : fq;
  } else {
    const double fi = (-3.0 + 2.25 * q) * (1.0 / HV_KERNEL_PI) * ih5;
    const double t = 2.0 - q;
    const double fo = (-0.75 / HV_KERNEL_PI) * t * t * ih5 * hr;
    f = q < 1.0 ? fi : fo;
  }
  if ((int)k & KERNEL_2D) f *= kernel_to_2d(k, h); /* the meridional plane's normalisation */
  return q >= 2.0 ? 0.0 : f;
}

/* kernel_w_h3 (kernel.h) with its pieces as selects, for a constant k. */
static inline __attribute__((always_inline)) double tile_kernel_w_h3(enum kernel_kind k, double q)
{
  const enum kernel_kind b = KERNEL_BASE(k);
  double w;
  if (b == KERNEL_WENDLAND_C2) {
    const double t = 1.0 - 0.5 * q;
    w = 21.0 / (16.0 * HV_KERNEL_PI) * t * t * t * t * (2.0 * q + 1.0);
  } else if (b == KERNEL_QUADRATIC) {
    w = 5.0 / (4.0 * HV_KERNEL_PI) * (0.1875 * q * q - 0.75 * q + 0.75);
  } else {
    const double wi = (1.0 - 1.5 * q * q + 0.75 * q * q * q) * (1.0 / HV_KERNEL_PI);
    const double t = 2.0 - q;
    const double wo = 0.25 / HV_KERNEL_PI * t * t * t;
    w = q < 1.0 ? wi : wo;
  }
  if ((int)k & KERNEL_2D) w *= kernel_to_2d(k, 1.0); /* h² W in the meridional plane */
  return q >= 2.0 ? 0.0 : w;
}

/* A real particle's selected neighbours, js[0..n): candidate indices of its cell's
 * search (first pass) or partner slots (second pass). */
struct partners {
  uint32_t i;
  size_t n, cap;
  uint32_t *js;
};

/* Takes the nsel neighbours of real i selected in ns into l (candidate indices when
 * slots is 0, else their slots), and asks for their records' first `lines` lines in rec:
 * the records are scattered over the slots, and the copy into a tile waited on each in
 * turn; asked for one particle ahead, they arrive while the previous particle's pairs
 * are computed. */
static void partners_take(const double *rec, int lines, int slots, const struct nsearch *ns,
                          size_t nsel, uint32_t i, struct partners *l)
{
  if (nsel > l->cap) {
    free(l->js);
    l->cap = nsel + nsel / 2 + 64;
    l->js = malloc(l->cap * sizeof *l->js);
    if (!l->js) HV_FATAL("out of memory: %zu bytes for a neighbour list", l->cap * sizeof *l->js);
  }
  l->i = i;
  l->n = nsel;
  for (size_t k = 0; k < nsel; k++) {
    const uint32_t q = ns->sel[k], j = ns->j[q];
    const double *wj = rec + PR_LEN * (size_t)j;
    l->js[k] = slots ? j : q;
    for (int c = 0; c < lines; c++) __builtin_prefetch(wj + 8 * c);
  }
}

/* The first pass's tile fields: the candidate's x, h (from the search), the density
 * record's v, mⱼ/ρⱼ, ρ (partner.h); 2mⱼ/ρ₀ⱼ; and per pair, as 0/1, the contact rules
 * (density_tile_fill): never counted (a condensed particle and a gas),
 * not counted while separating (two pieces with ρᵢ ≤ ρ₀ᵢ), weighed by 2mⱼ/ρ₀ⱼ instead of
 * Vⱼ, in the density diffusion, in L and A (same piece, strength). */
enum {
  FD_X = 0,
  FD_H = 3,
  FD_V = 4,
  FD_VOL = 7,
  FD_RHO,
  FD_WREF,
  FD_NEVER,
  FD_SEP,
  FD_REF,
  FD_DD,
  FD_L,
  FD_N
};

/* Fills the density tile with the nsel neighbours of i selected in ns from the density
 * records drec, padded to whole vectors; returns the padded count. */
static size_t density_tile_fill(const struct density_pass *dp, const struct density_i *I,
                                uint32_t i, const struct nsearch *ns, const struct partners *l,
                                const double *drec, struct tile *t)
{
  const size_t nsel = l->n;
  const struct particles *p = dp->p;
  tile_reserve(t, nsel, FD_N);
  const size_t cap = t->cap, n = tile_round(nsel);
  double *restrict a = t->a;
  const int sep = p->rho[i] <= I->m->rho0, mati = p->mat[i];
  /* The contact rules of the continuity sum, per pair:
     - a pair of different bodies separating may unload a compressed particle back to its
       reference density, but not stretch it beyond: contact carries no tension, in the
       density as in the forces (FD_SEP, with the pair's motion in the vector loop);
     - a condensed particle's density follows condensed neighbours only: a gas particle's
       volume mⱼ/ρⱼ is hundreds of times its own, and its velocity would set the
       compression of a fragment flying through the gas; the gas still pushes it through
       the pressure force (docs/models.md) (FD_NEVER);
     - a neighbour counts with at most twice its reference volume, 2mⱼ/ρ₀ⱼ: sprayed debris
       of another body far below ρ₀ would otherwise weigh a lone particle's compression by
       many times its mass's volume, and within a body of condensed material a cluster of
       expanding debris whose volumes mⱼ/ρⱼ overlap would feed its own expansion
       (docs/models.md, "Contact between bodies"). Above ρ₀/2 nothing changes (FD_REF);
     - sph.density_diffusion (Molteni & Colagrossi 2009): ψᵢⱼ·∇ᵢWᵢⱼ =
       2(ρⱼ − ρᵢ)(xⱼ − xᵢ)·(xᵢ − xⱼ) f/r² = −2(ρⱼ − ρᵢ) f (f < 0): the particle's density
       relaxes towards its neighbours' — a discrete Laplacian of ρ, zero in a uniform or
       linear density field; never across two pieces or two materials, whose densities
       differ by right, nor with expanded material (FD_DD). */
  for (size_t k = 0; k < nsel; k++) {
    const uint32_t q = l->js[k];
    const double *wj = drec + PR_LEN * (size_t)ns->j[q];
    a[FD_X * cap + k] = ns->x[q];
    a[(FD_X + 1) * cap + k] = ns->y[q];
    a[(FD_X + 2) * cap + k] = ns->z[q];
    a[FD_H * cap + k] = ns->h[q];
    for (int f = 0; f < 5; f++) a[(FD_V + f) * cap + k] = wj[DR_V + f]; /* v, m/ρ, ρ */
    const int32_t kind = (int32_t)wj[DR_KIND];
    const int same = (kind >> 2) == I->piece, gas = kind & 1, below = (kind >> 1) & 1;
    const double rhoj = wj[DR_RHO];
    a[FD_WREF * cap + k] = wj[DR_WREF];
    a[FD_NEVER * cap + k] = I->cond && gas;
    a[FD_SEP * cap + k] = !same && sep;
    a[FD_REF * cap + k] = (!same || I->cond) && below;
    a[FD_DD * cap + k] = I->dd && same && (int)wj[DR_MAT] == mati && rhoj >= I->dd_rho;
    a[FD_L * cap + k] = I->strong && same;
  }
  /* neutral lanes: never counted, 4hᵢ away (q ≥ 2) */
  for (size_t k = nsel; k < n; k++) {
    for (int f = 0; f < FD_N; f++) a[f * cap + k] = 0.0;
    a[FD_X * cap + k] = I->x + 4.0 * I->h;
    a[(FD_X + 1) * cap + k] = I->y;
    a[(FD_X + 2) * cap + k] = I->z;
    a[FD_H * cap + k] = I->h;
    a[FD_VOL * cap + k] = 0.0;
    a[FD_RHO * cap + k] = 1.0;
    a[FD_NEVER * cap + k] = 1.0;
  }
  return n;
}

/* i's first-pass sums over the n lanes of its density tile, for kernel kk and the
 * options sw (the switch's L and A), lsum (the strength's L), asum (its A), dd (density
 * diffusion), each a constant where it is called: density_pair_sums's sums, their
 * branches as selects. */
static inline __attribute__((always_inline)) void
density_tile_sums(const struct density_i *I, double rhoi, const struct tile *t, size_t n,
                  enum kernel_kind kk, int sw, int lsum, int asum, int dd, struct density_sums *s)
{
  const size_t cap = t->cap;
  const double *restrict a = t->a;
  const double *restrict X = a + FD_X * cap, *restrict Y = a + (FD_X + 1) * cap,
                         *restrict Z = a + (FD_X + 2) * cap, *restrict H = a + FD_H * cap;
  const double *restrict VX = a + FD_V * cap, *restrict VY = a + (FD_V + 1) * cap,
                         *restrict VZ = a + (FD_V + 2) * cap, *restrict VOL = a + FD_VOL * cap,
                         *restrict RHO = a + FD_RHO * cap, *restrict WREF = a + FD_WREF * cap;
  const double *restrict NEVER = a + FD_NEVER * cap, *restrict SEP = a + FD_SEP * cap,
                         *restrict REF = a + FD_REF * cap, *restrict DD = a + FD_DD * cap,
                         *restrict LM = a + FD_L * cap;
  const double xi = I->x, yi = I->y, zi = I->z, hi = I->h, vxi = I->vx, vyi = I->vy, vzi = I->vz;
  /* each lane's sums, added in lane order at the end (as force_tile_sums) */
  double acc[38][TILE_W] = {{0}};
  for (size_t b = 0; b < n; b += TILE_W)
#pragma omp simd
    for (size_t l = 0; l < TILE_W; l++) {
      const size_t k = b + l;
      const double dx = xi - X[k], dy = yi - Y[k], dz = zi - Z[k];
      const double r = sqrt(dx * dx + dy * dy + dz * dz), hij = 0.5 * (hi + H[k]);
      const double f = tile_kernel_f(kk, r, hij);
      const double ux = VX[k] - vxi, uy = VY[k] - vyi, uz = VZ[k] - vzi;
      const double w = VOL[k] * f, udx = ux * dx + uy * dy + uz * dz; /* mⱼ/ρⱼ f */
      /* the contact rules (density_tile_fill): whether j counts, and its weight */
      const int64_t in = !((int64_t)(NEVER[k] != 0.0) | ((int64_t)(SEP[k] != 0.0) & (udx <= 0.0)));
      const double wd = REF[k] != 0.0 ? WREF[k] * f : w;
      const double wi = in ? wd : 0.0;
      acc[0][l] -= wi * udx;
      if (dd) {
        const double dterm = w * 2.0 * (RHO[k] - rhoi) * 0.5 * (hi + H[k]);
        const double ddm = in ? DD[k] : 0.0;
        acc[1][l] -= ddm != 0.0 ? dterm : 0.0;
      }
      if (sw) { /* avsw_add */
        const double v = in ? w : 0.0;
        acc[20][l] += v * ux * dx;
        acc[21][l] += v * ux * dy;
        acc[22][l] += v * ux * dz;
        acc[23][l] += v * uy * dx;
        acc[24][l] += v * uy * dy;
        acc[25][l] += v * uy * dz;
        acc[26][l] += v * uz * dx;
        acc[27][l] += v * uz * dy;
        acc[28][l] += v * uz * dz;
        acc[29][l] -= v * dx * dx;
        acc[30][l] -= v * dx * dy;
        acc[31][l] -= v * dx * dz;
        acc[32][l] -= v * dy * dx;
        acc[33][l] -= v * dy * dy;
        acc[34][l] -= v * dy * dz;
        acc[35][l] -= v * dz * dx;
        acc[36][l] -= v * dz * dy;
        acc[37][l] -= v * dz * dz;
      }
      if (lsum) { /* sph_grad_add_L, and sph_grad_add_A: A = Σ Vⱼ (xⱼ − xᵢ) ⊗ ∇ᵢWᵢⱼ */
        const double lm = in ? LM[k] : 0.0;
        const double v = lm != 0.0 ? w : 0.0;
        acc[2][l] += v * ux * dx;
        acc[3][l] += v * ux * dy;
        acc[4][l] += v * ux * dz;
        acc[5][l] += v * uy * dx;
        acc[6][l] += v * uy * dy;
        acc[7][l] += v * uy * dz;
        acc[8][l] += v * uz * dx;
        acc[9][l] += v * uz * dy;
        acc[10][l] += v * uz * dz;
        if (asum) {
          acc[11][l] -= v * dx * dx;
          acc[12][l] -= v * dx * dy;
          acc[13][l] -= v * dx * dz;
          acc[14][l] -= v * dy * dx;
          acc[15][l] -= v * dy * dy;
          acc[16][l] -= v * dy * dz;
          acc[17][l] -= v * dz * dx;
          acc[18][l] -= v * dz * dy;
          acc[19][l] -= v * dz * dz;
        }
      }
    }
  double tot[38] = {0};
  for (int q = 0; q < 38; q++)
    for (int l = 0; l < TILE_W; l++) tot[q] += acc[q][l];
  s->sum = tot[0];
  s->ddiff = tot[1];
  for (int k = 0; k < 9; k++) {
    s->L[k] = tot[2 + k];
    s->A[k] = tot[11 + k];
    s->Lsw[k] = tot[20 + k];
    s->Asw[k] = tot[29 + k];
  }
}

/* One vector loop for each kernel and each combination of the options (as
 * force_sums). */
#define DENSITY_SUMS_KK(KK)                                                                        \
  switch ((I->sw << 3) | (I->strong << 2) | (I->corr << 1) | I->dd) {                              \
  case 0: density_tile_sums(I, rhoi, t, n, KK, 0, 0, 0, 0, s); break;                              \
  case 1: density_tile_sums(I, rhoi, t, n, KK, 0, 0, 0, 1, s); break;                              \
  case 4: density_tile_sums(I, rhoi, t, n, KK, 0, 1, 0, 0, s); break;                              \
  case 5: density_tile_sums(I, rhoi, t, n, KK, 0, 1, 0, 1, s); break;                              \
  case 6: density_tile_sums(I, rhoi, t, n, KK, 0, 1, 1, 0, s); break;                              \
  case 7: density_tile_sums(I, rhoi, t, n, KK, 0, 1, 1, 1, s); break;                              \
  case 8: density_tile_sums(I, rhoi, t, n, KK, 1, 0, 0, 0, s); break;                              \
  case 9: density_tile_sums(I, rhoi, t, n, KK, 1, 0, 0, 1, s); break;                              \
  case 12: density_tile_sums(I, rhoi, t, n, KK, 1, 1, 0, 0, s); break;                             \
  case 13: density_tile_sums(I, rhoi, t, n, KK, 1, 1, 0, 1, s); break;                             \
  case 14: density_tile_sums(I, rhoi, t, n, KK, 1, 1, 1, 0, s); break;                             \
  default: density_tile_sums(I, rhoi, t, n, KK, 1, 1, 1, 1, s); break;                             \
  }

static void density_sums(const struct density_pass *dp, const struct density_i *I, double rhoi,
                         const struct tile *t, size_t n, struct density_sums *s)
{
  switch ((int)dp->sp->kernel) { /* a constant kind in each, 2D (KERNEL_2D: axisymmetric) or 3D */
  case KERNEL_WENDLAND_C2: DENSITY_SUMS_KK(KERNEL_WENDLAND_C2); break;
  case KERNEL_QUADRATIC: DENSITY_SUMS_KK(KERNEL_QUADRATIC); break;
  case KERNEL_CUBIC_SPLINE: DENSITY_SUMS_KK(KERNEL_CUBIC_SPLINE); break;
  case KERNEL_WENDLAND_C2 | KERNEL_2D:
    DENSITY_SUMS_KK((enum kernel_kind)(KERNEL_WENDLAND_C2 | KERNEL_2D));
    break;
  case KERNEL_QUADRATIC | KERNEL_2D:
    DENSITY_SUMS_KK((enum kernel_kind)(KERNEL_QUADRATIC | KERNEL_2D));
    break;
  default: DENSITY_SUMS_KK((enum kernel_kind)(KERNEL_CUBIC_SPLINE | KERNEL_2D)); break;
  }
}
#undef DENSITY_SUMS_KK

/* The velocity gradient L of real i from its sums, corrected where asked; with the
 * reconstruction also its stored gradient (0 without strength: no reconstruction for
 * its pairs). */
static inline void density_gradient(const struct density_pass *dp, uint32_t i,
                                    const struct density_i *I, int recon, struct density_sums *s)
{
  double *L = s->L;
  if (dp->gradv) {
    double *Gi = dp->gradv + 9 * (size_t)i;
    for (int t = 0; t < 9; t++) Gi[t] = recon ? L[t] : 0.0;
    if (recon) {
      sph_correct_gradient(Gi, s->A);
      if (dp->sp->grad_correction) /* the stress uses the same corrected gradient */
        for (int t = 0; t < 9; t++) L[t] = Gi[t];
    } else if (I->strong && dp->sp->grad_correction) {
      sph_correct_gradient(L, s->A);
    }
  } else if (I->corr) {
    sph_correct_gradient(L, s->A);
  }
}

/* The first pass for real l->i with its neighbours l (candidates in ns), through tile
 * t. */
static inline void density_rate_particle(const struct density_pass *dp, const struct nsearch *ns,
                                         const struct partners *l, struct tile *t)
{
  const uint32_t i = l->i;
  struct particles *p = dp->p;
  const struct sph_params *sp = dp->sp;
  const struct material *mi = &dp->mat[p->mat[i]];
  struct density_i I = {.x = p->x[0][i],
                        .y = p->x[1][i],
                        .z = p->x[2][i],
                        .h = p->h[i],
                        .vx = p->v[0][i],
                        .vy = p->v[1][i],
                        .vz = p->v[2][i],
                        .m = mi};
  I.strong = has_strength(mi, p->fstate[i]);
  /* the reconstruction's gradient: intact strength particles only (split ones with
     friction keep the standard viscosity, as without it) */
  const int recon = I.strong && p->fstate[i] < FRACTURE_SPLIT;
  I.piece = sph_piece_of(sp->piece, p->body[i]);
  I.cond = mi->eos != EOS_IDEAL_GAS;
  /* the correction matrix: for the stress with sph.gradient_correction, and for the
     reconstruction always (its limiter needs gradients exact for linear fields) */
  I.corr = I.strong && (sp->grad_correction || (dp->gradv && recon));
  I.sw = p->av;
  /* density diffusion between condensed states only (ρ ≥ ρ₀/2 on both sides), where it
     was tested (docs/models.md) */
  I.dd_rho = 0.5 * mi->rho0;
  I.dd = sp->density_diffusion > 0.0 && I.cond && p->rho[i] >= I.dd_rho;
  struct density_sums s = {0};
  const size_t n = density_tile_fill(dp, &I, i, ns, l, dp->drec, t);
  density_sums(dp, &I, p->rho[i], t, n, &s);
  p->drho[i] = p->rho[i] * s.sum + (I.dd ? sp->density_diffusion * p->cs[i] * s.ddiff : 0.0);
  if (I.sw)
    p->alpha[i] =
        avsw_update(sp, s.Lsw, s.Asw, p->alpha[i], p->divv[i], I.h, p->cs[i], dp->dt, &p->divv[i]);
  density_gradient(dp, i, &I, recon, &s);
  if (I.strong) {
    if (p->axisym) s.L[8] = I.vy / sph_rz_radius(I.y, I.h); /* the hoop rate v_r/r (rz.h) */
    update_stress(p, i, mi, s.L, p->step_dt ? p->step_dt[i] : dp->dt); /* its own step */
  } else {
    p->de[i] = 0.0;
    for (int k = 0; k < 6; k++) p->S[k][i] = p->S1[k][i] = 0.0;
  }
}

/* sph.viscosity.reconstruct: the cache's velocity gradients, sized for every slot and
 * marked stale until the ghosts' are refreshed; NULL without it. */
static double *gradv_reserve(const struct particles *p, const struct sph_params *sp,
                             struct sph_cache *cache)
{
  if (!(sp->reconstruct && cache)) return NULL;
  const size_t nall = p->n + p->n_ghost;
  if (nall > cache->gcap) {
    cache->gcap = nall + nall / 4 + 64;
    free(cache->gradv);
    cache->gradv = hv_malloc(cache->gcap * 9 * sizeof *cache->gradv, "velocity gradients");
  }
  cache->gradv_valid = 0;
  return cache->gradv;
}

void sph_density_rate_solid(struct particles *p, const struct nbr_grid *g,
                            const struct sph_params *sp, struct sph_cache *cache,
                            const struct material *mat, double dt)
{
  if (cache) cache_layout(cache, g);
  double *rec;
  int32_t *tag;
  partner_reserve(cache, p->n + p->n_ghost, &rec, &tag);
  const struct density_pass dp = {p, sp, mat, gradv_reserve(p, sp, cache), dt, rec};
  const int skip = sp->skip_resting && cache && !p->av;
  /* individual steps (step.h): the velocity gradients of the reals not evaluated now are
     those of their last evaluation, kept in the particle store (gvx, gvy, gvz: the cache's
     are per slot, and slots move when the particles are reordered or absorbed) */
  double *const *gvs[3] = {p->gvx, p->gvy, p->gvz};
  if (dp.gradv && p->active) {
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < p->n; i++)
      if (!p->active[i])
        for (int t = 0; t < 9; t++) dp.gradv[9 * i + (size_t)t] = gvs[t / 3][t % 3][i];
  }
  if (skip) rest_mark_first(p, g, cache);
  partner_pack_density(p, sp, mat, g, skip ? cache->rest : NULL, rec);
#pragma omp parallel
  {
    struct nsearch ns = {0};
    struct tile t = {0};
    struct partners l[2] = {{0}};
#pragma omp for schedule(dynamic, 8)
    for (size_t c = 0; c < g->ncells; c++) {
      if (skip && cache->rest[c]) { /* at rest: what the pass would write */
        rest_write_first(p, g, c, dp.gradv, p->active);
        continue;
      }
      int gathered = 0, have = 0, cur = 0;
      /* one particle behind the search (partners_take) */
      for (uint32_t ii = g->cell_start[c]; ii < g->cell_start[c + 1]; ii++) {
        const uint32_t i = g->order[ii];
        if (i >= p->n || (p->active && !p->active[i])) continue; /* inactive: step.h */
        const size_t nsel = nsearch_neighbours(&ns, &gathered, g, c, ii, p, NULL, cache);
        partners_take(rec, 1, 0, &ns, nsel, i, &l[cur ^ 1]);
        if (have) density_rate_particle(&dp, &ns, &l[cur], &t);
        cur ^= 1;
        have = 1;
      }
      if (have) density_rate_particle(&dp, &ns, &l[cur], &t);
    }
    nsearch_free(&ns);
    tile_free(&t);
    free(l[0].js);
    free(l[1].js);
  }
  if (dp.gradv && p->active) {
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < p->n; i++)
      if (p->active[i])
        for (int t = 0; t < 9; t++) gvs[t / 3][t % 3][i] = dp.gradv[9 * i + (size_t)t];
  }
  if (cache) cache->valid = 1;
  if (!cache) {
    free(rec);
    free(tag);
  }
}

void sph_artificial_stress(struct particles *p, const struct sph_params *sp,
                           const struct material *mat)
{
  if (!p->solid) return;
  const double eps = sp->as_eps;
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < p->n; i++) {
    double R[6] = {0, 0, 0, 0, 0, 0};
    double sig[6];
    for (int k = 0; k < 6; k++) sig[k] = p->S[k][i];
    sig[0] -= p->p[i];
    sig[1] -= p->p[i];
    sig[2] -= p->p[i];
    const struct material *mi = &mat[p->mat[i]];
    if (eps > 0 && has_strength(mi, p->fstate[i]) &&
        !fracture_no_tension(&mi->frac, p->fstate[i]) && sym3_max_bound(sig) > 0.0 &&
        !sym3_negative_definite(sig)) { /* no tension: R = 0, the same bits */
      double lam[3], Q[9], d[3];
      sym3_eigen(sig, lam, Q);
      const double r2 = p->rho[i] * p->rho[i];
      int any = 0;
      for (int k = 0; k < 3; k++) {
        d[k] = lam[k] > 0 ? -eps * lam[k] / r2 : 0.0;
        any |= lam[k] > 0;
      }
      if (any) sym3_from_eigen(Q, d, R);
    }
    for (int k = 0; k < 6; k++) p->R[k][i] = R[k];
  }
}

/* The force pass's inputs, set once per call. */
struct force_pass {
  struct particles *p;
  const struct material *mat;
  const int32_t *piece; /* sph_params.piece */
  const double *rec;    /* partner records */
  const int32_t *tag;   /* partner tags */
  const double *gradv;  /* sph.viscosity.reconstruct's gradients, else NULL */
  struct pair_visc pv;
  enum kernel_kind kk;
  int use_as;            /* artificial stress */
  int recon_contact;     /* the reconstruction for pairs of two pieces too */
  double as_n, inv_w_dp; /* its exponent n, and 1/(W(Δp, h)·h³) with Δp = h/η */
};

/* Particle i's side of the force pass, the same for all its pairs: p/ρ² and S/ρ² from
 * its own record (σ' for a split particle without tension), max(p/ρ², 0), its R, its
 * α (the switch) and its velocity gradient (the reconstruction). */
struct force_i {
  double x, y, z, h, vx, vy, vz, c, rho, pr, P, Pic, S[6], R[6], alpha, G[9];
  int R_any, gas;
  int32_t piece;
};

/* The force tile's fields: the partner record's x, h, v, m, p/ρ², S/ρ², ρ; the sound
 * speed; the pair's kind as 0/1 (same piece; the partner a gas; the artificial stress
 * applies; the reconstruction applies); the partner's α, R and velocity gradient G; the
 * artificial stress's fⁿ when n ≠ 4; the gas interface pressure term (0 unless the pair
 * is a gas against condensed material). */
enum {
  FT_X = 0,
  FT_H = 3,
  FT_V = 4,
  FT_M = 7,
  FT_P = 8,
  FT_S = 9,
  FT_RHO = 15,
  FT_C,
  FT_SAME,
  FT_GAS,
  FT_AS,
  FT_REC,
  FT_AV,
  FT_R,
  FT_G = FT_R + 6,
  FT_FN = FT_G + 9,
  FT_PGC,
  FT_N
};

/* Fills the tile with the nsel partners of i selected in ns, padded to whole vectors;
 * returns the padded count. */
static size_t force_tile_fill(const struct force_pass *fp, const struct force_i *I,
                              const uint32_t *js, size_t nsel, struct tile *t)
{
  tile_reserve(t, nsel, FT_N);
  const size_t cap = t->cap, n = tile_round(nsel);
  double *restrict a = t->a;
  t->as = 0;
  for (size_t k = 0; k < nsel; k++) {
    const uint32_t j = js[k];
    const double *wj = fp->rec + PR_LEN * (size_t)j;
    const int32_t kind = (int32_t)wj[PR_KIND], tj = kind >> 1;
    for (int f = 0; f < FT_C; f++) a[f * cap + k] = wj[f]; /* PR_X … PR_RHO */
    a[FT_C * cap + k] = wj[PR_C];
    const int same = (tj >> 1) == I->piece;
    a[FT_SAME * cap + k] = same;
    a[FT_GAS * cap + k] = kind & 1;
    /* a gas against condensed material: the gas's interface pressure 2 p̂_gas/(ρᵢρⱼ)
       (force_tile_sums), here: rare, and its division would cost every lane */
    double pgc = 0.0;
    if (!same && I->gas != (kind & 1)) {
      const double rr = 1.0 / (I->rho * wj[PR_RHO]);
      const double pg = I->gas ? I->pr : wj[PR_P] * wj[PR_RHO] * wj[PR_RHO];
      pgc = pg > 0.0 ? 2.0 * pg * rr : 0.0;
    }
    a[FT_PGC * cap + k] = pgc;
    if (fp->use_as) {
      const int on = same && (I->R_any | (tj & 1));
      a[FT_AS * cap + k] = on;
      t->as |= on;
    }
    if (fp->gradv) {
      a[FT_REC * cap + k] = same || fp->recon_contact;
      const double *Gj = fp->gradv + 9 * (size_t)j;
      for (int s = 0; s < 9; s++) a[(FT_G + s) * cap + k] = Gj[s];
    }
    if (fp->pv.av) a[FT_AV * cap + k] = fp->pv.av[j];
  }
  /* neutral lanes: a partner of zero mass at rest relative to i, 4hᵢ away (q ≥ 2: no
     kernel, no approach), which adds only zeros */
  for (size_t k = nsel; k < n; k++) {
    for (int f = 0; f < FT_N; f++) a[f * cap + k] = 0.0;
    a[FT_X * cap + k] = I->x + 4.0 * I->h;
    a[(FT_X + 1) * cap + k] = I->y;
    a[(FT_X + 2) * cap + k] = I->z;
    a[FT_H * cap + k] = I->h;
    a[FT_V * cap + k] = I->vx;
    a[(FT_V + 1) * cap + k] = I->vy;
    a[(FT_V + 2) * cap + k] = I->vz;
    a[FT_RHO * cap + k] = I->rho;
    a[FT_SAME * cap + k] = 1.0;
  }
  /* the artificial stress only where a pair carries it (R ≠ 0 on either side: in
     tension, rare): otherwise the loop without it, the same sums */
  if (!t->as) return n;
  for (size_t k = 0; k < nsel; k++) {
    const double *wj = fp->rec + PR_LEN * (size_t)js[k];
    for (int s = 0; s < 6; s++) a[(FT_R + s) * cap + k] = wj[PR_AS + s];
  }
  /* its fⁿ for an exponent other than 4: pow does not vectorise (with 4 the vector loop
     takes the product and this field stays 0) */
  if (fp->as_n == 4.0)
    for (size_t k = 0; k < nsel; k++) a[FT_FN * cap + k] = 0.0;
  else
    for (size_t k = 0; k < n; k++) {
      const double dx = I->x - a[FT_X * cap + k], dy = I->y - a[(FT_X + 1) * cap + k],
                   dz = I->z - a[(FT_X + 2) * cap + k];
      const double r = sqrt(dx * dx + dy * dy + dz * dz), hij = 0.5 * (I->h + a[FT_H * cap + k]);
      const double fr = kernel_w_h3(fp->kk, r * (1.0 / hij)) * fp->inv_w_dp;
      a[FT_FN * cap + k] = pow(fr, fp->as_n);
    }
  return n;
}

/* i's sums over the n lanes of its force tile, for kernel kk (a constant where it is
 * called): Σ mⱼ aᵢⱼ into out[0..2], Σ mⱼ ėᵢⱼ into out[3], the largest −μᵢⱼ of an
 * approaching pair into out[4] and its largest pair α into out[5].
 *
 * Per pair (unit mⱼ; gᵢⱼ = ∇ᵢWᵢⱼ = f rᵢⱼ):
 *   Πᵢⱼ (pair.h's pair_viscosity): 0 unless the pair approaches (vᵢⱼ·rᵢⱼ < 0);
 *   same piece: T = σᵢ/ρᵢ² + σⱼ/ρⱼ² (+ (Rᵢ + Rⱼ) fᵢⱼⁿ), aᵢⱼ = (T − Πᵢⱼ I)·gᵢⱼ,
 *     ėᵢⱼ = (pᵢ/ρᵢ² + ½Πᵢⱼ) vᵢⱼ·gᵢⱼ − ½ vᵢⱼ·(Rₛ fⁿ gᵢⱼ) (the artificial stress's work: the
 *     pair force is symmetric, so this keeps the total energy);
 *   gas against condensed material: the interface pressure is the gas's,
 *     2 p̂_gas/(ρᵢρⱼ) (p̂ = max(p, 0)): a uniform gas against a wall at rest is in
 *     balance (the wall particle's volume stands in for a gas particle's), and the
 *     condensed side's stress does not enter — at an SPH free surface it is not the
 *     traction there, and the soft gas sets the interface pressure: the condensed side
 *     acts through its motion, which compresses the gas (its density rate sums over
 *     every neighbour). The mass-weighted pᵢ/ρᵢ² + pⱼ/ρⱼ² blew the gas off a plate at
 *     rest. The pair's whole work goes to the gas: the condensed particle's density
 *     does not see the gas (pass 1), so neither does its energy, and the drag's heat
 *     is the gas's bow shock;
 *   contact between two pieces: compression only, max(pᵢ/ρᵢ², 0) + max(pⱼ/ρⱼ², 0). */
static inline __attribute__((always_inline)) void
force_tile_sums(const struct force_pass *fp, const struct force_i *I, const struct tile *t,
                size_t n, enum kernel_kind kk, int sw, int recon, int use_as, double out[6])
{
  const size_t cap = t->cap;
  const double *restrict a = t->a;
  const double *restrict X = a + FT_X * cap, *restrict Y = a + (FT_X + 1) * cap,
                         *restrict Z = a + (FT_X + 2) * cap, *restrict H = a + FT_H * cap;
  const double *restrict VX = a + FT_V * cap, *restrict VY = a + (FT_V + 1) * cap,
                         *restrict VZ = a + (FT_V + 2) * cap;
  const double *restrict M = a + FT_M * cap, *restrict PJ = a + FT_P * cap,
                         *restrict RHO = a + FT_RHO * cap, *restrict C = a + FT_C * cap;
  const double *restrict S0 = a + FT_S * cap, *restrict S1 = a + (FT_S + 1) * cap,
                         *restrict S2 = a + (FT_S + 2) * cap, *restrict S3 = a + (FT_S + 3) * cap,
                         *restrict S4 = a + (FT_S + 4) * cap, *restrict S5 = a + (FT_S + 5) * cap;
  const double *restrict SAME = a + FT_SAME * cap, *restrict GAS = a + FT_GAS * cap,
                         *restrict AS = a + FT_AS * cap, *restrict REC = a + FT_REC * cap,
                         *restrict AV = a + FT_AV * cap, *restrict FN = a + FT_FN * cap,
                         *restrict PGC = a + FT_PGC * cap;
  const double *restrict R0 = a + FT_R * cap, *restrict R1 = a + (FT_R + 1) * cap,
                         *restrict R2 = a + (FT_R + 2) * cap, *restrict R3 = a + (FT_R + 3) * cap,
                         *restrict R4 = a + (FT_R + 4) * cap, *restrict R5 = a + (FT_R + 5) * cap;
  const double *restrict G0 = a + FT_G * cap, *restrict G1 = a + (FT_G + 1) * cap,
                         *restrict G2 = a + (FT_G + 2) * cap, *restrict G3 = a + (FT_G + 3) * cap,
                         *restrict G4 = a + (FT_G + 4) * cap, *restrict G5 = a + (FT_G + 5) * cap,
                         *restrict G6 = a + (FT_G + 6) * cap, *restrict G7 = a + (FT_G + 7) * cap,
                         *restrict G8 = a + (FT_G + 8) * cap;
  const double xi = I->x, yi = I->y, zi = I->z, hi = I->h, vxi = I->vx, vyi = I->vy, vzi = I->vz;
  const double ci = I->c, rhoi = I->rho, Pi = I->P, Pic = I->Pic, avi = I->alpha;
  const double Si0 = I->S[0], Si1 = I->S[1], Si2 = I->S[2], Si3 = I->S[3], Si4 = I->S[4],
               Si5 = I->S[5];
  const double Ri0 = I->R[0], Ri1 = I->R[1], Ri2 = I->R[2], Ri3 = I->R[3], Ri4 = I->R[4],
               Ri5 = I->R[5];
  const double *Gi = I->G;
  const double eps = fp->pv.eps, alpha = fp->pv.alpha, beta = fp->pv.beta, bfac = fp->pv.bfac;
  const double inv_w_dp = fp->inv_w_dp;
  /* 64-bit flags: a 32-bit type in the loop would make gcc take 16 lanes, more than a
     block */
  const int64_t gasi = I->gas;
  const double c4 = fp->as_n == 4.0 ? 1.0 : 0.0;
  /* each lane's sums, added in lane order at the end: whole vectors of TILE_W lanes (n
     is a multiple), no remainder loop, and one sum per lane instead of a vector sum per
     block */
  double lx[TILE_W] = {0}, ly[TILE_W] = {0}, lz[TILE_W] = {0}, le[TILE_W] = {0}, lmu[TILE_W] = {0},
         lam[TILE_W] = {0};
  for (size_t b = 0; b < n; b += TILE_W)
#pragma omp simd
    for (size_t l = 0; l < TILE_W; l++) {
      const size_t k = b + l;
      const double dx = xi - X[k], dy = yi - Y[k], dz = zi - Z[k];
      const double r2 = dx * dx + dy * dy + dz * dz, r = sqrt(r2), hij = 0.5 * (hi + H[k]);
      const double f = tile_kernel_f(kk, r, hij);
      const double dvx = vxi - VX[k], dvy = vyi - VY[k], dvz = vzi - VZ[k];
      const double vdx = dvx * dx + dvy * dy + dvz * dz;
      /* Πᵢⱼ, pair.h's pair_viscosity with its branches as selects */
      const int64_t app = vdx < 0.0;
      /* one division for 1/(r² + ε h²) and 1/ρ̄ᵢⱼ (as the kernel's) */
      const double den = r2 + eps * hij * hij, rhoij = 0.5 * (rhoi + RHO[k]);
      const double inv = 1.0 / (den * rhoij), iden = rhoij * inv, irho = den * inv;
      const double mu0 = hij * vdx * iden;
      lmu[l] = app && -mu0 > lmu[l] ? -mu0 : lmu[l];
      double mu = mu0;
      if (recon) { /* sph_recon_approach (recon.h) */
        const double gi = dx * (Gi[0] * dx + Gi[1] * dy + Gi[2] * dz) +
                          dy * (Gi[3] * dx + Gi[4] * dy + Gi[5] * dz) +
                          dz * (Gi[6] * dx + Gi[7] * dy + Gi[8] * dz);
        const double gj = dx * (G0[k] * dx + G1[k] * dy + G2[k] * dz) +
                          dy * (G3[k] * dx + G4[k] * dy + G5[k] * dz) +
                          dz * (G6[k] * dx + G7[k] * dy + G8[k] * dz);
        const double prod = gi * gj, sum = gi + gj;
        const double w = vdx - 0.5 * (4.0 * prod / (sum * sum)) * sum;
        const double wc = w > 0.0 ? 0.0 : (w < vdx ? vdx : w);
        const double ap = prod > 0.0 ? wc : vdx;
        const double mur = hij * ap * iden;
        mu = REC[k] != 0.0 ? mur : mu0;
      }
      double visc;
      if (sw) {
        const double aij = 0.5 * (avi + AV[k]);
        lam[l] = app && aij > lam[l] ? aij : lam[l];
        visc = aij * (-0.5 * (ci + C[k]) * mu + bfac * mu * mu) * irho;
      } else {
        visc = (-alpha * 0.5 * (ci + C[k]) * mu + beta * mu * mu) * irho;
      }
      visc = app ? visc : 0.0;
      const double gx = f * dx, gy = f * dy, gz = f * dz; /* ∇ᵢWᵢⱼ */
      /* same piece */
      double T0 = Si0 + S0[k], T1 = Si1 + S1[k], T2 = Si2 + S2[k], T3 = Si3 + S3[k],
             T4 = Si4 + S4[k], T5 = Si5 + S5[k];
      double eas = 0.0;
      if (use_as) {
        const double Rs0 = Ri0 + R0[k], Rs1 = Ri1 + R1[k], Rs2 = Ri2 + R2[k], Rs3 = Ri3 + R3[k],
                     Rs4 = Ri4 + R4[k], Rs5 = Ri5 + R5[k];
        const double fr = tile_kernel_w_h3(kk, r * (1.0 / hij)) * inv_w_dp;
        /* fⁿ: (f²)² for n = 4 (FN is 0 then), else FN (c4 = 0); arithmetic, not a select
         on the loop-invariant n4, which gcc 12 does not vectorise */
        const double fn = (fr * fr) * (fr * fr) * c4 + FN[k];
        const int64_t on = AS[k] != 0.0;
        T0 = on ? T0 + Rs0 * fn : T0;
        T1 = on ? T1 + Rs1 * fn : T1;
        T2 = on ? T2 + Rs2 * fn : T2;
        T3 = on ? T3 + Rs3 * fn : T3;
        T4 = on ? T4 + Rs4 * fn : T4;
        T5 = on ? T5 + Rs5 * fn : T5;
        const double rx = (Rs0 * gx + Rs3 * gy + Rs5 * gz) * fn;
        const double ry = (Rs3 * gx + Rs1 * gy + Rs4 * gz) * fn;
        const double rz = (Rs5 * gx + Rs4 * gy + Rs2 * gz) * fn;
        eas = on ? -0.5 * (dvx * rx + dvy * ry + dvz * rz) : 0.0;
      }
      const double Psame = Pi + PJ[k] + visc;
      /* gas against condensed material */
      const double pgc = PGC[k]; /* (force_tile_fill) */
      /* contact: compression only */
      const double Pcon = Pic + (PJ[k] > 0 ? PJ[k] : 0.0) + visc;
      const int64_t same = SAME[k] != 0.0, mixed = gasi != (int64_t)(GAS[k] != 0.0);
      const double P = same ? Psame : (mixed ? pgc + visc : Pcon);
      const double Pme = same ? Pi : (mixed ? (gasi ? pgc : 0.0) : Pic);
      const double vw = same ? 0.5 : (mixed ? (gasi ? 1.0 : 0.0) : 0.5);
      T0 = same ? T0 : 0.0;
      T1 = same ? T1 : 0.0;
      T2 = same ? T2 : 0.0;
      T3 = same ? T3 : 0.0;
      T4 = same ? T4 : 0.0;
      T5 = same ? T5 : 0.0;
      const double ax = (T0 - P) * gx + T3 * gy + T5 * gz;
      const double ay = T3 * gx + (T1 - P) * gy + T4 * gz;
      const double az = T5 * gx + T4 * gy + (T2 - P) * gz;
      const double e = (Pme + vw * visc) * vdx * f + eas;
      const double mj = M[k];
      lx[l] += mj * ax;
      ly[l] += mj * ay;
      lz[l] += mj * az;
      le[l] += mj * e;
    }
  double sx = 0.0, sy = 0.0, sz = 0.0, se = 0.0, mumax = 0.0, amax = 0.0;
  for (int l = 0; l < TILE_W; l++) {
    sx += lx[l];
    sy += ly[l];
    sz += lz[l];
    se += le[l];
    mumax = lmu[l] > mumax ? lmu[l] : mumax;
    amax = lam[l] > amax ? lam[l] : amax;
  }
  out[0] = sx;
  out[1] = sy;
  out[2] = sz;
  out[3] = se;
  out[4] = mumax;
  out[5] = amax;
}

/* One vector loop for each kernel and each combination of the switch, the
 * reconstruction and the artificial stress, each known at compile time: gcc 12
 * vectorises no select on a loop-invariant flag, and the branch-free forms of the
 * options it leaves out would cost every pair their work. */
#define FORCE_SUMS_KK(KK)                                                                          \
  switch (((fp->pv.av != NULL) << 2) | ((fp->gradv != NULL) << 1) | (t->as != 0)) {                \
  case 0: force_tile_sums(fp, I, t, n, KK, 0, 0, 0, s); break;                                     \
  case 1: force_tile_sums(fp, I, t, n, KK, 0, 0, 1, s); break;                                     \
  case 2: force_tile_sums(fp, I, t, n, KK, 0, 1, 0, s); break;                                     \
  case 3: force_tile_sums(fp, I, t, n, KK, 0, 1, 1, s); break;                                     \
  case 4: force_tile_sums(fp, I, t, n, KK, 1, 0, 0, s); break;                                     \
  case 5: force_tile_sums(fp, I, t, n, KK, 1, 0, 1, s); break;                                     \
  case 6: force_tile_sums(fp, I, t, n, KK, 1, 1, 0, s); break;                                     \
  default: force_tile_sums(fp, I, t, n, KK, 1, 1, 1, s); break;                                    \
  }

static void force_sums(const struct force_pass *fp, const struct force_i *I, const struct tile *t,
                       size_t n, double s[6])
{
  switch ((int)fp->kk) { /* a constant kind in each, 2D (KERNEL_2D: axisymmetric) or 3D */
  case KERNEL_WENDLAND_C2: FORCE_SUMS_KK(KERNEL_WENDLAND_C2); break;
  case KERNEL_QUADRATIC: FORCE_SUMS_KK(KERNEL_QUADRATIC); break;
  case KERNEL_CUBIC_SPLINE: FORCE_SUMS_KK(KERNEL_CUBIC_SPLINE); break;
  case KERNEL_WENDLAND_C2 | KERNEL_2D:
    FORCE_SUMS_KK((enum kernel_kind)(KERNEL_WENDLAND_C2 | KERNEL_2D));
    break;
  case KERNEL_QUADRATIC | KERNEL_2D:
    FORCE_SUMS_KK((enum kernel_kind)(KERNEL_QUADRATIC | KERNEL_2D));
    break;
  default: FORCE_SUMS_KK((enum kernel_kind)(KERNEL_CUBIC_SPLINE | KERNEL_2D)); break;
  }
}
#undef FORCE_SUMS_KK

/* The second pass for real l->i with its partners l, through tile t. */
static inline void forces_particle(const struct force_pass *fp, const struct partners *l,
                                   struct tile *t)
{
  const uint32_t i = l->i;
  const size_t nsel = l->n;
  struct particles *p = fp->p;
  const double *wi = fp->rec + PR_LEN * (size_t)i, *cs = p->cs;
  struct force_i I = {.x = p->x[0][i],
                      .y = p->x[1][i],
                      .z = p->x[2][i],
                      .h = p->h[i],
                      .vx = p->v[0][i],
                      .vy = p->v[1][i],
                      .vz = p->v[2][i],
                      .c = cs[i],
                      .rho = p->rho[i],
                      .pr = p->p[i],
                      .P = wi[PR_P]};
  I.Pic = I.P > 0 ? I.P : 0.0;
  for (int k = 0; k < 6; k++) {
    I.S[k] = wi[PR_S + k];
    I.R[k] = p->R[k][i];
    I.R_any |= I.R[k] != 0.0;
  }
  I.piece = sph_piece_of(fp->piece, p->body[i]);
  I.gas = fp->mat[p->mat[i]].eos == EOS_IDEAL_GAS;
  I.alpha = fp->pv.av ? fp->pv.av[i] : 0.0;
  if (fp->gradv)
    for (int k = 0; k < 9; k++) I.G[k] = fp->gradv[9 * (size_t)i + k];
  const size_t n = force_tile_fill(fp, &I, l->js, nsel, t);
  double s[6];
  force_sums(fp, &I, t, n, s);
  p->a[0][i] = s[0];
  p->a[1][i] = s[1];
  p->a[2][i] = s[2];
  p->de[i] += s[3];
  /* the largest pair α (time step): αᵢ raised by its approaching pairs' with the switch,
     α without it */
  const double amax = fp->pv.av ? (s[5] > I.alpha ? s[5] : I.alpha) : fp->pv.alpha;
  /* with the switch the α c part takes the largest pair α, and the β μ part stays whole:
     it follows the approach speed, which the step must resolve whatever α (Noh's first
     step, every α still 0, crossed particles with it scaled too) */
  p->vsig[i] = sph_signal_speed(nsel > 0, I.c, amax, fp->pv.beta, s[4],
                                sqrt(I.vx * I.vx + I.vy * I.vy + I.vz * I.vz));
}

void sph_forces_solid(struct particles *p, const struct nbr_grid *g, const struct sph_params *sp,
                      struct sph_cache *cache, const struct material *mat)
{
  const size_t nt = p->n + p->n_ghost;
  double *rec;
  int32_t *tag;
  partner_reserve(cache, nt, &rec, &tag);
  partner_pack(p, sp, mat, rec, tag);
  const double *av = p->av ? p->alpha : NULL; /* the switch: αᵢ of every slot */
  const struct force_pass fp = {p,
                                mat,
                                sp->piece,
                                rec,
                                tag,
                                sp->reconstruct && cache && cache->gradv_valid ? cache->gradv
                                                                               : NULL,
                                pair_visc_params(sp, av),
                                sp->kernel,
                                sp->as_eps > 0,
                                sp->reconstruct_contact,
                                sp->as_n,
                                1.0 / kernel_w_h3(sp->kernel, 1.0 / sp->eta)};
  /* sph.skip_resting (rest.c): the mid-step state of the cells the first pass
     skipped */
  const int skip = sp->skip_resting && cache && cache->valid && !av;
  if (skip) rest_mark_second(p, g, cache, rec, tag);
  long rested = 0;
#pragma omp parallel reduction(+ : rested)
  {
    struct nsearch ns = {0};
    struct tile t = {0};
    struct partners l[2] = {{0}};
#pragma omp for schedule(dynamic, 8)
    for (size_t c = 0; c < g->ncells; c++) {
      if (skip && (cache->rest[c] & 2)) {
        rested += rest_write_second(p, g, c, sp, p->active);
        continue;
      }
      /* a cell the first pass skipped has no stored neighbours: search */
      const struct sph_cache *load = skip && (cache->rest[c] & 1) ? NULL : cache;
      int gathered = 0, have = 0, cur = 0;
      /* one particle behind the search: its partners' records were asked for while the
         one before it was computed */
      for (uint32_t ii = g->cell_start[c]; ii < g->cell_start[c + 1]; ii++) {
        const uint32_t i = g->order[ii];
        if (i >= p->n || (p->active && !p->active[i])) continue; /* inactive: step.h */
        const size_t nsel = nsearch_neighbours(&ns, &gathered, g, c, ii, p, load, NULL);
        partners_take(rec, 3, 1, &ns, nsel, i, &l[cur ^ 1]);
        if (have) forces_particle(&fp, &l[cur], &t);
        cur ^= 1;
        have = 1;
      }
      if (have) forces_particle(&fp, &l[cur], &t);
    }
    nsearch_free(&ns);
    tile_free(&t);
    free(l[0].js);
    free(l[1].js);
  }
  if (cache) cache->rested = rested;
  if (!cache) {
    free(rec);
    free(tag);
  }
}
