/* Point-set spectra in 1D, without binning: per trial of K points x_j in
 * [0, 1) the periodogram P(f) = |sum_j e^{-2 pi i f x_j}|^2 / K at integer
 * frequencies f = 0..F, and over trials its running mean and standard error
 * per frequency (Welford; mergeable with Chan's update). Random points give
 * P(f) = 1 at every f != 0; P(0) = K always. The points are real, so
 * P(-f) = P(f): only f >= 0 is stored and read-outs accept |f| <= F.
 *
 * The phases e^{-2 pi i f x_j} are advanced by one complex multiplication
 * per frequency and recomputed from sin and cos every 32 frequencies (a few
 * 1e-15 of rounding); the sum over points is an outer product of short phase
 * rows (below), four points at a time: O(K F) multiply-adds.
 *
 * Size: sizeof(mcs_pointset) is 2064 + 16 (F + 1) + 18 S bytes with
 * F = MCS_MAX_FREQ_1D and S = F + 1 rounded up to a multiple of 32 (x86-64):
 * 37 472 at the default 1024, 4 832 at 64. It holds no pointers, so it may
 * be copied. */
#ifndef MCSPEC_POINTSET_H
#define MCSPEC_POINTSET_H

#include <stddef.h>
#include <stdint.h>
#include "config.h" /* MCS_MAX_FREQ_1D, the largest cutoff F */
#include "status.h"
#include "pattern.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Frequencies are split as f = a B + b, b < B, so that
 * e^{-2 pi i f x} = e^{-2 pi i a B x} e^{-2 pi i b x}: per point a row of B
 * low phases and a row of (F + 1)/B high ones, and the sum over points is an
 * outer product (the same vectorised kernel as the 2D spectrum). */
#define MCS_POINTSET_BLOCK 32
#define MCS_POINTSET_SPAN \
    (((MCS_MAX_FREQ_1D) + MCS_POINTSET_BLOCK) / MCS_POINTSET_BLOCK * MCS_POINTSET_BLOCK)

typedef struct {
    size_t freq_max;                   /* F, 1..MCS_MAX_FREQ_1D; 0 before init */
    uint64_t count;                    /* trials added */
    double mean[MCS_MAX_FREQ_1D + 1];  /* running mean of P(f), f = 0..F */
    double m2[MCS_MAX_FREQ_1D + 1];    /* Welford sum of squared deviations */
    double re[MCS_POINTSET_SPAN];      /* scratch: S(f) of the current trial, f < span */
    double im[MCS_POINTSET_SPAN];
    double low[4][2][MCS_POINTSET_BLOCK];                        /* scratch: e^{-2 pi i b x_p} */
    double high[4][2][MCS_POINTSET_SPAN / MCS_POINTSET_BLOCK];   /* scratch: e^{-2 pi i a B x_p} */
} mcs_pointset;

/* Empties the accumulator for frequencies 0..freq_max. MCS_ERR_NULL,
 * MCS_ERR_FREQ_RANGE (freq_max = 0 or above MCS_MAX_FREQ_1D). *acc untouched
 * on error. */
mcs_status mcs_pointset_init(mcs_pointset *acc, size_t freq_max);

/* Adds one trial: points[k] in [0, 1), any k >= 1 (trials may differ in K;
 * each periodogram is normalised by its own K). MCS_ERR_NULL, MCS_ERR_UNINIT,
 * MCS_ERR_K_RANGE (k = 0), MCS_ERR_POINT_RANGE (outside [0,1) or NaN),
 * MCS_ERR_COUNT (the count at MCS_MAX_COUNT). *acc untouched on error. */
mcs_status mcs_pointset_add(mcs_pointset *acc, size_t k, const double *points);

/* mcs_pointset_add for float points, read in place: each coordinate widens to double
 * exactly, so the statistics are bit-equal to mcs_pointset_add's on the widened
 * points (a float just below 1.0f is in [0,1); 1.0f is not). Statuses as
 * mcs_pointset_add. */
mcs_status mcs_pointset_add_f(mcs_pointset *acc, size_t k, const float *points);

/* dst <- dst union src: the statistics of one pass over both trial streams,
 * to rounding. src unchanged; dst == src allowed. MCS_ERR_NULL,
 * MCS_ERR_UNINIT, MCS_ERR_MISMATCH (different F), MCS_ERR_COUNT (the counts
 * would pass MCS_MAX_COUNT), MCS_ERR_ALIAS (src and dst overlapping without
 * being the same object). dst untouched on error. */
mcs_status mcs_pointset_merge(mcs_pointset *dst, const mcs_pointset *src);

/* Trials added. MCS_ERR_NULL, MCS_ERR_UNINIT. */
mcs_status mcs_pointset_count(const mcs_pointset *acc, uint64_t *count);

/* Mean periodogram <P(f)> for |freq| <= F. MCS_ERR_NULL, MCS_ERR_UNINIT,
 * MCS_ERR_FREQ_RANGE, MCS_ERR_EMPTY (no trials). *out untouched on error. */
mcs_status mcs_pointset_power(const mcs_pointset *acc, long freq, double *out);

/* Standard error of <P(f)> over the trials. MCS_ERR_EMPTY for < 2 trials;
 * otherwise as mcs_pointset_power. */
mcs_status mcs_pointset_power_stderr(const mcs_pointset *acc, long freq, double *out);

/* Exact <P(f)> of K points of a 1D pattern kind, unbinned (the N -> infinity
 * limit of the binned patterns): random 1 (f != 0); stratified
 * 1 - sinc^2(pi f / K) (f != 0; sinc x = sin x / x); uniform and jitter K
 * where K divides f, else 0 (deterministic up to a phase); P(0) = K for all.
 * MCS_ERR_NULL, MCS_ERR_K_RANGE (k = 0), MCS_ERR_KIND (homogenized: defined
 * only on N bins; or an unknown kind). */
mcs_status mcs_pointset_exact_power(mcs_pattern_kind kind, size_t k, long freq, double *out);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_POINTSET_H */
