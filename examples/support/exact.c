#include "exact.h"
#include "readout.h"

static mcs_status exact_init(ex_exact *ex, const mcs_pattern *pat, int full)
{
    ex->n = pat->n;
    ex->k = pat->k;
    ex->full = full;
    mcs_status st = ex->full ? mcs_theory_init(&ex->theory, pat)
                             : mcs_theory_spectrum_init(&ex->spectrum, pat);
    if (st != MCS_OK)
        return st;
    if (!ex->full)
        return mcs_theory_power_spectrum(&ex->spectrum, ex->n, ex->power);
    for (size_t q = 0; q < ex->n; ++q) {
        double v = 0.0;
        ex->power[q] = ex_or_na(mcs_theory_power(&ex->theory, q, &v), &v);
    }
    return MCS_OK;
}

mcs_status ex_exact_init(ex_exact *ex, const mcs_pattern *pat)
{
    return exact_init(ex, pat, pat->n <= (size_t)MCS_MAX_COV_N);
}

mcs_status ex_exact_init_spectrum(ex_exact *ex, const mcs_pattern *pat)
{
    return exact_init(ex, pat, 0);
}

const mcs_theory *ex_exact_theory(const ex_exact *ex)
{
    return ex->full ? &ex->theory : NULL;
}

double ex_exact_power(const ex_exact *ex, size_t freq)
{
    return freq < ex->n ? ex->power[freq] : EX_NA;
}

ex_complex ex_exact_mean(const ex_exact *ex, size_t freq)
{
    double a = 0.0, b = 0.0;
    mcs_status st = ex->full ? mcs_theory_mean(&ex->theory, freq, &a, &b)
                             : mcs_theory_spectrum_mean(&ex->spectrum, freq, &a, &b);
    return ex_complex_or_na(st, &a, &b);
}

ex_complex ex_exact_cross(const ex_exact *ex, size_t freq_k, size_t freq_l)
{
    double a = 0.0, b = 0.0;
    mcs_status st = ex->full ? mcs_theory_cross(&ex->theory, freq_k, freq_l, &a, &b)
                             : mcs_theory_spectrum_cross(&ex->spectrum, freq_k, freq_l, &a, &b);
    return ex_complex_or_na(st, &a, &b);
}

ex_complex ex_exact_covariance(const ex_exact *ex, size_t freq_k, size_t freq_l)
{
    double a = 0.0, b = 0.0;
    mcs_status st =
        ex->full ? mcs_theory_covariance(&ex->theory, freq_k, freq_l, &a, &b)
                 : mcs_theory_spectrum_covariance(&ex->spectrum, freq_k, freq_l, &a, &b);
    return ex_complex_or_na(st, &a, &b);
}

double ex_exact_mean_power(const ex_exact *ex)
{
    double sum = 0.0;
    for (size_t q = 1; q < ex->n; ++q)
        sum += ex_exact_power(ex, q);
    return ex->n > 1u ? sum / (double)(ex->n - 1u) : EX_NA;
}

double ex_exact_estimator_mean(const ex_exact *ex, const double *f)
{
    double v = 0.0;
    mcs_status st = ex->full
                        ? mcs_theory_estimator_mean(&ex->theory, ex->n, ex->k, f, &v)
                        : mcs_theory_spectrum_estimator_mean(&ex->spectrum, ex->n, ex->k, f, &v);
    return ex_or_na(st, &v);
}

double ex_exact_variance(const ex_exact *ex, const double *f)
{
    double v = 0.0;
    mcs_status st = ex->full ? mcs_theory_variance(&ex->theory, ex->n, ex->k, f, &v)
                             : mcs_theory_spectrum_variance(&ex->spectrum, ex->n, ex->k, f, &v);
    return ex_or_na(st, &v);
}

double ex_exact_estimator_covariance(const ex_exact *ex, const double *f, const double *g)
{
    double v = 0.0;
    mcs_status st =
        ex->full ? mcs_theory_estimator_covariance(&ex->theory, ex->n, ex->k, f, g, &v)
                 : mcs_theory_spectrum_estimator_covariance(&ex->spectrum, ex->n, ex->k, f, g, &v);
    return ex_or_na(st, &v);
}

size_t ex_large_n(size_t n)
{
    size_t factor = EX_LARGE_N_FACTOR;
    if (factor * n > (size_t)MCS_MAX_N)
        factor = (size_t)MCS_MAX_N / n;
    return factor >= 2u ? factor * n : 0u;
}
