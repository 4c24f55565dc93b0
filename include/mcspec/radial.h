/* psa's spectral statistics of a radial power spectrum (docs/measures.md):
 * the effective Nyquist frequency and the oscillation metric of Heck,
 * Schloemer and Deussen (2013, "Blue noise sampling with controlled
 * aliasing", ACM TOG 32(3)), as psa computes them (statistics.cpp:
 * EffectiveNyquist, OscillationsMetric), in 1D and 2D.
 *
 * The input is a radial power P_i at frequencies nu_i = i step,
 * i = 0..n-1 (cycles per unit length): for mcs_pointset2d_radial, annulus
 * i (i <= |f| < i + 1) at its inner radius with step 1, which is psa's
 * convention (its Curve::ToX is a bin's left edge); for mcs_pointset_power
 * in 1D, P at frequency i. Entry 0 (the zero frequency, where a periodogram
 * has P = K) is never read. With d the dimension and the frequency scale
 * K^(1/d) (sqrt(K) in 2D, as psa):
 *
 *   effective Nyquist: the cumulative mean power
 *       C_i = sum_{j=1..i} P_j d nu_j^(d-1) step / nu_i^d
 *     (the mean of P over the disk |f| < nu_i in 2D, over (0, nu_i] in 1D);
 *     from i0 = floor(K^(1/d) / 2 / step) up, the first i with C_i > 0.5,
 *     then down from it the first j >= 1 with C_j < 0.1; the value is
 *     nu_j / K^(1/d), which is psa's printed "Eff. Nyquist" (it keeps
 *     nu_j / 2 and prints it times 2 / sqrt(K)). 0 when no such j exists
 *     (psa's 0).
 *   oscillations: nu_o the first frequency (i >= 1) at which P reaches a
 *     new maximum of at least 0.98 (psa scans for the running maximum until
 *     it passes 0.98); x1 = min(nu_o + 5 K^(1/d), n step); then
 *       10 sqrt( int_{nu_o}^{x1} (P - 1)^2 d nu^(d-1) dnu / (x1^d - nu_o^d) ),
 *     ten times the RMS deviation of P from 1 over the annulus (2D) or
 *     interval (1D), the integral by the trapezoid rule over the samples
 *     from nu_o's to the one after x1 (psa's Integrate, in double where psa
 *     uses float).
 *
 * The values of one set's periodogram carry its noise (P of random points
 * has unit variance per wave vector); psa applies them to the mean over
 * its sets. mcspec stats gives both: the mean and standard error of the
 * per-set values, and the values of the mean spectrum. */
#ifndef MCSPEC_RADIAL_H
#define MCSPEC_RADIAL_H

#include <stddef.h>
#include "status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The range of step, and the largest |P| (a periodogram is at most K):
 * with them no intermediate overflows (the sums run in index units). */
#define MCS_RADIAL_MIN_STEP 1e-100
#define MCS_RADIAL_MAX_STEP 1e100
#define MCS_RADIAL_MAX_POWER 1e100

/* The effective Nyquist frequency of power[n] (above), over K^(1/d), into
 * *out. dim 1 or 2, k points per set (>= 1), step in [MCS_RADIAL_MIN_STEP,
 * MCS_RADIAL_MAX_STEP]; power[n] caller-owned, read only (entry 0 not at
 * all). MCS_ERR_NULL, MCS_ERR_DOMAIN (dim; step; n < 2), MCS_ERR_K_RANGE
 * (k = 0), MCS_ERR_NOT_FINITE (a power NaN or infinite), MCS_ERR_MAGNITUDE
 * (a |power| above MCS_RADIAL_MAX_POWER). *out untouched on error. */
mcs_status mcs_radial_effective_nyquist(size_t dim, size_t k, size_t n, const double *power,
                                        double step, double *out);

/* The oscillation metric of power[n] (above), into *out. Arguments and
 * statuses as mcs_radial_effective_nyquist, and MCS_ERR_DOMAIN when the
 * range [nu_o, x1] is empty (nu_o at the end of the array). */
mcs_status mcs_radial_oscillations(size_t dim, size_t k, size_t n, const double *power,
                                   double step, double *out);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_RADIAL_H */
