/* The autocorrelation accumulator (N up to MCS_MAX_N): per trial the circular
 * autocorrelation A(d) = sum_n s_n s_{n+d} (mod N), enough for the power
 * spectrum by Wiener-Khinchin, |S_k|^2 = (1/N) sum_d e^{-2 pi i k d/N} A(d),
 * and for <S_k>; one DFT through a caller's mcs_dft at read-out. Where the
 * full second moment is needed (cross spectra, Var[I] of a non-stationary
 * pattern), see moment.h.
 *
 * A trial of K < N samples adds A(d) from its sample pairs, O(K^2). A trial
 * of K >= N samples is binned to its s first, and adds the centred
 * A_c(d) = sum_n (s_n - c)(s_{n+d} - c), c = S/N the mean of its s (S the
 * trial's total weight), O(N^2 / 2) <= O(K^2 / 2): A(d) = A_c(d) + S^2/N, and
 * the constant S^2/N, kept apart, adds to the k = 0 power only. Dense trials
 * are nearly flat (s_n ~ K/N for every unbiased pattern), so the centring
 * removes what would cancel at read-out: at N = 3, K = 1000 (jitter with
 * importance) the plain sums of pair products drifted from the spectrum
 * accumulator by 3.6e-3 to 1.8e-2 over 40 000 trials. Every sum is kept with
 * Kahan's compensation, so the error grows neither with K nor with the number
 * of trials.
 *
 * Size: about 32 * MCS_MAX_N bytes (131 120 at the default 4096 on x86-64:
 * sums, their compensations and one trial's scratch). It holds no pointers. */
#ifndef MCSPEC_AUTOCORR_H
#define MCSPEC_AUTOCORR_H

#include <stddef.h>
#include <stdint.h>
#include "config.h"
#include "status.h"
#include "dft.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Half-length storage of the autocorrelation: lags d = 0..MCS_MAX_N/2. */
#define MCS_AUTOCORR_HALF ((MCS_MAX_N) / 2 + 1)

/* Largest total weight of one trial, sum_j w_j = S, the accumulator takes:
 * 2^220 (about 1.7e66), as MCS_MOMENT_MAX_TRIAL. Every lag sum of a trial is
 * then below (2 S)^2 = 2^442, and over MCS_MAX_COUNT trials below 2^496: no
 * square overflows and every read-out is finite. */
#define MCS_AUTOCORR_MAX_TRIAL 1.684996666696915e+66

typedef struct {
    size_t n;                          /* N, 1..MCS_MAX_N; 0 before init */
    uint64_t count;                    /* trials added, at most MCS_MAX_COUNT */
    double sum_s[MCS_MAX_N];           /* sum over trials of s_n */
    double lo_s[MCS_MAX_N];            /* Kahan compensation of sum_s */
    double sum_lag[MCS_AUTOCORR_HALF]; /* sum over trials of A(d) (K < N) or A_c(d)
                                          (K >= N), d = 0..N/2 (A(N-d) = A(d)), the
                                          d = 0 and d = N/2 entries halved (see
                                          mcs_autocorr_add_bins) */
    double lo_lag[MCS_AUTOCORR_HALF];  /* Kahan compensation of sum_lag */
    double sum_dc;                     /* sum over the K >= N trials of S^2/N */
    double lo_dc;                      /* Kahan compensation of sum_dc */
    double work[MCS_MAX_N];            /* scratch of one K >= N trial: its s */
} mcs_autocorr;

/* Every call below returns MCS_ERR_UNINIT for an object not set up by
 * mcs_autocorr_init (n out of range), and MCS_ERR_INVARIANT for one
 * overwritten since, changing nothing: a count above MCS_MAX_COUNT or, at
 * read-out and merge, sums that no trials give (a value NaN, infinite or
 * above 2^500, a sum of weights or the lag-0 sum below 0, a lag sum past
 * the lag-0 one, a compensation past an ulp of its sum, sums of weights and
 * of squares no trials share: the invariants of docs/format.md, kind 3,
 * checked by the code the loader runs). O(N) per read-out or merge, nothing
 * per trial. */

/* Empties the accumulator for n bins. MCS_ERR_NULL, MCS_ERR_N_RANGE
 * (n = 0 or n > MCS_MAX_N). *acc untouched on error. */
mcs_status mcs_autocorr_init(mcs_autocorr *acc, size_t n);

/* Adds one trial in sparse form. For k < N: A(d) gets w_j w_j' for every pair
 * with n_j' - n_j = d (mod N); both orders of a pair land on lags d and N - d,
 * which share one stored entry, so the entry for 0 < d < N/2 gets w w' once,
 * and lags 0 and N/2 (where both orders land on the same lag) get half of
 * A(d) and are doubled at read-out. For k >= N: the same folding of A_c(d)
 * (see above). bins[k] in [0, N), weights[k] finite and >= 0 with sum at most
 * MCS_AUTOCORR_MAX_TRIAL, neither array overlapping *acc. MCS_ERR_NULL,
 * MCS_ERR_UNINIT, MCS_ERR_K_RANGE (k = 0), MCS_ERR_BIN_RANGE,
 * MCS_ERR_NOT_FINITE, MCS_ERR_NEGATIVE, MCS_ERR_MAGNITUDE, MCS_ERR_COUNT
 * (count at MCS_MAX_COUNT), MCS_ERR_ALIAS. *acc untouched on error. */
mcs_status mcs_autocorr_add_bins(mcs_autocorr *acc, size_t k, const size_t *bins,
                                 const double *weights);

/* dst <- dst union src (sums add). src unchanged; dst == src allowed (other
 * overlap: MCS_ERR_ALIAS). MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_MISMATCH
 * (different N), MCS_ERR_COUNT (the counts add up past MCS_MAX_COUNT),
 * MCS_ERR_INVARIANT (either's sums no trials give, see above). dst
 * untouched on error. */
mcs_status mcs_autocorr_merge(mcs_autocorr *dst, const mcs_autocorr *src);

/* Number of trials added. MCS_ERR_NULL, MCS_ERR_UNINIT. */
mcs_status mcs_autocorr_count(const mcs_autocorr *acc, uint64_t *count);

/* <S_k> for all k = 0..n-1 (eq. 15), one DFT of <s> through plan (its N must
 * equal the accumulator's; its scratch is overwritten). re[n], im[n] written
 * (exactly n entries each); they must overlap neither each other, the
 * accumulator nor the plan. MCS_ERR_NULL, MCS_ERR_UNINIT (acc or plan),
 * MCS_ERR_INVARIANT, MCS_ERR_MISMATCH (n or plan N), MCS_ERR_EMPTY,
 * MCS_ERR_ALIAS. Every check,
 * including one that the transform's input and output are finite (the
 * stored sums are bounded, see MCS_AUTOCORR_MAX_TRIAL), is made before
 * anything is written, and the transform's status is returned: never
 * MCS_OK with an untransformed or non-finite result. Outputs untouched on
 * error. */
mcs_status mcs_autocorr_mean(const mcs_autocorr *acc, mcs_dft *plan, size_t n, double *re,
                             double *im);

/* <|S_k|^2> for all k = 0..n-1 by Wiener-Khinchin, one DFT of <A> through
 * plan. power[n] written (exactly n entries; it must overlap neither the
 * accumulator nor the plan). Statuses as mcs_autocorr_mean.
 * Rounding: every power is within (2N + 16 ceil(log2 N) + 192 + T N^2 eps)
 * eps <A(0)> of the exact mean of |S_k|^2 over the T trials (eps =
 * DBL_EPSILON; <A(0)> the mean over the trials of sum_n s_n^2, of sum_n
 * (s_n - S/N)^2 for a trial of K >= N samples, whose lags are kept
 * centred: the largest |<A(d)>|, which the transform sums N of): the lag
 * sums carry (N + 8 + T N^2 eps) eps of it, the transform at most (N + 2) u
 * on its direct path and (8 log2 N + 16) u on the FFT paths (u = eps / 2),
 * and the bound leaves room for twice the rounding of the loader's own
 * direct sums, so that every record that loads reads out; plus 64 (N + 8)
 * DBL_TRUE_MIN for underflow, whatever <A(0)> is. A power is never
 * negative: one below 0 within that bound reads 0 (a trial of weight 2^100
 * among ordinary ones left -2.7e39 at a k where every trial's |S_k|^2 is
 * about 1, beside 2.5e57 at k = 0); one below it is no spectrum of any
 * trials, MCS_ERR_INVARIANT. That check needs the transform, which runs in
 * power[]: on that one error power[] holds the unclamped powers, and
 * every other error leaves it untouched. */
mcs_status mcs_autocorr_power(const mcs_autocorr *acc, mcs_dft *plan, size_t n, double *power);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_AUTOCORR_H */
