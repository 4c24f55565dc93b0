/* The read-outs of integrands (eq. 8 averaged, Var[I] and Cov(I_f, I_g)):
 * quadratic forms over a view's moments, measured or exact (readout.h), and
 * the checks of their integrands. */
#include "readout.h"
#include "core/internal.h"

#include <float.h>
#include <math.h>

double mcs_readout_form(const mcs_readout *view, size_t k, const double *f, const double *g)
{
    /* Cov(s)_mn = <s_m s_n> - <s_m><s_n>, summed row by row. */
    const size_t n = view->n;
    const double sc = view->scale;
    double sum = 0.0;
    for (size_t m = 0; m < n; ++m) {
        const double mean_m = mcs_readout_first(view, m) * sc;
        double acc = 0.0;
        for (size_t b = 0; b < n; ++b)
            acc += (mcs_readout_second(view, m, b) * sc - mean_m * (mcs_readout_first(view, b) * sc)) * g[b];
        sum += f[m] * acc;
    }
    const double kd = (double)k;
    return sum / (kd * kd);
}

/* Rounding bound of a form over the moments: (2N + 16) DBL_EPSILON times the
 * sum of the magnitudes of its terms, (1/K^2) sum |f_m| |g_n| (|<s_m s_n>| +
 * |<s_m>| |<s_n>|) (of d = s - c with a shift). Each term carries the few
 * roundings of the moments and of its product, and a sum of N terms at most
 * N more (twice: rows, then the sum of rows). Measured moments add the
 * rounding their sums carry (mcs_readout_accumulated). */
double mcs_readout_form_bound(const mcs_readout *view, size_t k, const double *f,
                              const double *g)
{
    const size_t n = view->n;
    const double sc = view->scale;
    double sum = 0.0;
    for (size_t m = 0; m < n; ++m) {
        const double mean_m = fabs(mcs_readout_first(view, m) * sc);
        double acc = 0.0;
        for (size_t b = 0; b < n; ++b)
            acc += (fabs(mcs_readout_second(view, m, b) * sc) + mean_m * fabs(mcs_readout_first(view, b) * sc)) *
                   fabs(g[b]);
        sum += fabs(f[m]) * acc;
    }
    const double kd = (double)k;
    return ((2.0 * (double)n + 16.0) * DBL_EPSILON * sum + mcs_readout_accumulated(view, f, g)) /
           (kd * kd);
}

/* ---- the estimator -------------------------------------------------------- */

mcs_status mcs_readout_check_integrand(const mcs_readout_source *src, size_t n, size_t k,
                                       const double *f, mcs_readout *view)
{
    if (f == NULL) /* as mcs_readout_open_n would say, stated here for the analyser */
        return MCS_ERR_NULL;
    mcs_status st = mcs_readout_open_n(1, src, n, view);
    if (st != MCS_OK)
        return st;
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    if (view->k != 0u && k != view->k) /* exact moments are for one K */
        return MCS_ERR_MISMATCH;
    if (!mcs_all_finite_(n, f))
        return MCS_ERR_NOT_FINITE;
    return MCS_OK;
}

mcs_status mcs_readout_check_integrands(const mcs_readout_source *src, size_t n, size_t k,
                                        const double *f, const double *g, mcs_readout *view)
{
    mcs_status st = g == NULL ? MCS_ERR_NULL : mcs_readout_check_integrand(src, n, k, f, view);
    return st == MCS_OK ? mcs_readout_check_integrand(src, n, k, g, view) : st;
}

/* *out = value if finite; an integrand so large that the value overflows is
 * MCS_ERR_MAGNITUDE (the object's own values cannot make it overflow). */
static mcs_status finite_result(double value, double *out)
{
    return isfinite(value) ? mcs_set_(out, value) : MCS_ERR_MAGNITUDE;
}

/* <I> = (1/K) sum_n f_n <s_n>. */
static double estimator_mean_at(const mcs_readout *view, size_t k, const double *f)
{
    double sum = 0.0;
    for (size_t b = 0; b < view->n; ++b)
        sum += f[b] * mcs_readout_mean_entry(view, b);
    return sum / (double)k;
}

mcs_status mcs_readout_integrand_value(const mcs_readout_source *src, size_t n,
                                       size_t k, const double *f, mcs_readout_value value,
                                       double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    mcs_readout v;
    mcs_status st = mcs_readout_check_integrand(src, n, k, f, &v);
    return st == MCS_OK ? finite_result(value(&v, k, f), out) : st;
}

mcs_status mcs_readout_estimator_mean(const mcs_readout_source *src, size_t n,
                                      size_t k, const double *f, double *out)
{
    return mcs_readout_integrand_value(src, n, k, f, estimator_mean_at, out);
}

mcs_status mcs_readout_variance(const mcs_readout_source *src, size_t n, size_t k,
                                const double *f, double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    mcs_readout v;
    mcs_status st = mcs_readout_check_integrand(src, n, k, f, &v);
    if (st != MCS_OK)
        return st;
    double var = mcs_readout_form(&v, k, f, f);
    if (var < 0.0) { /* f^T Cov f: never negative but for rounding */
        st = mcs_readout_clamp(mcs_readout_form_bound(&v, k, f, f), &var);
        if (st != MCS_OK)
            return st;
    }
    return finite_result(var, out);
}

mcs_status mcs_readout_estimator_covariance(const mcs_readout_source *src, size_t n,
                                            size_t k, const double *f, const double *g,
                                            double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    mcs_readout v;
    mcs_status st = mcs_readout_check_integrands(src, n, k, f, g, &v);
    return st == MCS_OK ? finite_result(mcs_readout_form(&v, k, f, g), out) : st;
}
