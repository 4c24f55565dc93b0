/* The exact discrete moments of a pattern: what the patterns should measure.
 *
 * <s_n> and <s_m s_n> of every pattern kind, with and without importance, for
 * any K and any N up to MCS_MAX_COV_N (K need not divide N). A sample u_j in
 * [0,1) lands in bin n when it falls in the bin's interval I_n of canonical u
 * (its CDF interval [cdf[n], cdf[n+1]) with importance, [n/N, (n+1)/N)
 * without) and then weighs 1/p_n, so the moments are interval overlaps:
 *
 *     <s_n>     = (1/p_n)       sum_j      P(u_j in I_n)
 *     <s_m s_n> = (1/(p_m p_n)) sum_{j,j'} P(u_j in I_m and u_j' in I_n)
 *
 * Per kind (t = u K, so stratum j is [j, j+1) and bin n is [A_n, B_n)):
 * - random: independent u_j, P = lengths, products for j != j'.
 * - stratified: u_j uniform on stratum j; sum_j of the same-stratum overlap
 *   products is removed from the independent K^2 L_m L_n. Strata need not
 *   line up with bins (K not dividing N, or importance).
 * - homogenized: the stratified moments averaged over the N cyclic whole-bin
 *   shifts the generator draws uniformly from [0, N).
 * - uniform: deterministic. u_j is binned by the generator's own arithmetic,
 *   so a u_j exactly on a bin edge (every u_j when N/K is even: not a
 *   measure-zero event for a deterministic pattern) lands where
 *   mcs_pattern_draw puts it: without importance that is the exact
 *   floor((2j + 1) N / (2K)).
 * - jitter (also warped by importance, which the note leaves open): the count
 *   of samples in bin n as a function of the shared beta is
 *   r_n(beta) = ceil(B_n - beta) - ceil(A_n - beta), a step function with at
 *   most two steps in [0,1); <r_m r_n> is the exact integral of the product
 *   of two such step functions.
 * Each kind costs O(N^2) (O(N^3) for homogenized, O(K + N^2) for uniform)
 * whatever K is.
 *
 * The read-out is the same, call for call, as that of the measured moments
 * in moment.h (and runs the same code): <S_k> (eq. 15), <S_k S_l*> (eq. 16),
 * Cov(S_k, S_l), and the exact mean and Var[I] = (1/K^2) f^T Cov(s) f of the
 * estimator of a caller's f. The note's closed forms are in eq.h.
 *
 * Conventions: n = N bins, k = K samples per trial, freq a frequency index in
 * [0, N); S_k = N^{-1/2} sum_n e^{-2 pi i k n / N} s_n (eq. 7). Every function
 * validates all inputs before writing anything: on error every output and
 * the theory object are byte-for-byte unchanged. Nothing allocates, and no
 * work arrays live on the stack: transforms are taken one coefficient at a
 * time, at the costs noted per function (all well under a second at N = 64). */
#ifndef MCSPEC_THEORY_H
#define MCSPEC_THEORY_H

#include <stddef.h>
#include "config.h"
#include "status.h"
#include "pattern.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Exact first and second moments of one pattern. Caller-owned (static,
 * stack or arena); filled by mcs_theory_init. sizeof(mcs_theory) at the
 * default MCS_MAX_COV_N = 64 is 34,336 bytes on LP64 (the N x N second
 * moment is 32 KiB of it). */
typedef struct {
    mcs_pattern_kind kind; /* pattern kind the moments are for */
    size_t n;              /* bins N, 1..MCS_MAX_COV_N (0: not initialised) */
    size_t k;              /* samples per trial K, >= 1 */
    int has_importance;    /* 1 if the pattern warps through an importance function */
    double mean_s[MCS_MAX_COV_N]; /* <s_n>, n in [0, N) */
    double second[MCS_MAX_COV_N * MCS_MAX_COV_N]; /* <s_m s_n> at [bin_m * N + bin_n] (packed
                                                     with stride N, symmetric) */
    double cos_table[MCS_MAX_COV_N]; /* cos(2 pi j / N): twiddles with exact index reduction */
    double sin_table[MCS_MAX_COV_N]; /* sin(2 pi j / N) */
} mcs_theory;

/* Computes the exact <s_n> and <s_m s_n> of pat (any kind, with or without
 * importance, any K >= 1, pat->n <= MCS_MAX_COV_N). pat is read, not kept.
 * MCS_ERR_NULL, MCS_ERR_N_RANGE (pat->n > MCS_MAX_COV_N), MCS_ERR_UNINIT
 * (pat->n == 0, pat->k == 0, unknown kind, or an importance function of the
 * wrong n), MCS_ERR_KIND (homogenized with importance). *th untouched on error. */
mcs_status mcs_theory_init(mcs_theory *th, const mcs_pattern *pat);

/* ---- Read-out: the expectations. Every call returns MCS_ERR_NULL,
 * MCS_ERR_UNINIT, and as stated; outputs are untouched on error. ---- */

/* <s_bin>. MCS_ERR_BIN_RANGE (bin >= N). */
mcs_status mcs_theory_bin_mean(const mcs_theory *th, size_t bin, double *out);

/* <s_m s_n> for bins bin_m, bin_n (symmetric). MCS_ERR_BIN_RANGE. */
mcs_status mcs_theory_bin_second(const mcs_theory *th, size_t bin_m, size_t bin_n,
                                 double *out);

/* <S_freq> (eq. 15) from <s>. O(N). MCS_ERR_FREQ_RANGE (freq >= N). */
mcs_status mcs_theory_mean(const mcs_theory *th, size_t freq, double *re, double *im);

/* Power spectrum <|S_freq|^2>, the real diagonal of eq. 16 (freq 0 included).
 * O(N^2). MCS_ERR_FREQ_RANGE. */
mcs_status mcs_theory_power(const mcs_theory *th, size_t freq, double *out);

/* <S_k S_l*> (eq. 16) for k = freq_k, l = freq_l, by separable direct sums.
 * O(N^2). MCS_ERR_FREQ_RANGE. */
mcs_status mcs_theory_cross(const mcs_theory *th, size_t freq_k, size_t freq_l, double *re,
                            double *im);

/* Cov(S_k, S_l) = <S_k S_l*> - <S_k><S_l>*. O(N^2). MCS_ERR_FREQ_RANGE. */
mcs_status mcs_theory_covariance(const mcs_theory *th, size_t freq_k, size_t freq_l,
                                 double *re, double *im);

/* Every <S_k S_l*> at once, O(N^3): re[k * n + l] + i im[k * n + l], caller
 * arrays of n * n (exactly n * n entries are written), n equal to th->n, else
 * MCS_ERR_MISMATCH. */
mcs_status mcs_theory_cross_matrix(const mcs_theory *th, size_t n, double *re, double *im);

/* Every Cov(S_k, S_l) at once, O(N^3), laid out as mcs_theory_cross_matrix. */
mcs_status mcs_theory_covariance_matrix(const mcs_theory *th, size_t n, double *re,
                                        double *im);

/* <I> = (1/K) sum_n f_n <s_n> (eq. 9 in the primal domain); equals eq. 11 for
 * every unbiased kind, not for uniform. f[n], n == th->n, else
 * MCS_ERR_MISMATCH; f finite, else MCS_ERR_NOT_FINITE. k is the K of the
 * pattern, named as for mcs_moment_estimator_mean: MCS_ERR_K_RANGE (k = 0),
 * MCS_ERR_MISMATCH (k != th->k). */
mcs_status mcs_theory_estimator_mean(const mcs_theory *th, size_t n, size_t k, const double *f,
                                     double *out);

/* Exact Var[I] = (1/K^2) f^T Cov(s) f for I = (1/K) sum_n f_n s_n (eq. 8).
 * Arguments and statuses as mcs_theory_estimator_mean. */
mcs_status mcs_theory_variance(const mcs_theory *th, size_t n, size_t k, const double *f,
                               double *out);

/* Cov(I_f, I_g) = (1/K^2) f^T Cov(s) g for two integrands estimated from the
 * SAME trial (correlated sampling, the Cov[f,g] of eq. 2 and 5). f[n], g[n];
 * statuses as mcs_theory_estimator_mean. */
mcs_status mcs_theory_estimator_covariance(const mcs_theory *th, size_t n, size_t k,
                                           const double *f, const double *g, double *out);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_THEORY_H */
