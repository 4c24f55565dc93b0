/* The autocorrelation accumulator (N up to MCS_MAX_N): per trial the circular
 * autocorrelation A(d) = sum_n s_n s_{n+d} (mod N) from the sparse form in
 * O(K^2), enough for the power spectrum by Wiener-Khinchin,
 * |S_k|^2 = (1/N) sum_d e^{-2 pi i k d/N} A(d), and for <S_k>; one DFT
 * through a caller's mcs_dft at read-out. Where the full second moment is
 * needed (cross spectra, Var[I] of a non-stationary pattern), see moment.h.
 *
 * Size: about 12 * MCS_MAX_N bytes (49 176 at the default 4096 on x86-64).
 * It holds plain sums (a merge is exact up to the order of additions) and no
 * pointers. */
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

typedef struct {
    size_t n;                          /* N, 1..MCS_MAX_N; 0 before init */
    uint64_t count;                    /* trials added */
    double sum_s[MCS_MAX_N];           /* sum over trials of s_n */
    double sum_a[MCS_AUTOCORR_HALF];   /* sum over trials of A(d), d = 0..N/2
                                          (A(N-d) = A(d)), the d = 0 and d = N/2
                                          entries halved (see mcs_autocorr_add_bins) */
} mcs_autocorr;

/* Empties the accumulator for n bins. MCS_ERR_NULL, MCS_ERR_N_RANGE
 * (n = 0 or n > MCS_MAX_N). *acc untouched on error. */
mcs_status mcs_autocorr_init(mcs_autocorr *acc, size_t n);

/* Adds one trial in sparse form, O(k^2): A(d) gets w_j w_j' for every pair
 * with n_j' - n_j = d (mod N). Both orders of a pair land on lags d and N - d,
 * which share one stored entry, so the entry for 0 < d < N/2 gets w w' once,
 * and lags 0 and N/2 (where both orders land on the same lag) get half of
 * A(d) and are doubled at read-out. bins[k] in [0, N), weights[k] finite and
 * >= 0. MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_K_RANGE (k = 0),
 * MCS_ERR_BIN_RANGE, MCS_ERR_NOT_FINITE, MCS_ERR_NEGATIVE.
 * *acc untouched on error. */
mcs_status mcs_autocorr_add_bins(mcs_autocorr *acc, size_t k, const size_t *bins,
                                 const double *weights);

/* dst <- dst union src (sums add). src unchanged; dst == src allowed.
 * MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_MISMATCH (different N). dst untouched on error. */
mcs_status mcs_autocorr_merge(mcs_autocorr *dst, const mcs_autocorr *src);

/* Number of trials added. MCS_ERR_NULL, MCS_ERR_UNINIT. */
mcs_status mcs_autocorr_count(const mcs_autocorr *acc, uint64_t *count);

/* <S_k> for all k = 0..n-1 (eq. 15), one DFT of <s> through plan (its N must
 * equal the accumulator's; its scratch is overwritten). re[n], im[n] written
 * (exactly n entries each). MCS_ERR_NULL, MCS_ERR_UNINIT (acc or plan),
 * MCS_ERR_MISMATCH (n or plan N), MCS_ERR_EMPTY, MCS_ERR_NOT_FINITE (a sum
 * overflowed). Outputs untouched on error. */
mcs_status mcs_autocorr_mean(const mcs_autocorr *acc, mcs_dft *plan, size_t n, double *re,
                             double *im);

/* <|S_k|^2> for all k = 0..n-1 by Wiener-Khinchin, one DFT of <A> through
 * plan. power[n] written (exactly n entries). Statuses as mcs_autocorr_mean. */
mcs_status mcs_autocorr_power(const mcs_autocorr *acc, mcs_dft *plan, size_t n, double *power);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_AUTOCORR_H */
