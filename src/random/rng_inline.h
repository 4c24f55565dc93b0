/* Unchecked PCG32 steps shared by the library's hot loops (private header).
 * The public mcs_rng_* functions validate and then call these. */
#ifndef MCSPEC_RNG_INLINE_H
#define MCSPEC_RNG_INLINE_H

#include <stddef.h>
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

/* The double of the outputs of states hi and lo: 27 + 26 = 53 random bits,
 * so every double k / 2^53 in [0,1) is reachable. a 2^26 + b is formed in
 * floating point, exactly: the integer a << 26 | b, converted once, is the
 * same bits, but the draw's loop is bound by integer instructions and ran
 * 3% slower with it. */
static inline double mcs_rng_double_of_(uint64_t hi, uint64_t lo)
{
    double a = (double)(mcs_rng_output_(hi) >> 5), b = (double)(mcs_rng_output_(lo) >> 6);
    return (a * 67108864.0 + b) * (1.0 / 9007199254740992.0);
}

static inline double mcs_rng_double_(mcs_rng *rng)
{
    uint64_t s = rng->state, s1 = s * MCS_PCG_MULT + rng->inc;
    rng->state = s1 * MCS_PCG_MULT + rng->inc;
    return mcs_rng_double_of_(s, s1);
}

/* a^2, a^4 (mod 2^64) and 1 + a + a^2 + a^3, constants: s_{i+m} = a^m s_i +
 * c (1 + a + ... + a^(m-1)), one multiply-add from s_i. */
#define MCS_PCG_MULT2 (MCS_PCG_MULT * MCS_PCG_MULT)
#define MCS_PCG_MULT4 (MCS_PCG_MULT2 * MCS_PCG_MULT2)
#define MCS_PCG_SUM4 ((MCS_PCG_MULT + 1u) * (MCS_PCG_MULT2 + 1u))

/* The increments of one, two and four steps, for a generator of increment c. */
typedef struct {
    uint64_t c1, c2, c4;
} mcs_rng_lanes_;

static inline mcs_rng_lanes_ mcs_rng_lanes_of_(uint64_t c)
{
    mcs_rng_lanes_ l = {c, c * (MCS_PCG_MULT + 1u), c * MCS_PCG_SUM4};
    return l;
}

/* Two doubles from state s, bit for bit those of two mcs_rng_double_ calls;
 * returns the state four steps on. One step of the LCG is a multiply-add
 * that the next step waits for; the state four steps on is one multiply-add
 * from s, so the chain a loop waits on is a quarter as long and the
 * sequence is unchanged. s_{i+1} and s_{i+2} are one multiply-add from s_i
 * too, s_{i+3} one step from s_{i+2}: a jump to it (a^3 and its increment)
 * would hold two more registers, which the draw's loop has not got on
 * x86-64 (it reloaded constants every turn), and a step from s_{i+1} to
 * s_{i+2} made the chain inside a turn long enough to cost 10% at K = 64. */
static inline uint64_t mcs_rng_two_doubles_(uint64_t s, const mcs_rng_lanes_ *l, double *v0,
                                            double *v1)
{
    const uint64_t s2 = s * MCS_PCG_MULT2 + l->c2;
    *v0 = mcs_rng_double_of_(s, s * MCS_PCG_MULT + l->c1);
    *v1 = mcs_rng_double_of_(s2, s2 * MCS_PCG_MULT + l->c1);
    return s * MCS_PCG_MULT4 + l->c4;
}

/* count doubles, bit for bit those of count mcs_rng_double_ calls, leaving
 * the same state. */
static inline void mcs_rng_fill_doubles_(mcs_rng *rng, size_t count, double *out)
{
    const mcs_rng_lanes_ l = mcs_rng_lanes_of_(rng->inc);
    uint64_t s = rng->state;
    size_t j = 0;
    for (; j + 2u <= count; j += 2u)
        s = mcs_rng_two_doubles_(s, &l, &out[j], &out[j + 1u]);
    rng->state = s;
    if (j < count)
        out[j] = mcs_rng_double_(rng);
}

#endif /* MCSPEC_RNG_INLINE_H */
