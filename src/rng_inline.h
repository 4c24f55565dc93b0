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

/* The output of PCG32 state `old`, XSH-RR: xorshift high bits down, then
 * rotate by the top 5 bits. */
static inline uint32_t mcs_rng_output_(uint64_t old)
{
    uint32_t xorshifted = (uint32_t)(((old >> 18u) ^ old) >> 27u);
    uint32_t rot = (uint32_t)(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
}

static inline uint32_t mcs_rng_next_(mcs_rng *rng)
{
    uint64_t old = rng->state;
    rng->state = old * MCS_PCG_MULT + rng->inc;
    return mcs_rng_output_(old);
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

/* count doubles, bit for bit those of count mcs_rng_double_ calls, leaving
 * the same state. One step of the LCG is a multiply-add that the next step
 * waits for; two samples take four steps, and s_{i+4} = a^4 s_i + c (a^3 +
 * a^2 + a + 1) (mod 2^64) follows from s_i in one multiply-add, while s_{i+1},
 * s_{i+2}, s_{i+3} are formed from s_i beside it: the chain the loop waits
 * on is a quarter as long, and the sequence is unchanged. */
static inline void mcs_rng_fill_doubles_(mcs_rng *rng, size_t count, double *out)
{
    const uint64_t a = MCS_PCG_MULT, c = rng->inc;
    const uint64_t a2 = a * a, c2 = c * (a + 1u);
    const uint64_t a3 = a2 * a, c3 = c2 * a + c;
    const uint64_t a4 = a2 * a2, c4 = c2 * (a2 + 1u);
    uint64_t s = rng->state;
    size_t j = 0;
    for (; j + 2u <= count; j += 2u) {
        uint64_t s1 = s * a + c, s2 = s * a2 + c2, s3 = s * a3 + c3;
        double h0 = (double)(mcs_rng_output_(s) >> 5), l0 = (double)(mcs_rng_output_(s1) >> 6);
        double h1 = (double)(mcs_rng_output_(s2) >> 5), l1 = (double)(mcs_rng_output_(s3) >> 6);
        out[j] = (h0 * 67108864.0 + l0) * (1.0 / 9007199254740992.0);
        out[j + 1u] = (h1 * 67108864.0 + l1) * (1.0 / 9007199254740992.0);
        s = s * a4 + c4;
    }
    rng->state = s;
    if (j < count)
        out[j] = mcs_rng_double_(rng);
}

#endif /* MCSPEC_RNG_INLINE_H */
