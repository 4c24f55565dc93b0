/* PCG32 (O'Neill, XSH-RR 64/32): 64-bit LCG state, 32-bit output permuted
 * from the old state. Bit-exact with pcg32_srandom_r / pcg32_random_r. */
#ifndef MCSPEC_RNG_H
#define MCSPEC_RNG_H

#include <stdint.h>
#include "status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    uint64_t state; /* LCG state */
    uint64_t inc;   /* stream increment, always odd once seeded */
} mcs_rng;

/* Seed as pcg32_srandom_r(initstate, initseq). MCS_ERR_NULL. */
mcs_status mcs_rng_seed(mcs_rng *rng, uint64_t initstate, uint64_t initseq);

/* Every draw below (and every library call that draws, e.g. mcs_pattern_draw)
 * returns MCS_ERR_UNINIT for a generator that was never seeded: seeding makes
 * the increment odd, so an even one (a zeroed struct, whose LCG would output
 * zeros forever and make a rejection loop spin) is detected before any draw.
 * Any state with an odd increment is a full-period PCG32 stream and is used.
 * An output inside *rng is refused (MCS_ERR_ALIAS): the state steps first. */

/* Next 32-bit output into *out. MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_ALIAS
 * (rng and *out untouched). */
mcs_status mcs_rng_u32(mcs_rng *rng, uint32_t *out);

/* Uniform integer in [0, bound) without modulo bias (rejects draws below
 * -bound % bound). MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_ALIAS, MCS_ERR_BOUND
 * for bound 0 (rng and *out untouched). */
mcs_status mcs_rng_bounded(mcs_rng *rng, uint32_t bound, uint32_t *out);

/* Uniform double in [0, 1) with 53 random bits (two outputs): k / 2^53 for a
 * uniform integer k < 2^53. MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_ALIAS (rng and
 * *out untouched). */
mcs_status mcs_rng_double(mcs_rng *rng, double *out);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_RNG_H */
