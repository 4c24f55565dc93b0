#include "mcspec/welford.h"

#include <math.h>
#include <stddef.h>

mcs_status mcs_welford_init(mcs_welford *acc)
{
    if (acc == NULL)
        return MCS_ERR_NULL;
    acc->count = 0u;
    acc->mean = 0.0;
    acc->m2 = 0.0;
    acc->m3 = 0.0;
    acc->m4 = 0.0;
    return MCS_OK;
}

mcs_status mcs_welford_add(mcs_welford *acc, double x)
{
    if (acc == NULL)
        return MCS_ERR_NULL;
    if (!isfinite(x))
        return MCS_ERR_NOT_FINITE;
    /* Welford/Pebay: deviations from the running mean, higher moments first
     * because they use the old lower ones; no raw power sums, so no
     * cancellation when the mean is large. */
    double n1 = (double)acc->count, n = n1 + 1.0;
    double delta = x - acc->mean;
    double dn = delta / n, dn2 = dn * dn, term1 = delta * dn * n1;
    acc->m4 += term1 * dn2 * (n * n - 3.0 * n + 3.0) + 6.0 * dn2 * acc->m2 - 4.0 * dn * acc->m3;
    acc->m3 += term1 * dn * (n - 2.0) - 3.0 * dn * acc->m2;
    acc->m2 += term1;
    acc->mean += dn;
    acc->count += 1u;
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
    /* Chan, Golub and LeVeque for M2, Pebay for M3 and M4: combine through
     * the gap between the two means. */
    const mcs_welford a = *dst;
    double na = (double)a.count, nb = (double)src->count, n = na + nb;
    double d = src->mean - a.mean, d2 = d * d;
    dst->mean = a.mean + d * (nb / n);
    dst->m2 = a.m2 + src->m2 + d2 * na * nb / n;
    dst->m3 = a.m3 + src->m3 + d2 * d * na * nb * (na - nb) / (n * n) +
              3.0 * d * (na * src->m2 - nb * a.m2) / n;
    dst->m4 = a.m4 + src->m4 + d2 * d2 * na * nb * (na * na - na * nb + nb * nb) / (n * n * n) +
              6.0 * d2 * (na * na * src->m2 + nb * nb * a.m2) / (n * n) +
              4.0 * d * (na * src->m3 - nb * a.m3) / n;
    dst->count = a.count + src->count;
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

mcs_status mcs_welford_variance_stderr(const mcs_welford *acc, double *stderr_out)
{
    if (acc == NULL || stderr_out == NULL)
        return MCS_ERR_NULL;
    if (acc->count < 4u)
        return MCS_ERR_EMPTY;
    double c = (double)acc->count;
    double s2 = acc->m2 / (c - 1.0), mu4 = acc->m4 / c;
    double v = (mu4 - (c - 3.0) / (c - 1.0) * s2 * s2) / c;
    *stderr_out = sqrt(v > 0.0 ? v : 0.0);
    return MCS_OK;
}
