#include "mcspec/autocorr.h"
#include "internal.h"

#include <math.h>
#include <string.h>

mcs_status mcs_autocorr_init(mcs_autocorr *acc, size_t n)
{
    mcs_status st = mcs_check_init_(acc, n, (size_t)MCS_MAX_N);
    if (st != MCS_OK)
        return st;
    memset(acc, 0, sizeof *acc);
    acc->n = n; /* last: only a complete object counts as initialised */
    return MCS_OK;
}

static mcs_status autocorr_check(const mcs_autocorr *acc)
{
    return mcs_check_object_(acc, acc != NULL ? acc->n : 0u, (size_t)MCS_MAX_N);
}

mcs_status mcs_autocorr_add_bins(mcs_autocorr *acc, size_t k, const size_t *bins,
                                 const double *weights)
{
    mcs_status st = bins == NULL || weights == NULL ? MCS_ERR_NULL : autocorr_check(acc);
    if (st == MCS_OK)
        st = mcs_check_sparse_(acc->n, k, bins, weights);
    if (st != MCS_OK)
        return st;
    /* Folded storage: an unordered pair {j, j'} at circular distance
     * e = min(d, N - d) adds w w' to sum_a[e]; a sample with itself adds
     * w^2 / 2 to sum_a[0]. Then A(e) = sum_a[e] for 0 < e < N/2, and
     * A(0) = 2 sum_a[0], A(N/2) = 2 sum_a[N/2] (read-out), because there both
     * orders of a pair land on the same lag. */
    const size_t n = acc->n;
    double *a = acc->sum_a;
    for (size_t j = 0; j < k; ++j) {
        const size_t b = bins[j];
        const double w = weights[j];
        acc->sum_s[b] += w;
        a[0] += 0.5 * w * w;
        for (size_t jj = j + 1u; jj < k; ++jj) {
            const size_t c = bins[jj];
            const size_t d = c >= b ? c - b : c + n - b;
            const size_t e = d <= n - d ? d : n - d;
            a[e] += w * weights[jj];
        }
    }
    acc->count += 1u;
    return MCS_OK;
}

mcs_status mcs_autocorr_merge(mcs_autocorr *dst, const mcs_autocorr *src)
{
    mcs_status st = src == NULL ? MCS_ERR_NULL : autocorr_check(dst);
    if (st == MCS_OK)
        st = autocorr_check(src);
    if (st == MCS_OK && dst->n != src->n)
        st = MCS_ERR_MISMATCH;
    if (st != MCS_OK)
        return st;
    const size_t n = dst->n, h = n / 2u;
    for (size_t j = 0; j < n; ++j)
        dst->sum_s[j] += src->sum_s[j];
    for (size_t j = 0; j <= h; ++j)
        dst->sum_a[j] += src->sum_a[j];
    dst->count += src->count;
    return MCS_OK;
}

mcs_status mcs_autocorr_count(const mcs_autocorr *acc, uint64_t *count)
{
    mcs_status st = count == NULL ? MCS_ERR_NULL : autocorr_check(acc);
    if (st == MCS_OK)
        *count = acc->count;
    return st;
}

static mcs_status autocorr_readout(const mcs_autocorr *acc, const mcs_dft *plan, size_t n,
                                   const double *out)
{
    mcs_status st = plan == NULL || out == NULL ? MCS_ERR_NULL : autocorr_check(acc);
    if (st == MCS_OK && n != acc->n)
        st = MCS_ERR_MISMATCH;
    if (st == MCS_OK)
        st = mcs_dft_check(plan, n); /* UNINIT or MISMATCH */
    if (st == MCS_OK && acc->count == 0u)
        st = MCS_ERR_EMPTY;
    return st;
}

mcs_status mcs_autocorr_mean(const mcs_autocorr *acc, mcs_dft *plan, size_t n, double *re,
                             double *im)
{
    if (im == NULL)
        return MCS_ERR_NULL;
    mcs_status st = autocorr_readout(acc, plan, n, re);
    if (st != MCS_OK)
        return st;
    if (!mcs_all_finite_(n, acc->sum_s)) /* an overflowed sum: refuse before writing */
        return MCS_ERR_NOT_FINITE;
    const double inv = 1.0 / (double)acc->count;
    for (size_t j = 0; j < n; ++j)
        re[j] = acc->sum_s[j] * inv;
    return mcs_dft_real(plan, n, re, re, im); /* eq. 15 */
}

mcs_status mcs_autocorr_power(const mcs_autocorr *acc, mcs_dft *plan, size_t n, double *power)
{
    mcs_status st = autocorr_readout(acc, plan, n, power);
    if (st != MCS_OK)
        return st;
    if (!mcs_all_finite_(n / 2u + 1u, acc->sum_a))
        return MCS_ERR_NOT_FINITE;
    /* <A(d)> for every lag, unfolded (see mcs_autocorr_add_bins), then
     * Wiener-Khinchin: <|S_k|^2> = (1/N) sum_d e^{-2 pi i k d/N} <A(d)>, i.e.
     * N^{-1/2} times eq. 7 applied to <A>. A is even, so the result is real. */
    const double inv = 1.0 / (double)acc->count;
    power[0] = 2.0 * acc->sum_a[0] * inv;
    for (size_t d = 1; d < n; ++d) {
        const size_t e = d <= n - d ? d : n - d;
        const double twice = (2u * e == n) ? 2.0 : 1.0;
        power[d] = twice * acc->sum_a[e] * inv;
    }
    (void)mcs_dft_real(plan, n, power, power, NULL);
    const double scale = 1.0 / sqrt((double)n);
    for (size_t k = 0; k < n; ++k)
        power[k] *= scale;
    return MCS_OK;
}
