#include "mcspec/importance.h"
#include "importance_internal.h"
#include "internal.h"

#include <math.h>

mcs_status mcs_importance_init(mcs_importance *imp, size_t n, const double *weights)
{
    if (imp == NULL || weights == NULL)
        return MCS_ERR_NULL;
    if (n == 0u || n > (size_t)MCS_MAX_N)
        return MCS_ERR_N_RANGE;

    /* Validate everything before writing, so a failed call changes nothing.
     * Kahan summation: the normalisation should not depend on bin order. */
    double sum = 0.0, comp = 0.0;
    for (size_t b = 0; b < n; ++b) {
        double w = weights[b];
        if (!isfinite(w))
            return MCS_ERR_NOT_FINITE;
        if (w < 0.0)
            return MCS_ERR_NEGATIVE;
        if (w == 0.0)
            return MCS_ERR_ZERO_WEIGHT;
        double y = w - comp;
        double t = sum + y;
        comp = (t - sum) - y;
        sum = t;
    }
    if (!isfinite(sum))
        return MCS_ERR_NOT_FINITE;
    /* A weight so small next to the sum that g_n underflows would make 1/p_n infinite. */
    for (size_t b = 0; b < n; ++b)
        if (!(weights[b] / sum > 0.0) || !isfinite(sum / (weights[b] * (double)n)))
            return MCS_ERR_ZERO_WEIGHT;

    double inv_sum_p = 0.0;
    imp->n = n;
    imp->cdf[0] = 0.0;
    for (size_t b = 0; b < n; ++b) {
        double g = weights[b] / sum;
        imp->g[b] = g;
        imp->p[b] = (double)n * g;
        inv_sum_p += 1.0 / imp->p[b];
        double c = imp->cdf[b] + g;
        imp->cdf[b + 1] = c < 1.0 ? c : 1.0; /* keep monotone under rounding */
    }
    imp->cdf[n] = 1.0; /* exact, so every u in [0,1) has a bin */
    imp->harmonic_mean = (double)n / inv_sum_p;
    return MCS_OK;
}

double mcs_importance_point_in_bin(size_t n, size_t b, double t)
{
    double nd = (double)n;
    double x = ((double)b + t) / nd;
    /* Rounding may push x across a bin edge; step back by ulps (at most a few). */
    while (x >= 1.0 || floor(x * nd) > (double)b)
        x = nextafter(x, 0.0);
    while (floor(x * nd) < (double)b)
        x = nextafter(x, 1.0);
    return x;
}

void mcs_importance_warp_unchecked(const mcs_importance *imp, double u, double *x, size_t *bin)
{
    /* Largest b with cdf[b] <= u: cdf[0] = 0 <= u < 1 = cdf[n]. */
    size_t lo = 0u, hi = imp->n;
    while (hi - lo > 1u) {
        size_t mid = lo + (hi - lo) / 2u;
        if (imp->cdf[mid] <= u)
            lo = mid;
        else
            hi = mid;
    }
    double width = imp->cdf[lo + 1u] - imp->cdf[lo];
    double t = width > 0.0 ? (u - imp->cdf[lo]) / width : 0.0;
    if (t < 0.0)
        t = 0.0;
    if (t >= 1.0)
        t = nextafter(1.0, 0.0);
    *bin = lo;
    *x = mcs_importance_point_in_bin(imp->n, lo, t);
}

mcs_status mcs_importance_warp(const mcs_importance *imp, double u, double *x, size_t *bin)
{
    if (imp == NULL)
        return MCS_ERR_NULL;
    if (!mcs_importance_is_valid_(imp))
        return MCS_ERR_UNINIT;
    if (!(u >= 0.0 && u < 1.0))
        return MCS_ERR_POINT_RANGE;
    double xx;
    size_t bb;
    mcs_importance_warp_unchecked(imp, u, &xx, &bb);
    if (x != NULL)
        *x = xx;
    if (bin != NULL)
        *bin = bb;
    return MCS_OK;
}

/* N^{-1/2} sum_b e^{-2 pi i freq b/N} / p_b; trig per term (N up to MCS_MAX_N,
 * so no table), with exact index reduction. */
void mcs_importance_q_unchecked(const mcs_importance *imp, size_t freq, double *re, double *im)
{
    size_t n = imp->n;
    double r = 0.0, i = 0.0;
    for (size_t b = 0; b < n; ++b) {
        double a = mcs_twiddle_angle_((freq * b) % n, n);
        double q = 1.0 / imp->p[b];
        r += cos(a) * q;
        i -= sin(a) * q;
    }
    double scale = 1.0 / sqrt((double)n);
    *re = r * scale;
    *im = i * scale;
}

mcs_status mcs_importance_q(const mcs_importance *imp, size_t freq, double *re, double *im)
{
    if (imp == NULL || re == NULL || im == NULL)
        return MCS_ERR_NULL;
    if (!mcs_importance_is_valid_(imp))
        return MCS_ERR_UNINIT;
    if (freq >= imp->n)
        return MCS_ERR_FREQ_RANGE;
    mcs_importance_q_unchecked(imp, freq, re, im);
    return MCS_OK;
}
