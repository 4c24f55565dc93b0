#include "mcspec/moment.h"
#include "acc_internal.h"
#include "readout.h"
#include "core/simd.h"

#include <string.h>

mcs_status mcs_moment_init(mcs_moment *acc, size_t n)
{
    mcs_status st = mcs_check_init_(acc, n, (size_t)MCS_MAX_COV_N);
    if (st != MCS_OK)
        return st;
    memset(acc, 0, sizeof *acc);
    mcs_twiddles_(n, acc->cos_table, acc->sin_table);
    acc->simd = mcs_cpu_avx2_(); /* asked once: slow in a virtual machine */
    acc->n = n; /* last: only a complete object counts as initialised */
    return MCS_OK;
}

/* The object's own check: set up (UNINIT), a count in range and an open
 * batch that fits in it (INVARIANT: overwritten since). */
static mcs_status moment_check(const mcs_moment *acc)
{
    mcs_status st = mcs_check_object_(acc, acc != NULL ? acc->n : 0u, (size_t)MCS_MAX_COV_N);
    if (st == MCS_OK &&
        (acc->count > (uint64_t)MCS_MAX_COUNT || (acc->simd != 0 && acc->simd != 1) ||
         acc->batch_count >= (uint64_t)MCS_MOMENT_BATCH || acc->batch_sparse > acc->batch_count ||
         (acc->batch_count != 0u && acc->batch_count >= acc->count)))
        st = MCS_ERR_INVARIANT;
    return st;
}

/* Sparse trials of at most this many pair products per trial, K (K + 1) / 2,
 * go in as products of s; larger ones densely (moment.h). The crossover of
 * the two kernels, timed on this project's machine (AMD EPYC, gcc 12 -O2,
 * AVX2 copy; ns per trial, pairs against dense rows): N = 16, K = 12: 46
 * against 56, K = 16: 76 against 64; N = 64, K = 28: 186 against 242,
 * K = 36: 297 against 272. The pairs cost about 0.46 ns each, the dense
 * rows about 0.46 (N^2 / 32 + 7 N) ns: the fixed work of a trial over N
 * bins dominates at small N. */
static size_t sparse_terms_max(size_t n)
{
    return n * n / 32u + 7u * n;
}

/* The open batch into the compensated sums: d sums += what the batch adds
 * (readout.h), with Kahan's compensation; each entry of the full matrix is
 * formed by the same symmetric expression, so both triangles stay equal. */
static void fold_batch(mcs_moment *acc)
{
    const size_t n = acc->n;
    const double sparse = (double)acc->batch_sparse;
    for (size_t m = 0; m < n; ++m)
        for (size_t q = 0; q < n; ++q) {
            const size_t i = m * n + q;
            mcs_kahan_add_(&acc->sum_dd[i], &acc->lo_dd[i],
                           mcs_batch_second_(acc->batch_w, acc->batch_s, acc->shift, sparse,
                                             n, m, q));
        }
    for (size_t m = 0; m < n; ++m)
        mcs_kahan_add_(&acc->sum_d[m], &acc->lo_d[m],
                       mcs_batch_first_(acc->batch_s, acc->batch_d, acc->shift, sparse, m));
    memset(acc->batch_w, 0, n * n * sizeof acc->batch_w[0]);
    memset(acc->batch_s, 0, n * sizeof acc->batch_s[0]);
    memset(acc->batch_d, 0, n * sizeof acc->batch_d[0]);
    acc->batch_count = 0u;
    acc->batch_sparse = 0u;
}

/* One trial into the batch; the batch is folded when full. */
static void close_trial(mcs_moment *acc)
{
    acc->count += 1u;
    acc->batch_count += 1u;
    if (acc->batch_count >= (uint64_t)MCS_MOMENT_BATCH)
        fold_batch(acc);
}

#define MCS_SIMD_BODY "accumulators/moment_simd.h"
#include "core/simd_clones.h"

/* Half of x x^T into the batch, by the copy the object's simd flag picks. */
static void add_rows(mcs_moment *acc, const double *x)
{
#if MCS_AVX2_CLONES
    if (acc->simd) {
        moment_rows_avx2(acc->n, x, acc->batch_w);
        return;
    }
#endif
    moment_rows_generic(acc->n, x, acc->batch_w);
}

/* work holds the trial's s, of k samples (0: unknown, a dense trial). The
 * first trial becomes the shift c (its d is 0: no sums change). A later one
 * goes into the batch as s s^T or as d d^T (d = s - c), whichever has fewer
 * rows that are not 0: d where s is close to c (a stratified trial: none),
 * s where it is sparse (random ones). As s only if k <= N, where <s^2> is at
 * most about twice Var(s) and the fold's cancellation costs a bit or two:
 * with many samples to a bin (N = 3, K = 1000: s ~ 333, Var ~ 1) only the
 * shifted form keeps the digits. */
static void add_dense_work(mcs_moment *acc, size_t k)
{
    const size_t n = acc->n;
    double *restrict x = acc->work;
    if (acc->count == 0u) {
        memcpy(acc->shift, x, n * sizeof x[0]);
        acc->count = 1u;
        return;
    }
    size_t rows_s = 0u, rows_d = 0u;
    for (size_t m = 0; m < n; ++m) {
        rows_s += x[m] != 0.0;
        rows_d += x[m] != acc->shift[m];
    }
    if (k != 0u && k <= n && rows_s < rows_d) {
        for (size_t m = 0; m < n; ++m)
            acc->batch_s[m] += x[m];
        acc->batch_sparse += 1u;
    } else {
        for (size_t m = 0; m < n; ++m) {
            x[m] -= acc->shift[m];
            acc->batch_d[m] += x[m];
        }
    }
    add_rows(acc, x);
    close_trial(acc);
}

/* A trial of few samples: s into batch_s, and for every pair j <= i of
 * samples w_j w_i at [bin_j][bin_i] (halved for j = i), whichever triangle
 * that is: the batch's half products add both orders of every pair. */
static void add_sparse(mcs_moment *acc, size_t k, const size_t *bins, const double *weights)
{
    const size_t n = acc->n;
    double *restrict w = acc->batch_w;
    for (size_t j = 0; j < k; ++j) {
        const size_t bj = bins[j];
        const double wj = weights[j];
        double *restrict row = &w[bj * n];
        acc->batch_s[bj] += wj;
        row[bj] += 0.5 * (wj * wj);
        size_t i = j + 1u;
        for (; i + 2u <= k; i += 2u) { /* two pairs a step: less loop overhead */
            const size_t b0 = bins[i], b1 = bins[i + 1u];
            const double p0 = wj * weights[i], p1 = wj * weights[i + 1u];
            row[b0] += p0;
            row[b1] += p1;
        }
        if (i < k)
            row[bins[i]] += wj * weights[i];
    }
    acc->batch_sparse += 1u;
    close_trial(acc);
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
    if (acc->count != 0u && k <= acc->n && k * (k + 1u) / 2u <= sparse_terms_max(acc->n)) {
        add_sparse(acc, k, bins, weights);
        return MCS_OK;
    }
    /* s of the trial: per-bin sums of its weights (eq. 38) */
    memset(acc->work, 0, acc->n * sizeof acc->work[0]);
    for (size_t j = 0; j < k; ++j)
        acc->work[bins[j]] += weights[j];
    add_dense_work(acc, k);
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
    add_dense_work(acc, 0u);
    return MCS_OK;
}

/* dst's sums of d += src's (closed sums and open batch), moved from src's
 * shift c_b to dst's c_a first: with e = c_b - c_a and T_b trials,
 * sum (s - c_a) = sum (s - c_b) + T_b e and sum (s - c_a)(s - c_a)^T =
 * sum (s - c_b)(s - c_b)^T + sum_b e^T + e sum_b^T + T_b e e^T. dst's own
 * batch is folded first. src's first sums with its batch, sum_b, are formed
 * once into dst's scratch; the second sums go first, while both first sums
 * are unchanged; every src value is read before its dst entry is written,
 * so dst == src (e = 0, its batch folded) doubles the sums. */
static void merge_sums(mcs_moment *dst, const mcs_moment *src)
{
    const size_t n = dst->n;
    const double tb = (double)src->count, sparse = (double)src->batch_sparse;
    const int open = src->batch_count != 0u;
    double *restrict sum_b = dst->work;
    for (size_t m = 0; m < n; ++m)
        sum_b[m] = src->sum_d[m] +
                   (open ? mcs_batch_first_(src->batch_s, src->batch_d, src->shift, sparse, m)
                         : 0.0);
    for (size_t m = 0; m < n; ++m) {
        const double em = src->shift[m] - dst->shift[m];
        for (size_t c = 0; c < n; ++c) {
            const size_t i = m * n + c;
            const double ec = src->shift[c] - dst->shift[c];
            const double move = (sum_b[m] * ec + em * sum_b[c]) + tb * (em * ec);
            mcs_kahan_merge_(&dst->sum_dd[i], &dst->lo_dd[i], src->sum_dd[i], src->lo_dd[i]);
            if (open)
                mcs_kahan_add_(&dst->sum_dd[i], &dst->lo_dd[i],
                               mcs_batch_second_(src->batch_w, src->batch_s, src->shift,
                                                 sparse, n, m, c));
            mcs_kahan_add_(&dst->sum_dd[i], &dst->lo_dd[i], move);
        }
    }
    for (size_t m = 0; m < n; ++m) {
        mcs_kahan_merge_(&dst->sum_d[m], &dst->lo_d[m], src->sum_d[m], src->lo_d[m]);
        if (open)
            mcs_kahan_add_(&dst->sum_d[m], &dst->lo_d[m],
                           mcs_batch_first_(src->batch_s, src->batch_d, src->shift, sparse, m));
        mcs_kahan_add_(&dst->sum_d[m], &dst->lo_d[m], tb * (src->shift[m] - dst->shift[m]));
    }
}

/* Everything a trial changes, copied from src into an empty dst. */
static void copy_sums(mcs_moment *dst, const mcs_moment *src)
{
    const size_t n = dst->n, n1 = n * sizeof(double), nn = n * n1;
    memcpy(dst->shift, src->shift, n1);
    memcpy(dst->sum_d, src->sum_d, n1);
    memcpy(dst->lo_d, src->lo_d, n1);
    memcpy(dst->sum_dd, src->sum_dd, nn);
    memcpy(dst->lo_dd, src->lo_dd, nn);
    memcpy(dst->batch_s, src->batch_s, n1);
    memcpy(dst->batch_d, src->batch_d, n1);
    memcpy(dst->batch_w, src->batch_w, nn);
    dst->batch_count = src->batch_count;
    dst->batch_sparse = src->batch_sparse;
}

mcs_status mcs_moment_merge(mcs_moment *dst, const mcs_moment *src)
{
    mcs_status st = mcs_check_pair_(moment_check(dst), moment_check(src));
    if (st == MCS_OK)
        st = mcs_check_merge_(dst, src, sizeof *dst, dst->n == src->n, dst->count, src->count);
    if (st != MCS_OK || src->count == 0u)
        return st;
    if (dst->count == 0u) {
        copy_sums(dst, src); /* src's shift, sums and batch as they are */
    } else {
        if (dst->batch_count != 0u)
            fold_batch(dst);
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

/* ---- read-out (src/accumulators/readout.c): <s> = c + sum_d / count, and the
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
    if (!mcs_all_below_(n, acc->shift, MCS_MOMENT_LIMIT_S_) || !mcs_all_stored_(n, acc->sum_d) ||
        !mcs_all_stored_(n * n, acc->sum_dd) ||
        !mcs_all_below_(n, acc->batch_s, MCS_MOMENT_LIMIT_S_) ||
        !mcs_all_below_(n, acc->batch_d, MCS_MOMENT_LIMIT_S_) ||
        !mcs_all_below_(n * n, acc->batch_w, MCS_MOMENT_LIMIT_W_))
        return MCS_ERR_INVARIANT;
    /* k = 0: the accumulator does not know K, the caller names it */
    *view = (mcs_readout){.n = n,
                          .k = 0u,
                          .scale = 1.0 / (double)acc->count,
                          .first = acc->sum_d,
                          .second = acc->sum_dd,
                          .cos_table = acc->cos_table,
                          .sin_table = acc->sin_table,
                          .shift = acc->shift};
    if (acc->batch_count != 0u) {
        view->batch_w = acc->batch_w;
        view->batch_s = acc->batch_s;
        view->batch_d = acc->batch_d;
        view->batch_sparse = (double)acc->batch_sparse;
        view->batch_terms = (double)acc->batch_count * (double)sparse_terms_max(n);
    }
    return MCS_OK;
}

MCS_READOUT_DEFINE(moment, mcs_moment, mcs_readout_open_moment)
