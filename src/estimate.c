#include "mcspec/estimate.h"

#include <math.h>

mcs_status mcs_estimate_bins(size_t n, const double *f, size_t k, const size_t *bins,
                             const double *weights, double *out)
{
    if (f == NULL || bins == NULL || weights == NULL || out == NULL)
        return MCS_ERR_NULL;
    if (n == 0u)
        return MCS_ERR_N_RANGE;
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    double sum = 0.0;
    for (size_t j = 0; j < k; ++j) {
        if (bins[j] >= n)
            return MCS_ERR_BIN_RANGE;
        double w = weights[j], fv = f[bins[j]];
        if (!isfinite(w) || !isfinite(fv))
            return MCS_ERR_NOT_FINITE;
        if (w < 0.0)
            return MCS_ERR_NEGATIVE;
        sum += fv * w;
    }
    *out = sum / (double)k; /* eq. 8: I = (1/K) sum_n f_n s_n */
    return MCS_OK;
}

mcs_status mcs_estimate_points(mcs_integrand f, void *ctx, size_t k, const double *points,
                               const double *weights, double *out)
{
    if (f == NULL || points == NULL || out == NULL)
        return MCS_ERR_NULL;
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    for (size_t j = 0; j < k; ++j) {
        if (!(points[j] >= 0.0 && points[j] < 1.0))
            return MCS_ERR_POINT_RANGE;
        if (weights != NULL && !isfinite(weights[j]))
            return MCS_ERR_NOT_FINITE;
        if (weights != NULL && weights[j] < 0.0)
            return MCS_ERR_NEGATIVE;
    }
    double sum = 0.0;
    for (size_t j = 0; j < k; ++j) {
        double fv = f(points[j], ctx);
        if (!isfinite(fv))
            return MCS_ERR_NOT_FINITE;
        sum += weights != NULL ? fv * weights[j] : fv;
    }
    *out = sum / (double)k;
    return MCS_OK;
}

mcs_status mcs_welford_init(mcs_welford *acc)
{
    if (acc == NULL)
        return MCS_ERR_NULL;
    acc->count = 0u;
    acc->mean = 0.0;
    acc->m2 = 0.0;
    return MCS_OK;
}

mcs_status mcs_welford_add(mcs_welford *acc, double x)
{
    if (acc == NULL)
        return MCS_ERR_NULL;
    if (!isfinite(x))
        return MCS_ERR_NOT_FINITE;
    /* Welford: update the mean first, then M2 with the old and new deviations;
     * no sum of squares, so no cancellation when the mean is large. */
    acc->count += 1u;
    double delta = x - acc->mean;
    acc->mean += delta / (double)acc->count;
    acc->m2 += delta * (x - acc->mean);
    return MCS_OK;
}

mcs_status mcs_welford_merge(mcs_welford *dst, const mcs_welford *src)
{
    if (dst == NULL || src == NULL)
        return MCS_ERR_NULL;
    if (src->count == 0u)
        return MCS_OK;
    if (dst->count == 0u) {
        *dst = *src;
        return MCS_OK;
    }
    /* Chan, Golub and LeVeque: combine means and M2 through the mean gap. */
    double na = (double)dst->count, nb = (double)src->count, n = na + nb;
    double delta = src->mean - dst->mean;
    dst->mean += delta * (nb / n);
    dst->m2 += src->m2 + delta * delta * (na * nb / n);
    dst->count += src->count;
    return MCS_OK;
}

mcs_status mcs_welford_mean(const mcs_welford *acc, double *mean)
{
    if (acc == NULL || mean == NULL)
        return MCS_ERR_NULL;
    if (acc->count == 0u)
        return MCS_ERR_EMPTY;
    *mean = acc->mean;
    return MCS_OK;
}

mcs_status mcs_welford_variance(const mcs_welford *acc, double *variance)
{
    if (acc == NULL || variance == NULL)
        return MCS_ERR_NULL;
    if (acc->count < 2u)
        return MCS_ERR_EMPTY;
    *variance = acc->m2 / (double)(acc->count - 1u);
    return MCS_OK;
}

mcs_status mcs_welford_stderr(const mcs_welford *acc, double *stderr_out)
{
    if (acc == NULL || stderr_out == NULL)
        return MCS_ERR_NULL;
    if (acc->count < 2u)
        return MCS_ERR_EMPTY;
    *stderr_out = sqrt(acc->m2 / (double)(acc->count - 1u) / (double)acc->count);
    return MCS_OK;
}
