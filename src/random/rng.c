#include "mcspec/rng.h"
#include "core/internal.h"
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

/* The checks of every draw: both pointers, a seeded generator, and an
 * output (out_bytes long) outside it: the state is stepped before the output
 * is written, so an output in it would overwrite the next state. */
static mcs_status check_draw(const mcs_rng *rng, const void *out, size_t out_bytes)
{
    if (rng == NULL || out == NULL)
        return MCS_ERR_NULL;
    if (!mcs_rng_is_seeded_(rng))
        return MCS_ERR_UNINIT;
    return mcs_overlap_(out, out_bytes, rng, sizeof *rng) ? MCS_ERR_ALIAS : MCS_OK;
}

mcs_status mcs_rng_u32(mcs_rng *rng, uint32_t *out)
{
    mcs_status st = check_draw(rng, out, sizeof *out);
    if (st != MCS_OK)
        return st;
    *out = mcs_rng_next_(rng);
    return MCS_OK;
}

mcs_status mcs_rng_bounded(mcs_rng *rng, uint32_t bound, uint32_t *out)
{
    mcs_status st = check_draw(rng, out, sizeof *out);
    if (st != MCS_OK)
        return st;
    if (bound == 0u)
        return MCS_ERR_BOUND;
    *out = mcs_rng_bounded_(rng, bound);
    return MCS_OK;
}

mcs_status mcs_rng_double(mcs_rng *rng, double *out)
{
    mcs_status st = check_draw(rng, out, sizeof *out);
    if (st != MCS_OK)
        return st;
    *out = mcs_rng_double_(rng);
    return MCS_OK;
}
