/* random.h: the library's random numbers (reproducible from a seed). */
#ifndef DM_RANDOM_H
#define DM_RANDOM_H

#include <stdint.h>

typedef struct dm_rng {
    uint64_t s[4];
} dm_rng;
void dm_rng_seed(dm_rng *r, uint64_t seed);
uint64_t dm_rng_next(dm_rng *r);
double dm_rng_uniform(dm_rng *r);

#endif /* DM_RANDOM_H */
