/* boundary.c — see boundary.h. */
#include "boundary/boundary.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "config/config.h"
#include "core/error.h"

const char *const bnd_kind_names[] = {"open", "periodic", "wall", "symmetry", "absorbing", NULL};
static const char *const geometry_names[] = {"3d", "axisymmetric", NULL};

static int is_mirror(int kind) { return kind == BND_WALL || kind == BND_SYMMETRY; }

void boundary_init(struct boundary *b)
{
  memset(b, 0, sizeof *b);
  for (int d = 0; d < 3; d++) {
    b->lo[d] = -HUGE_VAL;
    b->hi[d] = HUGE_VAL;
  }
}

void boundary_free(struct boundary *b)
{
  free(b->src);
  free(b->flip);
  free(b->side);
  boundary_init(b);
}

int boundary_any(const struct boundary *b)
{
  for (int d = 0; d < 3; d++)
    if (b->kind[d][0] != BND_OPEN || b->kind[d][1] != BND_OPEN) return 1;
  return 0;
}

/* domain.symmetry (none, half, quarter), or its older form domain.half_model: true
 * (symmetry: half), not both. A half model's z_min face, and a quarter model's z_min and
 * y_min faces, are symmetry planes through the impact axis y = 0, z = 0: given open (the
 * default) or symmetry, taken as symmetry; any other kind refused. */
static int read_symmetry(struct boundary *b, struct cfg *c, struct hv_error *err)
{
  static const char *const sym_names[] = {"none", "half", "quarter", NULL};
  char where[256];
  int no = 0, sym = 0;
  const int has_sym = cfg_has(c, "domain.symmetry"), has_half = cfg_has(c, "domain.half_model");
  if (has_sym && has_half)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: domain.half_model: give either 'symmetry' or "
                        "'half_model' (half_model: true is symmetry: half), not both",
                        cfg_where(c, "domain.half_model", where, sizeof where));
  if (has_half) {
    if (cfg_get_bool(c, "domain.half_model", &no, &b->half_model, err)) return -1;
    sym = b->half_model;
  } else if (cfg_get_choice(c, "domain.symmetry", "none", sym_names, &sym, err)) {
    return -1;
  }
  const char *key = has_half ? "domain.half_model" : "domain.symmetry";
  b->half_model = sym >= 1;
  b->quarter_model = sym == 2;
  for (int d = 2; d >= 1; d--) {
    if (d == 1 && !b->quarter_model) break;
    if (d == 2 && !b->half_model) continue;
    if (b->kind[d][0] != BND_OPEN && b->kind[d][0] != BND_SYMMETRY)
      return hv_error_set(err, HV_EXIT_INPUT,
                          "%s: %s: the %c_min face of a %s model is the symmetry "
                          "plane %c = 0; it cannot be '%s'",
                          cfg_where(c, key, where, sizeof where), key, "xyz"[d], sym_names[sym],
                          "xyz"[d], bnd_kind_names[b->kind[d][0]]);
    b->kind[d][0] = BND_SYMMETRY;
  }
  return 0;
}

int boundary_read(struct boundary *b, struct cfg *c, struct hv_error *err)
{
  static const char *face[3][2] = {{"x_min", "x_max"}, {"y_min", "y_max"}, {"z_min", "z_max"}};
  boundary_init(b);
  char key[128], where[256];
  int geometry = 0;
  if (cfg_get_choice(c, "domain.geometry", geometry_names[0], geometry_names, &geometry, err))
    return -1;
  if (geometry == 1) return boundary_read_axisym(b, c, err);
  for (int d = 0; d < 3; d++) {
    /* either the shorthand `x: kind` for both faces, or `x_min`/`x_max`; only what
       the case gives is read (and so recorded in used_parameters.yaml) */
    snprintf(key, sizeof key, "domain.boundary.%c", "xyz"[d]);
    int both = BND_OPEN;
    int has_both = cfg_has(c, key);
    if (has_both && cfg_get_choice(c, key, NULL, bnd_kind_names, &both, err)) return -1;
    for (int s = 0; s < 2; s++) {
      snprintf(key, sizeof key, "domain.boundary.%s", face[d][s]);
      if (has_both && cfg_has(c, key))
        return hv_error_set(err, HV_EXIT_INPUT,
                            "%s: domain.boundary.%s: give either '%c' or "
                            "'%s', not both",
                            cfg_where(c, key, where, sizeof where), face[d][s], "xyz"[d],
                            face[d][s]);
      b->kind[d][s] = both;
      if (!has_both &&
          cfg_get_choice(c, key, bnd_kind_names[BND_OPEN], bnd_kind_names, &b->kind[d][s], err))
        return -1;
    }
    if ((b->kind[d][0] == BND_PERIODIC) != (b->kind[d][1] == BND_PERIODIC))
      return hv_error_set(err, HV_EXIT_INPUT,
                          "%s: domain.boundary: periodic in %c needs "
                          "both %s and %s periodic",
                          cfg_where(c, "domain.boundary", where, sizeof where), "xyz"[d],
                          face[d][0], face[d][1]);
  }
  if (read_symmetry(b, c, err)) return -1;
  b->has_box = cfg_has(c, "domain.min") || cfg_has(c, "domain.max") || boundary_any(b);
  if (!b->has_box) return 0;
  double lo[3], hi[3];
  if (cfg_get_vec3(c, "domain.min", UNIT_LENGTH, NULL, lo, err) ||
      cfg_get_vec3(c, "domain.max", UNIT_LENGTH, NULL, hi, err))
    return -1;
  if (b->half_model && lo[2] != 0.0)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: domain.min: a %s model starts at z = 0 "
                        "(the symmetry plane), not z = %g m",
                        cfg_where(c, "domain.min", where, sizeof where),
                        b->quarter_model ? "quarter" : "half", lo[2]);
  if (b->quarter_model && lo[1] != 0.0)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: domain.min: a quarter model starts at y = 0 "
                        "(its second symmetry plane), not y = %g m",
                        cfg_where(c, "domain.min", where, sizeof where), lo[1]);
  for (int d = 0; d < 3; d++) {
    if (!(hi[d] > lo[d]))
      return hv_error_set(err, HV_EXIT_INPUT, "%s: domain.max must exceed domain.min in %c",
                          cfg_where(c, "domain.max", where, sizeof where), "xyz"[d]);
    b->lo[d] = lo[d];
    b->hi[d] = hi[d];
  }
  return 0;
}

void boundary_apply(const struct boundary *b, struct particles *p)
{
  for (int d = 0; d < 3; d++) {
    const double lo = b->lo[d], hi = b->hi[d], L = hi - lo;
    double *x = p->x[d], *v = p->v[d];
    if (b->kind[d][0] == BND_PERIODIC) {
      for (size_t i = 0; i < p->n; i++) {
        if (x[i] < lo)
          x[i] += L;
        else if (x[i] >= hi)
          x[i] -= L;
      }
      continue;
    }
    /* v0, the step's start velocity, is mirrored too: a particle that crosses the face
       in the predictor (step.c) takes its corrector's velocity v0 + Δt a from it, and
       with v0 unmirrored it ran back into the face for the step's second half, ending
       it where it began (test_timestep, part 5); at the step's end v0 is spent */
    double *v0 = p->v0[d];
    for (size_t i = 0; i < p->n; i++) {
      if (is_mirror(b->kind[d][0]) && x[i] < lo) {
        x[i] = 2.0 * lo - x[i];
        if (v[i] < 0.0) v[i] = -v[i];
        if (v0[i] < 0.0) v0[i] = -v0[i];
      } else if (is_mirror(b->kind[d][1]) && x[i] > hi) {
        x[i] = 2.0 * hi - x[i];
        if (v[i] > 0.0) v[i] = -v[i];
        if (v0[i] > 0.0) v0[i] = -v0[i];
      }
    }
  }
}

/* Shear components (bits for xy, yz, xz) reversed by a mirror normal to dimension d. */
static uint8_t mirror_flip(int d) { return d == 0 ? (1u | 4u) : d == 1 ? (1u | 2u) : (2u | 4u); }

static void apply_flip(struct particles *p, size_t g, uint8_t flip)
{
  if (!p->solid || !flip) return;
  for (int k = 0; k < 3; k++)
    if (flip & (1u << k)) {
      p->S[T_XY + k][g] = -p->S[T_XY + k][g];
      p->R[T_XY + k][g] = -p->R[T_XY + k][g];
    }
}

/* Room for `count` more ghosts: particle slots and the ghost tables. */
static void reserve_ghosts(struct boundary *b, struct particles *p, size_t count)
{
  const size_t total = p->n + p->n_ghost + count;
  particles_reserve(p, total);
  particles_touch(p, total - 1);
  if (p->n_ghost + count > b->cap) {
    b->cap = 2 * (p->n_ghost + count) + 1024;
    b->src = hv_realloc(b->src, b->cap * sizeof *b->src, "ghost sources");
    b->flip = hv_realloc(b->flip, b->cap * sizeof *b->flip, "ghost flips");
    b->side = hv_realloc(b->side, b->cap * sizeof *b->side, "ghost faces");
  }
}

/* The ghosts are made one dimension after the other, so that the ghosts of a corner are
 * ghosts of ghosts. Within a dimension the sources are reals and the earlier dimensions'
 * ghosts only: the dimension's ghosts are listed (source and face, in the order of the
 * sources and faces), then copied from their sources in parallel, then mirrored or
 * shifted. b->gstart[d]: the ghost count before dimension d, b->gstart[3] the total
 * (boundary_refresh_ghosts copies one dimension's ghosts at a time for the same reason). */
int boundary_make_ghosts(struct boundary *b, struct particles *p, double width, char *msg,
                         size_t msglen)
{
  p->n_ghost = 0;
  for (int d = 0; d < 3; d++) {
    const double lo = b->lo[d], hi = b->hi[d], L = hi - lo;
    const size_t nsrc = p->n + p->n_ghost;
    b->gstart[d] = p->n_ghost;
    if (b->kind[d][0] == BND_PERIODIC && L < 2.0 * width) {
      snprintf(msg, msglen,
               "the periodic domain is %.6g m long in %c, less than two "
               "interaction radii (2 x %.6g m)",
               L, "xyz"[d], width);
      return -1;
    }
    int make[2];
    for (int s = 0; s < 2; s++)
      make[s] = b->kind[d][s] != BND_OPEN && b->kind[d][s] != BND_ABSORBING;
    if (!make[0] && !make[1]) continue;
    size_t count = 0;
    for (size_t i = 0; i < nsrc; i++)
      count += (make[0] && p->x[d][i] < lo + width) + (make[1] && p->x[d][i] > hi - width);
    if (count == 0) continue;
    reserve_ghosts(b, p, count); /* may move the particle arrays */
    const double *x = p->x[d];
    const size_t k0 = p->n_ghost, g0 = nsrc;
    size_t k = k0;
    for (size_t i = 0; i < nsrc; i++)
      for (int s = 0; s < 2; s++) {
        if (!make[s] || !(s ? (x[i] > hi - width) : (x[i] < lo + width))) continue;
        b->src[k] = (uint32_t)i;
        b->side[k] = (uint8_t)s;
        k++;
      }
    particles_copy_many(p, g0, b->src + k0, count, PF_GHOST);
    const uint8_t mflip = mirror_flip(d);
    double *xd = p->x[d], *vd = p->v[d];
#pragma omp parallel for schedule(static)
    for (size_t q = 0; q < count; q++) {
      const size_t kk = k0 + q, g = g0 + q, src = b->src[kk];
      const int s = b->side[kk];
      const uint8_t prev = src >= p->n ? b->flip[src - p->n] : 0;
      if (b->kind[d][s] == BND_PERIODIC) {
        b->flip[kk] = prev;
        xd[g] = xd[src] + (s ? -L : L);
      } else { /* wall or symmetry plane: mirror; the copy carries the source's
                    (already flipped) values, so flip only the new mirror */
        b->flip[kk] = mflip ^ prev;
        apply_flip(p, g, mflip);
        xd[g] = 2.0 * (s ? hi : lo) - xd[src];
        vd[g] = -vd[src];
      }
    }
    p->n_ghost += count;
  }
  b->gstart[3] = p->n_ghost;
  return 0;
}

size_t boundary_absorb(struct boundary *b, struct particles *p)
{
  unsigned char *gone = NULL;
  size_t count = 0;
  for (int d = 0; d < 3; d++)
    for (int s = 0; s < 2; s++) {
      if (b->kind[d][s] != BND_ABSORBING) continue;
      for (size_t i = 0; i < p->n; i++) {
        const int out = s ? p->x[d][i] > b->hi[d] : p->x[d][i] < b->lo[d];
        if (!out) continue;
        if (!gone) gone = hv_calloc(p->n, 1, "absorbed particles");
        if (gone[i]) continue;
        gone[i] = 1;
        count++;
        struct absorbed *a = &b->absorbed;
        double v2 = 0.0;
        for (int k = 0; k < 3; k++) {
          a->mom[k] += p->m[i] * p->v[k][i];
          v2 += p->v[k][i] * p->v[k][i];
        }
        a->n++;
        a->mass += p->m[i];
        a->e_kin += 0.5 * p->m[i] * v2;
        a->e_int += p->m[i] * p->e[i];
      }
    }
  if (gone) {
    particles_remove(p, gone);
    free(gone);
  }
  return count;
}

void boundary_refresh_gradv(const struct boundary *b, size_t n, size_t n_ghost, double *G)
{
  for (int d = 0; d < 3; d++) { /* one dimension's ghosts at a time: see refresh_ghosts */
    const size_t k0 = b->gstart[d], k1 = b->gstart[d + 1] < n_ghost ? b->gstart[d + 1] : n_ghost;
#pragma omp parallel for schedule(static)
    for (size_t k = k0; k < k1; k++) {
      const size_t g = n + k, s = b->src[k];
      const uint8_t flip = b->flip[k] ^ (s >= n ? b->flip[s - n] : 0);
      double *Gg = G + 9 * g;
      for (int t = 0; t < 9; t++) Gg[t] = G[9 * s + t];
      /* a mirror normal to axis d reverses v_d and x_d, so ∂v_a/∂x_b changes sign when
         exactly one of a, b is d: the off-diagonal pairs whose shear bits the mirrors set
         (bit 0: xy, 1: yz, 2: xz); the diagonal never does */
      if (flip & 1u) {
        Gg[1] = -Gg[1];
        Gg[3] = -Gg[3];
      }
      if (flip & 2u) {
        Gg[5] = -Gg[5];
        Gg[7] = -Gg[7];
      }
      if (flip & 4u) {
        Gg[2] = -Gg[2];
        Gg[6] = -Gg[6];
      }
    }
  }
}

void boundary_refresh_ghosts(const struct boundary *b, struct particles *p)
{
  /* a ghost made from a ghost (a corner's) copies an already refreshed, already
   * mirrored source of an earlier dimension, and adds only its own mirror: the ghosts of
   * one dimension at a time, in parallel within it */
  const size_t n = p->n;
  for (int d = 0; d < 3; d++) {
    const size_t k0 = b->gstart[d],
                 k1 = b->gstart[d + 1] < p->n_ghost ? b->gstart[d + 1] : p->n_ghost;
#pragma omp parallel for schedule(static)
    for (size_t k = k0; k < k1; k++) {
      const size_t g = n + k, s = b->src[k];
      p->rho[g] = p->rho[s];
      p->p[g] = p->p[s];
      p->cs[g] = p->cs[s];
      p->e[g] = p->e[s];
      if (p->av) p->alpha[g] = p->alpha[s];
      if (p->solid) {
        for (int c = 0; c < 6; c++) {
          p->S[c][g] = p->S[c][s];
          p->R[c][g] = p->R[c][s];
        }
        p->damage[g] = p->damage[s];
        p->fstate[g] = p->fstate[s];
        apply_flip(p, g, b->flip[k] ^ (s >= n ? b->flip[s - n] : 0));
      }
    }
  }
}
