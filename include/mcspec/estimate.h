/* The Monte Carlo estimator I = (1/K) sum_n f_n s_n (eq. 8) and a scalar
 * Welford accumulator for its statistics over trials. */
#ifndef MCSPEC_ESTIMATE_H
#define MCSPEC_ESTIMATE_H

#include <stddef.h>
#include <stdint.h>
#include "status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Integrand callback for point samples: f(x) at x in [0,1). */
typedef double (*mcs_integrand)(double x, void *ctx);

/* I = (1/K) sum_j f[n_j] w_j, i.e. eq. 8 from the sparse form.
 * f[n]: the integrand per bin; bins[k], weights[k] one trial.
 * MCS_ERR_NULL, MCS_ERR_N_RANGE (n = 0), MCS_ERR_K_RANGE (k = 0),
 * MCS_ERR_BIN_RANGE, MCS_ERR_NOT_FINITE (weight or f[n_j]), MCS_ERR_NEGATIVE
 * (weight). *out untouched on error. */
mcs_status mcs_estimate_bins(size_t n, const double *f, size_t k, const size_t *bins,
                             const double *weights, double *out);

/* I = (1/K) sum_j f(x_j) w_j from points[k] in [0,1) and weights[k]
 * (weights may be NULL: all 1). MCS_ERR_NULL, MCS_ERR_K_RANGE,
 * MCS_ERR_POINT_RANGE, MCS_ERR_NOT_FINITE (weight or f value),
 * MCS_ERR_NEGATIVE. *out untouched on error. */
mcs_status mcs_estimate_points(mcs_integrand f, void *ctx, size_t k, const double *points,
                               const double *weights, double *out);

/* Scalar Welford accumulator: running mean and sums of 2nd, 3rd and 4th
 * powers of deviations (Pebay's one-pass update), numerically stable where
 * the textbook sum of squares cancels. The 4th moment gives the standard
 * error of the variance itself, which is what a measured Var[I] needs. */
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

#endif /* MCSPEC_ESTIMATE_H */
