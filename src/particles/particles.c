/* particles.c — storage operations driven by the field lists in particles.h. */
#include "particles/particles.h"

#include <stdlib.h>
#include <string.h>

#include "core/error.h"

size_t pf_type_size(enum pf_type t)
{
  switch (t) {
  case PF_INT32: return 4;
  case PF_INT64: return 8;
  case PF_DOUBLE: return 8;
  }
  return 8;
}

#define HV_PF_TYPE(ctype)                                                                          \
  _Generic((ctype)0, int32_t : PF_INT32, int64_t : PF_INT64, double : PF_DOUBLE)

/* Pointers to every component array of every field, allocated or not (all_fields). */
static int all_fields(struct particles *p, struct pfield *out)
{
  int k = 0;
#define HV_X(ctype, fname, funit, fflags, fdesc)                                                   \
  out[k] = (struct pfield){.name = #fname,                                                         \
                           .unit = funit,                                                          \
                           .desc = fdesc,                                                          \
                           .type = HV_PF_TYPE(ctype),                                              \
                           .ncomp = 1,                                                             \
                           .flags = fflags};                                                       \
  if (p) out[k].comp[0] = (void *)p->fname;                                                        \
  k++;
  HV_PARTICLE_SCALARS(HV_X)
#undef HV_X
#define HV_X(ctype, fname, funit, fflags, fdesc)                                                   \
  out[k] = (struct pfield){.name = #fname,                                                         \
                           .unit = funit,                                                          \
                           .desc = fdesc,                                                          \
                           .type = HV_PF_TYPE(ctype),                                              \
                           .ncomp = 3,                                                             \
                           .flags = fflags};                                                       \
  if (p)                                                                                           \
    for (int c_ = 0; c_ < 3; c_++) out[k].comp[c_] = (void *)p->fname[c_];                         \
  k++;
  HV_PARTICLE_VECTORS(HV_X)
#undef HV_X
#define HV_X(ctype, fname, funit, fflags, fdesc)                                                   \
  out[k] = (struct pfield){.name = #fname,                                                         \
                           .unit = funit,                                                          \
                           .desc = fdesc,                                                          \
                           .type = HV_PF_TYPE(ctype),                                              \
                           .ncomp = 6,                                                             \
                           .flags = fflags};                                                       \
  if (p)                                                                                           \
    for (int c_ = 0; c_ < 6; c_++) out[k].comp[c_] = (void *)p->fname[c_];                         \
  k++;
  HV_PARTICLE_TENSORS(HV_X)
#undef HV_X
  HV_CHECK(k <= HV_MAX_FIELDS, "too many particle fields (%d)", k);
  return k;
}

int particles_fields_all(struct particles *p, struct pfield *out) { return all_fields(p, out); }

static int field_allocated(const struct particles *p, const struct pfield *f)
{
  return (!(f->flags & PF_SOLID) || p->solid) && (!(f->flags & PF_AV) || p->av) &&
         (!(f->flags & PF_CRACK) || p->cracks) && (!(f->flags & PF_RING) || p->rings);
}

int particles_fields(struct particles *p, struct pfield *out)
{
  struct pfield all[HV_MAX_FIELDS];
  int n = all_fields(p, all), k = 0;
  for (int i = 0; i < n; i++)
    if (!p || field_allocated(p, &all[i])) out[k++] = all[i];
  return k;
}

size_t particles_bytes_per_particle(const struct particles *p)
{
  struct pfield f[HV_MAX_FIELDS];
  int nf = all_fields(NULL, f);
  size_t b = 0;
  for (int i = 0; i < nf; i++)
    if (p ? field_allocated(p, &f[i]) : !(f[i].flags & (PF_SOLID | PF_AV | PF_CRACK | PF_RING)))
      b += pf_type_size(f[i].type) * (size_t)f[i].ncomp;
  return b;
}

void particles_init(struct particles *p) { memset(p, 0, sizeof *p); }

void particles_free(struct particles *p)
{
  struct pfield f[HV_MAX_FIELDS];
  int nf = all_fields(p, f);
  for (int i = 0; i < nf; i++)
    for (int c = 0; c < f[i].ncomp; c++) free(f[i].comp[c]);
  memset(p, 0, sizeof *p);
}

/* Grows one component array to newcap. A new array (a == NULL) gets its first `used`
 * slots zeroed; the capacity beyond the used slots is left unwritten, so the pages
 * are not touched (they count in no resident set until a slot is used). */
static void *grow_array(void *a, size_t used, size_t newcap, size_t s, const char *name)
{
  char *q = hv_realloc(a, newcap * s, name);
  if (!a) memset(q, 0, used * s);
  return q;
}

static void reserve_to(struct particles *p, size_t newcap)
{
  struct pfield f[HV_MAX_FIELDS];
  int nf = all_fields(p, f);
  void **slot[HV_MAX_FIELDS][6];
  /* the pfield view holds copies of the pointers: write back through the struct */
  int k = 0;
#define HV_X(ctype, fname, funit, fflags, fdesc)                                                   \
  slot[k][0] = (void **)&p->fname;                                                                 \
  k++;
  HV_PARTICLE_SCALARS(HV_X)
#undef HV_X
#define HV_X(ctype, fname, funit, fflags, fdesc)                                                   \
  for (int c_ = 0; c_ < 3; c_++) slot[k][c_] = (void **)&p->fname[c_];                             \
  k++;
  HV_PARTICLE_VECTORS(HV_X)
#undef HV_X
#define HV_X(ctype, fname, funit, fflags, fdesc)                                                   \
  for (int c_ = 0; c_ < 6; c_++) slot[k][c_] = (void **)&p->fname[c_];                             \
  k++;
  HV_PARTICLE_TENSORS(HV_X)
#undef HV_X
  for (int i = 0; i < nf; i++) {
    if (!field_allocated(p, &f[i])) continue;
    size_t s = pf_type_size(f[i].type);
    for (int c = 0; c < f[i].ncomp; c++) {
      *slot[i][c] = grow_array(*slot[i][c], p->touched, newcap, s, f[i].name);
    }
  }
  p->cap = newcap;
}

void particles_reserve(struct particles *p, size_t cap)
{
  if (cap <= p->cap) return;
  size_t newcap = p->cap ? p->cap : 1024;
  while (newcap < cap) newcap += newcap / 2;
  reserve_to(p, newcap);
}

void particles_enable_solid(struct particles *p)
{
  if (p->solid) return;
  p->solid = 1;
  if (p->cap) reserve_to(p, p->cap); /* allocates the solid fields only */
}

void particles_enable_av(struct particles *p)
{
  if (p->av) return;
  p->av = 1;
  if (p->cap) reserve_to(p, p->cap); /* allocates the switch's fields only */
}

void particles_enable_crack(struct particles *p)
{
  if (p->cracks) return;
  p->cracks = 1;
  if (p->cap) reserve_to(p, p->cap); /* allocates the crack normals only */
}

void particles_enable_rings(struct particles *p)
{
  if (p->rings) return;
  p->rings = 1;
  if (p->cap) reserve_to(p, p->cap); /* allocates the rings' fields only */
}

size_t particles_add(struct particles *p, size_t count)
{
  size_t first = p->n;
  p->n_ghost = 0;
  particles_reserve(p, p->n + count);
  if (count == 0) return first; /* an empty store's arrays are NULL: no memset on them */
  struct pfield f[HV_MAX_FIELDS];
  int nf = particles_fields(p, f);
  for (int i = 0; i < nf; i++) {
    size_t s = pf_type_size(f[i].type);
    for (int c = 0; c < f[i].ncomp; c++) memset((char *)f[i].comp[c] + first * s, 0, count * s);
  }
  p->n += count;
  if (p->n > p->touched) p->touched = p->n;
  return first;
}

void particles_touch(struct particles *p, size_t slot)
{
  if (slot < p->touched) return;
  struct pfield f[HV_MAX_FIELDS];
  int nf = particles_fields(p, f);
  const size_t from = p->touched, count = slot + 1 - from;
  for (int i = 0; i < nf; i++) {
    size_t s = pf_type_size(f[i].type);
    for (int c = 0; c < f[i].ncomp; c++) memset((char *)f[i].comp[c] + from * s, 0, count * s);
  }
  p->touched = slot + 1;
}

void particles_copy(struct particles *p, size_t dst, size_t src, unsigned flags_mask)
{
#define HV_X(ctype, fname, funit, fflags, fdesc)                                                   \
  if (((fflags)&flags_mask) && p->fname) p->fname[dst] = p->fname[src];
  HV_PARTICLE_SCALARS(HV_X)
#undef HV_X
#define HV_X(ctype, fname, funit, fflags, fdesc)                                                   \
  if (((fflags)&flags_mask) && p->fname[0])                                                        \
    for (int c_ = 0; c_ < 3; c_++) p->fname[c_][dst] = p->fname[c_][src];
  HV_PARTICLE_VECTORS(HV_X)
#undef HV_X
#define HV_X(ctype, fname, funit, fflags, fdesc)                                                   \
  if (((fflags)&flags_mask) && p->fname[0])                                                        \
    for (int c_ = 0; c_ < 6; c_++) p->fname[c_][dst] = p->fname[c_][src];
  HV_PARTICLE_TENSORS(HV_X)
#undef HV_X
}

/* out[k] = in[idx[k]] for k < count, elements of type t: a work-sharing loop inside a
 * parallel region, a plain one outside. */
static void gather(enum pf_type t, void *out, const void *in, const uint32_t *idx, size_t count)
{
  if (t == PF_INT32) {
    int32_t *o = out;
    const int32_t *a = in;
#pragma omp for schedule(static)
    for (size_t k = 0; k < count; k++) o[k] = a[idx[k]];
  } else if (t == PF_INT64) {
    int64_t *o = out;
    const int64_t *a = in;
#pragma omp for schedule(static)
    for (size_t k = 0; k < count; k++) o[k] = a[idx[k]];
  } else {
    double *o = out;
    const double *a = in;
#pragma omp for schedule(static)
    for (size_t k = 0; k < count; k++) o[k] = a[idx[k]];
  }
}

void particles_copy_many(struct particles *p, size_t dst, const uint32_t *src, size_t count,
                         unsigned flags_mask)
{
  if (count == 0) return;
  struct pfield f[HV_MAX_FIELDS];
  const int nf = particles_fields(p, f);
#pragma omp parallel
  for (int i = 0; i < nf; i++) {
    if (!(f[i].flags & flags_mask)) continue;
    const size_t size = pf_type_size(f[i].type);
    for (int c = 0; c < f[i].ncomp; c++)
      gather(f[i].type, (char *)f[i].comp[c] + dst * size, f[i].comp[c], src, count);
  }
}

void particles_permute(struct particles *p, const uint32_t *order)
{
  size_t n = p->n;
  if (n == 0) return;
  void *tmp = hv_malloc(n * 8, "permutation buffer");
  struct pfield f[HV_MAX_FIELDS];
  int nf = particles_fields(p, f);
  for (int i = 0; i < nf; i++)
    for (int c = 0; c < f[i].ncomp; c++) {
      gather(f[i].type, tmp, f[i].comp[c], order, n);
      memcpy(f[i].comp[c], tmp, n * pf_type_size(f[i].type));
    }
  free(tmp);
  p->n_ghost = 0;
}

size_t particles_remove(struct particles *p, const unsigned char *remove)
{
  size_t k = 0;
  for (size_t i = 0; i < p->n; i++) {
    if (remove[i]) continue;
    if (k != i) particles_copy(p, k, i, ~0u);
    k++;
  }
  size_t removed = p->n - k;
  p->n = k;
  p->n_ghost = 0;
  return removed;
}
