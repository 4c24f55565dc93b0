/* psa's spectral check: the radial power the mean RDF implies (pcf.h),
 * the Hankel transform (2D) or cosine transform (1D) of g - 1 bin by bin. */
#include "mcspec/pcf.h"
#include "pcf_internal.h"

#include <math.h>
#include <stddef.h>

static const double pi = 3.14159265358979323846;

/* J1(x) = (1/2 pi) int_0^{2 pi} cos(t - x sin t) dt: the integrand is
 * periodic and entire, so the M-point trapezoid rule errs by about
 * J_{M-1}(x) + J_{M+1}(x) (Trefethen and Weideman 2014, "The exponentially
 * convergent trapezoidal rule"). Past the turning point J_{x + t x^(1/3)}(x)
 * is about (2/x)^(1/3) Ai(2^(1/3) t), below 1e-17 for t >= 12, so
 * M = |x| + 12 |x|^(1/3) + 40. Above 1e4, Hankel's expansion. */
double mcs_pcf_bessel_j1_(double x)
{
    if (fabs(x) > 1e4) {
        /* Hankel's expansion (Abramowitz and Stegun 9.2.5-9.2.10, mu = 4):
         * the first omitted term is below 1e-17 of the value here. */
        const double ax = fabs(x), z = 8.0 * ax, t = ax - 0.75 * pi;
        const double p = 1.0 - 3.0 * (-5.0) / (2.0 * z * z);
        const double q = 3.0 / z - 3.0 * (-5.0) * (-21.0) / (6.0 * z * z * z);
        const double j = sqrt(2.0 / (pi * ax)) * (p * cos(t) - q * sin(t));
        return x < 0.0 ? -j : j;
    }
    const size_t m = (size_t)(fabs(x) + 12.0 * cbrt(fabs(x))) + 40u;
    double sum = 0.0;
    for (size_t j = 0; j < m; ++j) {
        const double t = 2.0 * pi * (double)j / (double)m;
        sum += cos(t - x * sin(t));
    }
    return sum / (double)m;
}

/* The ring integral of e^{-2 pi i f.r} over [0, r) (absolute r): r J1(2 pi f r) / f
 * in 2D, sin(2 pi f r) / (pi f) in 1D; pi r^2 and 2 r at f = 0. */
static double ring_transform(size_t dim, double f, double r)
{
    if (f == 0.0)
        return dim == 1u ? 2.0 * r : pi * r * r;
    return dim == 1u ? sin(2.0 * pi * f * r) / (pi * f)
                     : r * mcs_pcf_bessel_j1_(2.0 * pi * f * r) / f;
}

mcs_status mcs_pcf_power(const mcs_pcf *acc, double freq, double *out)
{
    mcs_status st = out == NULL ? MCS_ERR_NULL : mcs_pcf_check_(acc);
    if (st != MCS_OK)
        return st;
    if (acc->estimator != MCS_PCF_RDF)
        return MCS_ERR_KIND;
    if (acc->count == 0u)
        return MCS_ERR_EMPTY;
    if (acc->k_min != acc->k_max)
        return MCS_ERR_MISMATCH;
    if (!(freq >= 0.0 && freq <= MCS_PCF_MAX_FREQ))
        return MCS_ERR_DOMAIN;
    const size_t k = acc->k_max;
    const double w = acc->radius / (double)acc->bins * mcs_pcf_spacing_(acc->dim, k);
    double sum = 0.0, prev = ring_transform(acc->dim, freq, 0.0);
    for (size_t b = 0; b < acc->bins; ++b) {
        const double next = ring_transform(acc->dim, freq, (double)(b + 1u) * w);
        sum += (acc->mean[b] - 1.0) * (next - prev);
        prev = next;
    }
    *out = 1.0 + (double)(k - 1u) * sum;
    return MCS_OK;
}
