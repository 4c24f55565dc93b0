/* Scalar Welford accumulator: running mean and sums of the 2nd, 3rd and 4th
 * powers of deviations (Pebay's one-pass update), numerically stable where
 * the textbook sum of squares cancels. The 4th moment gives the standard
 * error of the variance itself, which is what a measured Var[I] needs. */
#ifndef MCSPEC_WELFORD_H
#define MCSPEC_WELFORD_H

#include <stdint.h>
#include "config.h"
#include "status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Largest |x| mcs_welford_add accepts: 2^110 (about 1.3e33). Deviations are
 * then at most 2^111, so m4 over MCS_MAX_COUNT values stays below
 * 2^57 (2^110)^4 = 2^497 and every read-out, merge and intermediate product
 * is finite (a value of 1e100 used to overflow m4 into a NaN read-out). */
#define MCS_WELFORD_MAX_ABS 1.2980742146337069e+33

typedef struct {
    uint64_t count; /* values added, at most MCS_MAX_COUNT */
    double mean;    /* running mean */
    double m2;      /* sum of squared deviations from the running mean */
    double m3;      /* sum of cubed deviations */
    double m4;      /* sum of 4th powers of deviations */
} mcs_welford;

/* Every call below except init returns MCS_ERR_INVARIANT for an accumulator
 * that no sequence of calls produces (overwritten), changing nothing: count
 * above MCS_MAX_COUNT, a field NaN or infinite, |mean| above twice
 * MCS_WELFORD_MAX_ABS or not 0 with no values, m2 or m4 negative, or m2,
 * |m3|, m4 above (count - 1) times 2^224, 2^336, 2^448 (every value lies
 * within 2^111 of the mean; so no spread with one value). Within these
 * every read-out and merge is finite. */

/* Empties the accumulator. MCS_ERR_NULL. */
mcs_status mcs_welford_init(mcs_welford *acc);

/* Adds one value. MCS_ERR_NULL, MCS_ERR_INVARIANT, MCS_ERR_NOT_FINITE,
 * MCS_ERR_MAGNITUDE (|x| > MCS_WELFORD_MAX_ABS), MCS_ERR_COUNT (count at
 * MCS_MAX_COUNT). acc untouched on error. */
mcs_status mcs_welford_add(mcs_welford *acc, double x);

/* dst <- dst union src (Chan et al.; Pebay for m3, m4); src unchanged;
 * dst == src allowed (doubles every count and sum). MCS_ERR_NULL,
 * MCS_ERR_INVARIANT, MCS_ERR_COUNT (the counts add up past MCS_MAX_COUNT),
 * MCS_ERR_ALIAS (src and dst overlapping without being the same object).
 * dst untouched on error. */
mcs_status mcs_welford_merge(mcs_welford *dst, const mcs_welford *src);

/* Mean of the values added. MCS_ERR_NULL, MCS_ERR_INVARIANT, MCS_ERR_EMPTY (no values). */
mcs_status mcs_welford_mean(const mcs_welford *acc, double *mean);

/* Unbiased sample variance m2 / (count - 1). MCS_ERR_NULL, MCS_ERR_INVARIANT,
 * MCS_ERR_EMPTY (< 2 values). */
mcs_status mcs_welford_variance(const mcs_welford *acc, double *variance);

/* Standard error of the mean sqrt(variance / count). MCS_ERR_NULL,
 * MCS_ERR_INVARIANT, MCS_ERR_EMPTY (< 2). */
mcs_status mcs_welford_stderr(const mcs_welford *acc, double *stderr_out);

/* Standard error of the unbiased variance s^2, sqrt(V) with
 *     Var[s^2] = (mu4 - sigma^4) / c + 2 sigma^4 / (c (c - 1)),
 * c the count: the first term from the unbiased h-statistics (h4 - h22) / c,
 * clamped at 0 because mu4 >= sigma^4 for every distribution; the second,
 * which no distribution goes below, from s^4. Plugging the biased m4 / c
 * into the large-sample form instead made it collapse for two equally likely
 * values (mu4 = sigma^4), a chi-square(1) that was often far below the true
 * sqrt(2 / (c (c - 1))) sigma^2. It is never 0 unless every value is equal.
 * MCS_ERR_NULL, MCS_ERR_INVARIANT, MCS_ERR_EMPTY (< 4 values). */
mcs_status mcs_welford_variance_stderr(const mcs_welford *acc, double *stderr_out);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_WELFORD_H */
