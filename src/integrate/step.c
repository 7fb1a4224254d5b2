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

/* p and cs of every real from its ρ and e; the failure of the lowest slot is reported. */
static int update_eos(struct sim *s, struct hv_error *err)
{
  struct particles *p = &s->p;
  long bad = LONG_MAX;
#pragma omp parallel for schedule(static) reduction(min : bad)
  for (size_t i = 0; i < p->n; i++) {
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

static void update_h(struct sim *s)
{
  struct particles *p = &s->p;
  const double eta = s->sph.eta, hmin = s->sph.h_min, hmax = s->sph.h_max;
  const int rz = p->axisym;
  const double cap = rz && p->rings ? s->sph.rz_stretch_max : 0.0; /* r0 = 0: no cap */
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < p->n; i++) {
    /* axisymmetric: from the area mass, h = η (m/(2π r ρ))^(1/2), the in-plane spacing,
       with r no larger than cap × r0 (the ring's axial extent does not follow its hoop
       stretch) */
    double h;
    if (rz) {
      double r = sph_rz_radius(p->x[1][i], p->h[i]);
      if (cap > 0.0 && p->r0[i] > 0.0 && r > cap * p->r0[i]) r = cap * p->r0[i];
      h = eta * sqrt(p->m[i] / (2.0 * HV_KERNEL_PI * r * p->rho[i]));
    } else {
      h = eta * cbrt(p->m[i] / p->rho[i]);
    }
    p->h[i] = h < hmin ? hmin : (h > hmax ? hmax : h);
  }
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
static double next_dt(struct sim *s)
{
  struct particles *p = &s->p;
  const struct boundary *b = &s->bnd;
  double dt = HUGE_VAL;
  size_t who = SIZE_MAX;
  int kind = DT_CFL;
  int mirror[3][2], any_mirror = 0;
  for (int d = 0; d < 3; d++)
    for (int side = 0; side < 2; side++) {
      mirror[d][side] = b->kind[d][side] == BND_WALL || b->kind[d][side] == BND_SYMMETRY;
      any_mirror |= mirror[d][side];
    }
#pragma omp parallel
  {
    double tdt = HUGE_VAL;
    size_t twho = SIZE_MAX;
    int tkind = DT_CFL;
#pragma omp for schedule(static)
    for (size_t i = 0; i < p->n; i++) {
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
      for (int dim = 0; any_mirror && dim < 3; dim++) { /* approach to a mirror face */
        const double v = p->v[dim][i];
        double dist, u;
        if (mirror[dim][0] && v < 0.0) {
          dist = p->x[dim][i] - b->lo[dim];
          u = -v;
        } else if (mirror[dim][1] && v > 0.0) {
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
static int check_state(const struct sim *s, struct hv_error *err)
{
  const struct particles *p = &s->p;
  long bad = LONG_MAX;
#pragma omp parallel for schedule(static) reduction(min : bad)
  for (size_t i = 0; i < p->n; i++) {
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
static void clamp_to_rest(struct sim *s, double dt)
{
  struct particles *p = &s->p;
  const double tol = s->sph.rest_tol;
  if (!(tol > 0.0) || !p->solid) return;
  /* per material: the thresholds of v, e, ρ − ρ₀ and S (0: not a condensed material) */
  double vt[HV_MAX_MATERIALS], et[HV_MAX_MATERIALS], rt[HV_MAX_MATERIALS], st[HV_MAX_MATERIALS];
  for (int j = 0; j < s->nmat; j++) {
    const struct material *m = &s->mat[j];
    const int cond = m->rho0 > 0.0 && m->K0 > 0.0;
    const double c = cond ? sqrt(m->K0 / m->rho0) : 0.0;
    vt[j] = tol * c;
    et[j] = tol * c * c;
    rt[j] = tol * m->rho0;
    st[j] = cond ? tol * m->K0 : 0.0;
  }
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < p->n; i++) {
    const int j = p->mat[i];
    if (!(st[j] > 0.0)) continue;
    int rest = fabs(p->e[i]) <= et[j] && fabs(p->de[i]) * dt <= et[j] &&
               fabs(p->rho[i] - s->mat[j].rho0) <= rt[j];
    for (int k = 0; rest && k < 3; k++)
      rest = fabs(p->v[k][i]) <= vt[j] && fabs(p->a[k][i]) * dt <= vt[j];
    for (int k = 0; rest && k < 6; k++) rest = fabs(p->S1[k][i]) <= st[j];
    if (!rest) continue;
    for (int k = 0; k < 3; k++) p->v[k][i] = p->a[k][i] = 0.0;
    for (int k = 0; k < 6; k++) p->S1[k][i] = 0.0;
    p->e[i] = p->de[i] = 0.0;
    p->rho[i] = s->mat[j].rho0;
  }
}

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

int step_advance(struct sim *s, struct hv_error *err)
{
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
