#include "mcspec/importance.h"
#include "importance_internal.h"
#include "core/internal.h"

#include <math.h>

/* The grid of the generator's u (mcs_rng_double: k / 2^53). */
#define GRID 9007199254740992.0 /* 2^53 */

/* Neumaier's compensated sum: *sum + *lo is the total to about an ulp for
 * any order and sign of the terms (N up to MCS_MAX_N), so the normalisation
 * and the CDF do not depend on how many bins came before. */
static void neumaier_add(double *sum, double *lo, double x)
{
    const double t = *sum + x;
    *lo += fabs(*sum) >= fabs(x) ? (*sum - t) + x : (x - t) + *sum;
    *sum = t;
}

/* Checks the weights and finds the power of two that scales the largest into
 * [0.5, 1): every weight is then summed without overflow whatever its scale
 * (all equal at DBL_MAX, or at 5e-324). A weight may be 0 (a bin outside the
 * support), not all of them. *flat: all weights equal; *last: the last
 * bin with a positive weight. */
static mcs_status check_weights(size_t n, const double *weights, int *scale_exp, int *flat,
                                size_t *last)
{
    double max = 0.0;
    *flat = 1;
    for (size_t b = 0; b < n; ++b) {
        const double w = weights[b];
        if (!isfinite(w))
            return MCS_ERR_NOT_FINITE;
        if (w < 0.0)
            return MCS_ERR_NEGATIVE;
        if (w > 0.0)
            *last = b;
        max = w > max ? w : max;
        *flat &= w == weights[0];
    }
    if (!(max > 0.0))
        return MCS_ERR_ZERO_WEIGHT; /* nothing to sample */
    (void)frexp(max, scale_exp);
    return MCS_OK;
}

/* The scaled total, then every positive weight at least MCS_IMPORTANCE_MIN_G
 * of it (a weight scaled below the smallest normal is far below that); 0 is
 * the support condition, sampled exactly (never). */
static mcs_status scaled_total(size_t n, const double *weights, int scale_exp, double *total)
{
    double sum = 0.0, lo = 0.0;
    for (size_t b = 0; b < n; ++b)
        neumaier_add(&sum, &lo, ldexp(weights[b], -scale_exp));
    *total = sum + lo;
    for (size_t b = 0; b < n; ++b)
        if (weights[b] != 0.0 &&
            !(ldexp(weights[b], -scale_exp) >= (double)MCS_IMPORTANCE_MIN_G * *total))
            return MCS_ERR_ZERO_WEIGHT;
    return MCS_OK;
}

/* cdf[b] for b = 1 .. n-1: the running total over the scaled total, rounded
 * to the 2^-53 grid; cdf[0] = 0 and cdf[n] = 1 exactly. Each positive g_b is
 * at least 2^-32 - 2^-52, so the rounded entries rise strictly over it; a
 * zero weight adds exactly 0 to the running total, so its bin's two entries
 * are the same double (g_b = 0), and past the last positive weight every
 * entry is 1, exactly. */
static void fill_cdf(mcs_importance *imp, size_t n, const double *weights, int scale_exp,
                     double total, int flat, size_t last)
{
    double sum = 0.0, lo = 0.0;
    imp->cdf[0] = 0.0;
    for (size_t b = 1; b < n; ++b) {
        double c;
        if (flat) {
            c = (double)b / (double)n; /* the exact b/N, one rounding */
        } else {
            neumaier_add(&sum, &lo, ldexp(weights[b - 1u], -scale_exp));
            c = (sum + lo) / total;
        }
        imp->cdf[b] = b > last ? 1.0 : nearbyint(c * GRID) / GRID;
    }
    imp->cdf[n] = 1.0;
}

mcs_status mcs_importance_init(mcs_importance *imp, size_t n, const double *weights)
{
    if (imp == NULL || weights == NULL)
        return MCS_ERR_NULL;
    if (n == 0u || n > (size_t)MCS_MAX_N)
        return MCS_ERR_N_RANGE;
    /* Validate everything before writing, so a failed call changes nothing. */
    int scale_exp = 0, flat = 0;
    size_t last = 0u;
    double total = 0.0;
    mcs_status st = check_weights(n, weights, &scale_exp, &flat, &last);
    if (st == MCS_OK)
        st = scaled_total(n, weights, scale_exp, &total);
    if (st != MCS_OK)
        return st;

    imp->n = n;
    fill_cdf(imp, n, weights, scale_exp, total, flat, last);
    /* g_b is the exact length of I_b (two multiples of 2^-53 in [0, 1]), the
     * probability the generator's u lands there; p_b = N g_b weighs it. A
     * bin outside the support has g_b = p_b = 0 and is left out of H. */
    double inv_sum = 0.0, inv_lo = 0.0;
    int full = 1;
    for (size_t b = 0; b < n; ++b) {
        imp->g[b] = imp->cdf[b + 1u] - imp->cdf[b];
        imp->p[b] = flat ? 1.0 : (double)n * imp->g[b];
        full &= imp->p[b] > 0.0;
        if (imp->p[b] > 0.0)
            neumaier_add(&inv_sum, &inv_lo, 1.0 / imp->p[b]);
    }
    /* With every bin in the support H <= 1 exactly (the p_b average to 1:
     * the g_b telescope to 1); keep rounding from putting a nearly flat
     * function a hair above it. Without, H may pass 1 (up to N^2 / N_s^2). */
    const double h = (double)n / (inv_sum + inv_lo);
    imp->harmonic_mean = flat || (full && h > 1.0) ? 1.0 : h;
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
    /* In [0, 1) from a CDF init wrote; NaN only from a corrupted one (an
     * entry of -inf: inf / inf), which still gets a point in bin lo. */
    if (!(t >= 0.0))
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
    if (x != NULL && bin != NULL && mcs_overlap_(x, sizeof *x, bin, sizeof *bin))
        return MCS_ERR_ALIAS;
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
        if (imp->p[b] == 0.0)
            continue; /* outside the support: never sampled, 1/p_n read as 0 */
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
    if (mcs_overlap_(re, sizeof *re, im, sizeof *im))
        return MCS_ERR_ALIAS;
    /* An object mcs_importance_init made has every p_n 0 (left out) or
     * bounded below, so Q_k is finite; a corrupted one (a tiny p_n, or NaN)
     * is refused rather than read out as NaN or infinity. */
    if (!mcs_importance_sound_(imp))
        return MCS_ERR_INVARIANT;
    double r, i;
    mcs_importance_q_unchecked(imp, freq, &r, &i);
    if (!isfinite(r) || !isfinite(i))
        return MCS_ERR_INVARIANT;
    *re = r;
    *im = i;
    return MCS_OK;
}
