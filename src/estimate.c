#include "mcspec/estimate.h"
#include "internal.h"

#include <math.h>

mcs_status mcs_estimate_bins(size_t n, size_t k, const double *f, const size_t *bins,
                             const double *weights, double *out)
{
    if (f == NULL || bins == NULL || weights == NULL || out == NULL)
        return MCS_ERR_NULL;
    if (n == 0u)
        return MCS_ERR_N_RANGE;
    mcs_status st = mcs_check_sparse_(n, k, bins, weights);
    if (st != MCS_OK)
        return st;
    double sum = 0.0;
    for (size_t j = 0; j < k; ++j) {
        double fv = f[bins[j]];
        if (!isfinite(fv))
            return MCS_ERR_NOT_FINITE;
        sum += fv * weights[j];
    }
    *out = sum / (double)k; /* eq. 8: I = (1/K) sum_n f_n s_n */
    return MCS_OK;
}

mcs_status mcs_estimate_points(size_t k, mcs_estimate_integrand f, void *ctx,
                               const double *points, const double *weights, double *out)
{
    if (f == NULL || points == NULL || out == NULL)
        return MCS_ERR_NULL;
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    mcs_status st = mcs_check_points_(k, points, weights);
    if (st != MCS_OK)
        return st;
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
