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
 * per-particle function, whose loop over pairs takes the pair's geometry and viscosity
 * from pair.h (shared with the gas loops, sph.c) and its physics with the contact rules
 * from density_contact (first pass) and pair_force (second pass); the second pass reads
 * its partners from the records of partner.c.
 */
#include <math.h>
#include <stdlib.h>

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

/* The contact rules of the continuity sum: whether neighbour j (piece bj) enters i's
 * sums at all, and its weight there, *wd, from w = Vⱼ f. */
static inline int density_contact(const struct density_pass *dp, const struct density_i *I,
                                  uint32_t i, uint32_t j, int32_t bj, double w, double udx,
                                  double f, double *wd)
{
  const struct particles *p = dp->p;
  const double *m = p->m, *rho = p->rho;
  /* a pair of different bodies separating may unload a compressed particle back to its
     reference density, but not stretch it beyond: contact carries no tension, in the
     density as in the forces */
  if (bj != I->piece && udx <= 0.0 && rho[i] <= I->m->rho0) return 0;
  /* a condensed particle's density follows condensed neighbours only: a gas particle's
     volume mⱼ/ρⱼ is hundreds of times its own, and its velocity would set the
     compression of a fragment flying through the gas; the gas still pushes it through
     the pressure force (docs/models.md) */
  if (I->cond && dp->mat[p->mat[j]].eos == EOS_IDEAL_GAS) return 0;
  /* a neighbour counts with at most twice its reference volume, 2mⱼ/ρ₀ⱼ: sprayed debris
     of another body far below ρ₀ would otherwise weigh a lone particle's compression by
     many times its mass's volume, and within a body of condensed material a cluster of
     expanding debris whose volumes mⱼ/ρⱼ overlap would feed its own expansion
     (docs/models.md, "Contact between bodies"). Above ρ₀/2 nothing changes */
  *wd = w;
  if (bj != I->piece || I->cond) {
    const double rho0j = dp->mat[p->mat[j]].rho0;
    if (rho[j] < 0.5 * rho0j) *wd = 2.0 * m[j] / rho0j * f;
  }
  return 1;
}

/* Sums the first pass over the nsel neighbours of real i selected in ns. */
static inline void density_pair_sums(const struct density_pass *dp, const struct nsearch *ns,
                                     size_t nsel, uint32_t i, const struct density_i *I,
                                     struct density_sums *s)
{
  const struct particles *p = dp->p;
  const double *vx = p->v[0], *vy = p->v[1], *vz = p->v[2];
  const double *m = p->m, *rho = p->rho;
  const int32_t *body = p->body, *piece = dp->sp->piece;
  const enum kernel_kind kk = dp->sp->kernel;
  double sum = 0.0, ddiff = 0.0;
  for (size_t k = 0; k < nsel; k++) {
    const uint32_t q = ns->sel[k], j = ns->j[q];
    const struct pair pq =
        pair_geometry(kk, I->x, I->y, I->z, I->h, ns->x[q], ns->y[q], ns->z[q], ns->h[q]);
    const double dx = pq.dx, dy = pq.dy, dz = pq.dz, f = pq.f;
    const double ux = vx[j] - I->vx, uy = vy[j] - I->vy, uz = vz[j] - I->vz;
    const double w = m[j] / rho[j] * f, udx = ux * dx + uy * dy + uz * dz;
    const int32_t bj = sph_piece_of(piece, body[j]);
    double wd;
    if (!density_contact(dp, I, i, j, bj, w, udx, f, &wd)) continue;
    sum -= wd * udx;
    /* sph.density_diffusion (Molteni & Colagrossi 2009): ψᵢⱼ·∇ᵢWᵢⱼ =
       2(ρⱼ − ρᵢ)(xⱼ − xᵢ)·(xᵢ − xⱼ) f/r² = −2(ρⱼ − ρᵢ) f (f < 0): the particle's
       density relaxes towards its neighbours' — a discrete Laplacian of ρ, zero in a
       uniform or linear density field; never across two pieces or two materials,
       whose densities differ by right, nor with expanded material */
    if (I->dd && bj == I->piece && p->mat[j] == p->mat[i] && rho[j] >= I->dd_rho)
      ddiff -= w * 2.0 * (rho[j] - rho[i]) * 0.5 * (I->h + ns->h[q]);
    if (I->sw) avsw_add(s->Lsw, s->Asw, w, dx, dy, dz, ux, uy, uz);
    if (I->strong && bj == I->piece) {
      sph_grad_add_L(s->L, w, dx, dy, dz, ux, uy, uz);
      if (I->corr) /* A = Σ Vⱼ (xⱼ − xᵢ) ⊗ ∇ᵢWᵢⱼ; I for a complete neighbourhood */
        sph_grad_add_A(s->A, w, dx, dy, dz);
    }
  }
  s->sum = sum;
  s->ddiff = ddiff;
}

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

/* The first pass for real i with its nsel neighbours in ns. */
static inline void density_rate_particle(const struct density_pass *dp, const struct nsearch *ns,
                                         size_t nsel, uint32_t i)
{
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
  density_pair_sums(dp, ns, nsel, i, &I, &s);
  p->drho[i] = p->rho[i] * s.sum + (I.dd ? sp->density_diffusion * p->cs[i] * s.ddiff : 0.0);
  if (I.sw)
    p->alpha[i] =
        avsw_update(sp, s.Lsw, s.Asw, p->alpha[i], p->divv[i], I.h, p->cs[i], dp->dt, &p->divv[i]);
  density_gradient(dp, i, &I, recon, &s);
  if (I.strong) {
    if (p->axisym) s.L[8] = I.vy / sph_rz_radius(I.y, I.h); /* the hoop rate v_r/r (rz.h) */
    update_stress(p, i, mi, s.L, dp->dt);
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
  const struct density_pass dp = {p, sp, mat, gradv_reserve(p, sp, cache), dt};
  const int skip = sp->skip_resting && cache && !p->av;
  if (skip) rest_mark_first(p, g, cache);
#pragma omp parallel
  {
    struct nsearch ns = {0};
#pragma omp for schedule(dynamic, 8)
    for (size_t c = 0; c < g->ncells; c++) {
      if (skip && cache->rest[c]) { /* at rest: what the pass would write */
        rest_write_first(p, g, c, dp.gradv);
        continue;
      }
      int gathered = 0;
      for (uint32_t ii = g->cell_start[c]; ii < g->cell_start[c + 1]; ii++) {
        const uint32_t i = g->order[ii];
        if (i >= p->n) continue;
        const size_t nsel = nsearch_neighbours(&ns, &gathered, g, c, ii, p, NULL, cache);
        density_rate_particle(&dp, &ns, nsel, i);
      }
    }
    nsearch_free(&ns);
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
    if (eps > 0 && has_strength(mi, p->fstate[i]) &&
        !fracture_no_tension(&mi->frac, p->fstate[i]) && sym3_max_bound(sig) > 0.0) {
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
 * its own record (σ' for a split particle without tension), max(p/ρ², 0), its R. */
struct force_i {
  double x, y, z, h, vx, vy, vz, c, rho, pr, P, Pic, S[6], R[6];
  int R_any, gas;
  int32_t piece;
};

/* The pair force within one piece, per unit mⱼ, into acc: T = σᵢ/ρᵢ² + σⱼ/ρⱼ² (+ the
 * artificial stress), its deviatoric part explicit. Returns the artificial stress's
 * work per unit mⱼ. */
static inline double pair_stress(const struct force_pass *fp, const struct force_i *I,
                                 const double *wj, int32_t tj, const struct pair *q, double dvx,
                                 double dvy, double dvz, double visc, double acc[3])
{
  const double gx = q->f * q->dx, gy = q->f * q->dy, gz = q->f * q->dz; /* ∇ᵢWᵢⱼ */
  double T[6], eas = 0.0;
  for (int t = 0; t < 6; t++) T[t] = I->S[t] + wj[PR_S + t];
  if (fp->use_as && (I->R_any | (tj & 1))) {
    double Rs[6];
    for (int t = 0; t < 6; t++) Rs[t] = I->R[t] + wj[PR_AS + t];
    const double fr = kernel_w_h3(fp->kk, q->r * (1.0 / q->hij)) * fp->inv_w_dp;
    const double fn = fp->as_n == 4.0 ? (fr * fr) * (fr * fr) : pow(fr, fp->as_n);
    for (int t = 0; t < 6; t++) T[t] += Rs[t] * fn;
    /* its work, −½ vᵢⱼ·(Rₛ fⁿ ∇ᵢW) per unit m_j: the pair force is symmetric, so
       this keeps the total energy */
    const double rx = (Rs[T_XX] * gx + Rs[T_XY] * gy + Rs[T_XZ] * gz) * fn;
    const double ry = (Rs[T_XY] * gx + Rs[T_YY] * gy + Rs[T_YZ] * gz) * fn;
    const double rz = (Rs[T_XZ] * gx + Rs[T_YZ] * gy + Rs[T_ZZ] * gz) * fn;
    eas = -0.5 * (dvx * rx + dvy * ry + dvz * rz);
  }
  const double P = I->P + wj[PR_P] + visc;
  acc[0] = (T[T_XX] - P) * gx + T[T_XY] * gy + T[T_XZ] * gz;
  acc[1] = T[T_XY] * gx + (T[T_YY] - P) * gy + T[T_YZ] * gz;
  acc[2] = T[T_XZ] * gx + T[T_YZ] * gy + (T[T_ZZ] - P) * gz;
  return eas;
}

/* The pair force of i and its partner j (record wj, tag tj) per unit mⱼ, into acc, with
 * the contact rules; returns i's energy rate per unit mⱼ. */
static inline double pair_force(const struct force_pass *fp, const struct force_i *I, uint32_t j,
                                const double *wj, int32_t tj, const struct pair *q, double dvx,
                                double dvy, double dvz, double vdx, double visc, double acc[3])
{
  const double gx = q->f * q->dx, gy = q->f * q->dy, gz = q->f * q->dz; /* ∇ᵢWᵢⱼ */
  double P, Pme, vw = 0.5, eas = 0.0;
  if ((tj >> 1) == I->piece) {
    eas = pair_stress(fp, I, wj, tj, q, dvx, dvy, dvz, visc, acc);
    return (I->P + vw * visc) * vdx * q->f + eas;
  } else if (I->gas != (fp->mat[fp->p->mat[j]].eos == EOS_IDEAL_GAS)) {
    /* gas against condensed material: the interface pressure is the gas's,
       2 p̂_gas/(ρᵢρⱼ) (p̂ = max(p, 0)): a uniform gas against a wall at rest is in
       balance (the wall particle's volume stands in for a gas particle's), and the
       condensed side's stress does not enter — at an SPH free surface it is not the
       traction there, and the soft gas sets the interface pressure: the condensed side
       acts through its motion, which compresses the gas (its density rate sums over
       every neighbour). The mass-weighted pᵢ/ρᵢ² + pⱼ/ρⱼ² blew the gas off a plate at
       rest. The pair's whole work goes to the gas: the condensed particle's density
       does not see the gas (pass 1), so neither does its energy, and the drag's heat
       is the gas's bow shock */
    const double rr = 1.0 / (I->rho * wj[PR_RHO]);
    const double pg = I->gas ? I->pr : wj[PR_P] * wj[PR_RHO] * wj[PR_RHO];
    const double pgc = pg > 0.0 ? 2.0 * pg * rr : 0.0;
    P = pgc + visc;
    Pme = I->gas ? pgc : 0.0;
    vw = I->gas ? 1.0 : 0.0;
  } else { /* contact: compression only */
    P = I->Pic + (wj[PR_P] > 0 ? wj[PR_P] : 0.0) + visc;
    Pme = I->Pic;
  }
  acc[0] = -P * gx;
  acc[1] = -P * gy;
  acc[2] = -P * gz;
  return (Pme + vw * visc) * vdx * q->f + eas;
}

/* The second pass for real i with its nsel neighbours in ns. */
static inline void forces_particle(const struct force_pass *fp, const struct nsearch *ns,
                                   size_t nsel, uint32_t i)
{
  struct particles *p = fp->p;
  const double *wi = fp->rec + PR_LEN * (size_t)i, *cs = p->cs, *gradv = fp->gradv;
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
  double sx = 0.0, sy = 0.0, sz = 0.0, se = 0.0, mumax = 0.0;
  double amax = fp->pv.av ? fp->pv.av[i] : fp->pv.alpha; /* the largest pair α (time step) */
  for (size_t k = 0; k < nsel; k++) {
    const uint32_t j = ns->j[ns->sel[k]];
    const double *wj = fp->rec + PR_LEN * (size_t)j;
    const int32_t tj = fp->tag[j];
    const struct pair pq =
        pair_geometry(fp->kk, I.x, I.y, I.z, I.h, wj[PR_X], wj[PR_X + 1], wj[PR_X + 2], wj[PR_H]);
    const double dvx = I.vx - wj[PR_V], dvy = I.vy - wj[PR_V + 1], dvz = I.vz - wj[PR_V + 2];
    const double vdx = dvx * pq.dx + dvy * pq.dy + dvz * pq.dz;
    const int recon = gradv && ((tj >> 1) == I.piece || fp->recon_contact);
    const double visc = pair_viscosity(
        &fp->pv, i, j, &pq, vdx, recon ? gradv + 9 * (size_t)i : NULL,
        recon ? gradv + 9 * (size_t)j : NULL, I.c, cs[j], I.rho, wj[PR_RHO], &mumax, &amax);
    double acc[3];
    const double e = pair_force(fp, &I, j, wj, tj, &pq, dvx, dvy, dvz, vdx, visc, acc);
    const double mj = wj[PR_M];
    sx += mj * acc[0];
    sy += mj * acc[1];
    sz += mj * acc[2];
    se += mj * e;
  }
  p->a[0][i] = sx;
  p->a[1][i] = sy;
  p->a[2][i] = sz;
  p->de[i] += se;
  /* with the switch the α c part takes the largest pair α, and the β μ part stays whole:
     it follows the approach speed, which the step must resolve whatever α (Noh's first
     step, every α still 0, crossed particles with it scaled too) */
  p->vsig[i] = sph_signal_speed(nsel > 0, I.c, amax, fp->pv.beta, mumax, /* amax = α without it */
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
#pragma omp for schedule(dynamic, 8)
    for (size_t c = 0; c < g->ncells; c++) {
      if (skip && (cache->rest[c] & 2)) {
        rested += rest_write_second(p, g, c, sp);
        continue;
      }
      /* a cell the first pass skipped has no stored neighbours: search */
      const struct sph_cache *load = skip && (cache->rest[c] & 1) ? NULL : cache;
      int gathered = 0;
      for (uint32_t ii = g->cell_start[c]; ii < g->cell_start[c + 1]; ii++) {
        const uint32_t i = g->order[ii];
        if (i >= p->n) continue;
        const size_t nsel = nsearch_neighbours(&ns, &gathered, g, c, ii, p, load, NULL);
        forces_particle(&fp, &ns, nsel, i);
      }
    }
    nsearch_free(&ns);
  }
  if (cache) cache->rested = rested;
  if (!cache) {
    free(rec);
    free(tag);
  }
}
