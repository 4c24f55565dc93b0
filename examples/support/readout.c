#include "readout.h"

double ex_or_na(mcs_status st, const double *v)
{
    return st == MCS_OK ? *v : EX_NA;
}

ex_complex ex_complex_or_na(mcs_status st, const double *re, const double *im)
{
    ex_complex c = {EX_NA, EX_NA};
    if (st == MCS_OK) {
        c.re = *re;
        c.im = *im;
    }
    return c;
}

double ex_mean(const mcs_welford *w, double *stderr_out)
{
    double m = 0.0, se = 0.0;
    if (stderr_out != NULL)
        *stderr_out = ex_or_na(mcs_welford_stderr(w, &se), &se);
    return ex_or_na(mcs_welford_mean(w, &m), &m);
}

double ex_variance(const mcs_welford *w, double *stderr_out)
{
    double v = 0.0, se = 0.0;
    if (stderr_out != NULL)
        *stderr_out = ex_or_na(mcs_welford_variance_stderr(w, &se), &se);
    return ex_or_na(mcs_welford_variance(w, &v), &v);
}

double ex_spectrum_power(const mcs_spectrum *spectrum, size_t freq, double *stderr_out)
{
    double p = 0.0, se = 0.0;
    if (stderr_out != NULL)
        *stderr_out = ex_or_na(mcs_spectrum_power_stderr(spectrum, freq, &se), &se);
    return ex_or_na(mcs_spectrum_power(spectrum, freq, &p), &p);
}

size_t ex_fold(size_t m, size_t q)
{
    return q <= m / 2u ? q : m - q;
}
