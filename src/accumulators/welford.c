#include "mcspec/welford.h"
#include "acc_internal.h"

#include <math.h>
#include <stddef.h>

mcs_status mcs_welford_init(mcs_welford *acc)
{
    if (acc == NULL)
        return MCS_ERR_NULL;
    acc->count = 0u;
    acc->mean = 0.0;
    acc->m2 = 0.0;
    acc->m3 = 0.0;
    acc->m4 = 0.0;
    return MCS_OK;
}

/* What values within MCS_WELFORD_MAX_ABS (2^110) give: each lies within
 * 2^111 of the mean, so over c values m2, |m3| and m4 are at most
 * (c - 1) 2^222, 2^333, 2^444 (c (2^111)^p is at most (c - 1) 2^(111 p + 1)
 * for c >= 2, and there is no spread at all with one value), here with
 * room for rounding; the running mean stays within the values. Within these
 * every read-out and merge is finite (welford.h). */
#define SPREAD2 0x1p224
#define SPREAD3 0x1p336
#define SPREAD4 0x1p448
#define MEAN_LIMIT (2.0 * MCS_WELFORD_MAX_ABS)

/* A state some sequence of adds and merges produces: MCS_ERR_NULL without
 * acc, MCS_ERR_INVARIANT if overwritten (so no read-out is NaN, infinite or
 * stale): see the bounds above, and no mean without a value (NaN fails
 * every compare). */
static mcs_status welford_check(const mcs_welford *acc)
{
    if (acc == NULL)
        return MCS_ERR_NULL;
    if (acc->count > (uint64_t)MCS_MAX_COUNT)
        return MCS_ERR_INVARIANT;
    const double spread = acc->count > 0u ? (double)(acc->count - 1u) : 0.0;
    const int sound = fabs(acc->mean) <= (acc->count > 0u ? MEAN_LIMIT : 0.0) &&
                      acc->m2 >= 0.0 && acc->m2 <= spread * SPREAD2 &&
                      fabs(acc->m3) <= spread * SPREAD3 && acc->m4 >= 0.0 &&
                      acc->m4 <= spread * SPREAD4;
    return sound ? MCS_OK : MCS_ERR_INVARIANT;
}

mcs_status mcs_welford_add(mcs_welford *acc, double x)
{
    mcs_status st = welford_check(acc);
    if (st != MCS_OK)
        return st;
    if (!isfinite(x))
        return MCS_ERR_NOT_FINITE;
    if (fabs(x) > MCS_WELFORD_MAX_ABS)
        return MCS_ERR_MAGNITUDE;
    st = mcs_check_count_(acc->count, 1u);
    if (st != MCS_OK)
        return st;
    /* Welford/Pebay: deviations from the running mean, higher moments first
     * because they use the old lower ones; no raw power sums, so no
     * cancellation when the mean is large. */
    double n1 = (double)acc->count, n = n1 + 1.0;
    double delta = x - acc->mean;
    double dn = delta / n, dn2 = dn * dn, term1 = delta * dn * n1;
    acc->m4 += term1 * dn2 * (n * n - 3.0 * n + 3.0) + 6.0 * dn2 * acc->m2 - 4.0 * dn * acc->m3;
    acc->m3 += term1 * dn * (n - 2.0) - 3.0 * dn * acc->m2;
    acc->m2 += term1;
    acc->mean += dn;
    acc->count += 1u;
    return MCS_OK;
}

mcs_status mcs_welford_merge(mcs_welford *dst, const mcs_welford *src)
{
    mcs_status st = src == NULL ? MCS_ERR_NULL : welford_check(dst);
    if (st == MCS_OK)
        st = welford_check(src);
    if (st == MCS_OK) /* COUNT, then ALIAS for two objects that overlap (dst == src doubles) */
        st = mcs_check_merge_(dst, src, sizeof *dst, 1, dst->count, src->count);
    if (st != MCS_OK || src->count == 0u)
        return st;
    if (dst->count == 0u) {
        *dst = *src;
        return MCS_OK;
    }
    /* Chan, Golub and LeVeque for M2, Pebay for M3 and M4: combine through
     * the gap d between the two means. Both copied first (dst may be src);
     * the count products are taken as fractions fa = na/n, fb = nb/n, so no
     * intermediate grows past d^4 na (the textbook na nb (na^2 ...) / n^3
     * overflowed at counts near 2^50 with deviations near the limit). */
    const mcs_welford a = *dst, b = *src;
    const double na = (double)a.count, n = na + (double)b.count;
    const double fa = na / n, fb = (double)b.count / n;
    const double d = b.mean - a.mean, d2 = d * d;
    dst->mean = a.mean + d * fb;
    dst->m2 = a.m2 + b.m2 + d2 * na * fb;
    dst->m3 = a.m3 + b.m3 + d2 * d * na * fb * (fa - fb) + 3.0 * d * (fa * b.m2 - fb * a.m2);
    dst->m4 = a.m4 + b.m4 + d2 * d2 * na * fb * (fa * fa - fa * fb + fb * fb) +
              6.0 * d2 * (fa * fa * b.m2 + fb * fb * a.m2) + 4.0 * d * (fa * b.m3 - fb * a.m3);
    dst->count = a.count + b.count;
    return MCS_OK;
}

/* The checks of a read-out: acc and out, a valid state, at least `least` values. */
static mcs_status readout_check(const mcs_welford *acc, const double *out, uint64_t least)
{
    mcs_status st = out == NULL ? MCS_ERR_NULL : welford_check(acc);
    return st == MCS_OK && acc->count < least ? MCS_ERR_EMPTY : st;
}

mcs_status mcs_welford_mean(const mcs_welford *acc, double *mean)
{
    mcs_status st = readout_check(acc, mean, 1u);
    return st == MCS_OK ? mcs_set_(mean, acc->mean) : st;
}

mcs_status mcs_welford_variance(const mcs_welford *acc, double *variance)
{
    mcs_status st = readout_check(acc, variance, 2u);
    return st == MCS_OK ? mcs_set_(variance, acc->m2 / (double)(acc->count - 1u)) : st;
}

mcs_status mcs_welford_stderr(const mcs_welford *acc, double *stderr_out)
{
    mcs_status st = readout_check(acc, stderr_out, 2u);
    if (st != MCS_OK)
        return st;
    return mcs_set_(stderr_out, sqrt(acc->m2 / (double)(acc->count - 1u) / (double)acc->count));
}

mcs_status mcs_welford_variance_stderr(const mcs_welford *acc, double *stderr_out)
{
    mcs_status st = readout_check(acc, stderr_out, 4u);
    if (st != MCS_OK)
        return st;
    /* Var[s^2] = (mu4 - sigma^4)/c + 2 sigma^4/(c (c-1)). mu4 - sigma^4 from
     * the h-statistics h4 - h22 (unbiased; with central sample moments
     * q2 = m2/c, q4 = m4/c it is c [(c^2 - c + 2) q4 - (c^2 + 3c - 6) q2^2] /
     * ((c-1)(c-2)(c-3))), clamped at 0 as the true value is; sigma^4 of the
     * second term from s^4, which keeps it from collapsing (see welford.h). */
    const double c = (double)acc->count, q2 = acc->m2 / c, q4 = acc->m4 / c;
    const double excess = c * ((c * c - c + 2.0) * q4 - (c * c + 3.0 * c - 6.0) * q2 * q2) /
                          ((c - 1.0) * (c - 2.0) * (c - 3.0));
    const double s2 = acc->m2 / (c - 1.0);
    const double v = ((excess > 0.0 ? excess : 0.0) + 2.0 * s2 * s2 / (c - 1.0)) / c;
    /* finite for every state welford_check passes (below 2^610); refused,
     * never returned, were it not */
    return isfinite(v) ? mcs_set_(stderr_out, sqrt(v)) : MCS_ERR_INVARIANT;
}
