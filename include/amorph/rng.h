/* amorph/rng.h: the seeded pseudo-random stream (xoshiro256** algorithm, splitmix64 seeding).
 *
 * Random numbers are consumed only serially from one stream (the evolver's), so a run is the same
 * for any thread count. Every draw is defined on integers, so it is the same on every platform.
 */
#ifndef AMORPH_RNG_H
#define AMORPH_RNG_H

#include <stdint.h>
#include "amorph/real.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct am_rng {
    uint64_t s[4];   /* generator state; never all zero */
} am_rng;

void am_rng_seed(am_rng* r, uint64_t seed);          /* any seed, 0 included */
uint64_t am_rng_u64(am_rng* r);                      /* uniform 64-bit integer */
uint32_t am_rng_below(am_rng* r, uint32_t n);        /* uniform in [0, n), n >= 1, unbiased */
am_real am_rng_unit(am_rng* r);                      /* uniform in [0, 1) */
am_real am_rng_range(am_rng* r, am_real lo, am_real hi); /* uniform in [lo, hi) */
am_real am_rng_normal(am_rng* r);                    /* standard normal (Box-Muller on am_log/am_cos) */
int am_rng_chance(am_rng* r, am_real p);             /* 1 with probability p */

/* 64-bit FNV-1a style hashing used for golden hashes of runs and states */
#define AM_HASH_INIT UINT64_C(0xcbf29ce484222325)
uint64_t am_hash_bytes(uint64_t h, const void* data, unsigned long n);
uint64_t am_hash_u64(uint64_t h, uint64_t v);
uint64_t am_hash_real(uint64_t h, am_real v);        /* hashes the bit pattern (-0 folded to 0) */

#ifdef __cplusplus
}
#endif
#endif
