/* Helpers shared by the measures of a point set (discrepancy.c,
 * discrepancy_star.c, spacing.c): the caller's scratch, aligned in place,
 * and the state checks of their accumulators; private header. */
#ifndef MCSPEC_MEASURES_INTERNAL_H
#define MCSPEC_MEASURES_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "core/internal.h"
#include "mcspec/status.h"
#include "mcspec/welford.h"

/* The first address at or after work aligned to align bytes (a power of
 * two): the size queries add align bytes of slack, so a buffer of the
 * queried size holds the arrays whatever its own alignment. */
static inline void *mcs_meas_align_(void *work, size_t align)
{
    const uintptr_t a = (uintptr_t)work, pad = (uintptr_t)(-a & (uintptr_t)(align - 1u));
    return (unsigned char *)work + pad;
}

/* Whether a Welford some sequence of adds and merges produces: its own
 * read-out refuses the others with MCS_ERR_INVARIANT (an empty one answers
 * MCS_ERR_EMPTY, which is a valid state). */
static inline int mcs_meas_welford_ok_(const mcs_welford *w)
{
    double mean;
    return mcs_welford_mean(w, &mean) != MCS_ERR_INVARIANT;
}

/* The set-size range of an accumulator of count sets: 0, 0 while empty,
 * else 1 <= k_min <= k_max. */
static inline int mcs_meas_k_range_ok_(uint64_t count, size_t k_min, size_t k_max)
{
    return count == 0u ? k_min == 0u && k_max == 0u : k_min >= 1u && k_min <= k_max;
}

#endif /* MCSPEC_MEASURES_INTERNAL_H */
