/* rest.h — internal to src/sph: sph.skip_resting, the cells the solid passes leave out
 * (rest.c for the rule and why the results stay the same bits).
 */
#ifndef HV_SPH_REST_H
#define HV_SPH_REST_H

#include "sph/sph.h"

/* The first pass's resting cells: marks cache->rest bit 0. */
void rest_mark_first(const struct particles *p, const struct nbr_grid *g, struct sph_cache *cache);
/* Writes what the first pass would write for the reals of a resting cell c (with act,
 * individual steps: for those with act[i] != 0 only). */
void rest_write_first(struct particles *p, const struct nbr_grid *g, size_t c, double *gradv,
                      const int32_t *act);
/* The second pass's resting cells, from the partner records (partner.h) and p: marks
 * cache->rest bit 1. */
void rest_mark_second(const struct particles *p, const struct nbr_grid *g, struct sph_cache *cache,
                      const double *rec, const int32_t *tag);
/* Writes what the second pass would write for the reals of a resting cell c (with act:
 * those with act[i] != 0); returns their number. */
long rest_write_second(struct particles *p, const struct nbr_grid *g, size_t c,
                       const struct sph_params *sp, const int32_t *act);

#endif
