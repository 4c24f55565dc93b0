/* The normalised DFT of eq. 7, S_k = N^{-1/2} sum_n e^{-2 pi i k n/N} s_n,
 * of a real s, for every N from 1 to MCS_MAX_N.
 *
 * Two back ends behind the same calls, chosen when the library is built:
 *
 * - KissFFT (the default, and the only one for embedded builds): nothing
 *   allocates. Paths, chosen at init from the factorisation of N (see
 *   mcs_dft_path): N <= 2 is done by hand; even N whose half has only the
 *   factors 2, 3, 5 packs s into N/2 complex values, runs KissFFT's complex
 *   transform of size N/2 and untangles the real spectrum (what kiss_fftr
 *   does, but holding no pointers, so a plan can be copied); odd N with only
 *   the factors 3, 5 runs the complex KissFFT of size N; any N with a prime
 *   factor above 5 (where KissFFT would allocate scratch) uses a direct sum
 *   over the non-zero s_n with a twiddle table: O(N * nnz), exact index
 *   reduction, by the block-phase kernel (one table read per non-zero bin
 *   and block of 8 frequencies; baseline and AVX2 copies, same bits).
 *
 * - FFTW 3 (hosted builds only: `make FFT=fftw`, or -DMCSPEC_FFT=fftw with
 *   CMake; link -lfftw3): every N >= 3 runs FFTW's r2c transform. FFTW
 *   allocates its plan, once per N per process, the first time an mcs_dft
 *   is initialised for that N (planned with FFTW_MEASURE, under a lock, and
 *   kept for the life of the process); mcs_dft_real and mcs_dft_real_half
 *   never allocate. mcs_dft_init is then the one call that may allocate,
 *   and it is as thread-safe as FFTW's planner under that lock; transforms
 *   are thread-safe on distinct plans. FFTW is licensed under the GNU GPL
 *   (v2 or later): a program linked with an mcspec built this way is
 *   covered by the GPL unless it holds a commercial FFTW licence. mcspec
 *   itself (MIT) and its default build are not affected.
 *
 * Either way an mcs_dft holds no pointers: a copy is a working plan.
 *
 * Size: sizeof(mcs_dft) is about 64 * MCS_MAX_N bytes plus 8 KiB (271 936 at
 * the default 4096 on x86-64, 25 656 at MCS_MAX_N = 256 on Cortex-M, make
 * sizes): the twiddle table (2 * MCS_MAX_N
 * doubles), KissFFT's state (MCS_DFT_KISS_DOUBLES), complex scratch
 * (4 * MCS_MAX_N doubles, all of it needed by odd N) and the direct path's
 * block-phase scratch (18 * MCS_DFT_CHUNK words). */
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
    MCS_DFT_PATH_DIRECT = 4,       /* a prime factor above 5: direct sum with the twiddle table */
    MCS_DFT_PATH_FFTW = 5          /* FFTW back end, N >= 3: FFTW's r2c plan for N */
} mcs_dft_path;

/* Upper bound, in doubles, on KissFFT's state for a complex transform of any
 * size up to MCS_MAX_N: its header (under 300 bytes) plus one complex twiddle
 * per point. mcs_dft_init checks it against KissFFT's own size query. */
#define MCS_DFT_KISS_DOUBLES (64 + 2 * (MCS_MAX_N))

/* Non-zero bins the direct path takes per pass of its block-phase kernel
 * (and samples the spectrum's sparse path does). A pass sums its bins from
 * 0 and adds the sums to the output, so the chunk decides the rounding:
 * fixed, not following MCS_MAX_N (it was 16 below 1024), so that the same
 * data give the same bits, and the same records, at every capacity; 64, the
 * default build's, keeps its speed and its bits. */
#define MCS_DFT_CHUNK 64

/* Largest accepted sum of |s_n| over one input (2^1020, about 1.12e307): no
 * partial sum of the transform can then overflow, so a finite input always
 * gives a finite output. */
#define MCS_DFT_MAX_ABS_SUM 0x1p1020

/* A DFT plan. Caller-owned; holds no pointers (a copy is a working plan).
 * Fields are read by the spectrum module; treat them as read-only. */
typedef struct {
    size_t n;                                /* N, 1..MCS_MAX_N; 0 before init */
    size_t fft_len;                          /* length of the KissFFT transform (0 if none) */
    mcs_dft_path path;                       /* algorithm for this N */
    int simd;                                /* kernels: 0 baseline, 1 AVX2 (x86-64, set by init;
                                                both give the same bits) */
    /* The header fills 64 bytes (on 64-bit targets), so the arrays below
     * start at a multiple of 64 from the object (and, with MCS_MAX_N a
     * multiple of 8, all stay there, in mcs_spectrum too): in an object on a
     * 32-byte boundary (where gcc and clang put large static objects on
     * x86-64; aligned_alloc(64, ...) for the heap, whose malloc gives 16) no
     * AVX load straddles a cache line. Measured: the PAIR path's batch close
     * at N = 4093 ran 1.35x slower with the arrays at 8 or 16 mod 32, which
     * before this padding was every 32-aligned object. */
    double pad_[5];
    double cos_table[MCS_MAX_N];             /* cos(2 pi j / N), j < N */
    double sin_table[MCS_MAX_N];             /* sin(2 pi j / N), j < N */
    double kiss_state[MCS_DFT_KISS_DOUBLES]; /* KissFFT cfg, placed by the two-call size query */
    double work[4 * (MCS_MAX_N)];            /* complex scratch: input and output buffers */
    double direct_phase[16 * MCS_DFT_CHUNK]; /* direct path scratch: in-block phases ... */
    size_t direct_index[MCS_DFT_CHUNK];      /* ... twiddle index per bin ... */
    size_t direct_step[MCS_DFT_CHUNK];       /* ... and its step per block */
} mcs_dft;

/* The back end this library was built with: "kissfft" or "fftw3" (a static
 * string, never NULL). */
const char *mcs_dft_backend(void);

/* Prepares a plan for n points. MCS_ERR_NULL, MCS_ERR_N_RANGE (n = 0 or
 * n > MCS_MAX_N, or KissFFT asks for more state than the plan reserves).
 * With the FFTW back end a plan FFTW cannot make falls back to the KissFFT
 * paths. *plan untouched on error. */
mcs_status mcs_dft_init(mcs_dft *plan, size_t n);

/* MCS_OK if plan was set up by mcs_dft_init for n points (lets a caller
 * validate before writing anything). MCS_ERR_NULL, MCS_ERR_UNINIT,
 * MCS_ERR_MISMATCH (n != plan n). */
mcs_status mcs_dft_check(const mcs_dft *plan, size_t n);

/* All n frequencies of eq. 7: re[k] + i im[k] = S_k, k = 0..n-1, with
 * S_{n-k} = conj(S_k) exactly. s[n]: finite reals (any sign) whose absolute
 * values sum to at most MCS_DFT_MAX_ABS_SUM. re[n] written; im[n] written
 * unless im is NULL.
 * Aliasing: s is read in full before anything is written, so s may be re or
 * im, or overlap them anyhow. re and im must not overlap each other, and no
 * array may lie inside *plan (its scratch and tables): both are rejected
 * with MCS_ERR_ALIAS.
 * MCS_ERR_NULL (plan, s, re), MCS_ERR_UNINIT, MCS_ERR_MISMATCH (n != plan n),
 * MCS_ERR_ALIAS (as above), MCS_ERR_NOT_FINITE (a NaN or infinity in s),
 * MCS_ERR_MAGNITUDE (the sum of |s_n| above MCS_DFT_MAX_ABS_SUM). On error
 * neither outputs nor the plan change. */
mcs_status mcs_dft_real(mcs_dft *plan, size_t n, const double *s, double *re, double *im);

/* The non-redundant half: S_k for k = 0..n/2 (integer division), the rest
 * being their conjugates. s[n]; re[n/2 + 1], im[n/2 + 1] written (im may be
 * NULL). Aliasing and statuses as mcs_dft_real (re and im of n/2 + 1). */
mcs_status mcs_dft_real_half(mcs_dft *plan, size_t n, const double *s, double *re, double *im);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_DFT_H */
