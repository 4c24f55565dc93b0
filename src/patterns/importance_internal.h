/* Private: the unchecked parts of the importance module shared with pattern.c
 * (the warp) and the closed forms (Q_k). */
#ifndef MCSPEC_IMPORTANCE_INTERNAL_H
#define MCSPEC_IMPORTANCE_INTERNAL_H

#include <math.h>
#include <stddef.h>
#include "mcspec/importance.h"

/* Bin b as mcs_importance_init leaves it: p_b positive with a finite 1/p_b,
 * or 0 with g_b = 0 (outside the support). Anything else (a zeroed p_b of a
 * bin that is drawn, NaN, a negative or subnormal p_b) is an overwritten
 * object. */
static inline int mcs_importance_bin_ok_(const mcs_importance *imp, size_t b)
{
    const double p = imp->p[b];
    return (p > 0.0 && isfinite(1.0 / p)) || (p == 0.0 && imp->g[b] == 0.0);
}

/* The support is not empty and H is what init gives: cdf[N] = 1 and H
 * positive and finite (a zeroed object has neither). O(1). */
static inline int mcs_importance_support_ok_(const mcs_importance *imp)
{
    const double h = imp->harmonic_mean;
    return imp->cdf[imp->n] == 1.0 && h > 0.0 && isfinite(h);
}

/* Every bin and the support as init leaves them. O(N). */
static inline int mcs_importance_sound_(const mcs_importance *imp)
{
    int ok = mcs_importance_support_ok_(imp);
    for (size_t b = 0; ok && b < imp->n; ++b)
        ok = mcs_importance_bin_ok_(imp, b);
    return ok;
}

/* imp valid, u in [0,1): bin whose CDF interval holds u, and the warped x. */
void mcs_importance_warp_unchecked(const mcs_importance *imp, double u, double *x, size_t *bin);

/* Largest x in bin b of n (floor(n x) = b) close to (b + t)/n, t in [0,1). */
double mcs_importance_point_in_bin(size_t n, size_t b, double t);

/* imp valid, freq < imp->n: Q_freq of eq. 43 (see mcs_importance_q). */
void mcs_importance_q_unchecked(const mcs_importance *imp, size_t freq, double *re, double *im);

#endif /* MCSPEC_IMPORTANCE_INTERNAL_H */
