/* Importance function over N bins: g_n >= 0 with sum 1, the piecewise
 * constant density p(x) = N g_n on bin n (note section 4), its CDF and the
 * inverse-CDF warp of the canonical u in [0,1) to a point x in [0,1). */
#ifndef MCSPEC_IMPORTANCE_H
#define MCSPEC_IMPORTANCE_H

#include <stddef.h>
#include "config.h"
#include "status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    size_t n;                  /* number of bins N */
    double g[MCS_MAX_N];       /* normalised weights g_n, sum 1 */
    double p[MCS_MAX_N];       /* p_n = N g_n (eq. 38), mean 1 */
    double cdf[MCS_MAX_N + 1]; /* cdf[0] = 0, cdf[b+1] = g_0 + ... + g_b, cdf[n] = 1 exactly;
                                  bin b owns the CDF interval I_b = [cdf[b], cdf[b+1]) */
    double harmonic_mean;      /* H = N / sum_n 1/p_n (eq. 44) */
} mcs_importance;

/* Builds the importance function from n caller weights (any positive scale;
 * they are normalised). weights: n finite values > 0.
 * MCS_ERR_NULL, MCS_ERR_N_RANGE (n = 0 or n > MCS_MAX_N), MCS_ERR_NOT_FINITE,
 * MCS_ERR_NEGATIVE, MCS_ERR_ZERO_WEIGHT (a zero weight makes 1/p_n infinite).
 * On error *imp is untouched. */
mcs_status mcs_importance_init(mcs_importance *imp, size_t n, const double *weights);

/* Inverse-CDF warp: u in [0,1) lands in the bin b whose interval I_b holds it,
 * and goes to x = (b + (u - cdf[b]) / g_b) / N, with floor(N x) = b exactly.
 * x or bin may be NULL if not wanted. MCS_ERR_NULL (imp), MCS_ERR_UNINIT,
 * MCS_ERR_POINT_RANGE (u outside [0,1) or NaN); outputs untouched on error. */
mcs_status mcs_importance_warp(const mcs_importance *imp, double u, double *x, size_t *bin);

/* Q_freq = N^{-1/2} sum_n e^{-2 pi i freq n / N} / p_n: the eq. 7 transform of
 * 1/p (eq. 43), which carries every importance-sampled cross spectrum (eq. 43,
 * 49, 52); N^{-1/2} Q_0 = 1/H (eq. 44). O(N) with trig per term.
 * MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_FREQ_RANGE (freq >= imp->n).
 * Outputs untouched on error. */
mcs_status mcs_importance_q(const mcs_importance *imp, size_t freq, double *re, double *im);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_IMPORTANCE_H */
