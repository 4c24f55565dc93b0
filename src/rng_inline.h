/* Unchecked PCG32 steps shared by the library's hot loops (private header).
 * The public mcs_rng_* functions validate and then call these. */
#ifndef MCSPEC_RNG_INLINE_H
#define MCSPEC_RNG_INLINE_H

#include <stdint.h>
#include "mcspec/rng.h"

#define MCS_PCG_MULT UINT64_C(6364136223846793005)

/* Seeding makes the increment odd; a zeroed (never seeded) generator has an
 * even one, and its LCG from state 0 would output zeros forever. Every caller
 * of the unchecked steps below checks this first. */
static inline int mcs_rng_is_seeded_(const mcs_rng *rng)
{
    return (rng->inc & 1u) != 0u;
}

static inline uint32_t mcs_rng_next_(mcs_rng *rng)
{
    uint64_t old = rng->state;
    rng->state = old * MCS_PCG_MULT + rng->inc;
    /* XSH-RR: xorshift high bits down, then rotate by the top 5 bits. */
    uint32_t xorshifted = (uint32_t)(((old >> 18u) ^ old) >> 27u);
    uint32_t rot = (uint32_t)(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
}

/* bound > 0. Rejecting r < 2^32 mod bound leaves a whole number of copies of
 * [0, bound) in the accepted range, so r % bound is exactly uniform. */
static inline uint32_t mcs_rng_bounded_(mcs_rng *rng, uint32_t bound)
{
    uint32_t threshold = (uint32_t)(-bound) % bound;
    for (;;) {
        uint32_t r = mcs_rng_next_(rng);
        if (r >= threshold)
            return r % bound;
    }
}

/* 27 + 26 = 53 random bits, so every double k / 2^53 in [0,1) is reachable. */
static inline double mcs_rng_double_(mcs_rng *rng)
{
    uint32_t a = mcs_rng_next_(rng) >> 5;
    uint32_t b = mcs_rng_next_(rng) >> 6;
    return ((double)a * 67108864.0 + (double)b) * (1.0 / 9007199254740992.0);
}

#endif /* MCSPEC_RNG_INLINE_H */
