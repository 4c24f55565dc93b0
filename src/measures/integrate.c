/* The integration-error accumulator over sets (integrate.h). */
#include "mcspec/integrate.h"
#include "integrand_internal.h"
#include "measures_internal.h"

#include <stddef.h>
#include <string.h>

static int family_ok(mcs_integrand_family family)
{
    return (unsigned)family < (unsigned)MCS_INTEGRAND_FAMILIES; /* an enum may be unsigned (ARM) */
}

mcs_status mcs_integrate_init(mcs_integrate *acc, mcs_integrand_family family, size_t dim)
{
    if (acc == NULL)
        return MCS_ERR_NULL;
    if (!family_ok(family))
        return MCS_ERR_KIND;
    if (dim != 1u && dim != 2u)
        return MCS_ERR_DOMAIN;
    mcs_integrate a;
    memset(&a, 0, sizeof a);
    a.family = family;
    a.dim = dim;
    (void)mcs_welford_init(&a.sq);
    (void)mcs_welford_init(&a.exact);
    *acc = a;
    return MCS_OK;
}

/* MCS_OK, MCS_ERR_UNINIT or MCS_ERR_INVARIANT for an accumulator. */
static mcs_status check_acc(const mcs_integrate *acc)
{
    if (!family_ok(acc->family) || (acc->dim != 1u && acc->dim != 2u))
        return MCS_ERR_UNINIT;
    if (!mcs_meas_welford_ok_(&acc->sq) || !mcs_meas_welford_ok_(&acc->exact) ||
        acc->exact.count > acc->sq.count ||
        !mcs_meas_k_range_ok_(acc->sq.count, acc->k_min, acc->k_max))
        return MCS_ERR_INVARIANT;
    return MCS_OK;
}

/* The checks of an add, before anything is computed. */
static mcs_status check_add(const mcs_integrate *acc, size_t m, const mcs_integrand *fs, size_t k,
                            const double *points, mcs_integrate_reference reference,
                            size_t strata_x, size_t strata_y)
{
    if (acc == NULL || fs == NULL || points == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_acc(acc);
    if (st != MCS_OK)
        return st;
    if (k == 0u || m == 0u)
        return MCS_ERR_K_RANGE;
    if (reference != MCS_INTEGRATE_NONE && reference != MCS_INTEGRATE_RANDOM &&
        reference != MCS_INTEGRATE_JITTERED)
        return MCS_ERR_KIND;
    if (k > SIZE_MAX / acc->dim || m > SIZE_MAX / sizeof *fs)
        return MCS_ERR_POINT_RANGE;
    const size_t n = k * acc->dim;
    if (mcs_overlap_(points, n * sizeof *points, acc, sizeof *acc) ||
        mcs_overlap_(fs, m * sizeof *fs, acc, sizeof *acc))
        return MCS_ERR_ALIAS;
    for (size_t i = 0; i < m; ++i)
        if (!mcs_integ_valid_(&fs[i]))
            return MCS_ERR_UNINIT;
    for (size_t i = 0; i < m; ++i)
        if (fs[i].family != acc->family || fs[i].dim != acc->dim)
            return MCS_ERR_MISMATCH;
    if (reference == MCS_INTEGRATE_JITTERED &&
        (strata_x == 0u || strata_y == 0u || strata_x > k / strata_y ||
         strata_x * strata_y != k || (acc->dim == 1u && strata_y != 1u)))
        return MCS_ERR_MISMATCH;
    if (reference == MCS_INTEGRATE_JITTERED && k > (size_t)MCS_INTEGRAND_JITTERED_MAX_K)
        return MCS_ERR_K_RANGE;
    for (size_t i = 0; i < n; ++i)
        if (!(points[i] >= 0.0 && points[i] < 1.0))
            return MCS_ERR_POINT_RANGE;
    return mcs_check_count_(acc->sq.count, 1u);
}

mcs_status mcs_integrate_add(mcs_integrate *acc, size_t m, const mcs_integrand *fs, size_t k,
                             const double *points, mcs_integrate_reference reference,
                             size_t strata_x, size_t strata_y)
{
    mcs_status st = check_add(acc, m, fs, k, points, reference, strata_x, strata_y);
    if (st != MCS_OK)
        return st;
    double sq = 0.0, sq_lo = 0.0, ex = 0.0;
    for (size_t i = 0; i < m; ++i) {
        double sum = 0.0, lo = 0.0, i1, q;
        for (size_t j = 0; j < k; ++j)
            mcs_kahan_add_(&sum, &lo, mcs_integ_eval_(&fs[i], points + j * acc->dim));
        mcs_integ_moments_(&fs[i], &i1, &q);
        const double e = sum / (double)k - i1;
        mcs_kahan_add_(&sq, &sq_lo, e * e);
        if (reference == MCS_INTEGRATE_RANDOM) {
            const double v = q - i1 * i1;
            ex += (v > 0.0 ? v : 0.0) / (double)k;
        } else if (reference == MCS_INTEGRATE_JITTERED) {
            ex += mcs_integ_jittered_(&fs[i], strata_x, strata_y);
        }
    }
    if (reference == MCS_INTEGRATE_JITTERED && !mcs_integ_has_jittered_(&fs[0]))
        reference = MCS_INTEGRATE_NONE; /* no exact value (one family for all of fs) */
    mcs_integrate a = *acc;
    st = mcs_welford_add(&a.sq, sq / (double)m);
    if (st == MCS_OK && reference != MCS_INTEGRATE_NONE)
        st = mcs_welford_add(&a.exact, ex / (double)m);
    if (st != MCS_OK)
        return st;
    a.k_min = a.k_min == 0u || k < a.k_min ? k : a.k_min;
    a.k_max = k > a.k_max ? k : a.k_max;
    *acc = a;
    return MCS_OK;
}

mcs_status mcs_integrate_merge(mcs_integrate *dst, const mcs_integrate *src)
{
    if (dst == NULL || src == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_acc(dst);
    if (st == MCS_OK)
        st = check_acc(src);
    if (st != MCS_OK)
        return st;
    if (dst->family != src->family || dst->dim != src->dim)
        return MCS_ERR_MISMATCH;
    mcs_integrate a = *dst;
    st = mcs_welford_merge(&a.sq, &src->sq);
    if (st == MCS_OK)
        st = mcs_welford_merge(&a.exact, &src->exact);
    if (st != MCS_OK)
        return st;
    if (src->sq.count > 0u) {
        a.k_min = a.k_min == 0u || src->k_min < a.k_min ? src->k_min : a.k_min;
        a.k_max = src->k_max > a.k_max ? src->k_max : a.k_max;
    }
    *dst = a;
    return MCS_OK;
}

static mcs_status check_read(const mcs_integrate *acc, const double *out)
{
    if (acc == NULL || out == NULL)
        return MCS_ERR_NULL;
    return check_acc(acc);
}

mcs_status mcs_integrate_count(const mcs_integrate *acc, uint64_t *count)
{
    if (acc == NULL || count == NULL)
        return MCS_ERR_NULL;
    const mcs_status st = check_acc(acc);
    if (st == MCS_OK)
        *count = acc->sq.count;
    return st;
}

mcs_status mcs_integrate_mse(const mcs_integrate *acc, double *out)
{
    const mcs_status st = check_read(acc, out);
    return st != MCS_OK ? st : mcs_welford_mean(&acc->sq, out);
}

mcs_status mcs_integrate_mse_stderr(const mcs_integrate *acc, double *out)
{
    const mcs_status st = check_read(acc, out);
    return st != MCS_OK ? st : mcs_welford_stderr(&acc->sq, out);
}

mcs_status mcs_integrate_exact(const mcs_integrate *acc, double *out)
{
    const mcs_status st = check_read(acc, out);
    if (st != MCS_OK)
        return st;
    if (acc->sq.count == 0u)
        return MCS_ERR_EMPTY;
    if (acc->exact.count != acc->sq.count)
        return MCS_ERR_DOMAIN;
    return mcs_welford_mean(&acc->exact, out);
}
