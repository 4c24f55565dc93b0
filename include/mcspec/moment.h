/* The primal moment accumulator (eq. 15, 16): the first and second moments
 * of s over trials, each trial added from its sparse form, the Fourier
 * quantities formed only at read-out.
 *
 * It keeps the full second moment <s_m s_n> (N up to MCS_MAX_COV_N), hence
 * <S_k>, <|S_k|^2>, every <S_k S_l*> and Cov(S_k, S_l), and Var[I] of any f:
 * what a non-stationary pattern (stratified, importance sampled) needs. For
 * the power spectrum alone at any N, see autocorr.h.
 *
 * Accuracy and speed: the closed sums are of d = s - c, c a fixed shift,
 * with Kahan compensation. c is the s of the first trial on the bins each of
 * the first MCS_MOMENT_SETTLE trials fills, and 0 elsewhere: where trials
 * keep filling a bin with like weights (a stratified or importance-sampled
 * bin: s_n ~ 1e8 whose trials differ by 1) s - c keeps the digits, and
 * where s is mostly 0 shifting by 0 costs nothing (and a sparse trial
 * seldom meets a bin of the shift, the slower case below). Covariances are
 * shift-free, so they are read from the small d sums instead of as
 * <s_m s_n> - <s_m><s_n>, which cancelled: at N = 3, K = 1000 (jitter with
 * importance, s_n ~ 333, power at k = 1 ~ 0.8) plain sums of s s^T drifted
 * from the spectrum accumulator by 4e-3 after 40 000 trials, and kept
 * drifting. Trials go first into an open batch of plain sums, folded into the
 * compensated ones every MCS_MOMENT_BATCH trials, so the error grows neither
 * with K nor with the trial count, and a trial costs what a plain loop does:
 *   - a trial of few samples (at most 32, K (K + 1) / 2 pair products at
 *     most N^2 / 32 + 7 N, where the two kernels cost the same) adds the
 *     products of its s over its bins, O(K^2), N not involved: as s s^T if
 *     it has no bin where c is not 0 (there d = s, and d = -c on the
 *     shift's bins for every such trial: the fold adds those terms, none of
 *     them cancelling), as d d^T over its bins and the shift's if it has
 *     one (there s - c can be far below s and c, and products of s would
 *     cancel: issue 22);
 *   - a larger one adds d d^T densely (s s^T if it shares no bin with c and
 *     has fewer bins that are not 0), one vectorised row per bin where it is
 *     not 0: O(N^2) at most, none where s equals c.
 * A trial's s_n is the sum of its weights in bin n, in sample order, as a
 * double (what mcs_moment_add_dense takes); every batch entry then gets at
 * most one product a trial, so each sum of d_m d_n, closed and open batch
 * together, is within (MCS_MOMENT_BATCH + 64) eps sum_t |d_m d_n| <=
 * (MCS_MOMENT_BATCH + 64) eps sqrt(D_m D_n) of the exact sum over the
 * trials (D_m the sum of d_m^2; eps = DBL_EPSILON, about 3.7e-12 in all),
 * whatever the weights, for an object built by adds and by merges of
 * objects with the same shift. A merge moves src's sums to dst's shift
 * (e = c_src - c_dst), which adds up to 4 eps (sqrt(D^src_m) + sqrt(T_src)
 * |e_m|) (sqrt(D^src_n) + sqrt(T_src) |e_n|) to entry (m, n) beyond that,
 * unseen by the read-outs: a few eps sqrt(D_m D_n) while |e| is within the
 * spread of the data (each shift is values of trials), more only if a trial
 * that set a shift lies far from all the others. Read-outs, merges and records include the open batch: nothing
 * needs flushing, and a saved and loaded object is the same to the bit.
 *
 * The read-out calls are the same, with the same arguments, as those of the
 * exact moments in theory.h (mcs_theory_*), and run the same code: measured
 * and exact are the same call on two objects.
 *
 * Size: 8 * MCS_MAX_COV_N * (3 MCS_MAX_COV_N + 8) bytes and a 40-byte header (102 440
 * at the default 64 on x86-64; the compensation and the open batch each add
 * an N x N array). It holds no pointers. */
#ifndef MCSPEC_MOMENT_H
#define MCSPEC_MOMENT_H

#include <stddef.h>
#include <stdint.h>
#include "config.h"
#include "status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Largest total weight of one trial, sum_j w_j = sum_n s_n, the accumulator
 * takes: 2^220 (about 1.7e66). Each s_n and shift entry is then below it, so
 * every d_m d_n is below 2^440 and a sum over MCS_MAX_COUNT trials, merges
 * included, below 2^496: no square overflows and every read-out is finite.
 * A pattern's trial weighs at most 2^62 (pattern.h). */
#define MCS_MOMENT_MAX_TRIAL 1.684996666696915e+66

/* Trials in an open batch before it is folded into the compensated sums: a
 * fold costs O(N^2), a few nanoseconds a trial at N = 64 over this many. */
#define MCS_MOMENT_BATCH 16384u

/* Trials the shift c settles over: the first one's s, kept on the bins each
 * of the first MCS_MOMENT_SETTLE trials fills, 0 on the others. */
#define MCS_MOMENT_SETTLE 4u


typedef struct {
    size_t n;                                      /* N, 1..MCS_MAX_COV_N; 0 before init */
    uint64_t count;                                /* trials added, at most MCS_MAX_COUNT */
    uint64_t batch_count;                          /* of which in the open batch, below
                                                      MCS_MOMENT_BATCH (and below count) */
    uint64_t batch_sparse;                         /* of those, added as products of s */
    int simd;                                      /* kernels: 0 baseline, 1 AVX2 (set at init) */
    double shift[MCS_MAX_COV_N];                   /* c: s of the first trial where the first
                                                      MCS_MOMENT_SETTLE fill the bin, else 0 */
    double sum_d[MCS_MAX_COV_N];                   /* sum over closed trials of d_n = s_n - c_n */
    double sum_dd[MCS_MAX_COV_N * MCS_MAX_COV_N];  /* sum of d_m d_n at [bin_m * N + bin_n]
                                                      (both triangles, exactly symmetric) */
    double lo_d[MCS_MAX_COV_N];                    /* Kahan compensation of sum_d */
    double lo_dd[MCS_MAX_COV_N * MCS_MAX_COV_N];   /* Kahan compensation of sum_dd */
    double batch_s[MCS_MAX_COV_N];                 /* open batch: sum of s over its trials added
                                                      as s (none on a bin where c is not 0) */
    double batch_d[MCS_MAX_COV_N];                 /* sum of d over its other trials */
    double batch_w[MCS_MAX_COV_N * MCS_MAX_COV_N]; /* half products: batch_w + batch_w^T is the
                                                      sum of s s^T (sparse) and d d^T (dense) */
    double cos_table[MCS_MAX_COV_N];               /* cos(2 pi j / N) */
    double sin_table[MCS_MAX_COV_N];               /* sin(2 pi j / N) */
    double work[MCS_MAX_COV_N];                    /* scratch of one add: the trial's s, then d */
} mcs_moment;

/* Every call below returns MCS_ERR_UNINIT for an object not set up by
 * mcs_moment_init (n out of range), and MCS_ERR_INVARIANT for one
 * overwritten since, changing nothing: a count above MCS_MAX_COUNT or, at
 * read-out and merge, sums that no trials give (a value NaN, infinite or
 * beyond the trials' limits, a sum of squares below 0, a first sum past its
 * variance, an entry past Cauchy-Schwarz, a compensation past an ulp of its
 * sum, both triangles unequal, a twiddle table not that of N: the
 * invariants of docs/format.md, kind 2, checked by the code the loader
 * runs). Adds check only the counts: O(N^2) per read-out or merge, nothing
 * per trial. */

/* Empties the accumulator for n bins. MCS_ERR_NULL, MCS_ERR_N_RANGE
 * (n = 0 or n > MCS_MAX_COV_N). *acc untouched on error. */
mcs_status mcs_moment_init(mcs_moment *acc, size_t n);

/* Adds one trial in sparse form (eq. 38): bins[k] in [0, N), weights[k]
 * finite and >= 0, their sum at most MCS_MOMENT_MAX_TRIAL; neither array may
 * overlap *acc. MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_K_RANGE (k = 0),
 * MCS_ERR_BIN_RANGE, MCS_ERR_NOT_FINITE, MCS_ERR_NEGATIVE, MCS_ERR_MAGNITUDE,
 * MCS_ERR_COUNT (count at MCS_MAX_COUNT), MCS_ERR_ALIAS. *acc untouched on
 * error. */
mcs_status mcs_moment_add_bins(mcs_moment *acc, size_t k, const size_t *bins,
                               const double *weights);

/* Adds one trial given densely, s[n] (n equal to the accumulator's N), finite
 * and >= 0, sum at most MCS_MOMENT_MAX_TRIAL, not overlapping *acc.
 * MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_MISMATCH, MCS_ERR_NOT_FINITE,
 * MCS_ERR_NEGATIVE, MCS_ERR_MAGNITUDE, MCS_ERR_COUNT, MCS_ERR_ALIAS.
 * *acc untouched on error. */
mcs_status mcs_moment_add_dense(mcs_moment *acc, size_t n, const double *s);

/* dst <- dst union src (the sums add, src's moved to dst's shift first).
 * src unchanged; dst == src allowed (other overlap: MCS_ERR_ALIAS).
 * MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_MISMATCH (different N), MCS_ERR_COUNT
 * (the counts add up past MCS_MAX_COUNT), MCS_ERR_INVARIANT (either's sums
 * no trials give, see above). dst untouched on error. */
mcs_status mcs_moment_merge(mcs_moment *dst, const mcs_moment *src);

/* Number of trials added. MCS_ERR_NULL, MCS_ERR_UNINIT. */
mcs_status mcs_moment_count(const mcs_moment *acc, uint64_t *count);

/* ---- Read-out: the trial averages. Every call returns MCS_ERR_NULL,
 * MCS_ERR_UNINIT, MCS_ERR_EMPTY (no trials), and as stated; outputs are
 * untouched on error, and a complex result's re and im must be two different
 * doubles (MCS_ERR_ALIAS). ---- */

/* <s_bin>. MCS_ERR_BIN_RANGE (bin >= N). */
mcs_status mcs_moment_bin_mean(const mcs_moment *acc, size_t bin, double *out);

/* <s_m s_n> for bins bin_m, bin_n (symmetric). MCS_ERR_BIN_RANGE. */
mcs_status mcs_moment_bin_second(const mcs_moment *acc, size_t bin_m, size_t bin_n,
                                 double *out);

/* <S_freq> (eq. 15) from <s>. O(N). MCS_ERR_FREQ_RANGE (freq >= N). */
mcs_status mcs_moment_mean(const mcs_moment *acc, size_t freq, double *re, double *im);

/* <|S_freq|^2>, the real diagonal of eq. 16. O(N^2). MCS_ERR_FREQ_RANGE.
 * Never negative: a value below 0 within its rounding bound, (2N + 16) eps
 * (1/N) sum |<d_m d_n>| + 4 (N + 2) eps ((sum |<d_n>|)^2 + (sum |c_n| +
 * sum |<d_n>|)^2) / N and the sums' 3 (MCS_MOMENT_BATCH + 64) eps (sum_m
 * sqrt(<d_m^2>))^2 / N, reads 0; below that MCS_ERR_INVARIANT. */
mcs_status mcs_moment_power(const mcs_moment *acc, size_t freq, double *out);

/* <S_k S_l*> (eq. 16) for k = freq_k, l = freq_l (at k = l the power, as
 * mcs_moment_power). O(N^2). MCS_ERR_FREQ_RANGE. */
mcs_status mcs_moment_cross(const mcs_moment *acc, size_t freq_k, size_t freq_l, double *re,
                            double *im);

/* Cov(S_k, S_l) = <S_k S_l*> - <S_k><S_l>*. O(N^2). MCS_ERR_FREQ_RANGE.
 * On the diagonal (k = l, a variance) it is never negative: a value below 0
 * by no more than its rounding bound, 4 (N + 2) eps ((1/N) sum |<d_m d_n>|
 * + (sum |<d_n>|)^2 / N) for the read-out and 3 (MCS_MOMENT_BATCH + 64) eps
 * (sum_m sqrt(<d_m^2>))^2 / N for the sums (see above; <.> the average over
 * the trials), is returned as 0; one below that is not rounding, and the
 * object is refused (MCS_ERR_INVARIANT): its sums are those of no data
 * (overwritten, or a crafted record). */
mcs_status mcs_moment_covariance(const mcs_moment *acc, size_t freq_k, size_t freq_l,
                                 double *re, double *im);

/* Every <S_k S_l*> at once, O(N^3): re[k * n + l] + i im[k * n + l], caller
 * arrays of n * n (exactly n * n entries are written), n equal to the
 * accumulator's N, else MCS_ERR_MISMATCH. re and im must not overlap each
 * other or the accumulator (they are written while it is read):
 * MCS_ERR_ALIAS. */
mcs_status mcs_moment_cross_matrix(const mcs_moment *acc, size_t n, double *re, double *im);

/* Every Cov(S_k, S_l) at once, O(N^3), laid out as mcs_moment_cross_matrix,
 * statuses as there; the diagonal as mcs_moment_covariance. */
mcs_status mcs_moment_covariance_matrix(const mcs_moment *acc, size_t n, double *re,
                                        double *im);

/* <I> = (1/K) sum_n f_n <s_n> for K = k samples per trial (eq. 8 averaged).
 * f[n], n equal to the accumulator's N (MCS_ERR_MISMATCH), finite
 * (MCS_ERR_NOT_FINITE); k >= 1 (MCS_ERR_K_RANGE): the accumulator does not
 * know K, the caller names it. MCS_ERR_MAGNITUDE if f is so large that the
 * result overflows. */
mcs_status mcs_moment_estimator_mean(const mcs_moment *acc, size_t n, size_t k, const double *f,
                                     double *out);

/* Var[I] = (1/K^2) f^T Cov(s) f with Cov(s) = <s s^T> - <s><s>^T over the
 * trials added (the population covariance: the factor (T - 1)/T of a sample
 * variance is not applied), read from the shifted sums without that
 * cancellation. Within (2N + 16) eps (1/K^2) sum_{m,n} |f_m| |f_n|
 * (|<d_m d_n>| + |<d_m>| |<d_n>|) + 3 (MCS_MOMENT_BATCH + 64) eps (1/K^2)
 * (sum_m |f_m| sqrt(<d_m^2>))^2 of the exact value (the read-out, then the
 * sums: see above); never negative: a value below 0 within that reads 0,
 * one below it is MCS_ERR_INVARIANT. Arguments and statuses as
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
