#include "mcspec/moment.h"
#include "acc_internal.h"
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
    mcs_status st = mcs_check_object_(acc, acc != NULL ? acc->n : 0u, (size_t)MCS_MAX_COV_N);
    return st == MCS_OK && acc->count > (uint64_t)MCS_MAX_COUNT ? MCS_ERR_INVARIANT : st;
}

/* work holds the trial's s. The first trial becomes the shift c (its d is 0,
 * so the sums stay 0); later ones add d = s - c over the bins where it is not
 * 0: d_m into sum_d, d_m d_n into both mirrored sum_dd entries (the same
 * product, so the matrix stays exactly symmetric), all with Kahan's
 * compensation so the error does not grow with the number of trials. */
static void add_work(mcs_moment *acc)
{
    const size_t n = acc->n;
    if (acc->count == 0u) {
        memcpy(acc->shift, acc->work, n * sizeof acc->work[0]);
        acc->count = 1u;
        return;
    }
    size_t len = 0u;
    for (size_t m = 0; m < n; ++m) { /* compacts d != 0 without a branch (len <= m) */
        const double d = acc->work[m] - acc->shift[m];
        acc->work[len] = d;
        acc->work_bins[len] = m;
        len += d != 0.0;
    }
    for (size_t a = 0; a < len; ++a) {
        const size_t m = acc->work_bins[a];
        const double dm = acc->work[a];
        mcs_kahan_add_(&acc->sum_d[m], &acc->lo_d[m], dm);
        for (size_t b = a; b < len; ++b) {
            /* one Kahan step for the pair, copied to the mirror entry, which
             * has seen the same sequence of terms (so it holds the same) */
            const size_t c = acc->work_bins[b], i = m * n + c, mirror = c * n + m;
            mcs_kahan_add_(&acc->sum_dd[i], &acc->lo_dd[i], dm * acc->work[b]);
            acc->sum_dd[mirror] = acc->sum_dd[i];
            acc->lo_dd[mirror] = acc->lo_dd[i];
        }
    }
    acc->count += 1u;
}

mcs_status mcs_moment_add_bins(mcs_moment *acc, size_t k, const size_t *bins,
                               const double *weights)
{
    mcs_status st = bins == NULL || weights == NULL ? MCS_ERR_NULL : moment_check(acc);
    if (st == MCS_OK)
        st = mcs_check_add_sparse_(acc, sizeof *acc, acc->n, acc->count, k, bins, weights,
                                   MCS_MOMENT_MAX_TRIAL);
    if (st != MCS_OK)
        return st;
    /* s of the trial: per-bin sums of its weights (eq. 38) */
    memset(acc->work, 0, acc->n * sizeof acc->work[0]);
    for (size_t j = 0; j < k; ++j)
        acc->work[bins[j]] += weights[j];
    add_work(acc);
    return MCS_OK;
}

mcs_status mcs_moment_add_dense(mcs_moment *acc, size_t n, const double *s)
{
    mcs_status st = mcs_check_dense_(moment_check(acc), acc != NULL ? acc->n : 0u, n, s);
    if (st != MCS_OK)
        return st;
    double total = 0.0;
    for (size_t m = 0; m < n; ++m)
        total += s[m];
    st = mcs_check_add_(acc, sizeof *acc, acc->count, total, MCS_MOMENT_MAX_TRIAL, s,
                        n * sizeof *s, NULL, 0u);
    if (st != MCS_OK)
        return st;
    memcpy(acc->work, s, n * sizeof *s);
    add_work(acc);
    return MCS_OK;
}

/* dst's sums of d += src's, moved from src's shift c_b to dst's c_a first:
 * with e = c_b - c_a and T_b trials, sum (s - c_a) = sum (s - c_b) + T_b e
 * and sum (s - c_a)(s - c_a)^T = sum (s - c_b)(s - c_b)^T + sum_b e^T
 * + e sum_b^T + T_b e e^T. The second sums go first, while both first sums
 * are unchanged; every src value is read before its dst entry is written,
 * so dst == src (e = 0) doubles the sums. */
static void merge_sums(mcs_moment *dst, const mcs_moment *src)
{
    const size_t n = dst->n;
    const double tb = (double)src->count;
    for (size_t m = 0; m < n; ++m) {
        const double em = src->shift[m] - dst->shift[m], bm = src->sum_d[m];
        for (size_t c = 0; c < n; ++c) {
            const size_t i = m * n + c;
            const double ec = src->shift[c] - dst->shift[c];
            const double move = (bm * ec + em * src->sum_d[c]) + tb * (em * ec);
            mcs_kahan_merge_(&dst->sum_dd[i], &dst->lo_dd[i], src->sum_dd[i], src->lo_dd[i]);
            mcs_kahan_add_(&dst->sum_dd[i], &dst->lo_dd[i], move);
        }
    }
    for (size_t m = 0; m < n; ++m) {
        mcs_kahan_merge_(&dst->sum_d[m], &dst->lo_d[m], src->sum_d[m], src->lo_d[m]);
        mcs_kahan_add_(&dst->sum_d[m], &dst->lo_d[m], tb * (src->shift[m] - dst->shift[m]));
    }
}

mcs_status mcs_moment_merge(mcs_moment *dst, const mcs_moment *src)
{
    mcs_status st = mcs_check_pair_(moment_check(dst), moment_check(src));
    if (st == MCS_OK)
        st = mcs_check_merge_(dst, src, sizeof *dst, dst->n == src->n, dst->count, src->count);
    if (st != MCS_OK || src->count == 0u)
        return st;
    if (dst->count == 0u) { /* take src's shift and sums as they are */
        const size_t n = dst->n;
        memcpy(dst->shift, src->shift, n * sizeof dst->shift[0]);
        memcpy(dst->sum_d, src->sum_d, n * sizeof dst->sum_d[0]);
        memcpy(dst->lo_d, src->lo_d, n * sizeof dst->lo_d[0]);
        memcpy(dst->sum_dd, src->sum_dd, n * n * sizeof dst->sum_dd[0]);
        memcpy(dst->lo_dd, src->lo_dd, n * n * sizeof dst->lo_dd[0]);
    } else {
        merge_sums(dst, src);
    }
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

/* ---- read-out (src/readout.c): <s> = c + sum_d / count, and the
 * covariances come from the d sums alone (they do not depend on c) ---- */

mcs_status mcs_readout_open_moment(const void *obj, mcs_readout *view)
{
    const mcs_moment *acc = (const mcs_moment *)obj;
    mcs_status st = moment_check(acc);
    if (st != MCS_OK)
        return st;
    if (acc->count == 0u)
        return MCS_ERR_EMPTY;
    const size_t n = acc->n;
    if (!mcs_all_stored_(n, acc->shift) || !mcs_all_stored_(n, acc->sum_d) ||
        !mcs_all_stored_(n * n, acc->sum_dd))
        return MCS_ERR_INVARIANT;
    /* k = 0: the accumulator does not know K, the caller names it */
    *view = (mcs_readout){n,           0u,           1.0 / (double)acc->count, acc->sum_d,
                          acc->sum_dd, acc->cos_table, acc->sin_table,         acc->shift};
    return MCS_OK;
}

MCS_READOUT_DEFINE(moment, mcs_moment, mcs_readout_open_moment)
