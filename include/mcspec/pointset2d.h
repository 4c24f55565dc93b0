/* Point-set spectra in 2D, without binning (the renderer's view, as in psa,
 * utk and pbrt's pspec): per trial of K points x_j in [0,1)^2 the periodogram
 * P(f) = |sum_j e^{-2 pi i f.x_j}|^2 / K at integer wave vectors
 * f = (fx, fy), |fx|, |fy| <= F, and over trials
 *  - the running mean and standard error of P(f) per wave vector,
 *  - the radial average over the annulus of radius r (the wave vectors with
 *    r <= |f| < r + 1, r = 0..F, complete inside the square), as a per-trial
 *    scalar so its standard error is honest (the P(f) of one trial are
 *    correlated),
 *  - psa's anisotropy of annulus r: 10 log10(s^2 / m^2), s^2 the unbiased
 *    variance (divisor n_r - 1) over the annulus's n_r wave vectors of the
 *    mean periodogram and m its annulus mean (Schloemer and Heck, psa,
 *    Periodogram::Anisotropy). A periodogram that is isotropic but measured
 *    over T trials sits near -10 log10 T dB (P of random points has unit
 *    variance per wave vector).
 * Random points give P(f) = 1 for f != 0; P(0) = K always.
 *
 * The points are real, so P(-f) = P(f): wave vectors with fy > 0 and the
 * fy = 0 row are stored; read-outs at fy < 0 read P(-f). A trial's sums
 * S(f) come from one of two paths (pointset.h), and the same Welford update
 * takes P = |S|^2 / K from either:
 *  - DIRECT: an outer product of per-point phase rows e^{-2 pi i fx x} and
 *    e^{-2 pi i fy y}, each advanced by one complex multiplication per
 *    frequency and recomputed from sin and cos every 32 frequencies; four
 *    points update each stored wave vector at once. O(K F^2).
 *  - NUFFT: the type-1 NUFFT of nufft.h at MCS_POINTSET_NUFFT_TOL,
 *    O(K w^2 + n^2 log n), w = 16, n about 4F: |P_nufft(f) - P(f)| <=
 *    1e-9 max(P(f), 1) at every f for sets of up to MCS_POINTSET_NUFFT_MAX_K
 *    points (pointset.h derives the tolerance).
 * AUTO (the default) takes per trial the faster by the measured cost model
 * (src/pointsets/pointset_cost.c); mcs_pointset2d_set_path forces one.
 * Points come interleaved (x_0, y_0, x_1, ...) or planar (an x array and a
 * y array), as double or float: the same values give the same bits every
 * way.
 *
 * Memory: a fixed header over a caller-owned buffer, as pointset.h says
 * (mcs_pointset2d_size, then mcs_pointset2d_init; MCS_POINTSET2D_SIZE(F) or
 * _SIZE_DIRECT(F) for a static buffer). A copy of the header shares the
 * buffer; mcs_pointset2d_copy makes an independent object.
 *
 * Caps: F from 1 to MCS_POINTSET2D_MAX_FREQ (16384 with a 64-bit size_t,
 * 2048 with a 32-bit one, whose buffer is then 1.14 GB with the NUFFT,
 * 0.27 GB without). The buffer is about 64 (F + 1)^2 bytes without the
 * NUFFT (statistics and scratch over the stored half plane) and 260 to
 * 270 (F + 1)^2 with it (its output and staging, 32 F^2, and its grid,
 * 8 n^2 with n about 4.3 F): 27 MB at F = 320, 1.14 GB at F = 2048, 69 GB at
 * F = 16384. K as in pointset.h: any K >= 1 on the DIRECT path, up to
 * MCS_POINTSET_NUFFT_MAX_K = 2^24 on the NUFFT path. */
#ifndef MCSPEC_POINTSET2D_H
#define MCSPEC_POINTSET2D_H

#include <stddef.h>
#include <stdint.h>
#include "status.h"
#include "pattern2d.h"
#include "pointset.h" /* the paths, flags and NUFFT tolerance */

#ifdef __cplusplus
extern "C" {
#endif

/* Largest per-axis cutoff F. */
#if SIZE_MAX > 0xFFFFFFFFu
#define MCS_POINTSET2D_MAX_FREQ 16384
#else
#define MCS_POINTSET2D_MAX_FREQ 2048
#endif

/* Bytes of buffer for cutoff F (1..MCS_POINTSET2D_MAX_FREQ), as constant
 * expressions: SIZE_DIRECT(F) exactly what mcs_pointset2d_size reports with
 * MCS_POINTSET_DIRECT_ONLY, SIZE(F) at least what it reports with flags 0
 * (the NUFFT's grid within nufft.h's bound: at its tolerance sigma = 2, so
 * at most MCS_NUFFT_GRID_BOUND(1, F) points per axis, as in 1D). Stored
 * wave vectors: fx = -F..F by fy = 0..F, each row padded to an even 2F + 2
 * entries so the per-point update runs two wave vectors at a time. */
#define MCS_POINTSET2D_CELLS_(f) ((2u * (size_t)(f) + 2u) * ((size_t)(f) + 1u))
#define MCS_POINTSET2D_SIZE_DIRECT(f)                                                      \
    (63u + 64u + 4u * MCS_POINTSET_RUP_(8u * MCS_POINTSET2D_CELLS_(f)) +                   \
     2u * MCS_POINTSET_RUP_(8u * ((size_t)(f) + 1u)) +                                     \
     MCS_POINTSET_RUP_(128u * (2u * (size_t)(f) + 2u)))
#define MCS_POINTSET2D_STAGE_(f)                                                           \
    (2u * (2u * (size_t)(f) + 1u) * (2u * (size_t)(f) + 1u) > MCS_POINTSET_STAGE_MIN       \
         ? 2u * (2u * (size_t)(f) + 1u) * (2u * (size_t)(f) + 1u)                          \
         : (size_t)MCS_POINTSET_STAGE_MIN)
#if MCS_CONFIG_NUFFT
#define MCS_POINTSET2D_SIZE(f)                                                             \
    (MCS_POINTSET2D_SIZE_DIRECT(f) + MCS_POINTSET_RUP_(8u * MCS_POINTSET2D_STAGE_(f)) +     \
     MCS_POINTSET_RUP_(8u * MCS_NUFFT_GRID_BOUND(1, f) * MCS_NUFFT_GRID_BOUND(1, f) +       \
                       32u * MCS_NUFFT_GRID_BOUND(1, f) + 8u * (size_t)(f) + 1024u))
#else /* built without the NUFFT (config.h, pointset.h) */
#define MCS_POINTSET2D_SIZE(f) MCS_POINTSET2D_SIZE_DIRECT(f)
#endif

/* The header: set by mcs_pointset2d_init, read-only to the caller. The
 * pointers go into the caller's buffer; stored wave vector (fx, fy) sits at
 * [fy (2F + 2) + fx + F]. */
typedef struct {
    size_t freq_max;             /* F, 1..MCS_POINTSET2D_MAX_FREQ; 0 before init */
    unsigned flags;              /* init's flags */
    mcs_pointset_path path;      /* mcs_pointset2d_set_path (AUTO after init) */
    int wrap;                    /* mcs_pointset2d_set_wrap (0 after init) */
    void *mem;                   /* the caller's buffer, as given */
    size_t bytes;                /* bytes of it in use from mem (the size query's) */
    mcs_pointset_head *state;    /* the first 64-byte boundary in mem: F, trials added */
    double *mean, *m2;           /* mean P at (fx, fy) and its Welford M2 */
    double *ring_mean, *ring_m2; /* per annulus: mean over trials of the average, its M2 */
    double *re, *im;             /* scratch: S(f) of the current trial */
    double *phase;               /* scratch: [4][4][2F + 2] x rows (re, im), y rows (re, im) */
    double *stage;               /* the NUFFT's output and staging (NULL with DIRECT_ONLY) */
    mcs_nufft plan;              /* the NUFFT plan over the end of the buffer (dim 0: none) */
    uintptr_t key;               /* a hash of the fields above, set by init and the setters */
} mcs_pointset2d;

/* Bytes of buffer mcs_pointset2d_init needs for cutoff freq_max and flags
 * (0 or MCS_POINTSET_DIRECT_ONLY), into *bytes (MCS_POINTSET2D_SIZE_DIRECT(F)
 * exactly with MCS_POINTSET_DIRECT_ONLY, at most MCS_POINTSET2D_SIZE(F)
 * with 0). MCS_ERR_NULL,
 * MCS_ERR_FREQ_RANGE (0 or above MCS_POINTSET2D_MAX_FREQ), MCS_ERR_DOMAIN
 * (an unknown flag). *bytes untouched on error. */
mcs_status mcs_pointset2d_size(size_t freq_max, unsigned flags, size_t *bytes);

/* Empties the accumulator for |fx|, |fy| <= freq_max over mem[bytes] (any
 * alignment), path AUTO (DIRECT with MCS_POINTSET_DIRECT_ONLY), wrap off;
 * builds the NUFFT plan (O(F) work). Statuses as mcs_pointset2d_size, and
 * MCS_ERR_NULL (acc, mem), MCS_ERR_SPACE (bytes too small), MCS_ERR_ALIAS
 * (mem overlaps *acc). On error neither *acc nor mem changes. */
mcs_status mcs_pointset2d_init(mcs_pointset2d *acc, size_t freq_max, unsigned flags, void *mem,
                               size_t bytes);

/* *dst <- an independent copy of src over mem[bytes] (mcs_pointset_copy).
 * Statuses as mcs_pointset_copy. */
mcs_status mcs_pointset2d_copy(mcs_pointset2d *dst, void *mem, size_t bytes,
                               const mcs_pointset2d *src);

/* Forces a path, or AUTO; the path an add of k points would take; wrap of
 * the point 1.0 (pointset.h: mcs_pointset_set_path, _path_for, _set_wrap). */
mcs_status mcs_pointset2d_set_path(mcs_pointset2d *acc, mcs_pointset_path path);
mcs_status mcs_pointset2d_path_for(const mcs_pointset2d *acc, size_t k, mcs_pointset_path *path);
mcs_status mcs_pointset2d_set_wrap(mcs_pointset2d *acc, int wrap);

/* Adds one trial: points[2 k] interleaved (x_0, y_0, x_1, ...), each in
 * [0, 1) (or [0, 1] with wrap); any k >= 1. MCS_ERR_NULL, MCS_ERR_UNINIT,
 * MCS_ERR_K_RANGE (k = 0, or above MCS_POINTSET_NUFFT_MAX_K on a forced
 * NUFFT path), MCS_ERR_POINT_RANGE (a coordinate outside [0,1) or NaN),
 * MCS_ERR_ALIAS (points inside the object's header or buffer), MCS_ERR_COUNT
 * (the count at MCS_MAX_COUNT). Every point is checked before anything is
 * written: on error neither *acc nor its buffer changes. */
mcs_status mcs_pointset2d_add(mcs_pointset2d *acc, size_t k, const double *points);

/* mcs_pointset2d_add for float points, read in place: each coordinate widens to double
 * exactly, so the statistics are bit-equal to mcs_pointset2d_add's on the widened
 * points (a float just below 1.0f is in [0,1); 1.0f is not, unless wrapped).
 * Statuses as mcs_pointset2d_add. */
mcs_status mcs_pointset2d_add_f(mcs_pointset2d *acc, size_t k, const float *points);

/* The same trial as planar arrays: point j is (x[j], y[j]). Bit-equal to
 * mcs_pointset2d_add (or _add_f) of the interleaved points. Statuses as
 * mcs_pointset2d_add (MCS_ERR_NULL for x or y). */
mcs_status mcs_pointset2d_add_planar(mcs_pointset2d *acc, size_t k, const double *x,
                                     const double *y);
mcs_status mcs_pointset2d_add_planar_f(mcs_pointset2d *acc, size_t k, const float *x,
                                       const float *y);

/* dst <- dst union src (Chan et al.), to rounding one pass over both trial
 * streams. src unchanged; dst == src allowed. MCS_ERR_NULL, MCS_ERR_UNINIT,
 * MCS_ERR_MISMATCH (different F), MCS_ERR_COUNT (the counts would pass
 * MCS_MAX_COUNT), MCS_ERR_ALIAS (distinct objects whose headers or buffers
 * overlap). dst untouched on error. */
mcs_status mcs_pointset2d_merge(mcs_pointset2d *dst, const mcs_pointset2d *src);

/* Trials added. MCS_ERR_NULL, MCS_ERR_UNINIT. */
mcs_status mcs_pointset2d_count(const mcs_pointset2d *acc, uint64_t *count);

/* <P(fx, fy)> for |fx|, |fy| <= F. MCS_ERR_NULL, MCS_ERR_UNINIT,
 * MCS_ERR_FREQ_RANGE, MCS_ERR_EMPTY (no trials). *out untouched on error. */
mcs_status mcs_pointset2d_power(const mcs_pointset2d *acc, long freq_x, long freq_y, double *out);

/* Standard error of <P(fx, fy)>. MCS_ERR_EMPTY for < 2 trials. */
mcs_status mcs_pointset2d_power_stderr(const mcs_pointset2d *acc, long freq_x, long freq_y,
                                       double *out);

/* Radial average of annulus radius (0..F): the mean over trials of the
 * per-trial average of P over the annulus. Statuses as mcs_pointset2d_power
 * (MCS_ERR_FREQ_RANGE for radius > F). */
mcs_status mcs_pointset2d_radial(const mcs_pointset2d *acc, size_t radius, double *out);

/* Its standard error over the trials. MCS_ERR_EMPTY for < 2 trials. */
mcs_status mcs_pointset2d_radial_stderr(const mcs_pointset2d *acc, size_t radius, double *out);

/* psa's anisotropy of annulus radius (1..F) in dB, from the mean periodogram.
 * MCS_ERR_DOMAIN when it is not finite: annulus 0 (a single wave vector), an
 * annulus mean of 0 (below 1e-20: an exactly empty annulus, e.g. a grid's,
 * measures as rounding residue near K 1e-32), or zero variance over the
 * annulus. Otherwise statuses as mcs_pointset2d_power. */
mcs_status mcs_pointset2d_anisotropy(const mcs_pointset2d *acc, size_t radius, double *out_db);

/* Number of integer wave vectors in annulus radius (r <= |f| < r + 1), the
 * whole plane counted: 1 for r = 0, 8 for r = 1; exact, in O(radius) steps.
 * MCS_ERR_NULL, MCS_ERR_FREQ_RANGE (radius above MCS_POINTSET2D_MAX_FREQ:
 * no accumulator holds that annulus). *out untouched on error. */
mcs_status mcs_pointset2d_ring_size(size_t radius, size_t *out);

/* Exact <P(fx, fy)> of a 2D pattern, for any integer wave vector:
 *   random        1
 *   jittered      1 - sinc^2(pi fx/m) sinc^2(pi fy/n)             (m x n strata)
 *   grid, shifted K where m divides fx and n divides fy, else 0 (a comb;
 *                 the shift only changes the phase)
 *   n-rooks       1 + sinc^2(pi fx/K) sinc^2(pi fy/K) (K dx - 1)(K dy - 1)/(K - 1),
 *                 dx = [K divides fx], dy = [K divides fy] (1 for K = 1)
 * at f != 0 (sinc x = sin x / x), and K at f = 0. Derivation: E|S|^2 = K +
 * sum over pairs j != j' of E e_j E e_j'^* (independent coordinates), the
 * pair terms from the strata (a sinc per axis) and, for n-rooks, from the
 * random permutation (pairs of distinct columns).
 * MCS_ERR_NULL, MCS_ERR_UNINIT (pat not from mcs_pattern2d_init),
 * MCS_ERR_KIND (multi-jittered and cmj: no closed form here). */
mcs_status mcs_pointset2d_exact_power(const mcs_pattern2d *pat, long freq_x, long freq_y,
                                      double *out);

/* The exact radial average and psa anisotropy of annulus radius, from
 * mcs_pointset2d_exact_power over the annulus's wave vectors (no trial
 * noise: an exactly isotropic annulus, e.g. random points, has zero variance
 * and gives MCS_ERR_DOMAIN for the anisotropy). radius 0..MCS_POINTSET2D_MAX_FREQ
 * (the annuli an accumulator holds; O(radius^2) work); the anisotropy needs
 * radius >= 1. Statuses as mcs_pointset2d_exact_power, MCS_ERR_FREQ_RANGE
 * (radius above MCS_POINTSET2D_MAX_FREQ), and MCS_ERR_DOMAIN as
 * mcs_pointset2d_anisotropy. *out untouched on error. */
mcs_status mcs_pointset2d_exact_radial(const mcs_pattern2d *pat, size_t radius, double *out);
mcs_status mcs_pointset2d_exact_anisotropy(const mcs_pattern2d *pat, size_t radius,
                                           double *out_db);

/* ---- Batches (pointset_batch.c): for callers that pay per call, such as
 * a binding (python/mcspec). Bits as the per-set and per-frequency calls. */

/* Adds sets trials of k interleaved 2D points each: points[2 sets k], set t
 * at points[2 t k] (a C-order array of shape (sets, k, 2)). Bit for bit
 * sets calls of mcs_pointset2d_add in order. Statuses as mcs_pointset2d_add,
 * and MCS_ERR_K_RANGE for sets = 0 or 2 sets k too large, MCS_ERR_COUNT if
 * the count cannot take all sets. Every point of every set is checked first:
 * on error neither *acc nor its buffer changes. */
mcs_status mcs_pointset2d_add_sets(mcs_pointset2d *acc, size_t sets, size_t k,
                                   const double *points);

/* The same for float points (mcs_pointset2d_add_f). */
mcs_status mcs_pointset2d_add_sets_f(mcs_pointset2d *acc, size_t sets, size_t k,
                                     const float *points);

/* Every wave vector |fx|, |fy| <= F at once, the whole plane:
 * power[(fy + F) side + fx + F] = <P(fx, fy)> and power_stderr[...] its
 * standard error, bit for bit mcs_pointset2d_power and _power_stderr.
 * Caller arrays of side * side doubles, side = 2F + 1 (else
 * MCS_ERR_MISMATCH); either may be NULL, not both (MCS_ERR_NULL); no
 * overlap with each other or the object (MCS_ERR_ALIAS). MCS_ERR_UNINIT,
 * MCS_ERR_EMPTY (no trials, or fewer than 2 with power_stderr). Nothing
 * written on error. */
mcs_status mcs_pointset2d_read_all(const mcs_pointset2d *acc, size_t side, double *power,
                                   double *power_stderr);

/* Every annulus r = 0..F at once: radial[r], radial_stderr[r] and
 * anisotropy_db[r], bit for bit mcs_pointset2d_radial, _radial_stderr and
 * _anisotropy, with NaN in anisotropy_db[r] where that call gives
 * MCS_ERR_DOMAIN (always at r = 0). Arrays of n_out = F + 1 doubles (else
 * MCS_ERR_MISMATCH), any may be NULL, not all; statuses and overlap rules as
 * mcs_pointset2d_read_all (MCS_ERR_EMPTY below 2 trials with
 * radial_stderr). Nothing written on error. */
mcs_status mcs_pointset2d_radial_all(const mcs_pointset2d *acc, size_t n_out, double *radial,
                                     double *radial_stderr, double *anisotropy_db);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_POINTSET2D_H */
