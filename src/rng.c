#include "mcspec/rng.h"
#include "rng_inline.h"

#include <stddef.h>

mcs_status mcs_rng_seed(mcs_rng *rng, uint64_t initstate, uint64_t initseq)
{
    if (rng == NULL)
        return MCS_ERR_NULL;
    /* pcg32_srandom_r: the stream selector must be odd. */
    rng->state = 0u;
    rng->inc = (initseq << 1u) | 1u;
    (void)mcs_rng_next_(rng);
    rng->state += initstate;
    (void)mcs_rng_next_(rng);
    return MCS_OK;
}

mcs_status mcs_rng_u32(mcs_rng *rng, uint32_t *out)
{
    if (rng == NULL || out == NULL)
        return MCS_ERR_NULL;
    *out = mcs_rng_next_(rng);
    return MCS_OK;
}

mcs_status mcs_rng_bounded(mcs_rng *rng, uint32_t bound, uint32_t *out)
{
    if (rng == NULL || out == NULL)
        return MCS_ERR_NULL;
    if (bound == 0u)
        return MCS_ERR_BOUND;
    *out = mcs_rng_bounded_(rng, bound);
    return MCS_OK;
}

mcs_status mcs_rng_double(mcs_rng *rng, double *out)
{
    if (rng == NULL || out == NULL)
        return MCS_ERR_NULL;
    *out = mcs_rng_double_(rng);
    return MCS_OK;
}
