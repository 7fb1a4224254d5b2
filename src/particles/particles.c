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

#define HV_PF_TYPE(ctype) _Generic((ctype)0, int32_t: PF_INT32, int64_t: PF_INT64, double: PF_DOUBLE)

int particles_fields(struct particles *p, struct pfield *out)
{
  int k = 0;
#define HV_X(ctype, fname, funit, fflags, fdesc)                                       \
  out[k] = (struct pfield){.name = #fname, .unit = funit, .desc = fdesc,                \
                           .type = HV_PF_TYPE(ctype), .ncomp = 1, .flags = fflags,       \
                           .comp = {p ? (void *)p->fname : NULL, NULL, NULL}};          \
  k++;
  HV_PARTICLE_SCALARS(HV_X)
#undef HV_X
#define HV_X(ctype, fname, funit, fflags, fdesc)                                       \
  out[k] = (struct pfield){.name = #fname, .unit = funit, .desc = fdesc,                \
                           .type = HV_PF_TYPE(ctype), .ncomp = 3, .flags = fflags,       \
                           .comp = {p ? (void *)p->fname[0] : NULL,                     \
                                    p ? (void *)p->fname[1] : NULL,                     \
                                    p ? (void *)p->fname[2] : NULL}};                   \
  k++;
  HV_PARTICLE_VECTORS(HV_X)
#undef HV_X
  HV_CHECK(k <= HV_MAX_FIELDS, "too many particle fields (%d)", k);
  return k;
}

size_t particles_bytes_per_particle(void)
{
  struct pfield f[HV_MAX_FIELDS];
  int nf = particles_fields(NULL, f);
  size_t b = 0;
  for (int i = 0; i < nf; i++) b += pf_type_size(f[i].type) * (size_t)f[i].ncomp;
  return b;
}

void particles_init(struct particles *p) { memset(p, 0, sizeof *p); }

void particles_free(struct particles *p)
{
  struct pfield f[HV_MAX_FIELDS];
  int nf = particles_fields(p, f);
  for (int i = 0; i < nf; i++)
    for (int c = 0; c < f[i].ncomp; c++) free(f[i].comp[c]);
  memset(p, 0, sizeof *p);
}

void particles_reserve(struct particles *p, size_t cap)
{
  if (cap <= p->cap) return;
  size_t newcap = p->cap ? p->cap : 1024;
  while (newcap < cap) newcap += newcap / 2;
#define HV_X(ctype, fname, funit, fflags, fdesc)                                       \
  p->fname = hv_realloc(p->fname, newcap * sizeof(ctype), "particle field " #fname);     \
  memset(p->fname + p->cap, 0, (newcap - p->cap) * sizeof(ctype));
  HV_PARTICLE_SCALARS(HV_X)
#undef HV_X
#define HV_X(ctype, fname, funit, fflags, fdesc)                                       \
  for (int c_ = 0; c_ < 3; c_++) {                                                      \
    p->fname[c_] = hv_realloc(p->fname[c_], newcap * sizeof(ctype), "particle field " #fname); \
    memset(p->fname[c_] + p->cap, 0, (newcap - p->cap) * sizeof(ctype));                 \
  }
  HV_PARTICLE_VECTORS(HV_X)
#undef HV_X
  p->cap = newcap;
}

size_t particles_add(struct particles *p, size_t count)
{
  size_t first = p->n;
  p->n_ghost = 0;
  particles_reserve(p, p->n + count);
  struct pfield f[HV_MAX_FIELDS];
  int nf = particles_fields(p, f);
  for (int i = 0; i < nf; i++) {
    size_t s = pf_type_size(f[i].type);
    for (int c = 0; c < f[i].ncomp; c++) memset((char *)f[i].comp[c] + first * s, 0, count * s);
  }
  p->n += count;
  return first;
}

void particles_copy(struct particles *p, size_t dst, size_t src, unsigned flags_mask)
{
#define HV_X(ctype, fname, funit, fflags, fdesc)                                       \
  if ((fflags) & flags_mask) p->fname[dst] = p->fname[src];
  HV_PARTICLE_SCALARS(HV_X)
#undef HV_X
#define HV_X(ctype, fname, funit, fflags, fdesc)                                       \
  if ((fflags) & flags_mask) {                                                          \
    p->fname[0][dst] = p->fname[0][src];                                                \
    p->fname[1][dst] = p->fname[1][src];                                                \
    p->fname[2][dst] = p->fname[2][src];                                                \
  }
  HV_PARTICLE_VECTORS(HV_X)
#undef HV_X
}

void particles_permute(struct particles *p, const uint32_t *order)
{
  size_t n = p->n;
  if (n == 0) return;
  void *tmp = hv_malloc(n * 8, "permutation buffer");
  struct pfield f[HV_MAX_FIELDS];
  int nf = particles_fields(p, f);
  for (int i = 0; i < nf; i++) {
    for (int c = 0; c < f[i].ncomp; c++) {
      if (f[i].type == PF_INT32) {
        int32_t *a = f[i].comp[c], *t = tmp;
        for (size_t k = 0; k < n; k++) t[k] = a[order[k]];
        memcpy(a, t, n * sizeof *a);
      } else if (f[i].type == PF_INT64) {
        int64_t *a = f[i].comp[c], *t = tmp;
        for (size_t k = 0; k < n; k++) t[k] = a[order[k]];
        memcpy(a, t, n * sizeof *a);
      } else {
        double *a = f[i].comp[c], *t = tmp;
        for (size_t k = 0; k < n; k++) t[k] = a[order[k]];
        memcpy(a, t, n * sizeof *a);
      }
    }
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
