/* psa's effective Nyquist frequency and oscillation metric of a radial
 * power spectrum (radial.h). Both are computed in index units (nu_i = i
 * step): step cancels from C_i and from the oscillation's ratio, so only
 * the threshold index, the range's end and the returned frequency see it,
 * and no intermediate can overflow for powers and steps in range. */
#include "mcspec/radial.h"

#include <math.h>
#include <stddef.h>

static mcs_status check(size_t dim, size_t k, size_t n, const double *power, double step,
                        const double *out)
{
    if (power == NULL || out == NULL)
        return MCS_ERR_NULL;
    if ((dim != 1u && dim != 2u) || !(step >= MCS_RADIAL_MIN_STEP && step <= MCS_RADIAL_MAX_STEP) ||
        n < 2u)
        return MCS_ERR_DOMAIN;
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    for (size_t i = 1; i < n; ++i) {
        if (!isfinite(power[i]))
            return MCS_ERR_NOT_FINITE;
        if (fabs(power[i]) > MCS_RADIAL_MAX_POWER)
            return MCS_ERR_MAGNITUDE;
    }
    return MCS_OK;
}

/* x^d and d x^(d - 1) for d = 1, 2. */
static double pow_d(size_t dim, double x)
{
    return dim == 1u ? x : x * x;
}

static double weight(size_t dim, double x)
{
    return dim == 1u ? 1.0 : 2.0 * x;
}

static double scale_of(size_t dim, size_t k)
{
    return dim == 1u ? (double)k : sqrt((double)k);
}

/* C's term of index j: P_j d j^(d - 1). */
static double term(size_t dim, const double *power, size_t j)
{
    return power[j] * weight(dim, (double)j);
}

mcs_status mcs_radial_effective_nyquist(size_t dim, size_t k, size_t n, const double *power,
                                        double step, double *out)
{
    const mcs_status st = check(dim, k, n, power, step, out);
    if (st != MCS_OK)
        return st;
    const double scale = scale_of(dim, k), i0f = floor(scale / 2.0 / step);
    size_t i0 = i0f >= (double)n ? n : (size_t)i0f;
    i0 = i0 < 1u ? 1u : i0;
    double sum = 0.0; /* sum_{j=1..i} of the terms */
    for (size_t j = 1; j < i0 && j < n; ++j)
        sum += term(dim, power, j);
    for (size_t i = i0; i < n; ++i) {
        sum += term(dim, power, i);
        if (!(sum / pow_d(dim, (double)i) > 0.5))
            continue;
        /* Down from i: C_j from the same sum, less the terms above j. Once
         * this finds no j, psa's later i find none either (their only new
         * j is themselves, with C above 0.5), so the answer is 0. */
        double back = sum;
        for (size_t j = i; j > 0u; --j) {
            if (back / pow_d(dim, (double)j) < 0.1) {
                *out = (double)j * step / scale;
                return MCS_OK;
            }
            back -= term(dim, power, j);
        }
        break;
    }
    *out = 0.0;
    return MCS_OK;
}

mcs_status mcs_radial_oscillations(size_t dim, size_t k, size_t n, const double *power,
                                   double step, double *out)
{
    const mcs_status st = check(dim, k, n, power, step, out);
    if (st != MCS_OK)
        return st;
    size_t io = 1u;
    double maxp = 0.0;
    for (size_t i = 1; i < n && maxp < 0.98; ++i)
        if (power[i] > maxp) {
            maxp = power[i];
            io = i;
        }
    /* x0, x1 and the samples in index units. */
    const double x0 = (double)io, reach = 5.0 * scale_of(dim, k) / step;
    const double x1 = x0 + reach < (double)n ? x0 + reach : (double)n;
    const double i1f = floor(x1 + 1.0);
    const size_t i1 = i1f >= (double)(n - 1u) ? n - 1u : (size_t)i1f;
    if (!(x1 > x0) || i1 <= io)
        return MCS_ERR_DOMAIN;
    double sum = 0.0;
    for (size_t i = io; i <= i1; ++i) {
        const double dev = power[i] - 1.0;
        const double v = dev * dev * weight(dim, (double)i);
        sum += i == io || i == i1 ? 0.5 * v : v;
    }
    *out = 10.0 * sqrt(sum / (pow_d(dim, x1) - pow_d(dim, x0)));
    return MCS_OK;
}
