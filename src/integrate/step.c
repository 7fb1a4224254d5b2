/* step.c — the predictor–corrector step; see step.h for the scheme. */
#include "integrate/step.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "config/config.h"
#include "eos/eos.h"
#include "fracture/fracture.h"
#include "sph/rz.h"

double step_hmax(const struct particles *p)
{
  double hm = 0.0;
  for (size_t i = 0; i < p->n; i++)
    if (p->h[i] > hm) hm = p->h[i];
  return hm;
}

static int cmp_double(const void *a, const void *b)
{
  const double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* The h that sizes the cells: 1.1 × the median of the reals' h (from an evenly spaced
 * sample of at most 4096). The median follows the bulk of the particles, so that a
 * minority of small ones (a projectile, a thin plate beside a gas fill) does not make
 * the cells of everything else small: each particle's search visits cells out to its
 * own reach, so small cells cost the large particles many cells holding one or two
 * particles each, while large cells cost the small particles more candidates, which
 * are cheaper; the median was faster than a low percentile in every paper case
 * (docs/design.md, "Neighbour search"). The 10 % margin keeps a pair's support
 * h_i + h_j within one cell edge (2 × this) for the particles just above it: without
 * it, the largest h of almost every cell exceeded it a little and each cell also
 * searched the cells two away (125 instead of 27), a slower search (same section). */
static double cell_h_reals(const struct particles *p)
{
  enum { NS = 4096 };
  double s[NS];
  const size_t n = p->n, stride = n / NS + 1;
  size_t k = 0;
  for (size_t i = 0; i < n && k < NS; i += stride) s[k++] = p->h[i];
  if (k == 0) return HUGE_VAL;
  qsort(s, k, sizeof *s, cmp_double);
  return 1.1 * s[k / 2];
}

/* p and cs of every real (with mask: of those with mask[i] != 0) from its ρ and e; the
 * failure of the lowest slot is reported. */
static int update_eos_mask(struct sim *s, const int32_t *mask, struct hv_error *err)
{
  struct particles *p = &s->p;
  long bad = LONG_MAX;
#pragma omp parallel for schedule(static) reduction(min : bad)
  for (size_t i = 0; i < p->n; i++) {
    if (mask && !mask[i]) continue;
    struct eos_state st;
    const struct material *m = &s->mat[p->mat[i]];
    /* a plane of it opening (fracture.split: crack, fracture.energy): the EOS takes the
       material's density, without the plane's opening */
    const double rho_m = p->solid ? fracture_eos_density(p, i, &m->frac) : p->rho[i];
    if (!(p->rho[i] > 0) || !isfinite(p->rho[i]) || eos_evaluate(m, rho_m, p->e[i], &st) ||
        !isfinite(st.p) || !isfinite(st.cs)) {
      if ((long)i < bad) bad = (long)i;
      continue;
    }
    if (p->solid) st.p = fracture_pressure(&m->frac, p->fstate[i], st.p); /* split: no tension */
    if (m->str.enabled && (!p->solid || fracture_keeps_stress(&m->frac, p->fstate[i])))
      st.cs = sqrt(st.cs * st.cs + 4.0 / 3.0 * m->str.G / p->rho[i]); /* longitudinal */
    p->p[i] = st.p;
    p->cs[i] = st.cs;
  }
  if (bad == LONG_MAX) return 0;
  size_t i = (size_t)bad;
  const char *bname = s->body[p->body[i]].name, *mname = s->mat[p->mat[i]].name;
  if (!(p->rho[i] > 0) || !isfinite(p->rho[i])) /* ρⁿ exp(Δt Dρ/ρⁿ): 0 or inf */
    return hv_error_set(err, HV_EXIT_RUN,
                        "step %ld (t = %.9g s to %.9g s): particle %lld (body "
                        "'%s'): field rho: %g kg/m3 is not a positive finite density "
                        "(compressed or stretched beyond what the time step can follow)",
                        s->step, s->t, s->t + s->dt, (long long)p->id[i], bname, p->rho[i]);
  char what[512];
  struct eos_state st;
  const struct material *mb = &s->mat[p->mat[i]];
  const double rho_b = p->solid ? fracture_eos_density(p, i, &mb->frac) : p->rho[i]; /* as above */
  const int est = eos_evaluate(mb, rho_b, p->e[i], &st);
  eos_describe(mb, rho_b, p->e[i], est, what, sizeof what);
  if (est == EOS_OK) { /* taken, but not finite: say what came out */
    const size_t k = strlen(what);
    snprintf(what + k, sizeof what - k, " (p = %g Pa, c = %g m/s)", st.p, st.cs);
  }
  return hv_error_set(err, HV_EXIT_RUN,
                      "step %ld (t = %.9g s): particle %lld (body '%s', "
                      "material '%s'): field p: %s",
                      s->step, s->t, (long long)p->id[i], bname, mname, what);
}

static int update_eos(struct sim *s, struct hv_error *err) { return update_eos_mask(s, NULL, err); }

/* Ghosts and the cell grid at the current positions. */
static int build_neighbours(struct sim *s, struct hv_error *err)
{
  char msg[512];
  struct particles *p = &s->p;
  const double hmax = step_hmax(p), width = 2.0 * hmax;
  if (boundary_any(&s->bnd)) {
    boundary_apply(&s->bnd, p);
    if (boundary_make_ghosts(&s->bnd, p, width, msg, sizeof msg))
      return hv_error_set(err, HV_EXIT_INPUT, "domain: %s", msg);
  } else {
    p->n_ghost = 0;
  }
  const double *xs[3] = {p->x[0], p->x[1], p->x[2]};
  const double cell = nbr_cell_size(cell_h_reals(p), hmax);
  if (nbr_grid_build(&s->grid, xs, p->h, p->n + p->n_ghost, cell, msg, sizeof msg))
    return hv_error_set(err, HV_EXIT_RUN, "t = %.9g s: neighbour grid: %s", s->t, msg);
  return 0;
}

/* h of real i from its mass and density. */
static inline void update_h_one(struct sim *s, size_t i)
{
  struct particles *p = &s->p;
  const double eta = s->sph.eta, hmin = s->sph.h_min, hmax = s->sph.h_max;
  /* axisymmetric: from the area mass, h = η (m/(2π r ρ))^(1/2), the in-plane spacing,
     with r no larger than rz_stretch_max × r0 (the ring's axial extent does not follow
     its hoop stretch; r0 = 0: no cap) */
  double h;
  if (p->axisym) {
    const double cap = p->rings ? s->sph.rz_stretch_max : 0.0;
    double r = sph_rz_radius(p->x[1][i], p->h[i]);
    if (cap > 0.0 && p->r0[i] > 0.0 && r > cap * p->r0[i]) r = cap * p->r0[i];
    h = eta * sqrt(p->m[i] / (2.0 * HV_KERNEL_PI * r * p->rho[i]));
  } else {
    h = eta * cbrt(p->m[i] / p->rho[i]);
  }
  p->h[i] = h < hmin ? hmin : (h > hmax ? hmax : h);
}

static void update_h(struct sim *s)
{
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < s->p.n; i++) update_h_one(s, i);
}

/* Proposes the next step from the CFL and acceleration limits, and records which limit
 * (and which particle: the smallest slot among equal minima, so it does not depend on
 * the thread count) set it.
 * Mirror faces (wall, symmetry plane): a real at distance d from one, approaching it at
 * normal speed u, meets its own mirror image (a ghost) once d < h, and no ghost is
 * within its reach before (nor within any real's: a pair i, ghost of j interacts when
 * dᵢ + dⱼ < hᵢ + hⱼ, so only when dᵢ < hᵢ or dⱼ < hⱼ). Its neighbours do not see the
 * face coming: a block that moves as one has vsig = c(1 + 0.6α) whatever its speed, and
 * at Mach 50 crossed 6.8 h per step (with c(1 + 1.2α)), into the wall. So it may move at most
 * max(d − h, C_CFL h) towards the face per step, Δt ≤ max(d − h, C_CFL h)/u: up to
 * where its image comes within reach, then C_CFL h per step like a particle with no
 * neighbour, until the image's approach sets vsig (≥ 2.4 u for 0.001 h < d < h with
 * β = 2). It binds only when u > vsig, i.e. for an approach faster than c(1 + 0.6α)
 * (a particle with no neighbour has vsig = |v| ≥ u: never), so a
 * run without such an approach has the same steps bit for bit; recorded as the CFL
 * limit (docs/models.md, "Time step"). */
/* The mirror faces (wall, symmetry plane) of a boundary, for the approach limit. */
struct mirrors {
  int m[3][2], any;
};

static void mirrors_of(const struct boundary *b, struct mirrors *mr)
{
  mr->any = 0;
  for (int d = 0; d < 3; d++)
    for (int side = 0; side < 2; side++) {
      mr->m[d][side] = b->kind[d][side] == BND_WALL || b->kind[d][side] == BND_SYMMETRY;
      mr->any |= mr->m[d][side];
    }
}

/* Real i's own limit (CFL, acceleration, mirror-face approach, axis approach) and which
 * of them it is (*kind). */
static inline double own_limit(const struct sim *s, const struct mirrors *mr, size_t i, int *kind)
{
  const struct particles *p = &s->p;
  const struct boundary *b = &s->bnd;
  double d = s->tp.cfl * p->h[i] / (p->vsig[i] > 0 ? p->vsig[i] : 1e-300);
  int k = DT_CFL;
  double a2 = p->a[0][i] * p->a[0][i] + p->a[1][i] * p->a[1][i] + p->a[2][i] * p->a[2][i];
  if (a2 > 0) {
    double da = s->tp.cfl_acc * sqrt(p->h[i] / sqrt(a2));
    if (da < d) {
      d = da;
      k = DT_ACCELERATION;
    }
  }
  for (int dim = 0; mr->any && dim < 3; dim++) { /* approach to a mirror face */
    const double v = p->v[dim][i];
    double dist, u;
    if (mr->m[dim][0] && v < 0.0) {
      dist = p->x[dim][i] - b->lo[dim];
      u = -v;
    } else if (mr->m[dim][1] && v > 0.0) {
      dist = b->hi[dim] - p->x[dim][i];
      u = v;
    } else {
      continue;
    }
    const double dw = fmax(dist - p->h[i], s->tp.cfl * p->h[i]) / u;
    if (dw < d) {
      d = dw;
      k = DT_CFL;
    }
  }
  if (p->axisym && p->v[1][i] < 0.0) { /* towards the axis: at most half way per step */
    const double dr = 0.5 * sph_rz_radius(p->x[1][i], p->h[i]) / -p->v[1][i];
    if (dr < d) {
      d = dr;
      k = DT_CFL;
    }
  }
  *kind = k;
  return d;
}

static double next_dt(struct sim *s)
{
  struct particles *p = &s->p;
  double dt = HUGE_VAL;
  size_t who = SIZE_MAX;
  int kind = DT_CFL;
  struct mirrors mr;
  mirrors_of(&s->bnd, &mr);
#pragma omp parallel
  {
    double tdt = HUGE_VAL;
    size_t twho = SIZE_MAX;
    int tkind = DT_CFL;
#pragma omp for schedule(static)
    for (size_t i = 0; i < p->n; i++) {
      int k;
      const double d = own_limit(s, &mr, i, &k);
      p->dt[i] = d; /* its own limit, for the snapshots (output-files.md) */
      if (d < tdt) {
        tdt = d;
        twho = i;
        tkind = k;
      }
    }
#pragma omp critical(hv_next_dt)
    if (tdt < dt || (tdt == dt && twho < who)) {
      dt = tdt;
      who = twho;
      kind = tkind;
    }
  }
  s->dt_limit = (enum dt_limit)kind;
  s->dt_limit_id = who < p->n ? p->id[who] : -1;
  s->dt_limit_body = who < p->n ? p->body[who] : -1;
  if (s->dt_prop > 0 && dt > s->tp.growth * s->dt_prop) {
    dt = s->tp.growth * s->dt_prop;
    s->dt_limit = DT_GROWTH;
  }
  if (s->tp.dt_max > 0 && dt > s->tp.dt_max) {
    dt = s->tp.dt_max;
    s->dt_limit = DT_MAX;
  }
  return dt;
}

const char *step_limit_name(enum dt_limit k)
{
  static const char *const names[] = {"CFL h/v_sig", "acceleration sqrt(h/|a|)", "growth limit",
                                      "time.dt_max", "time.dt_init"};
  return names[k];
}

/* After a step: every real finite with ρ > 0; names the offender of the lowest slot. */
static int check_state_mask(const struct sim *s, const int32_t *mask, struct hv_error *err)
{
  const struct particles *p = &s->p;
  long bad = LONG_MAX;
#pragma omp parallel for schedule(static) reduction(min : bad)
  for (size_t i = 0; i < p->n; i++) {
    if (mask && !mask[i]) continue;
    int ok = p->rho[i] > 0 && isfinite(p->rho[i]) && isfinite(p->e[i]);
    for (int k = 0; k < 3; k++) ok = ok && isfinite(p->x[k][i]) && isfinite(p->v[k][i]);
    if (!ok && (long)i < bad) bad = (long)i;
  }
  if (bad == LONG_MAX) return 0;
  size_t i = (size_t)bad;
  const char *field = isnan(p->rho[i])       ? "rho (NaN)"
                      : !isfinite(p->rho[i]) ? "rho (infinite)"
                      : !(p->rho[i] > 0)     ? "rho (<= 0)"
                      : !isfinite(p->e[i])   ? "e (not finite)"
                                             : "x or v (not finite)";
  return hv_error_set(err, HV_EXIT_RUN,
                      "t = %.9g s, step %ld: particle %lld (body '%s'): "
                      "field %s: rho = %g kg/m3, e = %g J/kg, x = (%g, %g, %g) m",
                      s->t, s->step, (long long)p->id[i], s->body[p->body[i]].name, field,
                      p->rho[i], p->e[i], p->x[0][i], p->x[1][i], p->x[2][i]);
}

static int check_state(const struct sim *s, struct hv_error *err)
{
  return check_state_mask(s, NULL, err);
}

/* End of step for solids: S takes the end-of-step deviator (S1, the stress update's),
 * then fracture acts on σ = −pI + S (fracture_end_step). Returns how many particles
 * need their pressure evaluated again. */
static long end_stress(struct sim *s, double dt)
{
  struct particles *p = &s->p;
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < p->n; i++)
    for (int k = 0; k < 6; k++) p->S[k][i] = p->S1[k][i];
  return fracture_end_step(p, s->mat, dt);
}

/* sph.rest_tolerance. The SPH stencil carries a disturbance one kernel support per step,
 * much faster than sound (2h per step against c·dt ≈ 0.14 h): ahead of a wave, material
 * the wave has not reached takes values that decay by orders of magnitude per support
 * but are not zero (a whole backwall ahead of the debris; docs/case-files.md,
 * `rest_tolerance`), and sph.skip_resting, which needs exact zeros, then skips nothing.
 * A particle of a condensed material whose velocity, acceleration, energy, energy
 * rate, density offset and deviatoric stress are all within rest_tol of their scales
 * is put exactly at rest: v = a = 0, e = ė = 0, ρ = ρ₀, S₁ = 0 (p then follows from
 * the EOS). With the default 1e-14 this changes nothing above that fraction of the
 * material's own scales; a particle that any physical signal has reached is far above
 * it. Before the end-of-step EOS, so that p is the EOS's at (ρ₀, 0). */
struct rest_limits {
  /* per material: the thresholds of v, e, ρ − ρ₀ and S (0: not a condensed material) */
  double vt[HV_MAX_MATERIALS], et[HV_MAX_MATERIALS], rt[HV_MAX_MATERIALS], st[HV_MAX_MATERIALS];
};

static void rest_limits(const struct sim *s, struct rest_limits *r)
{
  const double tol = s->sph.rest_tol;
  for (int j = 0; j < s->nmat; j++) {
    const struct material *m = &s->mat[j];
    const int cond = m->rho0 > 0.0 && m->K0 > 0.0;
    const double c = cond ? sqrt(m->K0 / m->rho0) : 0.0;
    r->vt[j] = tol * c;
    r->et[j] = tol * c * c;
    r->rt[j] = tol * m->rho0;
    r->st[j] = cond ? tol * m->K0 : 0.0;
  }
}

/* clamp_to_rest for real i at the end of its step dt. */
static inline void clamp_one(struct sim *s, const struct rest_limits *r, size_t i, double dt)
{
  struct particles *p = &s->p;
  const int j = p->mat[i];
  if (!(r->st[j] > 0.0)) return;
  int rest = fabs(p->e[i]) <= r->et[j] && fabs(p->de[i]) * dt <= r->et[j] &&
             fabs(p->rho[i] - s->mat[j].rho0) <= r->rt[j];
  for (int k = 0; rest && k < 3; k++)
    rest = fabs(p->v[k][i]) <= r->vt[j] && fabs(p->a[k][i]) * dt <= r->vt[j];
  for (int k = 0; rest && k < 6; k++) rest = fabs(p->S1[k][i]) <= r->st[j];
  if (!rest) return;
  for (int k = 0; k < 3; k++) p->v[k][i] = p->a[k][i] = 0.0;
  for (int k = 0; k < 6; k++) p->S1[k][i] = 0.0;
  p->e[i] = p->de[i] = 0.0;
  p->rho[i] = s->mat[j].rho0;
}

static void clamp_to_rest(struct sim *s, double dt)
{
  struct particles *p = &s->p;
  if (!(s->sph.rest_tol > 0.0) || !p->solid) return;
  struct rest_limits r;
  rest_limits(s, &r);
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < p->n; i++) clamp_one(s, &r, i, dt);
}

static int tb_block_length(struct sim *s, struct hv_error *err);

int step_init(struct sim *s, struct hv_error *err)
{
  struct particles *p = &s->p;
  if (update_eos(s, err)) return -1;
  if (build_neighbours(s, err)) {
    /* before the first step the set-up is at fault (a body far out, a periodic domain
       of 1e308 m whose ghosts span it): bad input, said against the domain */
    if (err->code == HV_EXIT_RUN) {
      const char *key = s->cfg && cfg_has(s->cfg, "domain") ? "domain" : "bodies";
      char where[256] = "";
      if (s->cfg) cfg_where(s->cfg, key, where, sizeof where);
      hv_error_prefix(err,
                      "%s%s%s: the bodies with their boundary ghosts do not fit the "
                      "neighbour grid: ",
                      where, *where ? ": " : "", key);
      err->code = HV_EXIT_INPUT;
    }
    return -1;
  }
  sph_artificial_stress(p, &s->sph, s->mat);
  boundary_refresh_ghosts(&s->bnd, p);
  for (size_t i = 0; i < p->n; i++) p->de[i] = 0.0;
  sph_forces(p, &s->grid, &s->sph, NULL, s->mat);
  s->dt_prop = 0.0;
  const double dt = next_dt(s); /* with time.dt_init too: each particle's own limit */
  s->dt = s->dt_prop = s->tp.dt_init > 0 ? s->tp.dt_init : dt;
  if (s->tp.dt_init > 0) s->dt_limit = DT_INIT;
  if (p->indiv) { /* the first block from the own limits; time.dt_init bounds the first
                     steps (tb_want: within twice the last) */
    for (size_t i = 0; i < p->n; i++) {
      p->dt_own[i] = p->dt[i];
      p->dt_prev[i] = s->tp.dt_init > 0 ? 0.5 * s->tp.dt_init : HUGE_VAL;
      p->drho_s[i] = 0.0;
    }
    return tb_block_length(s, err);
  }
  return 0;
}

static void reorder(struct sim *s)
{
  struct particles *p = &s->p;
  uint32_t *order = hv_malloc((p->n + 1) * sizeof *order, "reorder");
  const double *xs[3] = {p->x[0], p->x[1], p->x[2]};
  if (nbr_sort_order(xs, p->n, nbr_cell_size(cell_h_reals(p), step_hmax(p)), order) == 0)
    particles_permute(p, order);
  free(order);
}

/* ---- individual (block) time steps: time.individual (step.h) ---------------------- */

/* The limiter's ratio: a particle's step at most 4 times its neighbours' (two levels),
 * as SWIFT's limiter (its bins within 2 of the neighbours'; Saitoh & Makino 2009 argue for
 * such a bound). It bounds how far the inactive neighbour of an evaluated particle moves
 * on stale rates during that particle's step. Measured 2026-12-08 on test_sedov with
 * individual steps: 2 took 9 % more evaluations and moved the energy error only from
 * −0.97 % to −0.89 %; without the limiter it is −2.36 %. */
#define TB_RATIO 4

/* The state of real i at sdt after its step start (x0, v0, ρ0, e0, S0) from its latest
 * rates a, ė, Dρ (this step's once evaluated, tb_done, else the last step's): the
 * corrector's own arithmetic, so that at sdt = its step it is the corrector's end state
 * bit for bit, v = v0 + Δt a, x = (x0 + ½Δt v0) + ½Δt v; between, the same quadratic
 * x0 + s v0 + ½s² a. A neighbour that is not evaluated at a tick is seen at this state
 * (its drift); S moves linearly from S0 to the stress update's S1. */
static inline void tb_state_at(struct particles *p, size_t i, double sdt, int logrho)
{
  const double h = 0.5 * sdt;
  for (int k = 0; k < 3; k++) {
    p->v[k][i] = p->v0[k][i] + sdt * p->a[k][i];
    p->x[k][i] = (p->x0[k][i] + h * p->v0[k][i]) + h * p->v[k][i];
  }
  p->rho[i] =
      logrho ? p->rho0[i] * exp(sdt * p->drho_s[i] / p->rho0[i]) : p->rho0[i] + sdt * p->drho_s[i];
  p->e[i] = p->e0[i] + sdt * p->de[i];
  if (!p->solid) return;
  if (!p->tb_done[i])
    for (int k = 0; k < 6; k++) p->S[k][i] = p->S0[k][i];
  else if (sdt == p->tb_dt[i])
    for (int k = 0; k < 6; k++) p->S[k][i] = p->S1[k][i];
  else
    for (int k = 0; k < 6; k++)
      p->S[k][i] = p->S0[k][i] + sdt / p->tb_dt[i] * (p->S1[k][i] - p->S0[k][i]);
}

/* Whether real i's drift leaves it where its step started: at rest with no rates (and
 * no change of stress), as most of a target far from an impact. Its state is its
 * start's then (tb_begin set it, and a drift or its predictor moves nothing), so the
 * drift and its pressure are skipped: the same bits, at a fraction of the cost. */
static inline int tb_still(const struct particles *p, size_t i)
{
  if (p->de[i] != 0.0 || p->drho_s[i] != 0.0) return 0;
  for (int k = 0; k < 3; k++)
    if (p->v0[k][i] != 0.0 || p->a[k][i] != 0.0) return 0;
  if (p->solid && p->tb_done[i])
    for (int k = 0; k < 6; k++)
      if (p->S1[k][i] != p->S0[k][i]) return 0;
  return 1;
}

/* The longest step, in ticks of tau, that real i may start at tick T of a block of TB
 * ticks: a power of two, at least 2 (the finest), that T is a multiple of (the steps of
 * a level start together), that ends by TB, within its own limit, within twice its last
 * step and within time.dt_max. Counts in *over a step that wanted less than the finest. */
static int32_t tb_want(const struct sim *s, size_t i, int32_t T, int32_t TB, double tau, long *over)
{
  const struct particles *p = &s->p;
  double lim = p->dt_own[i];
  if (2.0 * p->dt_prev[i] < lim) lim = 2.0 * p->dt_prev[i];
  if (s->tp.dt_max > 0 && s->tp.dt_max < lim) lim = s->tp.dt_max;
  int32_t len = 2;
  if (2.0 * tau > lim) ++*over;
  while (2 * len <= TB - T && T % (2 * len) == 0 && (double)(2 * len) * tau <= lim) len *= 2;
  return len;
}

/* Real i starts a step of len ticks at tick T. */
static inline void tb_begin(struct particles *p, size_t i, int32_t T, int32_t len, double tau)
{
  for (int k = 0; k < 3; k++) {
    p->x0[k][i] = p->x[k][i];
    p->v0[k][i] = p->v[k][i];
  }
  p->rho0[i] = p->rho[i];
  p->e0[i] = p->e[i];
  if (p->solid)
    for (int k = 0; k < 6; k++) p->S0[k][i] = p->S[k][i];
  p->tb_done[i] = 0;
  p->tb_start[i] = T;
  p->tb_len[i] = len;
  p->tb_end[i] = T + len;
  p->tb_mid[i] = T + len / 2;
  p->tb_dt[i] = (double)len * tau;
}

/* The end of the step of the reals with set[i] == flag at tick T, their state already
 * at T (tb_state_at, boundaries applied): what the global step does at its end (rest,
 * checks, EOS, fracture, h unless keep_h, the own limit), then each starts its next
 * step, the longest tb_want allows. */
static int tb_close(struct sim *s, const int32_t *set, int32_t T, int32_t TB, double tau,
                    int keep_h, struct hv_error *err)
{
  struct particles *p = &s->p;
  const size_t n = p->n;
  if (p->solid && s->sph.rest_tol > 0.0) {
    struct rest_limits r;
    rest_limits(s, &r);
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < n; i++)
      if (set[i]) {
        const double sdt = (double)(T - p->tb_start[i]) * tau;
        /* S1 is the stress the clamp tests and the step ends with */
        for (int k = 0; k < 6; k++) p->S1[k][i] = p->S[k][i];
        clamp_one(s, &r, i, sdt);
        for (int k = 0; k < 6; k++) p->S[k][i] = p->S1[k][i];
      }
  }
  if (check_state_mask(s, set, err) || update_eos_mask(s, set, err)) return -1;
  if (p->solid) {
    long again = 0;
    int32_t *redo = p->tb_cap; /* scratch here: the limiter reads it before */
#pragma omp parallel for schedule(static) reduction(+ : again)
    for (size_t i = 0; i < n; i++) {
      redo[i] = 0;
      if (set[i]) redo[i] = fracture_end_particle(p, i, s->mat, (double)(T - p->tb_start[i]) * tau);
      again += redo[i];
    }
    if (again > 0 && update_eos_mask(s, redo, err)) return -1;
  }
  struct mirrors mr;
  mirrors_of(&s->bnd, &mr);
  long over = 0;
#pragma omp parallel for schedule(static) reduction(+ : over)
  for (size_t i = 0; i < n; i++) {
    if (!set[i]) continue;
    if (!keep_h) update_h_one(s, i);
    int k;
    p->dt[i] = p->dt_own[i] = own_limit(s, &mr, i, &k);
    p->dt_prev[i] = (double)(T - p->tb_start[i]) * tau;
    if (T < TB) tb_begin(p, i, T, tb_want(s, i, T, TB, tau, &over), tau);
  }
  s->over_steps += over;
  return 0;
}

/* Real i's step, started at tb_start and not evaluated yet, set to end at tick te (its
 * mid-step then half-way), with len ticks for the limiter. */
static inline void tb_reschedule(struct particles *p, size_t i, int32_t te, int32_t len, double tau)
{
  const int32_t t0 = p->tb_start[i];
  p->tb_end[i] = te;
  p->tb_len[i] = len;
  p->tb_mid[i] = t0 + (te - t0) / 2;
  p->tb_dt[i] = (double)(te - t0) * tau;
}

/* The limiter (Saitoh & Makino 2009) at tick T, on the grid of this tick, for the reals
 * that started a step since the last one ran (set[i] != 0; not evaluated yet):
 *  - each takes at most TB_RATIO times the shortest step among its neighbours
 *    (repeated until none shortens: the steps only shorten, so it ends), but with its
 *    mid-step not before T;
 *  - a neighbour on a step more than TB_RATIO times theirs is woken, its step cut to
 *    the grid of the step TB_RATIO times theirs: evaluated already, it ends at the
 *    first tick of that grid from T on — at T itself it ends now (keeping its h until
 *    its next end: the grid of this tick holds the old one) and starts the shorter step,
 *    and the limiter goes on from it; not evaluated yet, it ends at the first tick of
 *    that grid that leaves its mid-step at T or later (at T: evaluated now), its rates
 *    then taken over the shortened step.
 * Every read is of the step lengths before a pass and every write a minimum, so the
 * result does not depend on the thread count. Returns 0 or -1 with err set. */
static int tb_limit(struct sim *s, int32_t *set, int32_t *next, int32_t T, int32_t TB, double tau,
                    struct hv_error *err)
{
  struct particles *p = &s->p;
  const size_t n = p->n;
  for (;;) {
    long changed;
    do {
      sph_step_exchange(p, &s->grid, set, p->tb_len, p->tb_cap, p->tb_wake);
      changed = 0;
#pragma omp parallel for schedule(static) reduction(+ : changed)
      for (size_t i = 0; i < n; i++) {
        if (!set[i] || p->tb_cap[i] >= INT32_MAX / TB_RATIO) continue;
        const int32_t t0 = p->tb_start[i];
        int32_t len = TB_RATIO * p->tb_cap[i];
        while (t0 + len / 2 < T) len *= 2; /* its mid-step not in the past */
        if (p->tb_len[i] > len) {
          tb_reschedule(p, i, t0 + len, len, tau);
          changed++;
        }
      }
    } while (changed);
    long now = 0;
#pragma omp parallel for schedule(static) reduction(+ : now)
    for (size_t i = 0; i < n; i++) {
      const int32_t w = p->tb_wake[i];
      p->tb_wake[i] = INT32_MAX;
      next[i] = 0;
      if (set[i] || w >= INT32_MAX / TB_RATIO || p->tb_len[i] <= TB_RATIO * w) continue;
      const int32_t len = TB_RATIO * w, t0 = p->tb_start[i];
      if (p->tb_done[i]) {
        if (T % len == 0) { /* ends now */
          next[i] = 1;
          now++;
        } else {
          p->tb_end[i] = (T / len + 1) * len;
          p->tb_len[i] = len;
        }
      } else {
        const int32_t from = 2 * T - t0, te = (from + len - 1) / len * len;
        tb_reschedule(p, i, te > t0 + len ? te : t0 + len, len, tau);
        if (p->tb_mid[i] == T) p->tb_act[i] = 1;
      }
    }
    if (!now) return 0;
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < n; i++) set[i] = next[i];
    if (tb_close(s, set, T, TB, tau, 1, err)) return -1;
  }
}

/* The rates of the reals whose mid-step is tick T (tb_act), as the global step's
 * passes 2–5 but for them alone; the others are seen at their drifted state. */
static int tb_evaluate(struct sim *s, struct hv_error *err)
{
  struct particles *p = &s->p;
  const size_t n = p->n;
  const int summed = s->sph.summation && !p->solid, logrho = !s->sph.continuity_mass && !summed;
  p->active = p->tb_act;
  p->step_dt = p->tb_dt;
  sph_density_rate(p, &s->grid, &s->sph, &s->cache, s->mat, s->dt);
  long count = 0;
#pragma omp parallel for schedule(static) reduction(+ : count)
  for (size_t i = 0; i < n; i++) {
    if (!p->tb_act[i]) continue;
    const double hdt = 0.5 * p->tb_dt[i];
    p->drho_s[i] = p->drho[i];
    if (summed) /* ρ holds the mid-step sum: the step goes on from it linearly (as the
                   global step's end, ρ* + ½Δt Dρ), the start taken back to match */
      p->rho0[i] = p->rho[i] - hdt * p->drho[i];
    else
      p->rho[i] =
          logrho ? p->rho0[i] * exp(hdt * p->drho[i] / p->rho0[i]) : p->rho0[i] + hdt * p->drho[i];
    count++;
  }
  int rc = update_eos_mask(s, p->tb_act, err);
  if (!rc) {
    sph_artificial_stress(p, &s->sph, s->mat);
    boundary_refresh_ghosts(&s->bnd, p);
    if (s->cache.gradv) { /* every real's: the others' from the store (sph_solid.c) */
      boundary_refresh_gradv(&s->bnd, p->n, p->n_ghost, s->cache.gradv);
      s->cache.gradv_valid = 1;
    }
    sph_forces(p, &s->grid, &s->sph, &s->cache, s->mat);
  }
  s->cache.valid = 0;
  s->cache.gradv_valid = 0;
  p->active = NULL;
  p->step_dt = NULL;
  if (rc) return -1;
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < n; i++)
    if (p->tb_act[i]) p->tb_done[i] = 1;
  s->evals += count;
  s->eval_ticks++;
  return 0;
}

/* The block's length from the reals' own limits: 2^(levels − 2) times the shortest, so
 * that a particle may shorten its step 4 times within the block before it reaches the
 * finest, and no longer than the longest limit. Sets what set it (progress line) and
 * fails below time.dt_min. */
static int tb_block_length(struct sim *s, struct hv_error *err)
{
  struct particles *p = &s->p;
  double lo = HUGE_VAL, hi = 0.0;
  size_t who = SIZE_MAX;
  for (size_t i = 0; i < p->n; i++) {
    if (p->dt_own[i] < lo) {
      lo = p->dt_own[i];
      who = i;
    }
    if (p->dt_own[i] > hi) hi = p->dt_own[i];
  }
  if (who == SIZE_MAX) return 0; /* no particle: the block stays */
  struct mirrors mr;
  mirrors_of(&s->bnd, &mr);
  int kind;
  own_limit(s, &mr, who, &kind);
  s->dt_limit = (enum dt_limit)kind;
  s->dt_limit_id = p->id[who];
  s->dt_limit_body = p->body[who];
  if (!(lo >= s->tp.dt_min))
    return hv_error_set(err, HV_EXIT_RUN,
                        "t = %.9g s, step %ld: the time step of particle %lld fell to %g s, "
                        "below time.dt_min = %g s",
                        s->t, s->step, (long long)p->id[who], lo, s->tp.dt_min);
  double D = ldexp(lo, s->tp.levels - 2);
  if (D > hi) D = hi;
  s->dt = s->dt_prop = D;
  return 0;
}

/* One block of s->dt: every real starts a step at its beginning (tick 0) and ends one
 * at its end (tick TB = 2^(levels+1)); between, each advances on its own steps of 2^j
 * ticks (tick = block/TB: the finest step, block/2^levels, is 2 ticks, its mid-step
 * the tick between). At a tick where steps end, those reals end theirs (tb_close) and
 * start the next; at a tick where mid-steps fall, every other real is drifted to it,
 * the grid is built, the limiter runs for the steps started since the last such tick,
 * and the reals whose mid-step it is get their rates (tb_evaluate). A tick with
 * neither is skipped. */
static int block_advance(struct sim *s, struct hv_error *err)
{
  struct particles *p = &s->p;
  if (s->reorder_every > 0 && s->step % s->reorder_every == 0) reorder(s);
  const int32_t TB = (int32_t)1 << (s->tp.levels + 1);
  const double tau = s->dt / TB;
  /* ρ over a step: as the global step, ρ0 exp(s Dρ/ρ0) in the volume form, linear in
     the mass form and with summation (tb_evaluate) */
  const int logrho = !s->sph.continuity_mass && !(s->sph.summation && !p->solid);
  const size_t n = p->n;
  /* set: the steps that end at a tick; next: scratch; pend: started since the last
     limiter */
  int32_t *set = hv_malloc((3 * n + 1) * sizeof *set, "individual steps"), *next = set + n,
          *pend = next + n;
  int rc = 0;
  long over = 0;
#pragma omp parallel for schedule(static) reduction(+ : over)
  for (size_t i = 0; i < n; i++) {
    pend[i] = 1;
    p->tb_wake[i] = INT32_MAX;
    p->tb_act[i] = 0;
    tb_begin(p, i, 0, tb_want(s, i, 0, TB, tau, &over), tau);
  }
  s->over_steps += over;
  for (int32_t T = 1; T <= TB && !rc; T++) {
    long nf = 0, ne = 0;
#pragma omp parallel for schedule(static) reduction(+ : nf, ne)
    for (size_t i = 0; i < n; i++) {
      set[i] = p->tb_end[i] == T;
      p->tb_act[i] = p->tb_mid[i] == T;
      nf += set[i];
      ne += p->tb_act[i];
    }
    if (nf) { /* steps end: their end state, then the next steps */
#pragma omp parallel for schedule(static)
      for (size_t i = 0; i < n; i++)
        if (set[i]) tb_state_at(p, i, (double)(T - p->tb_start[i]) * tau, logrho);
      p->n_ghost = 0;
      if (boundary_any(&s->bnd)) boundary_apply(&s->bnd, p);
      if (tb_close(s, set, T, TB, tau, 0, err)) {
        rc = -1;
        break;
      }
#pragma omp parallel for schedule(static)
      for (size_t i = 0; i < n; i++) pend[i] |= set[i];
    }
    if (!ne || T == TB) continue;
      /* every other real at T: the evaluated ones at their predictor (the global step's
       1.), the others drifted; the pressure of those that moved */
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < n; i++) {
      next[i] = 0;
      if (p->tb_act[i]) {
        const double hdt = 0.5 * p->tb_dt[i];
        for (int k = 0; k < 3; k++) {
          p->x[k][i] = p->x0[k][i] + hdt * p->v0[k][i];
          p->v[k][i] = p->v0[k][i] + hdt * p->a[k][i];
        }
        p->rho[i] = p->rho0[i];
        p->e[i] = p->e0[i] + hdt * p->de[i];
        if (p->solid)
          for (int k = 0; k < 6; k++) p->S[k][i] = p->S0[k][i];
      } else if (p->tb_start[i] != T && !tb_still(p, i)) { /* (one that started at T is
                                                               there) */
        tb_state_at(p, i, (double)(T - p->tb_start[i]) * tau, logrho);
        next[i] = 1;
      }
    }
    p->n_ghost = 0;
    if (boundary_any(&s->bnd)) boundary_apply(&s->bnd, p);
    if (update_eos_mask(s, next, err) || build_neighbours(s, err) ||
        tb_limit(s, pend, next, T, TB, tau, err)) {
      rc = -1;
      break;
    }
    ne = 0; /* the limiter may have moved a mid-step to T */
#pragma omp parallel for schedule(static) reduction(+ : ne)
    for (size_t i = 0; i < n; i++) {
      ne += p->tb_act[i];
      pend[i] = 0;
    }
    if (ne && tb_evaluate(s, err)) rc = -1;
  }
  free(set);
  if (rc) return -1;
  p->n_ghost = 0;
  s->t += s->dt;
  s->step++;
  if (tb_block_length(s, err)) return -1;
  if (boundary_any(&s->bnd)) boundary_absorb(&s->bnd, p);
  return 0;
}

int step_advance(struct sim *s, struct hv_error *err)
{
  if (s->p.indiv) return block_advance(s, err);
  struct particles *p = &s->p;
  const double dt = s->dt, hdt = 0.5 * dt;
  size_t n = p->n;
  if (s->reorder_every > 0 && s->step % s->reorder_every == 0) reorder(s);

    /* 1. predictor: coordinates, velocities and energy at mid-step (from the last
   *    step's rates); save the step start */
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < n; i++) {
    for (int k = 0; k < 3; k++) {
      p->v0[k][i] = p->v[k][i];
      p->x[k][i] += hdt * p->v[k][i];
      p->v[k][i] += hdt * p->a[k][i];
    }
    p->rho0[i] = p->rho[i];
    p->e0[i] = p->e[i];
    p->e[i] += hdt * p->de[i];
  }
  if (build_neighbours(s, err)) return -1;

  /* 2. density rate (and, for solids, the stress update) at mid-step; mid-step
   *    density and pressure; artificial stress; ghosts take the mid-step values */
  sph_density_rate(p, &s->grid, &s->sph, &s->cache, s->mat, dt);
  const int summed = s->sph.summation && !p->solid; /* rho holds the mid-step sum */
  /* continuity in the volume form, Dρ = ρ Σⱼ Vⱼ vᵢⱼ·∇ᵢWᵢⱼ, integrated as
     d ln ρ/dt = Dρ/ρ over the step with the mid-step rate: ρ = ρⁿ exp(Δt Dρ/ρⁿ), the
     same as ρⁿ + Δt Dρ to second order in Δt Dρ/ρⁿ (the scheme's order) and positive
     however fast a particle expands (debris whose h grows to h_max among receding
     neighbours: W.P.3 with density diffusion went below 0 at 5 µs with the linear
     update, before the neighbour-volume bound of sph_solid.c); the mass form, the
     exact rate of the summed density, is not proportional to ρ and stays linear */
  const int logrho = !s->sph.continuity_mass; /* an error with strength or fracture */
  if (!summed) {
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < n; i++)
      p->rho[i] =
          logrho ? p->rho0[i] * exp(hdt * p->drho[i] / p->rho0[i]) : p->rho0[i] + hdt * p->drho[i];
  }
  if (update_eos(s, err)) return -1;
  sph_artificial_stress(p, &s->sph, s->mat);
  boundary_refresh_ghosts(&s->bnd, p);
  if (s->cache.gradv) {
    boundary_refresh_gradv(&s->bnd, p->n, p->n_ghost, s->cache.gradv);
    s->cache.gradv_valid = 1;
  }

  /* 3–5. forces and energy rate at mid-step; velocity, coordinates, energy */
  sph_forces(p, &s->grid, &s->sph, &s->cache, s->mat);
  s->cache.valid = 0;
  s->cache.gradv_valid = 0;
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < n; i++) {
    for (int k = 0; k < 3; k++) {
      p->v[k][i] = p->v0[k][i] + dt * p->a[k][i];
      p->x[k][i] += hdt * p->v[k][i];
    }
    /* continuity: over the whole step; summation: from the mid-step sum */
    p->rho[i] = summed   ? p->rho[i] + hdt * p->drho[i]
                : logrho ? p->rho0[i] * exp(dt * p->drho[i] / p->rho0[i])
                         : p->rho0[i] + dt * p->drho[i];
    p->e[i] = p->e0[i] + dt * p->de[i];
  }
  p->n_ghost = 0;
  if (boundary_any(&s->bnd)) {
    boundary_apply(&s->bnd, p);
    boundary_absorb(&s->bnd, p);
  }

  /* 6. pressure, stress, fracture, smoothing length, next step */
  s->t += dt;
  s->step++;
  clamp_to_rest(s, dt);
  if (check_state(s, err) || update_eos(s, err)) return -1;
  if (p->solid) {
    /* new splits in tension lose it, opening planes move it: re-evaluate only when
       there are some */
    if (end_stress(s, dt) > 0 && update_eos(s, err)) return -1;
  }
  update_h(s);
  s->dt = s->dt_prop = next_dt(s);
  if (!(s->dt >= s->tp.dt_min))
    return hv_error_set(err, HV_EXIT_RUN,
                        "t = %.9g s, step %ld: the time step fell to %g s, "
                        "below time.dt_min = %g s",
                        s->t, s->step, s->dt, s->tp.dt_min);
  return 0;
}
