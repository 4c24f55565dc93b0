/* Importance function over N bins: g_n >= 0 with sum 1, the piecewise
 * constant density p(x) = N g_n on bin n (note section 4), its CDF and the
 * inverse-CDF warp of the canonical u in [0,1) to a point x in [0,1).
 *
 * A bin with g_n = 0 is outside the support: it is never drawn and never
 * weighted (s_n = 0 in every trial), so the estimator integrates f over the
 * support only, with bias -(1/N) sum over those bins of f_n (theory.h:
 * mcs_theory_bias). Every quantity with 1/p_n (Q_k, H, the closed forms of
 * eq.h) takes its sum over the support, 1/p_n read as 0 outside it. */
#ifndef MCSPEC_IMPORTANCE_H
#define MCSPEC_IMPORTANCE_H

#include <stddef.h>
#include "config.h"
#include "status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Smallest positive normalised weight g_n accepted: 2^-32 (about 2.3e-10).
 * The
 * generator draws u on the grid k / 2^53 (mcs_rng_double), so a CDF interval
 * holds whole grid steps of 2^-53: at g_n >= 2^-32 the g_n stored is within
 * about 2^-19 (relative) of the one asked for, the strata of stratified and
 * jitter patterns (u spaced at most 2^-52 apart) resolve it to about 2^-20,
 * and a sample weighs 1/p_n < 2^32 / N. A smaller positive weight is
 * rejected (MCS_ERR_ZERO_WEIGHT) rather than sampled with a probability it
 * does not have (at 1e-17 of the total, its bin would never be drawn); a
 * weight of exactly 0 is sampled as asked: never. */
#define MCS_IMPORTANCE_MIN_G 2.3283064365386963e-10

typedef struct {
    size_t n;                  /* number of bins N */
    double g[MCS_MAX_N];       /* g_n = cdf[n+1] - cdf[n] exactly: the probability that the
                                  generator's u lands in bin n; sum 1; 0 exactly for a zero
                                  weight, else at least about 2^-32 */
    double p[MCS_MAX_N];       /* p_n = N g_n (eq. 38), mean 1; exactly 1 for a flat function
                                  (where N g_n is 1 up to the rounding of the CDF); 0 outside
                                  the support */
    double cdf[MCS_MAX_N + 1]; /* cdf[0] = 0, cdf[b+1] = g_0 + ... + g_b, cdf[n] = 1 exactly;
                                  bin b owns the CDF interval I_b = [cdf[b], cdf[b+1]) (empty
                                  outside the support); every entry a multiple of 2^-53 (the
                                  grid of mcs_rng_double) */
    double harmonic_mean;      /* H: 1/H = (1/N) sum over the support of 1/p_n = N^{-1/2} Q_0
                                  (eq. 44); in (0, 1] when every g_n > 0, up to N^2 / N_s^2
                                  with N_s bins in the support */
} mcs_importance;

/* Builds the importance function from n caller weights (any positive scale,
 * 5e-324 to DBL_MAX: they are scaled by a power of two, then normalised).
 * weights: n finite values >= 0, not all 0; a 0 puts its bin outside the
 * support (above), a positive one below MCS_IMPORTANCE_MIN_G of the total
 * is refused.
 *
 * The estimator is unbiased for the distribution the generator really
 * samples: each CDF entry is rounded to the 2^-53 grid of the generator's u,
 * g_n is the exact length of the interval I_n between two entries, and
 * p_n = N g_n, so a sample lands in bin n with probability exactly g_n and
 * carries 1/p_n. Weights that are all equal give the flat function: p_n = 1
 * and H = 1 exactly, the uniform density, which a pattern treats as no
 * importance function at all (pattern.h).
 *
 * MCS_ERR_NULL, MCS_ERR_N_RANGE (n = 0 or n > MCS_MAX_N), MCS_ERR_NOT_FINITE,
 * MCS_ERR_NEGATIVE, MCS_ERR_ZERO_WEIGHT (every weight 0, or a positive one
 * below MCS_IMPORTANCE_MIN_G of the total). On error *imp is untouched. */
mcs_status mcs_importance_init(mcs_importance *imp, size_t n, const double *weights);

/* Inverse-CDF warp: u in [0,1) lands in the bin b whose interval I_b holds it
 * (never a bin outside the support: its interval is empty),
 * and goes to x = (b + (u - cdf[b]) / g_b) / N, with floor(N x) = b exactly.
 * x or bin may be NULL if not wanted (not one storage for both:
 * MCS_ERR_ALIAS). MCS_ERR_NULL (imp), MCS_ERR_UNINIT, MCS_ERR_POINT_RANGE
 * (u outside [0,1) or NaN); outputs untouched on error. */
mcs_status mcs_importance_warp(const mcs_importance *imp, double u, double *x, size_t *bin);

/* Q_freq = N^{-1/2} sum_n e^{-2 pi i freq n / N} / p_n: the eq. 7 transform of
 * 1/p (eq. 43), which carries every importance-sampled cross spectrum (eq. 43,
 * 49, 52); N^{-1/2} Q_0 = 1/H (eq. 44). The sum runs over the support (1/p_n
 * read as 0 where p_n = 0). O(N) with trig per term.
 * MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_FREQ_RANGE (freq >= imp->n),
 * MCS_ERR_ALIAS (re and im one double), MCS_ERR_INVARIANT (a result not
 * finite: only a corrupted object gives one). Outputs untouched on error. */
mcs_status mcs_importance_q(const mcs_importance *imp, size_t freq, double *re, double *im);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_IMPORTANCE_H */
