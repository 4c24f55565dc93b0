/* The note's binned framework in 2D: N = N1 x N2 bins (N1 = n_x columns
 * along x, N2 = n_y rows along y), s_n the weighted count of samples in bin
 * n = (n1, n2), and eq. 7 with the 2D DFT,
 *     S_k = N^{-1/2} sum_n e^{-2 pi i (k1 n1 / N1 + k2 n2 / N2)} s_n,
 * so that eq. 8 still reads I = (1/K) sum_n f_n s_n = (1/K) sum_k F_k^* S_k.
 *
 * The accumulator keeps, per wave vector, the running mean of S_k (complex)
 * and of |S_k|^2 with standard errors (Welford; Chan merge). s is real, so
 * S_{-k} = conj(S_k): rows k2 = 0..N2/2 are stored and read-outs for other
 * k2 are served by symmetry. A trial is added from its points (binned at
 * floor(N1 x), floor(N2 y)) as an outer product of two twiddle rows per
 * point, four points at a time: O(K N1 N2 / 2).
 *
 * Arrays over all wave vectors (f_re, f_im, and the output of
 * mcs_spectrum2d_transform) are full N1 x N2 planes indexed [k2 N1 + k1],
 * like caller arrays over bins, [n2 N1 + n1].
 *
 * Exact theory (the _exact_ calls) covers the 2D patterns whose binned
 * second moments have a closed form: random (any N1, N2), and jittered and
 * shifted grid when the strata are whole blocks of bins (m | N1, n | N2):
 *   random        Cov(S_k, S_l) = (K/N) (d_kl - d_k0 d_l0)
 *   jittered      Cov(S_k, S_l) = (K/N) d_kl - (K/N)^3 A(k) A(l)^* [k = l mod (m, n)]
 *                 A(k) = sum over one stratum's a x b bins u of
 *                 e^{-2 pi i (k1 u1/N1 + k2 u2/N2)}, a = N1/m, b = N2/n
 *   shifted grid  Cov(S_k, S_l) = (K^2/N) d_kl [m | k1, n | k2] - (K^2/N) d_k0 d_l0
 * with <S_k> = (K/sqrt N) d_k0 for all three (unbiased). The jittered pattern
 * is not stationary (its strata are fixed): its exact Var[I] needs the
 * cross terms (the 2D eq. 13), and eq. 14 with its power spectrum is only an
 * approximation; random and shifted grid are stationary and eq. 14 is exact.
 *
 * Every call below but init and the _exact_ ones returns MCS_ERR_INVARIANT,
 * changing nothing, for an accumulator holding values no calls produce
 * (overwritten), checked where read: a count above MCS_MAX_COUNT (every
 * call); a twiddle outside [-1, 1] or NaN (transform, add, merge); a
 * statistic NaN or beyond what trials within MCS_SPECTRUM_MAX_SUM give,
 * |<S_k>| above 2^101, <|S_k|^2> outside [0, 2^202], an M2 negative or above
 * (count - 1) 2^204 (of S_k) or 2^404 (of |S_k|^2), any value with no
 * trials (the read-outs at k, O(1); add, merge and variance14 check every
 * cell, O(N1 N2), and the pad column, which stays 0).
 *
 * Size: sizeof(mcs_spectrum2d) is 24 + 56 S (S/2 + 1) + 160 S bytes with
 * S = MCS_MAX_SIDE rounded up to even (x86-64): 128 536 at the default 64,
 * 35 608 at 32. It holds no pointers, so it may be copied. */
#ifndef MCSPEC_SPECTRUM2D_H
#define MCSPEC_SPECTRUM2D_H

#include <stddef.h>
#include <stdint.h>
#include "config.h" /* MCS_MAX_SIDE, the largest N1 and N2 */
#include "status.h"
#include "pattern2d.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Stored rows k2 = 0..N2/2, each padded to an even length for the kernel. */
#define MCS_SPECTRUM2D_STRIDE ((MCS_MAX_SIDE) + (MCS_MAX_SIDE) % 2)
#define MCS_SPECTRUM2D_CELLS (MCS_SPECTRUM2D_STRIDE * ((MCS_MAX_SIDE) / 2 + 1))

typedef struct {
    size_t n_x, n_y;                            /* N1, N2; 0 before init */
    uint64_t count;                             /* trials added */
    double mean_re[MCS_SPECTRUM2D_CELLS];       /* running mean of Re S_k, [k2 stride + k1] */
    double mean_im[MCS_SPECTRUM2D_CELLS];       /* running mean of Im S_k */
    double m2_s[MCS_SPECTRUM2D_CELLS];          /* Welford sum of |S_k - mean|^2 */
    double mean_pow[MCS_SPECTRUM2D_CELLS];      /* running mean of |S_k|^2 */
    double m2_pow[MCS_SPECTRUM2D_CELLS];        /* Welford M2 of |S_k|^2 */
    double re[MCS_SPECTRUM2D_CELLS];            /* scratch: S_k of the current trial */
    double im[MCS_SPECTRUM2D_CELLS];
    double cos_x[MCS_MAX_SIDE], sin_x[MCS_MAX_SIDE]; /* cos, sin (2 pi t / N1) */
    double cos_y[MCS_MAX_SIDE], sin_y[MCS_MAX_SIDE]; /* cos, sin (2 pi t / N2) */
    double rows[4][4][MCS_SPECTRUM2D_STRIDE];   /* scratch: per-point twiddle rows */
} mcs_spectrum2d;

/* Empties the accumulator for n_x x n_y bins and builds its twiddles.
 * MCS_ERR_NULL, MCS_ERR_N_RANGE (a side 0 or above MCS_MAX_SIDE). *acc
 * untouched on error. */
mcs_status mcs_spectrum2d_init(mcs_spectrum2d *acc, size_t n_x, size_t n_y);

/* Adds one trial of points[2 k] (x_0, y_0, ...) in [0,1)^2, binned at
 * (floor(N1 x), floor(N2 y)); weights[k] finite and >= 0 (1/p of the bin
 * under importance sampling), or NULL for all 1, summing to at most
 * MCS_SPECTRUM_MAX_SUM (2^100, as in spectrum.h: no square or fourth power
 * of the statistics can then overflow). MCS_ERR_NULL, MCS_ERR_UNINIT,
 * MCS_ERR_K_RANGE (k = 0), MCS_ERR_COUNT (the count at MCS_MAX_COUNT),
 * MCS_ERR_POINT_RANGE, MCS_ERR_NOT_FINITE, MCS_ERR_NEGATIVE,
 * MCS_ERR_MAGNITUDE (a sum above the bound). *acc untouched on error. */
mcs_status mcs_spectrum2d_add_points(mcs_spectrum2d *acc, size_t k, const double *points,
                                     const double *weights);

/* mcs_spectrum2d_add_points for float points, read in place: each
 * coordinate widens to double exactly, so the statistics are bit-equal to
 * the double call's on the widened points (a float just below 1.0f is in
 * [0,1); 1.0f is not). Statuses as mcs_spectrum2d_add_points. */
mcs_status mcs_spectrum2d_add_points_f(mcs_spectrum2d *acc, size_t k, const float *points,
                                       const double *weights);

/* dst <- dst union src (Chan et al.); src unchanged; dst == src allowed
 * (doubles the count, the same means). MCS_ERR_NULL, MCS_ERR_UNINIT,
 * MCS_ERR_INVARIANT (above), MCS_ERR_MISMATCH (different N1 or N2),
 * MCS_ERR_COUNT (the counts would pass MCS_MAX_COUNT), MCS_ERR_ALIAS (src
 * and dst overlapping without being the same object). dst untouched on
 * error. */
mcs_status mcs_spectrum2d_merge(mcs_spectrum2d *dst, const mcs_spectrum2d *src);

/* Trials added. MCS_ERR_NULL, MCS_ERR_UNINIT. */
mcs_status mcs_spectrum2d_count(const mcs_spectrum2d *acc, uint64_t *count);

/* <S_k> at k = (freq_k, freq_l), freq_k in [0, N1), freq_l in [0, N2).
 * MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_FREQ_RANGE, MCS_ERR_EMPTY,
 * MCS_ERR_ALIAS (re == im). Outputs untouched on error. */
mcs_status mcs_spectrum2d_mean(const mcs_spectrum2d *acc, size_t freq_k, size_t freq_l,
                               double *re, double *im);

/* <|S_k|^2>, and the standard errors of <|S_k|^2> and of <S_k> (complex
 * spread; MCS_ERR_EMPTY for < 2 trials). Statuses as mcs_spectrum2d_mean. */
mcs_status mcs_spectrum2d_power(const mcs_spectrum2d *acc, size_t freq_k, size_t freq_l,
                                double *out);
mcs_status mcs_spectrum2d_power_stderr(const mcs_spectrum2d *acc, size_t freq_k, size_t freq_l,
                                       double *out);
mcs_status mcs_spectrum2d_mean_stderr(const mcs_spectrum2d *acc, size_t freq_k, size_t freq_l,
                                      double *out);

/* The 2D eq. 7 of a real caller array: s[N1 N2] over bins [n2 N1 + n1] in,
 * re[N1 N2], im[N1 N2] over wave vectors [k2 N1 + k1] out (im may not be
 * NULL). Uses acc's twiddles only (acc is not changed). s, re and im must not
 * overlap (MCS_ERR_ALIAS), and the |s_n| sum to at most MCS_DFT_MAX_ABS_SUM
 * (else MCS_ERR_MAGNITUDE), so the outputs are finite. MCS_ERR_NULL,
 * MCS_ERR_UNINIT, MCS_ERR_NOT_FINITE. Outputs untouched on error. */
mcs_status mcs_spectrum2d_transform(const mcs_spectrum2d *acc, const double *s, double *re,
                                    double *im);

/* Eq. 14 in 2D from the measured power spectrum:
 * (1/K^2) sum_{k != 0} |F_k|^2 <|S_k|^2>, F = f_re + i f_im the transform of
 * the caller's f (full planes, as from mcs_spectrum2d_transform). Exact for
 * stationary patterns only. MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_K_RANGE
 * (k = 0), MCS_ERR_EMPTY, MCS_ERR_NOT_FINITE (f not finite),
 * MCS_ERR_MAGNITUDE (F so large that the result overflows: refused, never
 * returned as infinity). */
mcs_status mcs_spectrum2d_variance14(const mcs_spectrum2d *acc, size_t k, const double *f_re,
                                     const double *f_im, double *out);

/* Exact <S_k> and <|S_k|^2> of pattern pat on n_x x n_y bins (see above).
 * MCS_ERR_NULL, MCS_ERR_UNINIT (pat not from mcs_pattern2d_init),
 * MCS_ERR_KIND (grid, n-rooks, multi-jittered, cmj), MCS_ERR_DOMAIN (strata
 * not whole blocks of bins), MCS_ERR_N_RANGE, MCS_ERR_FREQ_RANGE. */
mcs_status mcs_spectrum2d_exact_mean(const mcs_pattern2d *pat, size_t n_x, size_t n_y,
                                     size_t freq_k, size_t freq_l, double *re, double *im);
mcs_status mcs_spectrum2d_exact_power(const mcs_pattern2d *pat, size_t n_x, size_t n_y,
                                      size_t freq_k, size_t freq_l, double *out);

/* Exact Cov(S_k, S_l) = <S_k S_l^*> - <S_k><S_l>^*, k = (k1, k2), l = (l1, l2).
 * Statuses as mcs_spectrum2d_exact_power, and MCS_ERR_ALIAS (re == im). */
mcs_status mcs_spectrum2d_exact_covariance(const mcs_pattern2d *pat, size_t n_x, size_t n_y,
                                           size_t k1, size_t k2, size_t l1, size_t l2,
                                           double *re, double *im);

/* Exact Var[I] of I = (1/K) sum_n f_n s_n from the spectrum, the 2D eq. 13
 * with every k, l: (1/K^2) sum_{k,l} F_k^* F_l Cov(S_k, S_l), in O(N) by the
 * structure above. f_re, f_im: full planes (mcs_spectrum2d_transform of f).
 * Statuses as mcs_spectrum2d_exact_power, MCS_ERR_NOT_FINITE (f not
 * finite) and MCS_ERR_MAGNITUDE (f so large that the result overflows). */
mcs_status mcs_spectrum2d_exact_variance(const mcs_pattern2d *pat, size_t n_x, size_t n_y,
                                         const double *f_re, const double *f_im, double *out);

/* Eq. 14 with the exact power spectrum: (1/K^2) sum_{k != 0} |F_k|^2 <|S_k|^2>.
 * Equal to mcs_spectrum2d_exact_variance for random and shifted grid; for
 * jittered it leaves out the cross terms. Statuses as
 * mcs_spectrum2d_exact_variance. */
mcs_status mcs_spectrum2d_exact_variance14(const mcs_pattern2d *pat, size_t n_x, size_t n_y,
                                           const double *f_re, const double *f_im, double *out);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_SPECTRUM2D_H */
