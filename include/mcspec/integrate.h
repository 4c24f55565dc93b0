/* The integration error of point sets over a family of integrands
 * (integrand.h; docs/measures.md, "Integration error"): per set of K points
 * and the m integrands given with it, the squared error of the estimate
 * (1/K) sum_j f(x_j) against the exact integral, averaged over the m
 * integrands; over sets, the mean (the MSE) and its standard error
 * (Welford, welford.h), and beside it the exact MSE of the pattern the sets
 * come from where it is known (random points, the jittered grid).
 *
 * What the standard error covers: the spread of the per-set values over
 * the sets. A caller that draws fresh integrands for every set (as the
 * command does) gets per-set values that are independent over sets, so
 * the standard error covers both the points and the integrands; one that
 * reuses the same m integrands for every set gets the error of the MSE of
 * those m integrands only. The exact column is averaged the same way (per
 * set, the mean over its integrands of the exact MSE), so measured and
 * exact estimate the same thing either way. */
#ifndef MCSPEC_INTEGRATE_H
#define MCSPEC_INTEGRATE_H

#include <stddef.h>
#include <stdint.h>
#include "status.h"
#include "welford.h"
#include "integrand.h"

#ifdef __cplusplus
extern "C" {
#endif

/* What a set is known to be, for the exact column. */
typedef enum {
    MCS_INTEGRATE_NONE = 0, /* no exact MSE (a point file, another pattern) */
    MCS_INTEGRATE_RANDOM,   /* independent uniform points: Var[f] / K */
    MCS_INTEGRATE_JITTERED  /* the jittered grid of strata_x x strata_y cells */
} mcs_integrate_reference;

/* The accumulator: fixed size, no pointers (it may be copied). */
typedef struct {
    mcs_integrand_family family; /* the integrands' family */
    size_t dim;                  /* 1 or 2; 0 before init */
    size_t k_min, k_max;         /* fewest and most points in a set added (0 before any) */
    mcs_welford sq;              /* per set: mean over its integrands of the squared error */
    mcs_welford exact;           /* per set: the mean of their exact MSE (sets with a reference) */
} mcs_integrate;

/* Empties acc for integrands of family in dim dimensions. MCS_ERR_NULL,
 * MCS_ERR_KIND (not a family), MCS_ERR_DOMAIN (dim not 1 or 2). *acc
 * untouched on error. */
mcs_status mcs_integrate_init(mcs_integrate *acc, mcs_integrand_family family, size_t dim);

/* Every call below but init returns MCS_ERR_UNINIT for an accumulator not
 * from mcs_integrate_init and MCS_ERR_INVARIANT for one no sequence of calls
 * produces (a Welford mcs_welford refuses, an exact count above the set
 * count, k_min above k_max), changing nothing. */

/* Adds one set of k points (points[k * dim] interleaved, in [0,1)) with
 * the m integrands fs[m] (each drawn for acc's family and dim): its mean
 * squared error over them, and with reference RANDOM or JITTERED the mean
 * of their exact MSE (mcs_integrand_variance / k, or
 * mcs_integrand_jittered_mse of strata_x x strata_y cells, which must
 * multiply to k, at most MCS_INTEGRAND_JITTERED_MAX_K; both strata are
 * ignored for NONE and RANDOM).
 * MCS_ERR_NULL, MCS_ERR_K_RANGE (k or m 0), MCS_ERR_POINT_RANGE,
 * MCS_ERR_MISMATCH (an integrand of another family or dim; strata that do
 * not multiply to k), MCS_ERR_K_RANGE (JITTERED above
 * MCS_INTEGRAND_JITTERED_MAX_K), MCS_ERR_KIND (not a reference), MCS_ERR_UNINIT (an
 * integrand no draw produces), MCS_ERR_ALIAS (points or fs overlapping
 * acc), MCS_ERR_COUNT, MCS_ERR_MAGNITUDE. *acc untouched on error. */
mcs_status mcs_integrate_add(mcs_integrate *acc, size_t m, const mcs_integrand *fs, size_t k,
                             const double *points, mcs_integrate_reference reference,
                             size_t strata_x, size_t strata_y);

/* dst <- dst union src (mcs_welford_merge); src unchanged; dst == src
 * allowed. MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_INVARIANT, MCS_ERR_MISMATCH
 * (another family or dim), MCS_ERR_COUNT. dst untouched on error. */
mcs_status mcs_integrate_merge(mcs_integrate *dst, const mcs_integrate *src);

/* Sets added. MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_INVARIANT. */
mcs_status mcs_integrate_count(const mcs_integrate *acc, uint64_t *count);

/* The mean over the sets of the per-set mean squared error. MCS_ERR_EMPTY
 * (no set). *out untouched on error. */
mcs_status mcs_integrate_mse(const mcs_integrate *acc, double *out);

/* Its standard error over the sets. MCS_ERR_EMPTY below 2 sets. */
mcs_status mcs_integrate_mse_stderr(const mcs_integrate *acc, double *out);

/* The mean over the sets of their exact MSE. MCS_ERR_EMPTY (no set),
 * MCS_ERR_DOMAIN (a set was added without a reference). */
mcs_status mcs_integrate_exact(const mcs_integrate *acc, double *out);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_INTEGRATE_H */
