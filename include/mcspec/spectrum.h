/* The Welford spectrum accumulator (eq. 7, 13, 14). Per trial it forms
 * S_k = N^{-1/2} sum_n e^{-2 pi i k n/N} s_n and updates, per frequency, the
 * running mean of S_k (complex) with the sum of |S_k - mean|^2, and the
 * running mean and M2 of |S_k|^2; so it reports <S_k>, <|S_k|^2> and the
 * standard error of each. Welford rather than sums of powers: <|S_0|^2> is
 * K^2/N while its variance may be tiny, and sums of squares would cancel.
 *
 * s is real, so S_{N-k} = conj(S_k): only k = 0..N/2 are computed and stored;
 * read-outs for k > N/2 are served by symmetry.
 *
 * Two ways to compute S_k from a trial of K (bin, weight) pairs, giving the
 * same numbers to rounding:
 * - sparse: S_k = N^{-1/2} sum_j w_j e^{-2 pi i k n_j/N} from the plan's
 *   twiddle table, O(K N);
 * - FFT: scatter into a dense s, then mcs_dft_real_half, O(N log N).
 * MCS_SPECTRUM_PATH_AUTO picks the cheaper one per trial from K and N.
 *
 * Size: sizeof(mcs_spectrum) is the embedded mcs_dft (about 64 * MCS_MAX_N
 * bytes) plus 7 * MCS_SPECTRUM_HALF + MCS_MAX_N doubles of statistics and
 * scratch: about 100 * MCS_MAX_N bytes in all (410 280 at the default 4096 on
 * x86-64, 26 280 at MCS_MAX_N = 256; shrink it with -DMCS_MAX_N=...). It holds
 * no pointers, so it may be copied. */
#ifndef MCSPEC_SPECTRUM_H
#define MCSPEC_SPECTRUM_H

#include <stddef.h>
#include <stdint.h>
#include "config.h"
#include "status.h"
#include "dft.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Stored frequencies k = 0..MCS_MAX_N/2, rounded up to an even count so the
 * per-frequency update can run two frequencies at a time (the pad stays 0). */
#define MCS_SPECTRUM_HALF (((MCS_MAX_N) / 2 + 2) / 2 * 2)

/* How a sparse trial is transformed. */
typedef enum {
    MCS_SPECTRUM_PATH_AUTO = 0,   /* cheaper of the two, chosen per trial (the default) */
    MCS_SPECTRUM_PATH_SPARSE = 1, /* always the O(K N) twiddle-table sum */
    MCS_SPECTRUM_PATH_FFT = 2     /* always dense s through mcs_dft_real_half */
} mcs_spectrum_path;

typedef struct {
    size_t n;                            /* N; 0 before init */
    uint64_t count;                      /* trials added */
    mcs_spectrum_path path;              /* path policy, AUTO after init */
    size_t sparse_max_k;                 /* AUTO takes the sparse path for k <= this */
    mcs_dft plan;                        /* DFT plan for N, twiddle table shared with the sparse path */
    double mean_re[MCS_SPECTRUM_HALF];   /* running mean of Re S_k */
    double mean_im[MCS_SPECTRUM_HALF];   /* running mean of Im S_k */
    double m2_s[MCS_SPECTRUM_HALF];      /* sum over trials of |S_k - mean|^2 (Welford) */
    double mean_pow[MCS_SPECTRUM_HALF];  /* running mean of |S_k|^2 */
    double m2_pow[MCS_SPECTRUM_HALF];    /* Welford M2 of |S_k|^2 */
    double s[MCS_MAX_N];                 /* scratch: dense s of the current trial */
    double re[MCS_SPECTRUM_HALF];        /* scratch: S_k of the current trial */
    double im[MCS_SPECTRUM_HALF];
} mcs_spectrum;

/* Empties the accumulator and builds its plan for n bins.
 * MCS_ERR_NULL, MCS_ERR_N_RANGE (n = 0 or n > MCS_MAX_N). *acc untouched on error. */
mcs_status mcs_spectrum_init(mcs_spectrum *acc, size_t n);

/* Chooses the path for later sparse trials (tests and benches force one).
 * MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_KIND (unknown path). */
mcs_status mcs_spectrum_set_path(mcs_spectrum *acc, mcs_spectrum_path path);

/* Adds one trial in sparse form, e.g. from mcs_pattern_draw: s_n is the sum
 * of weights[j] over the j with bins[j] = n (eq. 38). bins[k] in [0, N),
 * weights[k] finite and >= 0. MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_K_RANGE
 * (k = 0), MCS_ERR_BIN_RANGE, MCS_ERR_NOT_FINITE, MCS_ERR_NEGATIVE.
 * *acc untouched on error. */
mcs_status mcs_spectrum_add_bins(mcs_spectrum *acc, size_t k, const size_t *bins,
                                 const double *weights);

/* Adds one trial given densely: s[n], n equal to the accumulator's N, values
 * finite and >= 0. Always the FFT path. MCS_ERR_NULL, MCS_ERR_UNINIT,
 * MCS_ERR_MISMATCH (n), MCS_ERR_NOT_FINITE, MCS_ERR_NEGATIVE. *acc untouched on error. */
mcs_status mcs_spectrum_add_dense(mcs_spectrum *acc, size_t n, const double *s);

/* Adds one trial of caller points (a renderer's own samples): points[k] in
 * [0,1) land in bin floor(N x); weights[k] finite and >= 0, or NULL for all 1
 * (pass 1/p of the bin under importance sampling). MCS_ERR_NULL,
 * MCS_ERR_UNINIT, MCS_ERR_K_RANGE (k = 0), MCS_ERR_POINT_RANGE,
 * MCS_ERR_NOT_FINITE, MCS_ERR_NEGATIVE. *acc untouched on error. */
mcs_status mcs_spectrum_add_points(mcs_spectrum *acc, size_t k, const double *points,
                                   const double *weights);

/* dst <- dst union src (Chan et al.): the same statistics as one pass over
 * both trial streams, to rounding. src unchanged; dst == src is allowed.
 * MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_MISMATCH (different N). dst untouched on error. */
mcs_status mcs_spectrum_merge(mcs_spectrum *dst, const mcs_spectrum *src);

/* Number of trials added. MCS_ERR_NULL, MCS_ERR_UNINIT. */
mcs_status mcs_spectrum_count(const mcs_spectrum *acc, uint64_t *count);

/* <S_k> for freq in [0, N) (eq. 15 measured). MCS_ERR_NULL, MCS_ERR_UNINIT,
 * MCS_ERR_FREQ_RANGE, MCS_ERR_EMPTY (no trials). Outputs untouched on error. */
mcs_status mcs_spectrum_mean(const mcs_spectrum *acc, size_t freq, double *re, double *im);

/* Standard error of <S_k>: sqrt(E|S_k - <S_k>|^2 / (T - 1) / T), the complex
 * spread (real and imaginary parts together). MCS_ERR_EMPTY for < 2 trials;
 * otherwise as mcs_spectrum_mean. */
mcs_status mcs_spectrum_mean_stderr(const mcs_spectrum *acc, size_t freq, double *stderr_out);

/* <|S_k|^2> for freq in [0, N): the power spectrum (eq. 14, 23).
 * Statuses as mcs_spectrum_mean. */
mcs_status mcs_spectrum_power(const mcs_spectrum *acc, size_t freq, double *power);

/* Standard error of <|S_k|^2>. MCS_ERR_EMPTY for < 2 trials. */
mcs_status mcs_spectrum_power_stderr(const mcs_spectrum *acc, size_t freq, double *stderr_out);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_SPECTRUM_H */
