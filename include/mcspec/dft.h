/* The normalised DFT of eq. 7, S_k = N^{-1/2} sum_n e^{-2 pi i k n/N} s_n,
 * of a real s, for every N from 1 to MCS_MAX_N, without allocating.
 *
 * Paths, chosen at init from the factorisation of N (see mcs_dft_path):
 * N <= 2 is done by hand; even N whose half has only the factors 2, 3, 5 packs
 * s into N/2 complex values, runs KissFFT's complex transform of size N/2 and
 * untangles the real spectrum (what kiss_fftr does, but holding no pointers, so
 * a plan can be copied); odd N with only the factors 3, 5 runs the complex
 * KissFFT of size N; any N with a prime factor above 5 (where KissFFT would
 * allocate scratch) uses a direct sum over the non-zero s_n with a twiddle
 * table: O(N * nnz), exact index reduction, no allocation.
 *
 * Size: sizeof(mcs_dft) is about 64 * MCS_MAX_N bytes (262 680 at the default
 * 4096 on x86-64, 16 920 at MCS_MAX_N = 256): the twiddle table (2 * MCS_MAX_N
 * doubles), KissFFT's state (MCS_DFT_KISS_DOUBLES) and complex scratch
 * (4 * MCS_MAX_N doubles, all of it needed by odd N). */
#ifndef MCSPEC_DFT_H
#define MCSPEC_DFT_H

#include <stddef.h>
#include "config.h"
#include "status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Algorithm a plan uses (chosen by mcs_dft_init, reported for tests and benches). */
typedef enum {
    MCS_DFT_PATH_NONE = 0,         /* not initialised */
    MCS_DFT_PATH_TRIVIAL = 1,      /* N = 1 or 2, by hand */
    MCS_DFT_PATH_KISS_REAL = 2,    /* even N, N/2 is 2,3,5-smooth and >= 2: complex KissFFT of N/2 */
    MCS_DFT_PATH_KISS_COMPLEX = 3, /* odd N, 3,5-smooth: complex KissFFT of N */
    MCS_DFT_PATH_DIRECT = 4        /* a prime factor above 5: direct sum with the twiddle table */
} mcs_dft_path;

/* Upper bound, in doubles, on KissFFT's state for a complex transform of any
 * size up to MCS_MAX_N: its header (under 300 bytes) plus one complex twiddle
 * per point. mcs_dft_init checks it against KissFFT's own size query. */
#define MCS_DFT_KISS_DOUBLES (64 + 2 * (MCS_MAX_N))

/* A DFT plan. Caller-owned; holds no pointers (a copy is a working plan).
 * Fields are read by the spectrum module; treat them as read-only. */
typedef struct {
    size_t n;                                /* N, 1..MCS_MAX_N; 0 before init */
    size_t fft_len;                          /* length of the KissFFT transform (0 if none) */
    mcs_dft_path path;                       /* algorithm for this N */
    double cos_table[MCS_MAX_N];             /* cos(2 pi j / N), j < N */
    double sin_table[MCS_MAX_N];             /* sin(2 pi j / N), j < N */
    double kiss_state[MCS_DFT_KISS_DOUBLES]; /* KissFFT cfg, placed by the two-call size query */
    double work[4 * (MCS_MAX_N)];            /* complex scratch: input and output buffers */
} mcs_dft;

/* Prepares a plan for n points. MCS_ERR_NULL, MCS_ERR_N_RANGE (n = 0 or
 * n > MCS_MAX_N, or KissFFT asks for more state than the plan reserves).
 * *plan untouched on error. */
mcs_status mcs_dft_init(mcs_dft *plan, size_t n);

/* MCS_OK if plan was set up by mcs_dft_init for n points (lets a caller
 * validate before writing anything). MCS_ERR_NULL, MCS_ERR_UNINIT,
 * MCS_ERR_MISMATCH (n != plan n). */
mcs_status mcs_dft_check(const mcs_dft *plan, size_t n);

/* All n frequencies of eq. 7: re[k] + i im[k] = S_k, k = 0..n-1, with
 * S_{n-k} = conj(S_k) exactly. s[n]: finite reals (any sign). re[n] written;
 * im[n] written unless im is NULL. s may be the same array as re or im (but
 * must not point into plan->work, the plan's own scratch).
 * MCS_ERR_NULL (plan, s, re), MCS_ERR_UNINIT, MCS_ERR_MISMATCH (n != plan n),
 * MCS_ERR_NOT_FINITE. On error neither outputs nor the plan change. */
mcs_status mcs_dft_real(mcs_dft *plan, size_t n, const double *s, double *re, double *im);

/* The non-redundant half: S_k for k = 0..n/2 (integer division), the rest
 * being their conjugates. s[n]; re[n/2 + 1], im[n/2 + 1] written (im may be
 * NULL). s may alias re or im. Statuses as mcs_dft_real. */
mcs_status mcs_dft_real_half(mcs_dft *plan, size_t n, const double *s, double *re, double *im);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_DFT_H */
