/* The primal moment accumulator (eq. 15, 16): sums of s_n and s_m s_n over
 * trials, each trial added from its sparse form in O(K^2), the Fourier
 * quantities formed only at read-out.
 *
 * It keeps the full second moment <s_m s_n> (N up to MCS_MAX_COV_N), hence
 * <S_k>, <|S_k|^2>, every <S_k S_l*> and Cov(S_k, S_l), and Var[I] of any f:
 * what a non-stationary pattern (stratified, importance sampled) needs. For
 * the power spectrum alone at any N, see autocorr.h.
 *
 * The read-out calls are the same, with the same arguments, as those of the
 * exact moments in theory.h (mcs_theory_*), and run the same code: measured
 * and exact are the same call on two objects.
 *
 * Size: 8 * MCS_MAX_COV_N * (MCS_MAX_COV_N + 3) bytes and a header (34 320 at
 * the default 64 on x86-64). It holds plain sums (additive over trials, so a
 * merge is exact up to the order of additions) and no pointers. */
#ifndef MCSPEC_MOMENT_H
#define MCSPEC_MOMENT_H

#include <stddef.h>
#include <stdint.h>
#include "config.h"
#include "status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    size_t n;                                       /* N, 1..MCS_MAX_COV_N; 0 before init */
    uint64_t count;                                 /* trials added */
    double sum_s[MCS_MAX_COV_N];                    /* sum over trials of s_n */
    double sum_ss[MCS_MAX_COV_N * MCS_MAX_COV_N];   /* sum of s_m s_n at [bin_m * N + bin_n]
                                                       (both triangles, exactly symmetric) */
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
 * and >= 0; O(nnz N). MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_MISMATCH,
 * MCS_ERR_NOT_FINITE, MCS_ERR_NEGATIVE. *acc untouched on error. */
mcs_status mcs_moment_add_dense(mcs_moment *acc, size_t n, const double *s);

/* dst <- dst union src (sums add). src unchanged; dst == src allowed.
 * MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_MISMATCH (different N). dst untouched on error. */
mcs_status mcs_moment_merge(mcs_moment *dst, const mcs_moment *src);

/* Number of trials added. MCS_ERR_NULL, MCS_ERR_UNINIT. */
mcs_status mcs_moment_count(const mcs_moment *acc, uint64_t *count);

/* ---- Read-out: the trial averages. Every call returns MCS_ERR_NULL,
 * MCS_ERR_UNINIT, MCS_ERR_EMPTY (no trials), and as stated; outputs are
 * untouched on error. ---- */

/* <s_bin>. MCS_ERR_BIN_RANGE (bin >= N). */
mcs_status mcs_moment_bin_mean(const mcs_moment *acc, size_t bin, double *out);

/* <s_m s_n> for bins bin_m, bin_n (symmetric). MCS_ERR_BIN_RANGE. */
mcs_status mcs_moment_bin_second(const mcs_moment *acc, size_t bin_m, size_t bin_n,
                                 double *out);

/* <S_freq> (eq. 15) from <s>. O(N). MCS_ERR_FREQ_RANGE (freq >= N). */
mcs_status mcs_moment_mean(const mcs_moment *acc, size_t freq, double *re, double *im);

/* <|S_freq|^2>, the real diagonal of eq. 16. O(N^2). MCS_ERR_FREQ_RANGE. */
mcs_status mcs_moment_power(const mcs_moment *acc, size_t freq, double *out);

/* <S_k S_l*> (eq. 16) for k = freq_k, l = freq_l. O(N^2). MCS_ERR_FREQ_RANGE. */
mcs_status mcs_moment_cross(const mcs_moment *acc, size_t freq_k, size_t freq_l, double *re,
                            double *im);

/* Cov(S_k, S_l) = <S_k S_l*> - <S_k><S_l>*. O(N^2). MCS_ERR_FREQ_RANGE. */
mcs_status mcs_moment_covariance(const mcs_moment *acc, size_t freq_k, size_t freq_l,
                                 double *re, double *im);

/* Every <S_k S_l*> at once, O(N^3): re[k * n + l] + i im[k * n + l], caller
 * arrays of n * n (exactly n * n entries are written), n equal to the
 * accumulator's N, else MCS_ERR_MISMATCH. */
mcs_status mcs_moment_cross_matrix(const mcs_moment *acc, size_t n, double *re, double *im);

/* Every Cov(S_k, S_l) at once, O(N^3), laid out as mcs_moment_cross_matrix. */
mcs_status mcs_moment_covariance_matrix(const mcs_moment *acc, size_t n, double *re,
                                        double *im);

/* <I> = (1/K) sum_n f_n <s_n> for K = k samples per trial (eq. 8 averaged).
 * f[n], n equal to the accumulator's N (MCS_ERR_MISMATCH), finite
 * (MCS_ERR_NOT_FINITE); k >= 1 (MCS_ERR_K_RANGE): the accumulator does not
 * know K, the caller names it. */
mcs_status mcs_moment_estimator_mean(const mcs_moment *acc, size_t n, size_t k, const double *f,
                                     double *out);

/* Var[I] = (1/K^2) f^T Cov(s) f with Cov(s) = <s s^T> - <s><s>^T over the
 * trials added (the population covariance: the factor (T - 1)/T of a sample
 * variance is not applied). Arguments and statuses as
 * mcs_moment_estimator_mean. */
mcs_status mcs_moment_variance(const mcs_moment *acc, size_t n, size_t k, const double *f,
                               double *out);

/* Cov(I_f, I_g) = (1/K^2) f^T Cov(s) g for two integrands estimated from the
 * same trials. f[n], g[n]; statuses as mcs_moment_estimator_mean. */
mcs_status mcs_moment_estimator_covariance(const mcs_moment *acc, size_t n, size_t k,
                                           const double *f, const double *g, double *out);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_MOMENT_H */
