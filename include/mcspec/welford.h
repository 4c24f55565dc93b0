/* Scalar Welford accumulator: running mean and sums of the 2nd, 3rd and 4th
 * powers of deviations (Pebay's one-pass update), numerically stable where
 * the textbook sum of squares cancels. The 4th moment gives the standard
 * error of the variance itself, which is what a measured Var[I] needs. */
#ifndef MCSPEC_WELFORD_H
#define MCSPEC_WELFORD_H

#include <stdint.h>
#include "status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    uint64_t count; /* values added */
    double mean;    /* running mean */
    double m2;      /* sum of squared deviations from the running mean */
    double m3;      /* sum of cubed deviations */
    double m4;      /* sum of 4th powers of deviations */
} mcs_welford;

/* Empties the accumulator. MCS_ERR_NULL. */
mcs_status mcs_welford_init(mcs_welford *acc);

/* Adds one value. MCS_ERR_NULL, MCS_ERR_NOT_FINITE (acc untouched). */
mcs_status mcs_welford_add(mcs_welford *acc, double x);

/* dst <- dst union src (Chan et al.; Pebay for m3, m4); src unchanged. MCS_ERR_NULL. */
mcs_status mcs_welford_merge(mcs_welford *dst, const mcs_welford *src);

/* Mean of the values added. MCS_ERR_NULL, MCS_ERR_EMPTY (no values). */
mcs_status mcs_welford_mean(const mcs_welford *acc, double *mean);

/* Unbiased sample variance m2 / (count - 1). MCS_ERR_NULL, MCS_ERR_EMPTY (< 2 values). */
mcs_status mcs_welford_variance(const mcs_welford *acc, double *variance);

/* Standard error of the mean sqrt(variance / count). MCS_ERR_NULL, MCS_ERR_EMPTY (< 2). */
mcs_status mcs_welford_stderr(const mcs_welford *acc, double *stderr_out);

/* Standard error of the unbiased variance: sqrt((mu4 - (c-3)/(c-1) s^4) / c)
 * with mu4 = m4 / c, s^2 the unbiased variance and c the count (the
 * large-sample variance of the sample variance). MCS_ERR_NULL,
 * MCS_ERR_EMPTY (< 4 values). */
mcs_status mcs_welford_variance_stderr(const mcs_welford *acc, double *stderr_out);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_WELFORD_H */
