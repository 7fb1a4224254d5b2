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
 */
#include <math.h>
#include <stdlib.h>

#include "eos/eos.h"
#include "fracture/fracture.h"
#include "sph/avswitch.h"
#include "sph/cand.h"
#include "sph/recon.h"
#include "sph/sph.h"
#include "strength/strength.h"
#include "strength/sym3.h"

/* The piece of body b (bodies[i].part_of; every body its own without a table). */
static inline int32_t piece_of(const int32_t *piece, int32_t b)
{
  return piece ? piece[b] : b;
}

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
  const double Y = fracture_yield(&m->frac, p->fstate[i],
                                  strength_yield(&m->str, p->eps_p[i],
                                                 strength_equivalent_rate(L), p->e[i]),
                                  p->p[i]);
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
  if (p->cracks && fracture_opening(&m->frac, p->fstate[i])) {   /* the crack turns with the material */
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

/* sph.skip_resting. A particle whose neighbours (itself included) all have v = 0,
 * p = 0, S = 0 and R = 0, exactly, has exactly zero rates: no velocity difference for
 * the density rate, the velocity gradient and the viscosity, no stress for the forces;
 * its stress stays (S = 0, L = 0: nothing to update or return). A cell is skipped when
 * every cell of its candidate list (which covers every particle's search) holds only
 * such particles, "quiet". The first pass tests v and S at the step's start (the pass
 * changes S only from L); the second pass tests the mid-step v, p, S and R, and skips
 * only cells the first pass skipped. What a skipped particle's pass would have written
 * is written: 0 for ρ̇, the heating and a, S for S₁, and its signal speed, which
 * depends only on whether it has a neighbour (cand_any). The switch is excluded: its
 * αᵢ decays at rest. rest[c]: bit 0 the first pass skipped c, bit 1 the second. */
static void rest_alloc(struct sph_cache *cache, size_t ncells)
{
  if (ncells > cache->rcap) {
    cache->rcap = ncells + ncells / 4 + 64;
    free(cache->quiet);
    free(cache->rest);
    cache->quiet = hv_malloc(cache->rcap, "rest flags");
    cache->rest = hv_malloc(cache->rcap, "rest flags");
  }
}

/* Sets bit `bit` of rest[c] where every neighbour cell of c is quiet (and, for bit 1,
 * bit 0 is set). */
static void rest_mark(const struct nbr_grid *g, struct sph_cache *cache, int bit)
{
  const uint8_t *quiet = cache->quiet;
  uint8_t *rest = cache->rest;
#pragma omp parallel for schedule(static)
  for (size_t c = 0; c < g->ncells; c++) {
    int r = bit == 0 || (rest[c] & 1);
    for (uint32_t k = g->nbr_start[c]; r && k < g->nbr_start[c + 1]; k++)
      r = quiet[g->nbr_list[k]];
    rest[c] = (uint8_t)(bit == 0 ? r : (rest[c] & 1) | (r << 1));
  }
}

void sph_density_rate_solid(struct particles *p, const struct nbr_grid *g,
                            const struct sph_params *sp, struct sph_cache *cache,
                            const struct material *mat, double dt)
{
  if (cache) cache_layout(cache, g);
  const size_t n = p->n;
  const double *vx = p->v[0], *vy = p->v[1], *vz = p->v[2];
  const double *m = p->m, *rho = p->rho;
  const int32_t *body = p->body, *piece = sp->piece;
  const enum kernel_kind kk = sp->kernel;
  double *gradv = NULL;   /* sph.viscosity.reconstruct: L of every real */
  if (sp->reconstruct && cache) {
    const size_t nall = p->n + p->n_ghost;
    if (nall > cache->gcap) {
      cache->gcap = nall + nall / 4 + 64;
      free(cache->gradv);
      cache->gradv = hv_malloc(cache->gcap * 9 * sizeof *cache->gradv, "velocity gradients");
    }
    gradv = cache->gradv;
    cache->gradv_valid = 0;
  }
  const int skip = sp->skip_resting && cache && !p->av;
  const double ddelta = sp->density_diffusion;
  if (skip) {
    rest_alloc(cache, g->ncells);
#pragma omp parallel for schedule(static)
    for (size_t c = 0; c < g->ncells; c++) {
      int q = 1;
      for (uint32_t ii = g->cell_start[c]; q && ii < g->cell_start[c + 1]; ii++) {
        const uint32_t j = g->order[ii];
        q = vx[j] == 0.0 && vy[j] == 0.0 && vz[j] == 0.0;
        for (int k = 0; q && k < 6; k++) q = p->S[k][j] == 0.0;
      }
      cache->quiet[c] = (uint8_t)q;
    }
    rest_mark(g, cache, 0);
  }

#pragma omp parallel
  {
    struct cand cd = {0};
#pragma omp for schedule(dynamic, 8)
    for (size_t c = 0; c < g->ncells; c++) {
      int gathered = 0;
      if (skip && cache->rest[c]) {   /* at rest: what the pass would write */
        for (uint32_t ii = g->cell_start[c]; ii < g->cell_start[c + 1]; ii++) {
          const uint32_t i = g->order[ii];
          if (i >= n) continue;
          p->drho[i] = 0.0;
          p->de[i] = 0.0;
          for (int k = 0; k < 6; k++) p->S1[k][i] = p->S[k][i];
          if (gradv)
            for (int t = 0; t < 9; t++) gradv[9 * (size_t)i + t] = 0.0;
        }
        continue;
      }
      for (uint32_t ii = g->cell_start[c]; ii < g->cell_start[c + 1]; ii++) {
        const uint32_t i = g->order[ii];
        if (i >= n) continue;
        const size_t nsel = cand_neighbours(&cd, &gathered, g, c, ii, p, NULL, cache);
        const double xi = p->x[0][i], yi = p->x[1][i], zi = p->x[2][i], hi = p->h[i];
        const double vxi = vx[i], vyi = vy[i], vzi = vz[i];
        const struct material *mi = &mat[p->mat[i]];
        const int strong = has_strength(mi, p->fstate[i]);
        /* the reconstruction's gradient: intact strength particles only (split ones
           with friction keep the standard viscosity, as without it) */
        const int recon = strong && p->fstate[i] < FRACTURE_SPLIT;
        const int32_t bi = piece_of(piece, body[i]);
        const int cond_i = mi->eos != EOS_IDEAL_GAS;
        double sum = 0.0, L[9] = {0}, A[9] = {0};
        /* the correction matrix: for the stress with sph.gradient_correction, and for the
           reconstruction always (its limiter needs gradients exact for linear fields) */
        const int corr = strong && (sp->grad_correction || (gradv && recon));
        const int sw = p->av;   /* the viscosity switch's gradient, every neighbour */
        double Lsw[9] = {0}, Asw[9] = {0};
        /* density diffusion between condensed states only (ρ ≥ ρ₀/2 on both sides), where
           it was tested (W.P.3's debris failure once blamed on it was the continuity sum's:
           the volume bound below) */
        const double dd_rho = 0.5 * mi->rho0;
        const int dd = ddelta > 0.0 && cond_i && rho[i] >= dd_rho;
        double ddiff = 0.0;   /* Σⱼ Vⱼ ψᵢⱼ·∇ᵢWᵢⱼ hᵢⱼ, the density diffusion */
        for (size_t k = 0; k < nsel; k++) {
          const uint32_t q = cd.sel[k], j = cd.j[q];
          const double dx = xi - cd.x[q], dy = yi - cd.y[q], dz = zi - cd.z[q];
          const double r = sqrt(dx * dx + dy * dy + dz * dz);
          const double f = kernel_f(kk, r, 0.5 * (hi + cd.h[q]));
          const double ux = vx[j] - vxi, uy = vy[j] - vyi, uz = vz[j] - vzi;
          const double w = m[j] / rho[j] * f, udx = ux * dx + uy * dy + uz * dz;
          /* a pair of different bodies separating may unload a compressed particle
             back to its reference density, but not stretch it beyond: contact carries
             no tension, in the density as in the forces */
          const int32_t bj = piece_of(piece, body[j]);
          if (bj != bi && udx <= 0.0 && rho[i] <= mi->rho0) continue;
          /* a condensed particle's density follows condensed neighbours only: a gas
             particle's volume mⱼ/ρⱼ is hundreds of times its own, and its velocity
             would set the compression of a fragment flying through the gas (lone
             aluminium at 4 km/s in nitrogen reached 2.4 ρ₀); the gas still pushes it
             through the pressure force */
          if (cond_i && mat[p->mat[j]].eos == EOS_IDEAL_GAS) continue;
          /* a neighbour counts with at most twice its reference volume, 2mⱼ/ρ₀ⱼ:
             sprayed debris of another body far below ρ₀ (a hundredth of it in §2.4's
             cloud) would otherwise weigh a lone particle's compression by 37-73 times
             its mass's volume and drive it to 4 ρ₀ (docs/models.md, "Contact between
             bodies"); within a body of condensed material, a cluster of expanding
             debris whose volumes mⱼ/ρⱼ overlap feeds its own expansion (each one's
             divergence weighted by the others' growing volumes: W.P.3's projectile
             with density diffusion, ρ from 465 to 0 in 210 steps with up to 1 700
             neighbours at h_max). Above ρ₀/2 nothing changes */
          double wd = w;
          if (bj != bi || cond_i) {
            const double rho0j = mat[p->mat[j]].rho0;
            if (rho[j] < 0.5 * rho0j) wd = 2.0 * m[j] / rho0j * f;
          }
          sum -= wd * udx;
          /* sph.density_diffusion (Molteni & Colagrossi 2009): ψᵢⱼ·∇ᵢWᵢⱼ =
             2(ρⱼ − ρᵢ)(xⱼ − xᵢ)·(xᵢ − xⱼ) f/r² = −2(ρⱼ − ρᵢ) f (f < 0): the particle's
             density relaxes towards its neighbours' — a discrete Laplacian of ρ, zero
             in a uniform or linear density field; never across two pieces or two
             materials, whose densities differ by right, nor with expanded material */
          if (dd && bj == bi && p->mat[j] == p->mat[i] && rho[j] >= dd_rho)
            ddiff -= w * 2.0 * (rho[j] - rho[i]) * 0.5 * (hi + cd.h[q]);
          if (sw) avsw_add(Lsw, Asw, w, dx, dy, dz, ux, uy, uz);
          if (strong && bj == bi) {
            L[0] += w * ux * dx; L[1] += w * ux * dy; L[2] += w * ux * dz;
            L[3] += w * uy * dx; L[4] += w * uy * dy; L[5] += w * uy * dz;
            L[6] += w * uz * dx; L[7] += w * uz * dy; L[8] += w * uz * dz;
            if (corr) { /* A = Σ Vⱼ (xⱼ − xᵢ) ⊗ ∇ᵢWᵢⱼ; I for a complete neighbourhood */
              A[0] -= w * dx * dx; A[1] -= w * dx * dy; A[2] -= w * dx * dz;
              A[3] -= w * dy * dx; A[4] -= w * dy * dy; A[5] -= w * dy * dz;
              A[6] -= w * dz * dx; A[7] -= w * dz * dy; A[8] -= w * dz * dz;
            }
          }
        }
        p->drho[i] = rho[i] * sum + (dd ? ddelta * p->cs[i] * ddiff : 0.0);
        if (sw)
          p->alpha[i] = avsw_update(sp, Lsw, Asw, p->alpha[i], p->divv[i], hi, p->cs[i], dt,
                                    &p->divv[i]);
        if (gradv) {   /* corrected; 0 without strength: no reconstruction for its pairs */
          double *Gi = gradv + 9 * (size_t)i;
          for (int t = 0; t < 9; t++) Gi[t] = recon ? L[t] : 0.0;
          if (recon) {
            sph_correct_gradient(Gi, A);
            if (sp->grad_correction)   /* the stress uses the same corrected gradient */
              for (int t = 0; t < 9; t++) L[t] = Gi[t];
          } else if (strong && sp->grad_correction) {
            sph_correct_gradient(L, A);
          }
        } else if (corr) {
          sph_correct_gradient(L, A);
        }
        if (strong) {
          update_stress(p, i, mi, L, dt);
        } else {
          p->de[i] = 0.0;
          for (int k = 0; k < 6; k++) p->S[k][i] = p->S1[k][i] = 0.0;
        }
      }
    }
    cand_free_all(&cd);
  }
  if (cache) cache->valid = 1;
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
    if (eps > 0 && has_strength(mi, p->fstate[i]) && !fracture_no_tension(&mi->frac, p->fstate[i]) &&
        sym3_max_bound(sig) > 0.0) {
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

/* layout of a partner's record in sph_forces_solid (TW doubles, two cache lines) */
enum { TW_X = 0, TW_H = 3, TW_V = 4, TW_M = 7, TW_P = 8, TW_S = 9, TW_RHO = 15, TW_R = 16, TW = SPH_TW };

void sph_forces_solid(struct particles *p, const struct nbr_grid *g,
                      const struct sph_params *sp, struct sph_cache *cache,
                      const struct material *mat)
{
  const size_t n = p->n;
  const double *vx = p->v[0], *vy = p->v[1], *vz = p->v[2];
  const double *m = p->m, *rho = p->rho, *pr = p->p, *cs = p->cs;
  const double *px = p->x[0], *py = p->x[1], *pz = p->x[2], *ph = p->h;
  const int32_t *body = p->body, *piece = sp->piece;
  const enum kernel_kind kk = sp->kernel;
  const double alpha = sp->alpha, beta = sp->beta, eps = sp->eps, as_n = sp->as_n;
  const double *av = p->av ? p->alpha : NULL;   /* the switch: αᵢ of every slot */
  const double bfac = av ? beta / alpha : 0.0;
  const int use_as = sp->as_eps > 0;
  const double *gradv = sp->reconstruct && cache && cache->gradv_valid ? cache->gradv : NULL;
  const int recon_contact = sp->reconstruct_contact;   /* and for pairs of two pieces */
  /* W(Δp, h)·h³ with Δp = h/η: the reference value of the artificial-stress factor */
  const double inv_w_dp = 1.0 / kernel_w_h3(kk, 1.0 / sp->eta);
  /* Each particle's data as a partner (ghosts included) in two cache lines, read
     together for every pair instead of from 17 arrays: x, y, z, h, v, m, then p/ρ²,
     S/ρ² (computed once instead of once per pair: the same operations, so the same
     bits) and ρ; a third line with the artificial stress R, read only when a pair has
     one (bf: body × 2 + 1 when R ≠ 0). 196 bytes per particle, kept in the cache
     between steps (allocated here for a call without one). */
  const size_t nt = p->n + p->n_ghost;
  double *tw0 = NULL;
  int32_t *bf0 = NULL;
  if (cache && cache->tcap >= nt + 1) {
    tw0 = cache->tw;
    bf0 = cache->bf;
  } else {
    const size_t cap = cache ? nt + nt / 4 + 64 : nt + 1;
    if (cache) {
      free(cache->tw);
      free(cache->bf);
      cache->tw = NULL;
      cache->bf = NULL;
      cache->tcap = 0;
    }
    tw0 = aligned_alloc(64, cap * TW * sizeof *tw0);
    bf0 = malloc(cap * sizeof *bf0);
    if (!tw0 || !bf0)
      HV_FATAL("out of memory: %zu bytes for the pair terms", cap * (TW * sizeof *tw0 + 4));
    if (cache) {
      cache->tw = tw0;
      cache->bf = bf0;
      cache->tcap = cap;
    }
  }
  double *restrict tw = tw0;
  int32_t *restrict bf = bf0;
#pragma omp parallel for schedule(static)
  for (size_t j = 0; j < nt; j++) {
    const double rj2 = 1.0 / (rho[j] * rho[j]);
    double *w = tw + TW * j;
    w[TW_X] = px[j];
    w[TW_X + 1] = py[j];
    w[TW_X + 2] = pz[j];
    w[TW_H] = ph[j];
    w[TW_V] = vx[j];
    w[TW_V + 1] = vy[j];
    w[TW_V + 2] = vz[j];
    w[TW_M] = m[j];
    double Sj[6], pj = pr[j];
    for (int t = 0; t < 6; t++) Sj[t] = p->S[t][j];
    if (fracture_no_tension(&mat[p->mat[j]].frac, p->fstate[j]))
      pj = fracture_effective(pr[j], Sj, Sj);   /* split without tension: σ' (fracture.h) */
    w[TW_P] = pj * rj2;
    for (int t = 0; t < 6; t++) w[TW_S + t] = Sj[t] * rj2;
    w[TW_RHO] = rho[j];
    int rany = 0;
    for (int t = 0; t < 6; t++) {
      w[TW_R + t] = p->R[t][j];
      rany |= p->R[t][j] != 0.0;
    }
    w[TW_R + 6] = w[TW_R + 7] = 0.0;
    bf[j] = 2 * (piece_of(piece, body[j])) + rany;
  }
  /* sph.skip_resting (see rest_alloc): the mid-step state of the cells the first pass
     skipped */
  const int skip = sp->skip_resting && cache && cache->valid && !av;
  long rested = 0;
  if (skip) {
#pragma omp parallel for schedule(static)
    for (size_t c = 0; c < g->ncells; c++) {
      int q = 1;
      for (uint32_t ii = g->cell_start[c]; q && ii < g->cell_start[c + 1]; ii++) {
        const uint32_t j = g->order[ii];
        const double *w = tw + TW * (size_t)j;
        q = w[TW_V] == 0.0 && w[TW_V + 1] == 0.0 && w[TW_V + 2] == 0.0 && w[TW_P] == 0.0 &&
            pr[j] == 0.0 && !(bf[j] & 1);
        for (int t = 0; q && t < 6; t++) q = w[TW_S + t] == 0.0;
      }
      cache->quiet[c] = (uint8_t)q;
    }
    rest_mark(g, cache, 1);
  }

#pragma omp parallel reduction(+ : rested)
  {
    struct cand cd = {0};
#pragma omp for schedule(dynamic, 8)
    for (size_t c = 0; c < g->ncells; c++) {
      int gathered = 0;
      if (skip && (cache->rest[c] & 2)) {   /* at rest: a = 0, de unchanged, the signal */
        for (uint32_t ii = g->cell_start[c]; ii < g->cell_start[c + 1]; ii++) {
          const uint32_t i = g->order[ii];
          if (i >= n) continue;
          p->a[0][i] = p->a[1][i] = p->a[2][i] = 0.0;
          p->vsig[i] = sph_signal_speed(cand_any(g, c, p, i), cs[i], alpha, beta, 0.0, 0.0);
          rested++;
        }
        continue;
      }
      /* a cell the first pass skipped has no stored neighbours: search */
      const struct sph_cache *load = skip && (cache->rest[c] & 1) ? NULL : cache;
      for (uint32_t ii = g->cell_start[c]; ii < g->cell_start[c + 1]; ii++) {
        const uint32_t i = g->order[ii];
        if (i >= n) continue;
        const size_t nsel = cand_neighbours(&cd, &gathered, g, c, ii, p, load, NULL);
        const double xi = p->x[0][i], yi = p->x[1][i], zi = p->x[2][i], hi = p->h[i];
        const double vxi = vx[i], vyi = vy[i], vzi = vz[i];
        const double ci = cs[i], rhoi = rho[i];
        /* p/ρ² and S/ρ² from i's own record (σ' for a split particle without tension) */
        const double *wi = tw + TW * (size_t)i;
        const double Pi = wi[TW_P], Pic = Pi > 0 ? Pi : 0.0;
        double Si[6], Ri[6];
        int Ri_any = 0;
        for (int k = 0; k < 6; k++) {
          Si[k] = wi[TW_S + k];
          Ri[k] = p->R[k][i];
          Ri_any |= Ri[k] != 0.0;
        }
        const int32_t bi = piece_of(piece, body[i]);
        const int gas_i = mat[p->mat[i]].eos == EOS_IDEAL_GAS;
        double sx = 0.0, sy = 0.0, sz = 0.0, se = 0.0, mumax = 0.0;
        double amax = av ? av[i] : alpha;   /* the largest pair α (time step) */
        for (size_t k = 0; k < nsel; k++) {
          const uint32_t q = cd.sel[k], j = cd.j[q];
          const double *wj = tw + TW * (size_t)j;
          const double dx = xi - wj[TW_X], dy = yi - wj[TW_X + 1], dz = zi - wj[TW_X + 2];
          const double r2 = dx * dx + dy * dy + dz * dz, hij = 0.5 * (hi + wj[TW_H]);
          const double r = sqrt(r2), f = kernel_f(kk, r, hij);
          const double dvx = vxi - wj[TW_V], dvy = vyi - wj[TW_V + 1], dvz = vzi - wj[TW_V + 2];
          const double vdx = dvx * dx + dvy * dy + dvz * dz;
          double visc = 0.0;
          if (vdx < 0.0) {
            double mu = hij * vdx / (r2 + eps * hij * hij);
            if (-mu > mumax) mumax = -mu;   /* the time step sees the whole jump */
            if (gradv && ((bf[j] >> 1) == bi || recon_contact))
              mu = hij *
                   sph_recon_approach(vdx, gradv + 9 * (size_t)i, gradv + 9 * (size_t)j, dx, dy, dz) /
                   (r2 + eps * hij * hij);
            visc = sph_pair_visc(av, i, j, alpha, beta, bfac, ci, cs[j], mu, rhoi, wj[TW_RHO], &amax);
          }
          const double gx = f * dx, gy = f * dy, gz = f * dz;   /* ∇ᵢWᵢⱼ */
          double ax, ay, az, Pme, vw = 0.5, eas = 0.0;
          const int32_t bfj = bf[j];
          if ((bfj >> 1) == bi) {
            /* T = σᵢ/ρᵢ² + σⱼ/ρⱼ² (+ artificial stress), deviatoric part explicitly */
            double T[6];
            for (int t = 0; t < 6; t++) T[t] = Si[t] + wj[TW_S + t];
            if (use_as) {
              double Rs[6];
              if (Ri_any | (bfj & 1)) {
                for (int t = 0; t < 6; t++) Rs[t] = Ri[t] + wj[TW_R + t];
                const double fr = kernel_w_h3(kk, r * (1.0 / hij)) * inv_w_dp;
                const double fn = as_n == 4.0 ? (fr * fr) * (fr * fr) : pow(fr, as_n);
                for (int t = 0; t < 6; t++) T[t] += Rs[t] * fn;
                /* its work, −½ vᵢⱼ·(Rₛ fⁿ ∇ᵢW) per unit m_j: the pair force is
                   symmetric, so this keeps the total energy */
                const double rx = (Rs[T_XX] * gx + Rs[T_XY] * gy + Rs[T_XZ] * gz) * fn;
                const double ry = (Rs[T_XY] * gx + Rs[T_YY] * gy + Rs[T_YZ] * gz) * fn;
                const double rz = (Rs[T_XZ] * gx + Rs[T_YZ] * gy + Rs[T_ZZ] * gz) * fn;
                eas = -0.5 * (dvx * rx + dvy * ry + dvz * rz);
              }
            }
            const double P = Pi + wj[TW_P] + visc;
            ax = (T[T_XX] - P) * gx + T[T_XY] * gy + T[T_XZ] * gz;
            ay = T[T_XY] * gx + (T[T_YY] - P) * gy + T[T_YZ] * gz;
            az = T[T_XZ] * gx + T[T_YZ] * gy + (T[T_ZZ] - P) * gz;
            Pme = Pi;
          } else if (gas_i != (mat[p->mat[j]].eos == EOS_IDEAL_GAS)) {
            /* gas against condensed material: the interface pressure is the gas's,
               2 p̂_gas/(ρᵢρⱼ) (p̂ = max(p, 0)): a uniform gas against a wall at rest is in
               balance (the wall particle's volume stands in for a gas particle's), and the
               condensed side's stress does not enter — at an SPH free surface it is not the
               traction there (a thin plate under in-plane compression has p and σ_xx of tens
               of MPa at its face), and the soft gas sets the interface pressure: the
               condensed side acts through its motion, which compresses the gas (its density
               rate sums over every neighbour). The mass-weighted pᵢ/ρᵢ² + pⱼ/ρⱼ² blew the
               gas off a plate at rest. The pair's whole work goes to the gas: the condensed
               particle's density does not see the gas (pass 1), so neither does its
               energy, and the drag's heat is the gas's bow shock */
            const double rr = 1.0 / (rhoi * wj[TW_RHO]);
            const double pg = gas_i ? pr[i] : wj[TW_P] * wj[TW_RHO] * wj[TW_RHO];
            const double pgc = pg > 0.0 ? 2.0 * pg * rr : 0.0;
            const double P = pgc + visc;
            ax = -P * gx;
            ay = -P * gy;
            az = -P * gz;
            Pme = gas_i ? pgc : 0.0;
            vw = gas_i ? 1.0 : 0.0;
          } else { /* contact: compression only */
            const double P = Pic + (wj[TW_P] > 0 ? wj[TW_P] : 0.0) + visc;
            ax = -P * gx;
            ay = -P * gy;
            az = -P * gz;
            Pme = Pic;
          }
          const double mj = wj[TW_M];
          sx += mj * ax;
          sy += mj * ay;
          sz += mj * az;
          se += mj * ((Pme + vw * visc) * vdx * f + eas);
        }
        p->a[0][i] = sx;
        p->a[1][i] = sy;
        p->a[2][i] = sz;
        p->de[i] += se;
        /* with the switch the α c part takes the largest pair α, and the β μ part stays
           whole: it follows the approach speed, which the step must resolve whatever α
           (Noh's first step, every α still 0, crossed particles with it scaled too) */
        p->vsig[i] = sph_signal_speed(nsel > 0, ci, amax, beta, mumax,   /* amax = α without it */
                                      sqrt(vxi * vxi + vyi * vyi + vzi * vzi));
      }
    }
    cand_free_all(&cd);
  }
  if (cache) cache->rested = rested;
  if (!cache) {
    free(tw0);
    free(bf0);
  }
}
