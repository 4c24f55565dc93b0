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
    uint64_t inc;   /* stream increment, always odd */
} mcs_rng;

/* Seed as pcg32_srandom_r(initstate, initseq). MCS_ERR_NULL. */
mcs_status mcs_rng_seed(mcs_rng *rng, uint64_t initstate, uint64_t initseq);

/* Next 32-bit output into *out. MCS_ERR_NULL (rng untouched). */
mcs_status mcs_rng_u32(mcs_rng *rng, uint32_t *out);

/* Uniform integer in [0, bound) without modulo bias (rejects draws below
 * -bound % bound). MCS_ERR_NULL, MCS_ERR_BOUND for bound 0 (rng untouched). */
mcs_status mcs_rng_bounded(mcs_rng *rng, uint32_t bound, uint32_t *out);

/* Uniform double in [0, 1) with 53 random bits (two outputs). MCS_ERR_NULL. */
mcs_status mcs_rng_double(mcs_rng *rng, double *out);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_RNG_H */
