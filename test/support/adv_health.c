/* The read-outs of an object after a successful update: each one either
 * returns an error or a finite value, >= 0 where it is a power, a variance or
 * a standard error (issue 10: no MCS_OK with a poisoned or negative
 * read-out). */
#include "adv.h"

#include <math.h>
#include <stdio.h>

static char health_msg[160];
static long *health_calls;

/* One read-out's status and value: returns 1 (and says why) if it broke. */
static int bad(const char *what, size_t i, int st, double v, int nonneg)
{
    ++*health_calls;
    if (st != MCS_OK || (isfinite(v) && (!nonneg || v >= 0.0)))
        return 0;
    snprintf(health_msg, sizeof health_msg, "read-out %s(%zu) = %.17g with MCS_OK", what, i, v);
    return 1;
}

/* Makes the call first, then looks at its value (argument evaluation order
 * is unspecified, so the two must not share one call of bad). */
#define CHECK(what, i, call, v, nonneg)               \
    do {                                              \
        const int st_ = (call);                       \
        if (bad(what, (size_t)(i), st_, v, nonneg))   \
            return 1;                                 \
    } while (0)

static int welford_bad(const mcs_welford *a)
{
    double v = 0.0;
    CHECK("welford_mean", 0, mcs_welford_mean(a, &v), v, 0);
    CHECK("welford_variance", 0, mcs_welford_variance(a, &v), v, 1);
    CHECK("welford_stderr", 0, mcs_welford_stderr(a, &v), v, 1);
    CHECK("welford_variance_stderr", 0, mcs_welford_variance_stderr(a, &v), v, 1);
    return 0;
}

static int spectrum_bad(const mcs_spectrum *a)
{
    double re = 0.0, im = 0.0, v = 0.0;
    for (size_t f = 0; f < a->n; ++f) {
        CHECK("spectrum_mean re", f, mcs_spectrum_mean(a, f, &re, &im), re, 0);
        CHECK("spectrum_mean im", f, MCS_OK, im, 0);
        CHECK("spectrum_mean_stderr", f, mcs_spectrum_mean_stderr(a, f, &v), v, 1);
        CHECK("spectrum_power", f, mcs_spectrum_power(a, f, &v), v, 1);
        CHECK("spectrum_power_stderr", f, mcs_spectrum_power_stderr(a, f, &v), v, 1);
    }
    return 0;
}

/* Moment and theory share their read-outs; the integrand is a fixed ramp. */
typedef struct {
    mcs_status (*mean)(const void *, size_t, double *, double *);
    mcs_status (*power)(const void *, size_t, double *);
    mcs_status (*cov)(const void *, size_t, size_t, double *, double *);
    mcs_status (*var)(const void *, size_t, size_t, const double *, double *);
    mcs_status (*emean)(const void *, size_t, size_t, const double *, double *);
} second_ops;

static mcs_status m_mean(const void *o, size_t f, double *re, double *im) { return mcs_moment_mean(o, f, re, im); }
static mcs_status m_power(const void *o, size_t f, double *v) { return mcs_moment_power(o, f, v); }
static mcs_status m_cov(const void *o, size_t f, size_t g, double *re, double *im) { return mcs_moment_covariance(o, f, g, re, im); }
static mcs_status m_var(const void *o, size_t n, size_t k, const double *f, double *v) { return mcs_moment_variance(o, n, k, f, v); }
static mcs_status m_emean(const void *o, size_t n, size_t k, const double *f, double *v) { return mcs_moment_estimator_mean(o, n, k, f, v); }
static mcs_status t_mean(const void *o, size_t f, double *re, double *im) { return mcs_theory_mean(o, f, re, im); }
static mcs_status t_power(const void *o, size_t f, double *v) { return mcs_theory_power(o, f, v); }
static mcs_status t_cov(const void *o, size_t f, size_t g, double *re, double *im) { return mcs_theory_covariance(o, f, g, re, im); }
static mcs_status t_var(const void *o, size_t n, size_t k, const double *f, double *v) { return mcs_theory_variance(o, n, k, f, v); }
static mcs_status t_emean(const void *o, size_t n, size_t k, const double *f, double *v) { return mcs_theory_estimator_mean(o, n, k, f, v); }

static const second_ops moment_ops = {m_mean, m_power, m_cov, m_var, m_emean};
static const second_ops theory_ops = {t_mean, t_power, t_cov, t_var, t_emean};

static int second_bad(const second_ops *ops, const void *a, size_t n, size_t k)
{
    static double f[MCS_MAX_COV_N];
    double re = 0.0, im = 0.0, v = 0.0;
    for (size_t q = 0; q < n; ++q) {
        f[q] = 1.0 + 0.25 * (double)q;
        CHECK("mean re", q, ops->mean(a, q, &re, &im), re, 0);
        CHECK("mean im", q, MCS_OK, im, 0);
        CHECK("power", q, ops->power(a, q, &v), v, 1);
        CHECK("covariance(k,k) re", q, ops->cov(a, q, q, &re, &im), re, 1);
    }
    CHECK("variance", n, ops->var(a, n, k, f, &v), v, 1);
    CHECK("estimator_mean", n, ops->emean(a, n, k, f, &v), v, 0);
    return 0;
}

static int autocorr_bad(const mcs_autocorr *a)
{
    static mcs_dft plan;
    static double re[MCS_MAX_N], im[MCS_MAX_N];
    if (mcs_dft_init(&plan, a->n) != MCS_OK)
        return 0;
    const int st = mcs_autocorr_mean(a, &plan, a->n, re, im);
    for (size_t f = 0; f < a->n; ++f) {
        CHECK("autocorr_mean re", f, st, re[f], 0);
        CHECK("autocorr_mean im", f, st, im[f], 0);
    }
    const int sp = mcs_autocorr_power(a, &plan, a->n, re);
    for (size_t f = 0; f < a->n; ++f)
        CHECK("autocorr_power", f, sp, re[f], 1);
    return 0;
}

static int pointset_bad(const mcs_pointset *a)
{
    double v = 0.0;
    for (size_t f = 0; f <= a->freq_max; ++f) {
        CHECK("pointset_power", f, mcs_pointset_power(a, (long)f, &v), v, 1);
        CHECK("pointset_power_stderr", f, mcs_pointset_power_stderr(a, (long)f, &v), v, 1);
    }
    return 0;
}

static int pointset2d_bad(const mcs_pointset2d *a)
{
    const long fm = (long)a->freq_max;
    double v = 0.0;
    for (long fy = -fm; fy <= fm; ++fy)
        for (long fx = -fm; fx <= fm; ++fx) {
            const long i = (fy + fm) * (2 * fm + 1) + fx + fm;
            CHECK("pointset2d_power", i, mcs_pointset2d_power(a, fx, fy, &v), v, 1);
            CHECK("pointset2d_power_stderr", i, mcs_pointset2d_power_stderr(a, fx, fy, &v), v, 1);
        }
    for (size_t r = 0; r <= a->freq_max; ++r) {
        CHECK("pointset2d_radial", r, mcs_pointset2d_radial(a, r, &v), v, 1);
        CHECK("pointset2d_radial_stderr", r, mcs_pointset2d_radial_stderr(a, r, &v), v, 1);
        CHECK("pointset2d_anisotropy", r, mcs_pointset2d_anisotropy(a, r, &v), v, 0);
    }
    return 0;
}

static int spectrum2d_bad(const mcs_spectrum2d *a)
{
    double re = 0.0, im = 0.0, v = 0.0;
    for (size_t l = 0; l < a->n_y; ++l)
        for (size_t k = 0; k < a->n_x; ++k) {
            const size_t i = l * a->n_x + k;
            CHECK("spectrum2d_mean re", i, mcs_spectrum2d_mean(a, k, l, &re, &im), re, 0);
            CHECK("spectrum2d_mean im", i, MCS_OK, im, 0);
            CHECK("spectrum2d_power", i, mcs_spectrum2d_power(a, k, l, &v), v, 1);
            CHECK("spectrum2d_power_stderr", i, mcs_spectrum2d_power_stderr(a, k, l, &v), v, 1);
            CHECK("spectrum2d_mean_stderr", i, mcs_spectrum2d_mean_stderr(a, k, l, &v), v, 1);
        }
    return 0;
}

/* Exact spectra at any N: the whole power spectrum at once (O(N^2); above
 * N = 256 the power at 16 frequencies, O(N) each), the covariance of a few
 * frequencies with themselves, Var[I] of a ramp. */
static int tspec_bad(const mcs_theory_spectrum *ts)
{
    static double f[MCS_MAX_N], power[MCS_MAX_N];
    const size_t n = ts->n, at[4] = {0u, 1u, n / 2u, n - 1u};
    double re = 0.0, im = 0.0, v = 0.0;
    for (size_t q = 0; q < n; ++q)
        f[q] = 1.0 + 0.25 * (double)(q % 9u);
    if (n <= 256u) {
        const int st = mcs_theory_power_spectrum(ts, n, power);
        for (size_t q = 0; q < n; ++q)
            CHECK("theory_power_spectrum", q, st, power[q], 1);
    } else {
        for (size_t q = 0; q < n; q += n / 16u)
            CHECK("theory_spectrum_power", q, mcs_theory_spectrum_power(ts, q, &v), v, 1);
    }
    for (int j = 0; j < 4; ++j) {
        CHECK("theory_spectrum_mean re", at[j], mcs_theory_spectrum_mean(ts, at[j], &re, &im), re, 0);
        CHECK("theory_spectrum_covariance(k,k) re", at[j],
              mcs_theory_spectrum_covariance(ts, at[j], at[j], &re, &im), re, 1);
    }
    CHECK("theory_spectrum_variance", n, mcs_theory_spectrum_variance(ts, n, ts->k, f, &v), v, 1);
    return 0;
}

/* Importance: p_n finite and > 0, or 0 with g_n = 0 (a bin outside the
 * support), the CDF monotone up to exactly 1, and the harmonic mean in
 * (0, 1] as documented when every bin is in the support, positive and
 * finite otherwise. */
static int importance_bad(const mcs_importance *imp)
{
    const size_t n = imp->n;
    int full = 1;
    for (size_t j = 0; j < n; ++j) {
        const int outside = imp->p[j] == 0.0 && imp->g[j] == 0.0;
        full &= !outside;
        CHECK("importance p", j, MCS_OK, imp->p[j] > 0.0 || outside ? imp->p[j] : -1.0, 1);
        CHECK("importance cdf step", j, MCS_OK, imp->cdf[j + 1] - imp->cdf[j], 1);
    }
    const double h = imp->harmonic_mean;
    CHECK("importance cdf[n] - 1", n, MCS_OK, imp->cdf[n] == 1.0 ? 0.0 : -1.0, 1);
    CHECK("importance harmonic_mean in (0,1], or > 0 with bins outside the support", n, MCS_OK,
          h > 0.0 && (h <= 1.0 || !full) ? h : -1.0, 1);
    double re = 0.0, im = 0.0;
    CHECK("importance_q re", 0, mcs_importance_q(imp, 0, &re, &im), re, 1);
    return 0;
}

const char *adv_health(int type, const void *obj, long *calls)
{
    health_calls = calls;
    int broke = 0;
    switch (type) {
    case T_WELFORD: broke = welford_bad(obj); break;
    case T_SPECTRUM: broke = spectrum_bad(obj); break;
    case T_MOMENT:
        broke = second_bad(&moment_ops, obj, ((const mcs_moment *)obj)->n, 6u);
        break;
    case T_THEORY:
        broke = second_bad(&theory_ops, obj, ((const mcs_theory *)obj)->n,
                           ((const mcs_theory *)obj)->k);
        break;
    case T_AUTOCORR: broke = autocorr_bad(obj); break;
    case T_POINTSET: broke = pointset_bad(obj); break;
    case T_POINTSET2D: broke = pointset2d_bad(obj); break;
    case T_SPECTRUM2D: broke = spectrum2d_bad(obj); break;
    case T_IMP: broke = importance_bad(obj); break;
    case T_TSPEC: broke = ((const mcs_theory_spectrum *)obj)->n > 0u && tspec_bad(obj); break;
    default: break;
    }
    return broke ? health_msg : NULL;
}
