/* The Monte Carlo estimator I = (1/K) sum_n f_n s_n (eq. 8), from a trial in
 * sparse (bin, weight) form or from points and an integrand callback. Its
 * statistics over trials go to a mcs_welford (welford.h). */
#ifndef MCSPEC_ESTIMATE_H
#define MCSPEC_ESTIMATE_H

#include <stddef.h>
#include "status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Largest |f_n w_j| (one sample's term) the estimators accept: 2^110, the
 * same as MCS_WELFORD_MAX_ABS. I is a mean of terms, so |I| is within it too
 * and every estimate is a value mcs_welford_add takes; a term above it (or a
 * product f w that overflows) is refused with MCS_ERR_MAGNITUDE instead of
 * returning an infinite or imprecise I. out may be any caller double,
 * including an element of f or weights: it is written last. */
#define MCS_ESTIMATE_MAX_ABS 1.2980742146337069e+33

/* Integrand callback for point samples: f(x) at x in [0,1); ctx is the
 * caller's, passed through unchanged. */
typedef double (*mcs_estimate_integrand)(double x, void *ctx);

/* I = (1/K) sum_j f[n_j] w_j, i.e. eq. 8 from the sparse form.
 * f[n]: the integrand per bin; bins[k], weights[k] one trial.
 * MCS_ERR_NULL, MCS_ERR_N_RANGE (n = 0), MCS_ERR_K_RANGE (k = 0),
 * MCS_ERR_BIN_RANGE, MCS_ERR_NOT_FINITE (weight or f[n_j]), MCS_ERR_NEGATIVE
 * (weight), MCS_ERR_MAGNITUDE (a term). *out untouched on error. */
mcs_status mcs_estimate_bins(size_t n, size_t k, const double *f, const size_t *bins,
                             const double *weights, double *out);

/* I = (1/K) sum_j f(x_j) w_j from points[k] in [0,1) and weights[k]
 * (weights may be NULL: all 1). f is called once per point, after every
 * point and weight has been checked. MCS_ERR_NULL, MCS_ERR_K_RANGE,
 * MCS_ERR_POINT_RANGE, MCS_ERR_NOT_FINITE (weight or f value),
 * MCS_ERR_NEGATIVE, MCS_ERR_MAGNITUDE (a term). *out untouched on error. */
mcs_status mcs_estimate_points(size_t k, mcs_estimate_integrand f, void *ctx,
                               const double *points, const double *weights, double *out);

/* mcs_estimate_points for float points (a renderer's samples, read in
 * place): f gets each x_j widened to double, which is exact, so the result
 * is bit-equal to mcs_estimate_points on the widened points. A float just
 * below 1.0f is in [0,1); 1.0f is not. Statuses as mcs_estimate_points. */
mcs_status mcs_estimate_points_f(size_t k, mcs_estimate_integrand f, void *ctx,
                                 const float *points, const double *weights, double *out);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_ESTIMATE_H */
