/* Point-set spectra in 1D, without binning: per trial of K points x_j in
 * [0, 1) the periodogram P(f) = |sum_j e^{-2 pi i f x_j}|^2 / K at integer
 * frequencies f = 0..F, and over trials its running mean and standard error
 * per frequency (Welford; mergeable with Chan's update). Random points give
 * P(f) = 1 at every f != 0; P(0) = K always. The points are real, so
 * P(-f) = P(f): only f >= 0 is stored and read-outs accept |f| <= F.
 *
 * Two paths compute a trial's sums S(f) = sum_j e^{-2 pi i f x_j}, and the
 * same Welford update takes P = |S|^2 / K from either (so means and standard
 * errors come out the same way):
 *  - DIRECT: the phases e^{-2 pi i f x_j} advanced by one complex
 *    multiplication per frequency and recomputed from sin and cos every 32
 *    frequencies (a few 1e-15 of rounding); the sum over points an outer
 *    product of short phase rows (below), four points at a time: O(K F).
 *  - NUFFT: the type-1 non-uniform FFT of nufft.h at the tolerance
 *    MCS_POINTSET_NUFFT_TOL, O(K w + n log n) with w = 16 and n about 4F.
 *    Exact to that rounding: |P_nufft(f) - P(f)| <= 1e-9 max(P(f), 1) at
 *    every f for every set of up to MCS_POINTSET_NUFFT_MAX_K points (the
 *    tolerance's derivation is below).
 * AUTO (the default) takes, per trial, the path the cost model
 * (src/pointsets/pointset_cost.c, measured) says is faster for its K and
 * this F; mcs_pointset_set_path forces one.
 *
 * Memory: a fixed header (mcs_pointset) over a buffer the caller owns,
 * asked for in two calls as KissFFT does (mcs_pointset_size, then
 * mcs_pointset_init), or declared statically with MCS_POINTSET_SIZE(F)
 * (MCS_POINTSET_SIZE_DIRECT(F) without the NUFFT). The buffer holds every
 * statistic (the trial count included), the scratch of both paths and the
 * NUFFT plan's work memory; it needs no alignment (the arrays start at the
 * first multiple of 64 bytes in it) and must outlive the object, untouched
 * by anything else. A copy of the header is not a copy of the object: it
 * shares the buffer (so two such copies must never be used at once);
 * mcs_pointset_copy makes an independent object over another buffer.
 * Nothing allocates, prints or keeps global state.
 *
 * Caps: F from 1 to MCS_POINTSET_MAX_FREQ (2^24 with a 64-bit size_t, 2^22
 * with a 32-bit one, where the buffer then stays below 4 GB: about
 * 186 F bytes with the NUFFT, 34 F without); any K >= 1 on the DIRECT path,
 * up to MCS_POINTSET_NUFFT_MAX_K = 2^24 on the NUFFT path (AUTO takes DIRECT
 * above it). The size query refuses what would not fit size_t. */
#ifndef MCSPEC_POINTSET_H
#define MCSPEC_POINTSET_H

#include <stddef.h>
#include <stdint.h>
#include "config.h"
#include "status.h"
#include "pattern.h"
#include "nufft.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Largest cutoff F (plain numbers, so the command's --help can quote them). */
#if SIZE_MAX > 0xFFFFFFFFu
#define MCS_POINTSET_MAX_FREQ 16777216 /* 2^24: a 3.1 GB buffer */
#else
#define MCS_POINTSET_MAX_FREQ 4194304 /* 2^22: a 780 MB buffer */
#endif

/* Largest set the NUFFT path takes, 2^24 points, and the tolerance its plan
 * is built for (nufft.h): |c - c_exact| <= tol K at every mode, so
 * |Delta P| <= 2 tol |c| + tol^2 K with P = |c|^2 / K, that is
 * |Delta P| / max(P, 1) <= 2 tol sqrt(K / P) + tol^2 K / P for P >= 1 and
 * <= 2 tol sqrt(P K) + tol^2 K below: largest at P = 1 (not at P = K, where
 * it is 2 tol), 2 tol sqrt(K) + tol^2 K. For K = 2^24 and tol = 1e-13 that
 * is 8.2e-10 <= 1e-9 (tol = 5e-10, which bounds it at P = K, would allow
 * 4e-6 at P = 1). Smaller tolerances cost wider kernels for nothing: the
 * direct path's own rounding is near 1e-15 K. */
#define MCS_POINTSET_NUFFT_MAX_K 16777216
#define MCS_POINTSET_NUFFT_TOL 1e-13

/* Flags of mcs_pointset_size and mcs_pointset_init (and of the 2D
 * accumulator's): MCS_POINTSET_DIRECT_ONLY leaves the NUFFT's memory out of
 * the buffer (the staging array and the plan, most of it: for firmware,
 * which never has the sets the NUFFT is for); the object then takes the
 * DIRECT path only. A library built with MCS_CONFIG_NUFFT 0 (config.h)
 * treats every object so, whatever its flags (which are still checked and
 * kept): the sizes of DIRECT_ONLY, path AUTO after init with flags 0 but
 * the DIRECT path taken, the NUFFT path refused. */
#define MCS_POINTSET_DIRECT_ONLY 1u

/* The path of a trial's sums. */
typedef enum {
    MCS_POINTSET_PATH_AUTO = 0,   /* per trial the faster, by the cost model */
    MCS_POINTSET_PATH_DIRECT = 1, /* the direct sum, O(K F) (O(K F^2) in 2D) */
    MCS_POINTSET_PATH_NUFFT = 2   /* the type-1 NUFFT */
} mcs_pointset_path;

/* Frequencies are split as f = a B + b, b < B, so that
 * e^{-2 pi i f x} = e^{-2 pi i a B x} e^{-2 pi i b x}: per point a row of B
 * low phases and a row of (F + 1)/B high ones, and the sum over points is an
 * outer product (the same vectorised kernel as the 2D spectrum). */
#define MCS_POINTSET_BLOCK 32

/* Doubles of the NUFFT's output, which also stages points that cannot be
 * handed to the NUFFT where they are (wrapped ones): at least this many. */
#define MCS_POINTSET_STAGE_MIN 8192u

/* Bytes of buffer for cutoff F (1..MCS_POINTSET_MAX_FREQ), as constant
 * expressions for a static buffer: SIZE_DIRECT(F) is exactly what
 * mcs_pointset_size reports with MCS_POINTSET_DIRECT_ONLY, SIZE(F) at least
 * what it reports with flags 0 (the NUFFT's grid, at most
 * MCS_NUFFT_GRID_BOUND(1, F) points at its tolerance, sigma = 2, is known
 * only within a bound: nufft.h). Every array starts on 64 bytes, plus 63
 * for the buffer's own alignment. */
#define MCS_POINTSET_RUP_(b) (((size_t)(b) + 63u) / 64u * 64u)
#define MCS_POINTSET_BLOCKS_(f) ((size_t)(f) / (size_t)MCS_POINTSET_BLOCK + 1u)
#define MCS_POINTSET_SIZE_DIRECT(f)                                                         \
    ((size_t)63u + 64u + 2u * MCS_POINTSET_RUP_(8u * ((size_t)(f) + 1u)) +                \
     (size_t)16u * MCS_POINTSET_BLOCK * MCS_POINTSET_BLOCKS_(f) +                          \
     (size_t)64u * MCS_POINTSET_BLOCK + 64u * MCS_POINTSET_BLOCKS_(f))
#define MCS_POINTSET_STAGE_(f)                                                              \
    (2u * (2u * (size_t)(f) + 1u) > MCS_POINTSET_STAGE_MIN ? 2u * (2u * (size_t)(f) + 1u)   \
                                                           : (size_t)MCS_POINTSET_STAGE_MIN)
#if MCS_CONFIG_NUFFT
#define MCS_POINTSET_SIZE(f)                                                                \
    (MCS_POINTSET_SIZE_DIRECT(f) + MCS_POINTSET_RUP_(8u * MCS_POINTSET_STAGE_(f)) +          \
     MCS_POINTSET_RUP_(24u * MCS_NUFFT_GRID_BOUND(1, f) + 24u * (size_t)(f) + 1024u))
#else /* built without the NUFFT (config.h): every object is direct only */
#define MCS_POINTSET_SIZE(f) MCS_POINTSET_SIZE_DIRECT(f)
#endif

/* The head of an object's statistics, at the first 64-byte boundary of its
 * buffer (the 2D accumulator's too): F (and 0) and the trials added. */
typedef struct {
    size_t shape[2];
    uint64_t count;
} mcs_pointset_head;

/* The header: set by mcs_pointset_init, read-only to the caller. The
 * pointers go into the caller's buffer. */
typedef struct {
    size_t freq_max;        /* F, 1..MCS_POINTSET_MAX_FREQ; 0 before init */
    unsigned flags;         /* init's flags */
    mcs_pointset_path path; /* mcs_pointset_set_path (AUTO after init) */
    int wrap;               /* mcs_pointset_set_wrap (0 after init) */
    void *mem;              /* the caller's buffer, as given */
    size_t bytes;           /* bytes of it in use from mem (the size query's) */
    mcs_pointset_head *state; /* the first 64-byte boundary in mem: F, trials added */
    double *mean, *m2;      /* running mean of P(f) and its Welford M2, f = 0..F */
    double *re, *im;        /* scratch: S(f) of the current trial, f < span */
    double *low, *high;     /* scratch: [4][2][B] e^{-2 pi i b x_p}, [4][2][blocks] e^{-2 pi i a B x_p} */
    double *stage;          /* the NUFFT's output and staging (NULL with DIRECT_ONLY) */
    mcs_nufft plan;         /* the NUFFT plan over the end of the buffer (dim 0: none) */
    uintptr_t key;          /* a hash of the fields above, set by init and the setters */
} mcs_pointset;

/* Bytes of buffer mcs_pointset_init needs for cutoff freq_max and flags
 * (0 or MCS_POINTSET_DIRECT_ONLY), into *bytes (MCS_POINTSET_SIZE_DIRECT(F)
 * exactly with MCS_POINTSET_DIRECT_ONLY, at most MCS_POINTSET_SIZE(F) with 0). MCS_ERR_NULL, MCS_ERR_FREQ_RANGE (0 or above
 * MCS_POINTSET_MAX_FREQ), MCS_ERR_DOMAIN (an unknown flag). *bytes
 * untouched on error. */
mcs_status mcs_pointset_size(size_t freq_max, unsigned flags, size_t *bytes);

/* Empties the accumulator for frequencies 0..freq_max over mem[bytes] (any
 * alignment; bytes at least what mcs_pointset_size reports), path AUTO (or
 * DIRECT with MCS_POINTSET_DIRECT_ONLY), wrap off. Builds the NUFFT plan
 * (O(F) work). Statuses as mcs_pointset_size, and MCS_ERR_NULL (acc, mem),
 * MCS_ERR_SPACE (bytes too small), MCS_ERR_ALIAS (mem overlaps *acc). On
 * error neither *acc nor mem changes. */
mcs_status mcs_pointset_init(mcs_pointset *acc, size_t freq_max, unsigned flags, void *mem,
                             size_t bytes);

/* *dst <- an independent copy of src (same F, flags, path, wrap and
 * statistics) over mem[bytes], as mcs_pointset_init would set it up there.
 * src unchanged. dst == src is allowed (the object moves to mem, which must
 * not overlap its old buffer). MCS_ERR_NULL, MCS_ERR_UNINIT (src),
 * MCS_ERR_SPACE, MCS_ERR_ALIAS (mem overlaps *dst, *src or src's buffer).
 * *dst and mem untouched on error. */
mcs_status mcs_pointset_copy(mcs_pointset *dst, void *mem, size_t bytes, const mcs_pointset *src);

/* Forces a path for the trials that follow, or AUTO. MCS_ERR_NULL,
 * MCS_ERR_UNINIT, MCS_ERR_DOMAIN (unknown path, or NUFFT with
 * MCS_POINTSET_DIRECT_ONLY or in a library built with MCS_CONFIG_NUFFT 0).
 * *acc untouched on error. */
mcs_status mcs_pointset_set_path(mcs_pointset *acc, mcs_pointset_path path);

/* The path an add of k points would take now (DIRECT or NUFFT, never AUTO).
 * MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_K_RANGE (k = 0, or above
 * MCS_POINTSET_NUFFT_MAX_K on a forced NUFFT path). */
mcs_status mcs_pointset_path_for(const mcs_pointset *acc, size_t k, mcs_pointset_path *path);

/* Wrap (1) or not (0, after init) the point 1.0: with wrap on, a coordinate
 * of exactly 1.0 is taken as 0.0 (the same frequency content: e^{-2 pi i f}
 * = 1), as a float renderer's u x 2^-32 rounds to 1.0f for the top 128
 * values of u; everything else outside [0, 1), and NaN, is still refused.
 * MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_DOMAIN (wrap not 0 or 1). */
mcs_status mcs_pointset_set_wrap(mcs_pointset *acc, int wrap);

/* Adds one trial: points[k] in [0, 1) (or [0, 1] with wrap), any k >= 1
 * (trials may differ in K; each periodogram is normalised by its own K).
 * MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_K_RANGE (k = 0, or above
 * MCS_POINTSET_NUFFT_MAX_K on a forced NUFFT path), MCS_ERR_POINT_RANGE
 * (outside [0,1) or NaN), MCS_ERR_ALIAS (points inside the object's header
 * or buffer), MCS_ERR_COUNT (the count at MCS_MAX_COUNT). Every point is
 * checked before anything is written: on error neither *acc nor its buffer
 * changes. */
mcs_status mcs_pointset_add(mcs_pointset *acc, size_t k, const double *points);

/* mcs_pointset_add for float points, read in place: each coordinate widens to double
 * exactly, so the statistics are bit-equal to mcs_pointset_add's on the widened
 * points (a float just below 1.0f is in [0,1); 1.0f is not, unless wrapped).
 * Statuses as mcs_pointset_add. */
mcs_status mcs_pointset_add_f(mcs_pointset *acc, size_t k, const float *points);

/* dst <- dst union src: the statistics of one pass over both trial streams,
 * to rounding. src unchanged; dst == src allowed. MCS_ERR_NULL,
 * MCS_ERR_UNINIT, MCS_ERR_MISMATCH (different F), MCS_ERR_COUNT (the counts
 * would pass MCS_MAX_COUNT), MCS_ERR_ALIAS (distinct objects whose headers
 * or buffers overlap). dst untouched on error. */
mcs_status mcs_pointset_merge(mcs_pointset *dst, const mcs_pointset *src);

/* Trials added. MCS_ERR_NULL, MCS_ERR_UNINIT. */
mcs_status mcs_pointset_count(const mcs_pointset *acc, uint64_t *count);

/* Mean periodogram <P(f)> for |freq| <= F. MCS_ERR_NULL, MCS_ERR_UNINIT,
 * MCS_ERR_FREQ_RANGE, MCS_ERR_EMPTY (no trials). *out untouched on error. */
mcs_status mcs_pointset_power(const mcs_pointset *acc, long freq, double *out);

/* Standard error of <P(f)> over the trials. MCS_ERR_EMPTY for < 2 trials;
 * otherwise as mcs_pointset_power. */
mcs_status mcs_pointset_power_stderr(const mcs_pointset *acc, long freq, double *out);

/* Exact <P(f)> of K points of a 1D pattern kind, unbinned (the N -> infinity
 * limit of the binned patterns): random 1 (f != 0); stratified
 * 1 - sinc^2(pi f / K) (f != 0; sinc x = sin x / x); uniform and jitter K
 * where K divides f, else 0 (deterministic up to a phase); P(0) = K for all.
 * MCS_ERR_NULL, MCS_ERR_K_RANGE (k = 0), MCS_ERR_KIND (homogenized: defined
 * only on N bins; or an unknown kind). */
mcs_status mcs_pointset_exact_power(mcs_pattern_kind kind, size_t k, long freq, double *out);

/* ---- Batches (pointset_batch.c): for callers that pay per call, such as
 * a binding (python/mcspec). Bits as the per-set and per-frequency calls. */

/* Adds sets trials of k points each: points[sets * k], set t at
 * points[t k] (a C-order array of shape (sets, k)). The statistics are
 * bit for bit those of sets calls of mcs_pointset_add in order. Statuses as
 * mcs_pointset_add, and MCS_ERR_K_RANGE for sets = 0 or sets * k too large,
 * MCS_ERR_COUNT if the count cannot take all sets. Every point of every
 * set is checked first: on error neither *acc nor its buffer changes. */
mcs_status mcs_pointset_add_sets(mcs_pointset *acc, size_t sets, size_t k, const double *points);

/* The same for float points (mcs_pointset_add_f). */
mcs_status mcs_pointset_add_sets_f(mcs_pointset *acc, size_t sets, size_t k, const float *points);

/* Every frequency f = 0..F at once: power[f] = <P(f)> and power_stderr[f]
 * its standard error, bit for bit mcs_pointset_power and _power_stderr.
 * Caller arrays of n_out doubles, n_out = F + 1 (else MCS_ERR_MISMATCH);
 * either may be NULL, not both (MCS_ERR_NULL); they must overlap neither
 * each other nor the object (MCS_ERR_ALIAS). MCS_ERR_UNINIT, MCS_ERR_EMPTY
 * (no trials, or fewer than 2 with power_stderr). Nothing written on error. */
mcs_status mcs_pointset_read_all(const mcs_pointset *acc, size_t n_out, double *power,
                                 double *power_stderr);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_POINTSET_H */
