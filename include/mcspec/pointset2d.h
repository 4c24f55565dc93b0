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
 * fy = 0 row are stored; read-outs at fy < 0 read P(-f). Per trial the sum
 * is an outer product of per-point phase rows e^{-2 pi i fx x} and
 * e^{-2 pi i fy y}, each advanced by one complex multiplication per frequency
 * and recomputed from sin and cos every 32 frequencies; four points update
 * each stored wave vector at once. O(K F^2) multiply-adds per trial.
 *
 * Size: sizeof(mcs_pointset2d) is 16 + 64 (F+1)^2 + 272 (F+1) bytes with
 * F = MCS_MAX_FREQ (x86-64): 78 688 at the default 32, 23 136 at 16,
 * 288 096 at 64. It holds no pointers, so it may be copied. */
#ifndef MCSPEC_POINTSET2D_H
#define MCSPEC_POINTSET2D_H

#include <stddef.h>
#include <stdint.h>
#include "config.h" /* MCS_MAX_FREQ, the largest per-axis cutoff F */
#include "status.h"
#include "pattern2d.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Stored wave vectors: fx = -F..F by fy = 0..F, each row padded to an even
 * 2F + 2 entries so the per-point update runs two wave vectors at a time. */
#define MCS_POINTSET2D_ROW (2 * (MCS_MAX_FREQ) + 2)
#define MCS_POINTSET2D_CELLS (MCS_POINTSET2D_ROW * ((MCS_MAX_FREQ) + 1))

typedef struct {
    size_t freq_max;                             /* F, 1..MCS_MAX_FREQ; 0 before init */
    uint64_t count;                              /* trials added */
    double mean[MCS_POINTSET2D_CELLS];           /* mean P at (fx, fy): [fy (2F+2) + fx + F] */
    double m2[MCS_POINTSET2D_CELLS];             /* Welford M2 of P */
    double ring_mean[MCS_MAX_FREQ + 1];          /* mean over trials of the annulus average */
    double ring_m2[MCS_MAX_FREQ + 1];            /* its Welford M2 */
    double re[MCS_POINTSET2D_CELLS];             /* scratch: S(f) of the current trial */
    double im[MCS_POINTSET2D_CELLS];
    double phase[4][4][MCS_POINTSET2D_ROW];      /* scratch: x rows (re, im), y rows (re, im) */
} mcs_pointset2d;

/* Empties the accumulator for |fx|, |fy| <= freq_max. MCS_ERR_NULL,
 * MCS_ERR_FREQ_RANGE (0 or above MCS_MAX_FREQ). *acc untouched on error. */
mcs_status mcs_pointset2d_init(mcs_pointset2d *acc, size_t freq_max);

/* Adds one trial: points[2 k] interleaved (x_0, y_0, x_1, ...), each in
 * [0, 1); any k >= 1. MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_K_RANGE (k = 0),
 * MCS_ERR_POINT_RANGE (a coordinate outside [0,1) or NaN), MCS_ERR_COUNT (the
 * count at MCS_MAX_COUNT). *acc untouched on error. */
mcs_status mcs_pointset2d_add(mcs_pointset2d *acc, size_t k, const double *points);

/* mcs_pointset2d_add for float points, read in place: each coordinate widens to double
 * exactly, so the statistics are bit-equal to mcs_pointset2d_add's on the widened
 * points (a float just below 1.0f is in [0,1); 1.0f is not). Statuses as
 * mcs_pointset2d_add. */
mcs_status mcs_pointset2d_add_f(mcs_pointset2d *acc, size_t k, const float *points);

/* dst <- dst union src (Chan et al.), to rounding one pass over both trial
 * streams. src unchanged; dst == src allowed. MCS_ERR_NULL, MCS_ERR_UNINIT,
 * MCS_ERR_MISMATCH (different F), MCS_ERR_COUNT (the counts would pass
 * MCS_MAX_COUNT), MCS_ERR_ALIAS (src and dst overlapping without being the
 * same object). dst untouched on error. */
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
 * MCS_ERR_NULL, MCS_ERR_FREQ_RANGE (radius above MCS_MAX_FREQ: no
 * accumulator holds that annulus). *out untouched on error. */
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
 * and gives MCS_ERR_DOMAIN for the anisotropy). radius 0..MCS_MAX_FREQ (the
 * annuli an accumulator holds; O(radius^2) work); the anisotropy needs
 * radius >= 1. Statuses as mcs_pointset2d_exact_power, MCS_ERR_FREQ_RANGE
 * (radius above MCS_MAX_FREQ), and MCS_ERR_DOMAIN as
 * mcs_pointset2d_anisotropy. *out untouched on error. */
mcs_status mcs_pointset2d_exact_radial(const mcs_pattern2d *pat, size_t radius, double *out);
mcs_status mcs_pointset2d_exact_anisotropy(const mcs_pattern2d *pat, size_t radius,
                                           double *out_db);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_POINTSET2D_H */
