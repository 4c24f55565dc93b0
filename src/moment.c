#include "mcspec/moment.h"
#include "internal.h"
#include "readout.h"

#include <string.h>

mcs_status mcs_moment_init(mcs_moment *acc, size_t n)
{
    mcs_status st = mcs_check_init_(acc, n, (size_t)MCS_MAX_COV_N);
    if (st != MCS_OK)
        return st;
    memset(acc, 0, sizeof *acc);
    mcs_twiddles_(n, acc->cos_table, acc->sin_table);
    acc->n = n; /* last: only a complete object counts as initialised */
    return MCS_OK;
}

static mcs_status moment_check(const mcs_moment *acc)
{
    return mcs_check_object_(acc, acc != NULL ? acc->n : 0u, (size_t)MCS_MAX_COV_N);
}

/* Adds sample pair contributions. s_m s_n = sum over ordered pairs (j, j')
 * with n_j = m, n_j' = n of w_j w_j': a pair in two bins adds w w' to both
 * mirrored entries (so the matrix stays exactly symmetric), a pair in one
 * bin 2 w w' to its diagonal entry. */
static void add_sample_pairs(mcs_moment *acc, size_t k, const size_t *bins,
                             const double *weights)
{
    const size_t n = acc->n;
    double *ss = acc->sum_ss;
    for (size_t j = 0; j < k; ++j) {
        const size_t b = bins[j];
        const double w = weights[j];
        acc->sum_s[b] += w;
        ss[b * n + b] += w * w;
        for (size_t jj = j + 1u; jj < k; ++jj) {
            const size_t c = bins[jj];
            const double ww = w * weights[jj];
            if (b == c) {
                ss[b * n + b] += 2.0 * ww;
            } else {
                ss[b * n + c] += ww;
                ss[c * n + b] += ww;
            }
        }
    }
    acc->count += 1u;
}

mcs_status mcs_moment_add_bins(mcs_moment *acc, size_t k, const size_t *bins,
                               const double *weights)
{
    mcs_status st = bins == NULL || weights == NULL ? MCS_ERR_NULL : moment_check(acc);
    if (st == MCS_OK)
        st = mcs_check_sparse_(acc->n, k, bins, weights);
    if (st == MCS_OK)
        add_sample_pairs(acc, k, bins, weights);
    return st;
}

mcs_status mcs_moment_add_dense(mcs_moment *acc, size_t n, const double *s)
{
    mcs_status st = mcs_check_dense_(moment_check(acc), acc != NULL ? acc->n : 0u, n, s);
    if (st != MCS_OK)
        return st;
    /* Each non-zero bin as one sample of weight s_m: the diagonal gets s_m^2
     * and each pair of distinct bins s_m s_c in both mirrored entries. */
    double *ss = acc->sum_ss;
    for (size_t m = 0; m < n; ++m) {
        const double a = s[m];
        if (a == 0.0)
            continue;
        acc->sum_s[m] += a;
        ss[m * n + m] += a * a;
        for (size_t c = m + 1u; c < n; ++c) {
            const double v = a * s[c];
            ss[m * n + c] += v;
            ss[c * n + m] += v;
        }
    }
    acc->count += 1u;
    return MCS_OK;
}

mcs_status mcs_moment_merge(mcs_moment *dst, const mcs_moment *src)
{
    mcs_status st = src == NULL ? MCS_ERR_NULL : moment_check(dst);
    if (st == MCS_OK)
        st = moment_check(src);
    if (st == MCS_OK && dst->n != src->n)
        st = MCS_ERR_MISMATCH;
    if (st != MCS_OK)
        return st;
    const size_t n = dst->n;
    for (size_t j = 0; j < n; ++j)
        dst->sum_s[j] += src->sum_s[j];
    for (size_t j = 0; j < n * n; ++j)
        dst->sum_ss[j] += src->sum_ss[j];
    dst->count += src->count;
    return MCS_OK;
}

mcs_status mcs_moment_count(const mcs_moment *acc, uint64_t *count)
{
    mcs_status st = count == NULL ? MCS_ERR_NULL : moment_check(acc);
    if (st == MCS_OK)
        *count = acc->count;
    return st;
}

/* ---- read-out (src/readout.c): the trial averages are the sums / count ---- */

mcs_status mcs_readout_open_moment(const void *obj, mcs_readout *view)
{
    const mcs_moment *acc = (const mcs_moment *)obj;
    mcs_status st = moment_check(acc);
    if (st != MCS_OK)
        return st;
    if (acc->count == 0u)
        return MCS_ERR_EMPTY;
    /* k = 0: the accumulator does not know K, the caller names it */
    *view = (mcs_readout){acc->n,     0u,          1.0 / (double)acc->count, acc->sum_s,
                          acc->sum_ss, acc->cos_table, acc->sin_table};
    return MCS_OK;
}

MCS_READOUT_DEFINE(moment, mcs_moment, mcs_readout_open_moment)
