/* Fourier power of the torus-periodic integrands and the integration error
 * the point-set eq. 14 predicts from a measured periodogram (integrand.h). */
#include "mcspec/integrand.h"
#include "integrand_internal.h"
#include "core/internal.h"

#include <float.h>
#include <math.h>
#include <stddef.h>

/* J1 by its power series sum_j (-1)^j (x/2)^(2j+1) / (j! (j+1)!) below 15
 * (terms up to about e^15 / (15 pi) ~ 7e4 of a result of order 0.2: an
 * absolute error near 1e-11), and above by Hankel's asymptotic series
 * J1(x) = sqrt(2 / (pi x)) (P cos w - Q sin w), w = x - 3 pi / 4, summed to
 * its smallest term (about e^(-2x) < 1e-13 at x = 15). */
static double bessel_j1(double x)
{
    const double ax = fabs(x);
    double r;
    if (ax < 15.0) {
        const double q = 0.25 * ax * ax;
        double term = 0.5 * ax, sum = term;
        for (int j = 1; j < 200; ++j) {
            term *= -q / ((double)j * (double)(j + 1));
            sum += term;
            if (fabs(term) < 1e-17 * fabs(sum) && (double)j > ax)
                break;
        }
        r = sum;
    } else {
        double t = 1.0, p = 1.0, qs = 0.0, last = 1.0;
        for (int j = 1; j < 200; ++j) {
            const double odd = (double)(2 * j - 1);
            t *= (4.0 - odd * odd) / ((double)j * 8.0 * ax);
            if (fabs(t) > last || fabs(t) < 1e-17)
                break;
            last = fabs(t);
            switch (j & 3) { /* P = t0 - t2 + t4 ..., Q = t1 - t3 + t5 ... */
            case 1: qs += t; break;
            case 2: p -= t; break;
            case 3: qs -= t; break;
            default: p += t; break;
            }
        }
        const double w = ax - 0.75 * MCS_INTEG_PI;
        r = sqrt(2.0 / (MCS_INTEG_PI * ax)) * (p * cos(w) - qs * sin(w));
    }
    return x < 0.0 ? -r : r;
}

double mcs_integ_power_(const mcs_integrand *f, long kx, long ky)
{
    const double s = f->width;
    switch (f->family) {
    case MCS_INTEGRAND_GAUSSIAN_PERIODIC: {
        /* per axis (s sqrt(2 pi) exp(-2 pi^2 s^2 k^2))^2 */
        const double k2 = (double)kx * (double)kx + (double)ky * (double)ky;
        return pow(MCS_INTEG_TWO_PI * s * s, (double)f->dim) *
               exp(-2.0 * MCS_INTEG_TWO_PI * MCS_INTEG_PI * s * s * k2);
    }
    case MCS_INTEGRAND_DISK: {
        if (f->dim == 1u) {
            if (kx == 0)
                return 4.0 * s * s;
            const double v = sin(MCS_INTEG_TWO_PI * (double)kx * s) / (MCS_INTEG_PI * (double)kx);
            return v * v;
        }
        if (kx == 0 && ky == 0)
            return MCS_INTEG_PI * MCS_INTEG_PI * s * s * s * s;
        const double rho = sqrt((double)kx * (double)kx + (double)ky * (double)ky);
        const double v = s * bessel_j1(MCS_INTEG_TWO_PI * s * rho) / rho;
        return v * v;
    }
    case MCS_INTEGRAND_COSINE: {
        const long k[MCS_INTEGRAND_MAX_DIM] = {kx, ky};
        double p = 1.0;
        for (size_t i = 0; i < f->dim && i < (size_t)MCS_INTEGRAND_MAX_DIM; ++i)
            p *= k[i] == 0 ? 1.0
                 : (k[i] == f->freq[i] || k[i] == -f->freq[i]) ? 0.25 * f->amp[i] * f->amp[i]
                                                               : 0.0;
        return p;
    }
    default: break;
    }
    return 0.0;
}

mcs_status mcs_integrand_power(const mcs_integrand *f, long freq_x, long freq_y, double *out)
{
    if (f == NULL || out == NULL)
        return MCS_ERR_NULL;
    if (!mcs_integ_valid_(f))
        return MCS_ERR_UNINIT;
    if (!mcs_integrand_is_periodic(f->family))
        return MCS_ERR_DOMAIN;
    const long cap = (long)MCS_POINTSET_MAX_FREQ;
    if (freq_x < -cap || freq_x > cap || freq_y < -cap || freq_y > cap ||
        (f->dim == 1u && freq_y != 0))
        return MCS_ERR_FREQ_RANGE;
    return mcs_set_(out, mcs_integ_power_(f, freq_x, freq_y));
}

/* ---- Prediction -------------------------------------------------------------- */

/* A prediction's arguments and running sums, in one place: helpers of more
 * than six arguments pass some on the stack, which gcc's -fstack-usage
 * reports as a dynamic frame (make stack). */
typedef struct {
    const mcs_integrand *fs;
    size_t m, k;
    double *predicted, *tail;
    double s, w, p_tail; /* sum |f^|^2 <P>, sum |f^|^2, the largest P on the outer shell */
} prediction;

/* The checks both predictions share, of everything but the accumulator. */
static mcs_status check_family(const prediction *pr, size_t dim, const void *ps)
{
    const mcs_integrand *fs = pr->fs;
    const size_t m = pr->m;
    if (fs == NULL || ps == NULL || pr->predicted == NULL || pr->tail == NULL)
        return MCS_ERR_NULL;
    if (mcs_overlap_(pr->predicted, sizeof *pr->predicted, pr->tail, sizeof *pr->tail))
        return MCS_ERR_ALIAS;
    if (m == 0u || pr->k == 0u)
        return MCS_ERR_K_RANGE;
    for (size_t i = 0; i < m; ++i)
        if (!mcs_integ_valid_(&fs[i]))
            return MCS_ERR_UNINIT;
    for (size_t i = 0; i < m; ++i)
        if (fs[i].family != fs[0].family || fs[i].dim != dim)
            return MCS_ERR_MISMATCH;
    return mcs_integrand_is_periodic(fs[0].family) ? MCS_OK : MCS_ERR_DOMAIN;
}

/* Sums over the integrands for one wave vector q (counted `mult` times: q
 * and -q): |f^(q)|^2 <P(q)> into pr->s and |f^(q)|^2 into pr->w. */
static void add_wave(prediction *pr, long qx, long qy, double p, double mult)
{
    for (size_t i = 0; i < pr->m; ++i) {
        const double a = mult * mcs_integ_power_(&pr->fs[i], qx, qy);
        pr->s += a * p;
        pr->w += a;
    }
}

/* The results from the sums: terms is how many wave vectors were summed. */
static mcs_status finish(const prediction *pr, double terms)
{
    double q = 0.0;
    for (size_t i = 0; i < pr->m; ++i) {
        double i1, q1;
        mcs_integ_moments_(&pr->fs[i], &i1, &q1);
        q += q1;
    }
    const double left = q - pr->w; /* Parseval: sum over |q|_inf > F of |f^|^2 */
    const double rounding = (terms + 16.0) * DBL_EPSILON * q;
    const double kd = (double)pr->k, md = (double)pr->m;
    *pr->predicted = pr->s / (kd * md);
    *pr->tail = pr->p_tail * ((left > 0.0 ? left : 0.0) + rounding) / (kd * md);
    return MCS_OK;
}

mcs_status mcs_integrand_predict(const mcs_integrand *fs, size_t m, const mcs_pointset2d *ps,
                                 size_t k, double *predicted, double *tail)
{
    prediction pr = {fs, m, k, predicted, tail, 0.0, 0.0, 1.0};
    mcs_status st = check_family(&pr, 2u, ps);
    double p = 0.0;
    if (st == MCS_OK)
        st = mcs_pointset2d_power(ps, 0, 0, &p);
    if (st != MCS_OK)
        return st;
    const long fmax = (long)ps->freq_max;
    add_wave(&pr, 0, 0, 0.0, 1.0); /* k = 0: in the Parseval sum, not the error */
    for (long qy = 0; qy <= fmax; ++qy)
        for (long qx = qy == 0 ? 1 : -fmax; qx <= fmax; ++qx) {
            if (mcs_pointset2d_power(ps, qx, qy, &p) != MCS_OK)
                return MCS_ERR_INVARIANT;
            if ((qx == fmax || qx == -fmax || qy == fmax) && p > pr.p_tail)
                pr.p_tail = p;
            add_wave(&pr, qx, qy, p, 2.0);
        }
    return finish(&pr, (double)(2 * fmax + 1) * (double)(2 * fmax + 1));
}

mcs_status mcs_integrand_predict_1d(const mcs_integrand *fs, size_t m, const mcs_pointset *ps,
                                    size_t k, double *predicted, double *tail)
{
    prediction pr = {fs, m, k, predicted, tail, 0.0, 0.0, 1.0};
    mcs_status st = check_family(&pr, 1u, ps);
    double p = 0.0;
    if (st == MCS_OK)
        st = mcs_pointset_power(ps, 0, &p);
    if (st != MCS_OK)
        return st;
    const long fmax = (long)ps->freq_max;
    add_wave(&pr, 0, 0, 0.0, 1.0);
    for (long q = 1; q <= fmax; ++q) {
        if (mcs_pointset_power(ps, q, &p) != MCS_OK)
            return MCS_ERR_INVARIANT;
        if (q == fmax && p > pr.p_tail)
            pr.p_tail = p;
        add_wave(&pr, q, 0, p, 2.0);
    }
    return finish(&pr, (double)(2 * fmax + 1));
}
