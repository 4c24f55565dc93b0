/* Integrand families: drawing, evaluation, exact integrals and the
 * public checks (integrand.h). */
#include "mcspec/integrand.h"
#include "integrand_internal.h"
#include "core/internal.h"
#include "random/rng_inline.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

#define SQRT_PI 1.77245385090551602730
#define SQRT_2 1.41421356237309504880

const char *mcs_integrand_family_str(mcs_integrand_family family)
{
    switch (family) {
    case MCS_INTEGRAND_GAUSSIAN: return "gaussian";
    case MCS_INTEGRAND_GAUSSIAN_PERIODIC: return "gaussian_periodic";
    case MCS_INTEGRAND_HEAVISIDE: return "heaviside";
    case MCS_INTEGRAND_DISK: return "disk";
    case MCS_INTEGRAND_COSINE: return "cosine";
    case MCS_INTEGRAND_BLINN_PHONG: return "blinn_phong";
    case MCS_INTEGRAND_GAUSSIAN_MIXTURE: return "gaussian_mixture";
    case MCS_INTEGRAND_FAMILIES: break;
    }
    return "unknown";
}

int mcs_integrand_is_periodic(mcs_integrand_family family)
{
    return family == MCS_INTEGRAND_GAUSSIAN_PERIODIC || family == MCS_INTEGRAND_DISK ||
           family == MCS_INTEGRAND_COSINE;
}

static int family_ok(mcs_integrand_family family)
{
    return (unsigned)family < (unsigned)MCS_INTEGRAND_FAMILIES; /* an enum may be unsigned (ARM) */
}

int mcs_integrand_has_dim(mcs_integrand_family family, size_t dim)
{
    if (!family_ok(family) || (dim != 1u && dim != 2u))
        return 0;
    return family != MCS_INTEGRAND_BLINN_PHONG || dim == 2u; /* utk's BlinnPhong is 2D */
}

static int unit_ok(double x)
{
    return x >= 0.0 && x < 1.0;
}

static int in_range(double x, double lo, double hi)
{
    return x >= lo && x <= hi;
}

int mcs_integ_valid_(const mcs_integrand *f)
{
    if (!mcs_integrand_has_dim(f->family, f->dim))
        return 0;
    if (mcs_integ_is_utk_(f->family))
        return mcs_integ_utk_valid_(f);
    const size_t d = f->dim;
    for (size_t i = 0; i < d; ++i)
        if (f->family != MCS_INTEGRAND_COSINE && !unit_ok(f->centre[i]))
            return 0;
    switch (f->family) {
    case MCS_INTEGRAND_GAUSSIAN:
    case MCS_INTEGRAND_GAUSSIAN_PERIODIC:
        return in_range(f->width, MCS_INTEGRAND_GAUSSIAN_MIN_WIDTH,
                        MCS_INTEGRAND_GAUSSIAN_MAX_WIDTH);
    case MCS_INTEGRAND_DISK:
        return in_range(f->width, MCS_INTEGRAND_DISK_MIN_RADIUS, MCS_INTEGRAND_DISK_MAX_RADIUS);
    case MCS_INTEGRAND_HEAVISIDE: {
        if (d == 1u)
            return 1;
        const double n2 = f->normal[0] * f->normal[0] + f->normal[1] * f->normal[1];
        return fabs(n2 - 1.0) <= 1e-12; /* NaN fails too */
    }
    case MCS_INTEGRAND_BLINN_PHONG:
    case MCS_INTEGRAND_GAUSSIAN_MIXTURE:
        break;
    case MCS_INTEGRAND_COSINE:
        for (size_t i = 0; i < d; ++i)
            if (!unit_ok(f->amp[i]) || !in_range(f->phase[i], 0.0, MCS_INTEG_TWO_PI) ||
                f->freq[i] < 1 || f->freq[i] > MCS_INTEGRAND_COSINE_MAX_FREQ)
                return 0;
        return 1;
    case MCS_INTEGRAND_FAMILIES: break;
    }
    return 0;
}

mcs_status mcs_integrand_draw(mcs_integrand *f, mcs_integrand_family family, size_t dim,
                              mcs_rng *rng)
{
    if (f == NULL || rng == NULL)
        return MCS_ERR_NULL;
    if (!family_ok(family))
        return MCS_ERR_KIND;
    if (!mcs_integrand_has_dim(family, dim))
        return MCS_ERR_DOMAIN;
    if (!mcs_rng_is_seeded_(rng))
        return MCS_ERR_UNINIT;
    if (mcs_overlap_(f, sizeof *f, rng, sizeof *rng))
        return MCS_ERR_ALIAS;
    mcs_integrand g;
    memset(&g, 0, sizeof g);
    g.family = family;
    g.dim = dim;
    if (mcs_integ_is_utk_(family)) {
        mcs_integ_utk_draw_(&g, rng);
    } else if (family == MCS_INTEGRAND_COSINE) {
        for (size_t i = 0; i < dim; ++i) {
            g.amp[i] = mcs_rng_double_(rng);
            g.freq[i] = 1 + (long)mcs_rng_bounded_(rng, MCS_INTEGRAND_COSINE_MAX_FREQ);
            g.phase[i] = MCS_INTEG_TWO_PI * mcs_rng_double_(rng);
        }
    } else {
        for (size_t i = 0; i < dim; ++i)
            g.centre[i] = mcs_rng_double_(rng);
        const double u = mcs_rng_double_(rng);
        if (family == MCS_INTEGRAND_DISK)
            g.width = MCS_INTEGRAND_DISK_MIN_RADIUS +
                      u * (MCS_INTEGRAND_DISK_MAX_RADIUS - MCS_INTEGRAND_DISK_MIN_RADIUS);
        else if (family == MCS_INTEGRAND_HEAVISIDE && dim == 2u) {
            g.normal[0] = cos(MCS_INTEG_TWO_PI * u);
            g.normal[1] = sin(MCS_INTEG_TWO_PI * u);
        } else if (family != MCS_INTEGRAND_HEAVISIDE)
            g.width = MCS_INTEGRAND_GAUSSIAN_MIN_WIDTH +
                      u * (MCS_INTEGRAND_GAUSSIAN_MAX_WIDTH - MCS_INTEGRAND_GAUSSIAN_MIN_WIDTH);
    }
    *f = g;
    return MCS_OK;
}

/* ---- Evaluation ------------------------------------------------------------ */

/* The periodised 1D Gaussian at offset t = x - c in (-1, 1): the images
 * t - n, n = -3..3, skipping those below exp(-40) of the peak. */
static double periodic_gauss(double t, double s)
{
    const double inv = 1.0 / (2.0 * s * s), reach = 80.0 * s * s; /* t^2 / (2 s^2) > 40 */
    double sum = 0.0;
    for (int n = -MCS_INTEG_IMAGES; n <= MCS_INTEG_IMAGES; ++n) {
        const double u = t - (double)n;
        if (u * u <= reach)
            sum += exp(-u * u * inv);
    }
    return sum;
}

/* The toroidal distance of two coordinates in [0,1). */
static double torus_gap(double a, double b)
{
    const double t = fabs(a - b);
    return t <= 0.5 ? t : 1.0 - t;
}

double mcs_integ_eval_(const mcs_integrand *f, const double *x)
{
    const size_t d = f->dim;
    switch (f->family) {
    case MCS_INTEGRAND_GAUSSIAN: {
        double r2 = 0.0;
        for (size_t i = 0; i < d; ++i)
            r2 += (x[i] - f->centre[i]) * (x[i] - f->centre[i]);
        return exp(-r2 / (2.0 * f->width * f->width));
    }
    case MCS_INTEGRAND_GAUSSIAN_PERIODIC: {
        double v = 1.0;
        for (size_t i = 0; i < d; ++i)
            v *= periodic_gauss(x[i] - f->centre[i], f->width);
        return v;
    }
    case MCS_INTEGRAND_HEAVISIDE:
        if (d == 1u)
            return x[0] < f->centre[0] ? 1.0 : 0.0;
        return (x[0] - f->centre[0]) * f->normal[0] + (x[1] - f->centre[1]) * f->normal[1] > 0.0
                   ? 1.0
                   : 0.0;
    case MCS_INTEGRAND_DISK: {
        double r2 = 0.0;
        for (size_t i = 0; i < d; ++i) {
            const double t = torus_gap(x[i], f->centre[i]);
            r2 += t * t;
        }
        return r2 < f->width * f->width ? 1.0 : 0.0;
    }
    case MCS_INTEGRAND_COSINE: {
        double v = 1.0;
        for (size_t i = 0; i < d; ++i)
            v *= 1.0 + f->amp[i] * cos(MCS_INTEG_TWO_PI * (double)f->freq[i] * x[i] + f->phase[i]);
        return v;
    }
    case MCS_INTEGRAND_BLINN_PHONG:
    case MCS_INTEGRAND_GAUSSIAN_MIXTURE: return mcs_integ_utk_eval_(f, x);
    case MCS_INTEGRAND_FAMILIES: break;
    }
    return 0.0;
}

/* ---- Exact integrals ------------------------------------------------------- */

/* int_0^1 of the 1D Gaussian exp(-(x - c)^2 / (2 s^2)) (scale 1) and of its
 * square exp(-(x - c)^2 / s^2) (scale 2): with w = s sqrt(2 / scale),
 * w sqrt(pi) / 2 [erf((1 - c) / w) + erf(c / w)]. */
static double gauss_unit(double c, double s, double scale)
{
    const double w = s * sqrt(2.0 / scale);
    return 0.5 * w * SQRT_PI * (erf((1.0 - c) / w) + erf(c / w));
}

/* int over the torus of the periodised Gaussian squared, per axis:
 * s sqrt(pi) sum_n exp(-n^2 / (4 s^2)) (the overlaps of image pairs). */
static double periodic_square(double s)
{
    double sum = 0.0;
    for (int n = -2 * MCS_INTEG_IMAGES; n <= 2 * MCS_INTEG_IMAGES; ++n)
        sum += exp(-(double)(n * n) / (4.0 * s * s));
    return s * SQRT_PI * sum;
}

void mcs_integ_moments_(const mcs_integrand *f, double *integral, double *square)
{
    const size_t d = f->dim;
    double i1 = 1.0, q = 1.0;
    switch (f->family) {
    case MCS_INTEGRAND_GAUSSIAN:
        for (size_t i = 0; i < d; ++i) {
            i1 *= gauss_unit(f->centre[i], f->width, 1.0);
            q *= gauss_unit(f->centre[i], f->width, 2.0);
        }
        break;
    case MCS_INTEGRAND_GAUSSIAN_PERIODIC:
        for (size_t i = 0; i < d; ++i) {
            i1 *= f->width * SQRT_2 * SQRT_PI;
            q *= periodic_square(f->width);
        }
        break;
    case MCS_INTEGRAND_HEAVISIDE:
        i1 = q = mcs_integ_halfplane_area_(f, 0.0, 1.0, 0.0, 1.0);
        break;
    case MCS_INTEGRAND_DISK:
        i1 = q = d == 1u ? 2.0 * f->width : MCS_INTEG_PI * f->width * f->width;
        break;
    case MCS_INTEGRAND_COSINE:
        for (size_t i = 0; i < d; ++i)
            q *= 1.0 + 0.5 * f->amp[i] * f->amp[i];
        break;
    case MCS_INTEGRAND_BLINN_PHONG:
    case MCS_INTEGRAND_GAUSSIAN_MIXTURE: /* by quadrature, once, in the draw */
        i1 = f->integral;
        q = f->square;
        break;
    case MCS_INTEGRAND_FAMILIES: break;
    }
    *integral = i1;
    *square = q;
}

/* ---- The public calls ------------------------------------------------------- */

static mcs_status check(const mcs_integrand *f, const void *out)
{
    if (f == NULL || out == NULL)
        return MCS_ERR_NULL;
    return mcs_integ_valid_(f) ? MCS_OK : MCS_ERR_UNINIT;
}

mcs_status mcs_integrand_eval(const mcs_integrand *f, const double *x, double *out)
{
    mcs_status st = check(f, out);
    if (st == MCS_OK && x == NULL)
        st = MCS_ERR_NULL;
    if (st != MCS_OK)
        return st;
    for (size_t i = 0; i < f->dim; ++i)
        if (!unit_ok(x[i]))
            return MCS_ERR_POINT_RANGE;
    return mcs_set_(out, mcs_integ_eval_(f, x));
}

mcs_status mcs_integrand_estimate(const mcs_integrand *f, size_t k, const double *points,
                                  double *out)
{
    mcs_status st = check(f, out);
    if (st == MCS_OK && points == NULL)
        st = MCS_ERR_NULL;
    if (st != MCS_OK)
        return st;
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    if (k > SIZE_MAX / f->dim)
        return MCS_ERR_POINT_RANGE;
    const size_t n = k * f->dim;
    for (size_t i = 0; i < n; ++i)
        if (!unit_ok(points[i]))
            return MCS_ERR_POINT_RANGE;
    double sum = 0.0, lo = 0.0;
    for (size_t j = 0; j < k; ++j)
        mcs_kahan_add_(&sum, &lo, mcs_integ_eval_(f, points + j * f->dim));
    return mcs_set_(out, sum / (double)k);
}

mcs_status mcs_integrand_integral(const mcs_integrand *f, double *out)
{
    const mcs_status st = check(f, out);
    if (st != MCS_OK)
        return st;
    double i1, q;
    mcs_integ_moments_(f, &i1, &q);
    return mcs_set_(out, i1);
}

mcs_status mcs_integrand_variance(const mcs_integrand *f, double *out)
{
    const mcs_status st = check(f, out);
    if (st != MCS_OK)
        return st;
    double i1, q;
    mcs_integ_moments_(f, &i1, &q);
    const double v = q - i1 * i1;
    return mcs_set_(out, v > 0.0 ? v : 0.0);
}

mcs_status mcs_integrand_jittered_mse(const mcs_integrand *f, size_t strata_x, size_t strata_y,
                                      double *out)
{
    const mcs_status st = check(f, out);
    if (st != MCS_OK)
        return st;
    if (!mcs_integ_has_jittered_(f))
        return MCS_ERR_DOMAIN;
    if (strata_x == 0u || strata_y == 0u || (f->dim == 1u && strata_y != 1u) ||
        strata_x > (size_t)MCS_INTEGRAND_JITTERED_MAX_K / strata_y)
        return MCS_ERR_K_RANGE;
    return mcs_set_(out, mcs_integ_jittered_(f, strata_x, strata_y));
}
