/* Type-1 non-uniform FFT of a point set, in 1D and 2D (the fast path of the
 * point-set periodograms):
 *
 *     c_k = sum_{j<K} e^{-2 pi i k . x_j},   x_j in [0,1)^d,
 *     k integer with |k_1|, ..., |k_d| <= F,  d = 1 or 2,
 *
 * so that P(k) = |c_k|^2 / K. Method of Barnett, Magland and af Klinteberg
 * (2019, FINUFFT): each point is spread onto a periodic grid of n points per
 * axis, n >= sigma (2F + 1) with sigma = 2 (n even, with no prime factor
 * above 5, so KissFFT keeps to its radix-2, 3, 4, 5 butterflies and never
 * allocates), with the "exponential of semicircle" kernel
 * phi(z) = e^{beta (sqrt(1 - z^2) - 1)}, |z| <= 1, of w grid points,
 * beta = 2.30 w; the grid is transformed (the real grid packed into complex
 * KissFFT transforms: in 1D its even and odd points, in 2D pairs of rows,
 * then the kept columns) and each kept mode is divided by the kernel's
 * Fourier transform, computed once at init by Gauss-Legendre quadrature.
 * Cost O(K w^d + n^d log n) against O(K (2F + 1)^d) for the direct sum.
 *
 * Accuracy: |c_k - c_k^exact| <= tol K at every k (the bound relative to the
 * l1 norm of the strengths, here all 1) for 1e-14 <= tol <= 1e-1. Two
 * choices differ from FINUFFT's defaults to keep it in the worst case (one
 * point, or a cluster, at the least favourable offset): w is one or two
 * points wider than FINUFFT's ceil(log10(10 / tol)), which aims at a
 * relative l2 error near tol and measured up to 5 tol K (nufft.c, width_of:
 * tol = 1e-12 takes w = 15 in 1D and 2D against 13), and in 2D below
 * tol = 1e-13 sigma is 5/2, as at sigma = 2 the rounding of the grid sums
 * and transform, divided at the corner modes (F, F) by the kernel's
 * transform, held the error near 1.3e-14 K. Measured against a long double
 * direct sum (test_nufft.c, F up to 100 in 1D and 40 in 2D, K up to 5000,
 * random, clustered and edge points), max |c - c_direct| / (tol K) is at
 * most 0.33, 0.05, 0.05, 0.42 in 1D and 0.10, 0.09, 0.23, 0.35 in 2D at
 * tol = 1e-6, 1e-9, 1e-12, 1e-14. Below 1e-14 double rounding is the floor
 * (2e-15 K to 8e-15 K measured at tol = 1e-15).
 * Not in the bound: m points at the same place (closer than a small part of
 * a grid cell) add the same kernel values to the same grid points, one
 * rounding per add, which can reach m eps of their share of c_k, as the
 * K-term sums of a direct sum in double do (2500 points at each of two
 * places: 1.6e-13 K).
 * For the periodogram: |P_nufft(k) - P(k)| <= 2 tol |c_k| + tol^2 K, that is
 * about 2 tol sqrt(K / P(k)) relative to P(k): tol = 1e-12 keeps P(k) near 1
 * exact to 2e-9 at a million points.
 *
 * Memory: a fixed header (mcs_nufft) over a work buffer the caller owns,
 * asked for in two calls as KissFFT does (mcs_nufft_size, then
 * mcs_nufft_init), or declared statically with MCS_NUFFT_SIZE. The buffer
 * holds the grid (n^d doubles), KissFFT's state for one transform length,
 * one complex scratch row, the kernel corrections and (1D) twiddles. It
 * needs no alignment (the plan starts its arrays at the first multiple of
 * 64 bytes inside it). The header points into the buffer: the buffer must
 * outlive the plan and stay untouched between calls; copies of the header
 * share it, so one transform at a time per buffer. Nothing allocates,
 * prints or keeps global state.
 *
 * A library built with MCS_CONFIG_NUFFT 0 (config.h, for firmware) has no
 * NUFFT: every call below then returns MCS_ERR_DOMAIN and writes nothing
 * (the names stay, so code that links them still links). */
#ifndef MCSPEC_NUFFT_H
#define MCSPEC_NUFFT_H

#include <stddef.h>
#include <stdint.h>
#include "config.h"
#include "status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Accepted tolerances, inclusive. */
#define MCS_NUFFT_TOL_MIN 1e-15
#define MCS_NUFFT_TOL_MAX 1e-1

/* Widest kernel, in grid points per axis (tol = 1e-15). */
#define MCS_NUFFT_MAX_WIDTH 18

/* Largest cutoff F per dimension: the work buffer's size then fits size_t
 * and every transform length KissFFT's int (n is at most 4.3 F + 35 per
 * axis, 5.4 F + 36 in 2D below tol = 1e-13). */
#if SIZE_MAX > 0xFFFFFFFFu
#define MCS_NUFFT_MAX_FREQ_1D 67108864u /* 2^26: up to 8.1 GB of work memory */
#define MCS_NUFFT_MAX_FREQ_2D 65536u    /* 2^16: up to 0.55 TB (0.86 TB below 1e-13) */
#else
#define MCS_NUFFT_MAX_FREQ_1D 16777216u /* 2^24: up to 2.0 GB */
#define MCS_NUFFT_MAX_FREQ_2D 4096u     /* up to 2.4 GB (3.4 GB below 1e-13) */
#endif

/* An upper bound on the grid points n per axis for cutoff freq and any
 * tolerance: n is the least even number with no prime factor above 5 that is
 * at least m = max(sigma (2F + 1), 2 w), sigma = 2 (5/2 in 2D below
 * tol = 1e-13), w <= 18, and every such n is at most 15 m / 14 + 32
 * (checked for every m below 4e9 by test_nufft.c). */
#define MCS_NUFFT_GRID_BOUND_(m) ((((m) > 36u ? (m) : (size_t)36u) * 15u) / 14u + 32u)
#define MCS_NUFFT_GRID_BOUND(dim, freq) \
    MCS_NUFFT_GRID_BOUND_((dim) == 1 ? 4u * (size_t)(freq) + 2u : 5u * (size_t)(freq) + 3u)

/* Bytes of work memory that suffice for (dim, freq) at every accepted
 * tolerance, as a constant expression for a static buffer (at least what
 * mcs_nufft_size reports: 24 n + 24 F + 1 KiB in 1D, 8 n^2 + 32 n + 8 F +
 * 1 KiB in 2D, n bounded by MCS_NUFFT_GRID_BOUND). For freq within the caps
 * above; dim 1 or 2. */
#define MCS_NUFFT_SIZE(dim, freq)                                                  \
    ((dim) == 1 ? 24u * MCS_NUFFT_GRID_BOUND(1, freq) + 24u * (size_t)(freq) + 1024u \
                : 8u * MCS_NUFFT_GRID_BOUND(2, freq) * MCS_NUFFT_GRID_BOUND(2, freq) +  \
                      32u * MCS_NUFFT_GRID_BOUND(2, freq) + 8u * (size_t)(freq) + 1024u)

/* A plan: set by mcs_nufft_init, read-only to the caller. The pointers go
 * into the caller's work buffer. */
typedef struct {
    size_t dim;       /* d, 1 or 2; 0 before init */
    size_t freq;      /* F: modes |k_i| <= F */
    size_t n;         /* grid points per axis (even, factors 2, 3, 5 only) */
    size_t width;     /* w, kernel width in grid points, 2..MCS_NUFFT_MAX_WIDTH */
    double beta;      /* kernel shape, 2.30 w */
    double tol;       /* the tolerance asked */
    size_t fft_len;   /* KissFFT's length: n / 2 in 1D, n in 2D */
    size_t bytes;     /* bytes of the buffer in use, from mem on */
    void *mem;        /* the caller's buffer, as given */
    double *grid;     /* n^d doubles (2D: rows 2r and 2r + 1 interleaved, re and im
                         of the r-th complex row) */
    double *scratch;  /* fft_len complex values */
    double *corr;     /* F + 1: 1 / (kernel's Fourier transform at k / n) */
    double *twiddle;  /* 1D: F + 1 complex e^{-2 pi i k / n}; NULL in 2D */
    void *fft;        /* KissFFT state for fft_len */
    uintptr_t key;    /* a hash of the fields above, set by init */
} mcs_nufft;

/* Bytes of work memory mcs_nufft_init needs for (dim, freq, tol), into
 * *bytes (at most MCS_NUFFT_SIZE(dim, freq)). MCS_ERR_NULL (bytes),
 * MCS_ERR_DOMAIN (dim not 1 or 2, or tol outside [MCS_NUFFT_TOL_MIN,
 * MCS_NUFFT_TOL_MAX]), MCS_ERR_NOT_FINITE (tol NaN or infinite), MCS_ERR_FREQ_RANGE (freq
 * 0 or above MCS_NUFFT_MAX_FREQ_1D / _2D). *bytes untouched on error. */
mcs_status mcs_nufft_size(size_t dim, size_t freq, double tol, size_t *bytes);

/* Sets up *plan over mem[bytes] for d = dim, F = freq and tolerance tol:
 * grid size, kernel, its Fourier transform (O(w (F + 1)) work) and
 * KissFFT's state. mem: any alignment, bytes at least what mcs_nufft_size
 * reports; it must not overlap *plan. Statuses as mcs_nufft_size, and
 * MCS_ERR_NULL (plan, mem), MCS_ERR_SPACE (bytes too small), MCS_ERR_ALIAS
 * (mem overlaps *plan). On error neither *plan nor mem changes. */
mcs_status mcs_nufft_init(mcs_nufft *plan, size_t dim, size_t freq, double tol, void *mem,
                          size_t bytes);

/* c_k of the K = k points points[k * d] (interleaved: x_0, y_0, x_1, ... in
 * 2D), each coordinate in [0, 1). out[2 (2F + 1)^d]: c_k as interleaved
 * (re, im), row-major with k_y slowest (2D), complex index
 * (k_y + F) (2F + 1) + (k_x + F); in 1D index k + F. c_{-k} = conj(c_k)
 * exactly and c_0 is real. Uses the plan's work buffer as scratch.
 * out may overlap points (every point is read before out is written) but
 * neither may overlap *plan or its buffer.
 * MCS_ERR_NULL (plan, points, out), MCS_ERR_UNINIT (plan not from
 * mcs_nufft_init), MCS_ERR_K_RANGE (k = 0, or k d doubles would not fit
 * memory), MCS_ERR_ALIAS, MCS_ERR_POINT_RANGE (a coordinate outside [0, 1)
 * or NaN: every point is checked before anything is written). On error
 * neither out nor the buffer changes. */
mcs_status mcs_nufft_type1(mcs_nufft *plan, const double *points, size_t k, double *out);

/* mcs_nufft_type1 for float points, read in place: each coordinate widens to
 * double exactly, so out is bit-equal to mcs_nufft_type1's on the widened
 * points (a float just below 1.0f is in [0, 1); 1.0f is not). Statuses as
 * mcs_nufft_type1. */
mcs_status mcs_nufft_type1_f(mcs_nufft *plan, const float *points, size_t k, double *out);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_NUFFT_H */
