/* The primal accumulators (eq. 15, 16): sums of s_n and s_m s_n over trials,
 * each trial added from its sparse form in O(K^2), the Fourier quantities
 * formed only at read-out.
 *
 * mcs_moment (N up to MCS_MAX_COV_N): the full second moment <s_m s_n>, hence
 * <S_k>, <|S_k|^2>, every <S_k S_l*> and Cov(S_k, S_l) -- what a
 * non-stationary pattern (stratified, importance sampled) needs for Var[I].
 * Size: 8 * MCS_MAX_COV_N * (MCS_MAX_COV_N + 3) bytes and a header
 * (34 320 at the default 64 on x86-64).
 *
 * mcs_autocorr (N up to MCS_MAX_N): only the circular autocorrelation
 * A(d) = sum_n s_n s_{n+d} (mod N), enough for the power spectrum by
 * Wiener-Khinchin, |S_k|^2 = (1/N) sum_d e^{-2 pi i k d/N} A(d), and <S_k>;
 * one DFT through a caller's mcs_dft at read-out.
 * Size: about 12 * MCS_MAX_N bytes (49 176 at the default 4096 on x86-64).
 *
 * Both hold plain sums (additive over trials, so a merge is exact up to the
 * order of additions) and no pointers. */
#ifndef MCSPEC_MOMENT_H
#define MCSPEC_MOMENT_H

#include <stddef.h>
#include <stdint.h>
#include "config.h"
#include "status.h"
#include "dft.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    size_t n;                                       /* N, 1..MCS_MAX_COV_N; 0 before init */
    uint64_t count;                                 /* trials added */
    double sum_s[MCS_MAX_COV_N];                    /* sum over trials of s_n */
    double sum_ss[MCS_MAX_COV_N * MCS_MAX_COV_N];   /* sum of s_m s_n at [m * N + n],
                                                       upper triangle m <= n only */
    double cos_table[MCS_MAX_COV_N];                /* cos(2 pi j / N) */
    double sin_table[MCS_MAX_COV_N];                /* sin(2 pi j / N) */
} mcs_moment;

/* Empties the accumulator for n bins. MCS_ERR_NULL, MCS_ERR_N_RANGE
 * (n = 0 or n > MCS_MAX_COV_N). *acc untouched on error. */
mcs_status mcs_moment_init(mcs_moment *acc, size_t n);

/* Adds one trial in sparse form (eq. 38): bins[k] in [0, N), weights[k]
 * finite and >= 0. O(k^2). MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_K_RANGE
 * (k = 0), MCS_ERR_BIN_RANGE, MCS_ERR_NOT_FINITE, MCS_ERR_NEGATIVE.
 * *acc untouched on error. */
mcs_status mcs_moment_add_bins(mcs_moment *acc, size_t k, const size_t *bins,
                               const double *weights);

/* Adds one trial given densely, s[n] (n equal to the accumulator's N), finite
 * and >= 0; O(nnz^2). MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_MISMATCH,
 * MCS_ERR_NOT_FINITE, MCS_ERR_NEGATIVE. *acc untouched on error. */
mcs_status mcs_moment_add_dense(mcs_moment *acc, size_t n, const double *s);

/* dst <- dst union src (sums add). src unchanged; dst == src allowed.
 * MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_MISMATCH (different N). dst untouched on error. */
mcs_status mcs_moment_merge(mcs_moment *dst, const mcs_moment *src);

/* Number of trials added. MCS_ERR_NULL, MCS_ERR_UNINIT. */
mcs_status mcs_moment_count(const mcs_moment *acc, uint64_t *count);

/* Read-outs below: MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_EMPTY (no trials),
 * MCS_ERR_BIN_RANGE (bin index >= N) or MCS_ERR_FREQ_RANGE (frequency >= N),
 * MCS_ERR_MISMATCH (array length n != N). Outputs untouched on error. */

/* Primal mean <s_n>. */
mcs_status mcs_moment_mean_s(const mcs_moment *acc, size_t bin, double *mean);

/* Primal second moment <s_m s_n> (symmetric in m, n). */
mcs_status mcs_moment_second(const mcs_moment *acc, size_t m, size_t n, double *value);

/* <S_k> by eq. 15 from <s_n>. O(N). */
mcs_status mcs_moment_spectrum_mean(const mcs_moment *acc, size_t freq, double *re, double *im);

/* <|S_k|^2> by eq. 16 with l = k (real by the symmetry of <s_m s_n>). O(N^2). */
mcs_status mcs_moment_power(const mcs_moment *acc, size_t freq, double *power);

/* <S_k S_l*> by eq. 16. O(N^2). */
mcs_status mcs_moment_cross(const mcs_moment *acc, size_t k, size_t l, double *re, double *im);

/* Cov(S_k, S_l) = <S_k S_l*> - <S_k><S_l>*. O(N^2). */
mcs_status mcs_moment_covariance(const mcs_moment *acc, size_t k, size_t l, double *re,
                                 double *im);

/* Every <S_k S_l*> at once, O(N^3): re[k * n + l] + i im[k * n + l], arrays of
 * n * n with n equal to the accumulator's N. */
mcs_status mcs_moment_cross_matrix(const mcs_moment *acc, size_t n, double *re, double *im);

/* Every Cov(S_k, S_l) at once, O(N^3), laid out as mcs_moment_cross_matrix. */
mcs_status mcs_moment_covariance_matrix(const mcs_moment *acc, size_t n, double *re,
                                        double *im);

/* Half-length storage of the autocorrelation: lags d = 0..MCS_MAX_N/2. */
#define MCS_AUTOCORR_HALF ((MCS_MAX_N) / 2 + 1)

typedef struct {
    size_t n;                          /* N, 1..MCS_MAX_N; 0 before init */
    uint64_t count;                    /* trials added */
    double sum_s[MCS_MAX_N];           /* sum over trials of s_n */
    double sum_a[MCS_AUTOCORR_HALF];   /* sum over trials of A(d), d = 0..N/2
                                          (A(N-d) = A(d)), the d = 0 and d = N/2
                                          entries halved (see moment.c) */
} mcs_autocorr;

/* Empties the accumulator for n bins. MCS_ERR_NULL, MCS_ERR_N_RANGE
 * (n = 0 or n > MCS_MAX_N). *acc untouched on error. */
mcs_status mcs_autocorr_init(mcs_autocorr *acc, size_t n);

/* Adds one trial in sparse form, O(k^2): A(d) gets w_j w_j' for every pair
 * with n_j' - n_j = d (mod N). Arguments and statuses as mcs_moment_add_bins. */
mcs_status mcs_autocorr_add_bins(mcs_autocorr *acc, size_t k, const size_t *bins,
                                 const double *weights);

/* dst <- dst union src. As mcs_moment_merge. */
mcs_status mcs_autocorr_merge(mcs_autocorr *dst, const mcs_autocorr *src);

/* Number of trials added. MCS_ERR_NULL, MCS_ERR_UNINIT. */
mcs_status mcs_autocorr_count(const mcs_autocorr *acc, uint64_t *count);

/* <S_k> for all k = 0..n-1 (eq. 15), one DFT of <s> through plan (its N must
 * equal the accumulator's; its scratch is overwritten). re[n], im[n] written.
 * MCS_ERR_NULL, MCS_ERR_UNINIT (acc or plan), MCS_ERR_MISMATCH (n or plan N),
 * MCS_ERR_EMPTY. Outputs untouched on error. */
mcs_status mcs_autocorr_mean(const mcs_autocorr *acc, mcs_dft *plan, size_t n, double *re,
                             double *im);

/* <|S_k|^2> for all k = 0..n-1 by Wiener-Khinchin, one DFT of <A> through
 * plan. power[n] written. Statuses as mcs_autocorr_mean. */
mcs_status mcs_autocorr_power(const mcs_autocorr *acc, mcs_dft *plan, size_t n, double *power);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_MOMENT_H */
