#include "mcspec/estimate.h"
#include "core/internal.h"

#include <math.h>

/* One sample's term f w of eq. 8, f finite: MCS_ERR_NOT_FINITE for a
 * non-finite f, MCS_ERR_MAGNITUDE above MCS_ESTIMATE_MAX_ABS (an overflowed
 * product included, whose magnitude is infinite). */
static mcs_status add_term(double fv, double w, double *sum)
{
    if (!isfinite(fv))
        return MCS_ERR_NOT_FINITE;
    const double t = fv * w;
    if (!(fabs(t) <= MCS_ESTIMATE_MAX_ABS))
        return MCS_ERR_MAGNITUDE;
    *sum += t; /* at most K 2^110: no overflow */
    return MCS_OK;
}

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
    for (size_t j = 0; j < k && st == MCS_OK; ++j)
        st = add_term(f[bins[j]], weights[j], &sum);
    if (st != MCS_OK)
        return st;
    *out = sum / (double)k; /* eq. 8: I = (1/K) sum_n f_n s_n */
    return MCS_OK;
}

/* The body of both point calls, over double or float points (internal.h):
 * f sees each x_j widened exactly, so the two give the same bits. */
static MCS_ALWAYS_INLINE mcs_status estimate_points(size_t k, mcs_estimate_integrand f, void *ctx,
                                                    mcs_points_ points, const double *weights,
                                                    double *out)
{
    if (f == NULL || mcs_points_addr_(points) == NULL || out == NULL)
        return MCS_ERR_NULL;
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    mcs_status st = mcs_check_points_(k, points, weights);
    if (st != MCS_OK)
        return st;
    double sum = 0.0;
    for (size_t j = 0; j < k && st == MCS_OK; ++j)
        st = add_term(f(mcs_point_(points, j), ctx), weights != NULL ? weights[j] : 1.0, &sum);
    if (st != MCS_OK)
        return st;
    *out = sum / (double)k;
    return MCS_OK;
}

mcs_status mcs_estimate_points(size_t k, mcs_estimate_integrand f, void *ctx,
                               const double *points, const double *weights, double *out)
{
    return estimate_points(k, f, ctx, mcs_points_d_(points), weights, out);
}

mcs_status mcs_estimate_points_f(size_t k, mcs_estimate_integrand f, void *ctx,
                                 const float *points, const double *weights, double *out)
{
    return estimate_points(k, f, ctx, mcs_points_f_(points), weights, out);
}
