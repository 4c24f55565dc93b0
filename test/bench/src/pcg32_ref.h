/* PCG32 as in the reference implementation, pcg-c-basic 0.9 (pcg_basic.c,
 * Melissa O'Neill, Apache License 2.0): pcg32_srandom_r, pcg32_random_r,
 * pcg32_boundedrand_r, copied so that the bench's peers and floors draw with
 * their own generator, not the library's. Only the layout changed (static
 * inline, explicit casts for -Wconversion-clean C11). */
#ifndef BENCH_PCG32_REF_H
#define BENCH_PCG32_REF_H

#include <stdint.h>

typedef struct {
    uint64_t state; /* RNG state. All values are possible. */
    uint64_t inc;   /* Controls which RNG sequence (stream) is selected. Must *always* be odd. */
} pcg32_random_t;

static inline uint32_t pcg32_random_r(pcg32_random_t *rng)
{
    uint64_t oldstate = rng->state;
    rng->state = oldstate * 6364136223846793005ULL + rng->inc;
    uint32_t xorshifted = (uint32_t)(((oldstate >> 18u) ^ oldstate) >> 27u);
    uint32_t rot = (uint32_t)(oldstate >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((-rot) & 31u));
}

static inline void pcg32_srandom_r(pcg32_random_t *rng, uint64_t initstate, uint64_t initseq)
{
    rng->state = 0U;
    rng->inc = (initseq << 1u) | 1u;
    (void)pcg32_random_r(rng);
    rng->state += initstate;
    (void)pcg32_random_r(rng);
}

static inline uint32_t pcg32_boundedrand_r(pcg32_random_t *rng, uint32_t bound)
{
    uint32_t threshold = (uint32_t)(-bound) % bound;
    for (;;) {
        uint32_t r = pcg32_random_r(rng);
        if (r >= threshold)
            return r % bound;
    }
}

#endif /* BENCH_PCG32_REF_H */
