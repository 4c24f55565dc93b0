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
 * Every call below but size, init and the _exact_ ones returns
 * MCS_ERR_INVARIANT, changing nothing, for an accumulator holding values no
 * calls produce (its buffer overwritten), checked where read: a count above
 * MCS_MAX_COUNT or a head that no longer says N1, N2 (every call); a twiddle outside [-1, 1] or NaN (transform, add, merge); a
 * statistic NaN or beyond what trials within MCS_SPECTRUM_MAX_SUM give,
 * |<S_k>| above 2^101, <|S_k|^2> outside [0, 2^202], an M2 negative or above
 * (count - 1) 2^204 (of S_k) or 2^404 (of |S_k|^2), any value with no
 * trials (the read-outs at k, O(1); add, merge and variance14 check every
 * cell, O(N1 N2), and the pad column, which stays 0).
 *
 * Memory: a fixed header (mcs_spectrum2d) over a buffer the caller owns,
 * asked for in two calls (mcs_spectrum2d_size, then mcs_spectrum2d_init)
 * or declared statically with MCS_SPECTRUM2D_SIZE(N1, N2): about
 * 28 N1 N2 bytes (seven arrays over the stored half plane, five of them
 * statistics) plus the twiddles and per-point rows. Any alignment; the
 * buffer must outlive the object, untouched by anything else. The trial
 * count lives in the buffer with the statistics. A copy of the header
 * shares the buffer (so two such copies must never be used at once);
 * mcs_spectrum2d_copy makes an independent object.
 *
 * Caps: N1 and N2 from 1 to MCS_SPECTRUM2D_MAX_SIDE = 4096 (a 470 MB buffer
 * at 4096 x 4096, so it fits a 32-bit size_t); a point costs O(N1 N2 / 2). */
#ifndef MCSPEC_SPECTRUM2D_H
#define MCSPEC_SPECTRUM2D_H

#include <stddef.h>
#include <stdint.h>
#include "status.h"
#include "pattern2d.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Largest N1 and N2. */
#define MCS_SPECTRUM2D_MAX_SIDE 4096

/* Bytes of buffer for N1 x N2 bins (each 1..MAX_SIDE), as a constant
 * expression for a static buffer: exactly what mcs_spectrum2d_size
 * reports. Stored rows k2 = 0..N2/2, each padded to an even length for the
 * kernel; every array starts on 64 bytes, plus 63 for the buffer's own
 * alignment. */
#define MCS_SPECTRUM2D_RUP_(b) (((size_t)(b) + 63u) / 64u * 64u)
#define MCS_SPECTRUM2D_STRIDE_(nx) ((size_t)(nx) + (size_t)(nx) % 2u)
#define MCS_SPECTRUM2D_CELLS_(nx, ny) (MCS_SPECTRUM2D_STRIDE_(nx) * ((size_t)(ny) / 2u + 1u))
#define MCS_SPECTRUM2D_ROW_(nx, ny)                                                        \
    (MCS_SPECTRUM2D_STRIDE_(nx) > (size_t)(ny) / 2u + 1u ? MCS_SPECTRUM2D_STRIDE_(nx)      \
                                                         : (size_t)(ny) / 2u + 1u)
#define MCS_SPECTRUM2D_SIZE(nx, ny)                                                        \
    (63u + 64u + 7u * MCS_SPECTRUM2D_RUP_(8u * MCS_SPECTRUM2D_CELLS_(nx, ny)) +            \
     2u * MCS_SPECTRUM2D_RUP_(8u * (size_t)(nx)) + 2u * MCS_SPECTRUM2D_RUP_(8u * (size_t)(ny)) + \
     MCS_SPECTRUM2D_RUP_(128u * MCS_SPECTRUM2D_ROW_(nx, ny)))

/* The head of the statistics, at the first 64-byte boundary of the buffer:
 * N1, N2 and the trials added. */
typedef struct {
    size_t shape[2];
    uint64_t count;
} mcs_spectrum2d_head;

/* The header: set by mcs_spectrum2d_init, read-only to the caller. The
 * pointers go into the caller's buffer; stored wave vector (k1, k2) at
 * [k2 stride + k1], stride N1 rounded up to even. */
typedef struct {
    size_t n_x, n_y;               /* N1, N2; 0 before init */
    int wrap;                      /* mcs_spectrum2d_set_wrap (0 after init) */
    void *mem;                     /* the caller's buffer, as given */
    size_t bytes;                  /* bytes of it in use from mem (the size query's) */
    mcs_spectrum2d_head *state;    /* the first 64-byte boundary in mem: N1, N2, trials added */
    double *mean_re, *mean_im;     /* running mean of S_k */
    double *m2_s;                  /* Welford sum of |S_k - mean|^2 */
    double *mean_pow, *m2_pow;     /* running mean of |S_k|^2 and its Welford M2 */
    double *cos_x, *sin_x;         /* cos, sin (2 pi t / N1) */
    double *cos_y, *sin_y;         /* cos, sin (2 pi t / N2) */
    double *re, *im;               /* scratch: S_k of the current trial */
    double *rows;                  /* scratch: per-point twiddle rows */
    uintptr_t key;                 /* a hash of the fields above, set by init and set_wrap */
} mcs_spectrum2d;

/* Bytes of buffer mcs_spectrum2d_init needs for n_x x n_y bins, into *bytes
 * (MCS_SPECTRUM2D_SIZE(n_x, n_y) exactly). MCS_ERR_NULL, MCS_ERR_N_RANGE (a
 * side 0 or above MCS_SPECTRUM2D_MAX_SIDE). *bytes untouched on error. */
mcs_status mcs_spectrum2d_size(size_t n_x, size_t n_y, size_t *bytes);

/* Empties the accumulator for n_x x n_y bins over mem[bytes] (any
 * alignment; bytes at least what mcs_spectrum2d_size reports), wrap off,
 * and builds its twiddles. Statuses as mcs_spectrum2d_size, and
 * MCS_ERR_NULL (acc, mem), MCS_ERR_SPACE (bytes too small), MCS_ERR_ALIAS
 * (mem overlaps *acc). On error neither *acc nor mem changes. */
mcs_status mcs_spectrum2d_init(mcs_spectrum2d *acc, size_t n_x, size_t n_y, void *mem,
                               size_t bytes);

/* *dst <- an independent copy of src (same N1, N2, wrap and statistics)
 * over mem[bytes], as mcs_spectrum2d_init would set it up there. src
 * unchanged; dst == src is allowed (the object moves to mem). MCS_ERR_NULL,
 * MCS_ERR_UNINIT, MCS_ERR_INVARIANT (src's count), MCS_ERR_SPACE,
 * MCS_ERR_ALIAS (mem overlaps *dst, *src or src's buffer). *dst and mem
 * untouched on error. */
mcs_status mcs_spectrum2d_copy(mcs_spectrum2d *dst, void *mem, size_t bytes,
                               const mcs_spectrum2d *src);

/* Wrap (1) or not (0, after init) the point 1.0: with wrap on, a coordinate
 * of exactly 1.0 falls in bin 0 (pointset.h: mcs_pointset_set_wrap).
 * MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_INVARIANT, MCS_ERR_DOMAIN (wrap not
 * 0 or 1). */
mcs_status mcs_spectrum2d_set_wrap(mcs_spectrum2d *acc, int wrap);

/* Adds one trial of points[2 k] (x_0, y_0, ...) in [0,1)^2 (or [0, 1]^2
 * with wrap), binned at (floor(N1 x), floor(N2 y)); weights[k] finite and
 * >= 0 (1/p of the bin under importance sampling), or NULL for all 1,
 * summing to at most MCS_SPECTRUM_MAX_SUM (2^100, as in spectrum.h: no
 * square or fourth power of the statistics can then overflow).
 * MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_INVARIANT (above), MCS_ERR_COUNT
 * (the count at MCS_MAX_COUNT), MCS_ERR_K_RANGE (k = 0), MCS_ERR_ALIAS
 * (points or weights inside the object's header or buffer),
 * MCS_ERR_POINT_RANGE, MCS_ERR_NOT_FINITE, MCS_ERR_NEGATIVE,
 * MCS_ERR_MAGNITUDE (a sum above the bound). On error neither *acc nor its
 * buffer changes. */
mcs_status mcs_spectrum2d_add_points(mcs_spectrum2d *acc, size_t k, const double *points,
                                     const double *weights);

/* mcs_spectrum2d_add_points for float points, read in place: each
 * coordinate widens to double exactly, so the statistics are bit-equal to
 * the double call's on the widened points (a float just below 1.0f is in
 * [0,1); 1.0f is not). Statuses as mcs_spectrum2d_add_points. */
mcs_status mcs_spectrum2d_add_points_f(mcs_spectrum2d *acc, size_t k, const float *points,
                                       const double *weights);

/* The same trial as planar arrays: point j is (x[j], y[j]). Bit-equal to
 * mcs_spectrum2d_add_points (or _f) of the interleaved points. Statuses as
 * mcs_spectrum2d_add_points (MCS_ERR_NULL for x or y). */
mcs_status mcs_spectrum2d_add_points_planar(mcs_spectrum2d *acc, size_t k, const double *x,
                                            const double *y, const double *weights);
mcs_status mcs_spectrum2d_add_points_planar_f(mcs_spectrum2d *acc, size_t k, const float *x,
                                              const float *y, const double *weights);

/* dst <- dst union src (Chan et al.); src unchanged; dst == src allowed
 * (doubles the count, the same means). MCS_ERR_NULL, MCS_ERR_UNINIT,
 * MCS_ERR_INVARIANT (above), MCS_ERR_MISMATCH (different N1 or N2),
 * MCS_ERR_COUNT (the counts would pass MCS_MAX_COUNT), MCS_ERR_ALIAS
 * (distinct objects whose headers or buffers overlap). dst untouched on
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
 * not whole blocks of bins), MCS_ERR_N_RANGE (a side 0 or above
 * MCS_SPECTRUM2D_MAX_SIDE), MCS_ERR_FREQ_RANGE. */
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
