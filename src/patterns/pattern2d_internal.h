/* Private: the validity test of an mcs_pattern2d, shared by the pattern
 * module and the exact theory that reads its configuration (pointset_exact.c,
 * spectrum2d_exact.c). */
#ifndef MCSPEC_PATTERN2D_INTERNAL_H
#define MCSPEC_PATTERN2D_INTERNAL_H

#include <stddef.h>
#include "mcspec/pattern2d.h"

static inline int mcs_pattern2d_kind_is_valid_(mcs_pattern2d_kind kind)
{
    return (unsigned)kind < (unsigned)MCS_PATTERN2D_KIND_COUNT; /* enum may be unsigned */
}

/* Set up by mcs_pattern2d_init: a known kind, 1 <= K <= MCS_PATTERN2D_MAX_K,
 * strata m x n = K. */
static inline int mcs_pattern2d_is_valid_(const mcs_pattern2d *pat)
{
    return mcs_pattern2d_kind_is_valid_(pat->kind) && pat->k >= 1u &&
           pat->k <= (size_t)MCS_PATTERN2D_MAX_K && pat->strata_x >= 1u &&
           pat->k % pat->strata_x == 0u && pat->k / pat->strata_x == pat->strata_y;
}

#endif /* MCSPEC_PATTERN2D_INTERNAL_H */
