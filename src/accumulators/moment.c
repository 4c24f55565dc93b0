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
 * go in as products over their bins; larger ones densely (moment.h). The
 * crossover of the two kernels, timed on this project's machine (AMD EPYC,
 * gcc 12 -O2, AVX2 copy; ns per trial, pairs against dense rows): N = 16,
 * K = 12: 46 against 56, K = 16: 76 against 64; N = 64, K = 28: 186 against
 * 242, K = 36: 297 against 272. The pairs cost about 0.46 ns each, the
 * dense rows about 0.46 (N^2 / 32 + 7 N) ns: the fixed work of a trial over
 * N bins dominates at small N. */
static size_t sparse_terms_max(size_t n)
{
    return n * n / 32u + 7u * n;
}

/* Most entries a sparse trial's list holds (on the stack: 512 bytes): its
 * samples and, if it shares a bin with the shift, the shift's bins. A trial
 * that needs more goes in densely. */
#define LIST_LEN 32u

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

/* The shift settles over the first MCS_MOMENT_SETTLE trials: c keeps the
 * first trial's s only on the bins every one of them fills, and is 0
 * elsewhere. A bin that trial after trial fills is one the next ones fill
 * again, with weights like the first's (s - c small: the shift keeps the
 * digits that a cancelling <s^2> - <s>^2 would lose); on the others s is
 * mostly 0, so shifting by 0 costs nothing, and a sparse trial seldom meets
 * a bin of the shift (add_sparse_d: about K^4 / N^3 bins at K samples a
 * trial). Trial x (not yet added) drops the bins where it has no weight:
 * e = c there, c' = c - e, and the sums of d = s - c move to d + e (as a
 * merge moves them): sum d + T e and sum d d^T + (sum d) e^T + e (sum d)^T
 * + T e e^T, with T <= MCS_MOMENT_SETTLE trials, each of which has
 * d + e = s, so no entry grows past a few times its new size. */
static double dropped(const double *x, const double *c, size_t m)
{
    return x[m] == 0.0 ? c[m] : 0.0;
}

static void settle_shift(mcs_moment *acc, const double *x)
{
    const size_t n = acc->n;
    const double *c = acc->shift;
    size_t drops = 0u;
    for (size_t m = 0; m < n; ++m)
        drops += dropped(x, c, m) != 0.0;
    if (drops == 0u)
        return;
    if (acc->batch_count != 0u)
        fold_batch(acc); /* the sums to move are the closed ones */
    const double t = (double)acc->count;
    for (size_t m = 0; m < n; ++m) {
        const double em = dropped(x, c, m);
        for (size_t q = 0; q < n; ++q) {
            const double eq = dropped(x, c, q);
            if (em == 0.0 && eq == 0.0)
                continue;
            const size_t i = m * n + q;
            mcs_kahan_add_(&acc->sum_dd[i], &acc->lo_dd[i],
                           (em * acc->sum_d[q] + acc->sum_d[m] * eq) + t * (em * eq));
        }
    }
    for (size_t m = 0; m < n; ++m) {
        const double em = dropped(x, c, m);
        if (em != 0.0) {
            mcs_kahan_add_(&acc->sum_d[m], &acc->lo_d[m], t * em);
            acc->shift[m] = 0.0;
        }
    }
}

/* 1 when s (x) has weight on a bin of the shift. */
static int shares_shift(const mcs_moment *acc, const double *x)
{
    for (size_t m = 0; m < acc->n; ++m)
        if (x[m] != 0.0 && acc->shift[m] != 0.0)
            return 1;
    return 0;
}

/* work holds the trial's s. The first trial becomes the shift c (its d is
 * 0: no sums change), the next ones settle it (settle_shift). A later one
 * goes into the batch as s s^T or as d d^T (d = s - c), whichever has fewer
 * rows that are not 0 (a stratified trial: d has none; a random one: s has
 * fewer), but as s only if it has no bin where c is not 0: on such a bin
 * s - c may be far smaller than s and c, and products of s would cancel at
 * the fold (issue 22). */
static void add_dense_work(mcs_moment *acc)
{
    const size_t n = acc->n;
    double *restrict x = acc->work;
    if (acc->count == 0u) {
        memcpy(acc->shift, x, n * sizeof x[0]);
        acc->count = 1u;
        return;
    }
    if (acc->count < (uint64_t)MCS_MOMENT_SETTLE)
        settle_shift(acc, x);
    size_t rows_s = 0u, rows_d = 0u;
    for (size_t m = 0; m < n; ++m) {
        rows_s += x[m] != 0.0;
        rows_d += x[m] != acc->shift[m];
    }
    if (rows_s < rows_d && !shares_shift(acc, x)) {
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

/* x over a list of len entries (bins[j], vals[j]) into first[], and half of
 * x x^T into the open batch: x_j^2 / 2 at [b_j][b_j] and x_j x_i at
 * [b_j][b_i] for i > j, whichever triangle that is (the half products add
 * both orders). A bin listed twice has its value at one entry and 0 at the
 * others, whose products add exact zeros: every entry of the batch gets at
 * most one product that is not 0 a trial (the bound of moment.h). Inlined:
 * a call cost 10 % at K = 8. */
static MCS_ALWAYS_INLINE void add_list_products(double *restrict w, double *restrict first,
                                                size_t n, size_t len, const size_t *bins,
                                                const double *vals)
{
    for (size_t j = 0; j < len; ++j) {
        const size_t bj = bins[j];
        const double xj = vals[j];
        double *restrict row = &w[bj * n];
        first[bj] += xj;
        row[bj] += 0.5 * (xj * xj);
        size_t i = j + 1u;
        for (; i + 2u <= len; i += 2u) { /* two pairs a step: less loop overhead */
            const size_t b0 = bins[i], b1 = bins[i + 1u];
            const double p0 = xj * vals[i], p1 = xj * vals[i + 1u];
            row[b0] += p0;
            row[b1] += p1;
        }
        if (i < len)
            row[bins[i]] += xj * vals[i];
    }
}

/* The trial's s into x on its bins: 0 first, then each bin's weights in
 * sample order, so s_n is rounded as a dense trial's would be. */
static void scatter_trial(double *restrict x, size_t k, const size_t *bins, const double *weights)
{
    for (size_t j = 0; j < k; ++j)
        x[bins[j]] = 0.0;
    for (size_t j = 0; j < k; ++j)
        x[bins[j]] += weights[j];
}

/* vals[j] = x at bins[j] for the first sample of each bin, 0 for the rest
 * (x is set to 0 as each bin is read). Fixed places, no compaction: the
 * stores' addresses do not wait on the values (a compacted list took twice
 * the time). */
static void collect_trial(double *restrict x, size_t k, const size_t *bins, double *vals)
{
    for (size_t j = 0; j < k; ++j) {
        const size_t b = bins[j];
        vals[j] = x[b];
        x[b] = 0.0;
    }
}

/* vals[j] = s_n for the first sample of each bin n of the trial (its
 * weights summed in sample order, as a dense trial's are), 0 for the
 * others. A bin seen before (a bit per bin mod 64) is looked up among the
 * earlier samples: repeats are few. */
static void merge_repeats(size_t k, const size_t *bins, const double *weights, double *vals)
{
    uint64_t seen = 0u;
    for (size_t j = 0; j < k; ++j) {
        const size_t b = bins[j];
        const uint64_t bit = UINT64_C(1) << (b & 63u);
        size_t first = j;
        if (seen & bit)
            for (size_t i = 0; i < j; ++i)
                if (bins[i] == b) {
                    first = i;
                    break;
                }
        vals[j] = 0.0;
        vals[first] += weights[j]; /* first == j: 0 + w, exact */
        seen |= bit;
    }
}

/* A sparse trial on no bin of the shift: there d = s, and where c is not 0
 * d = -c, the same for every such trial. Its s goes into batch_s and half
 * of s s^T into the batch, one product per pair of bins; the fold adds the
 * terms in c (readout.h), none of which cancels the trial's. A trial whose
 * bins are distinct (`distinct`) is its own list: s_n is its one weight. */
static MCS_ALWAYS_INLINE void add_sparse_s(mcs_moment *acc, size_t k, const size_t *bins,
                                           const double *weights, int distinct)
{
    double vals[LIST_LEN];
    const double *v = weights;
    if (!distinct) {
        merge_repeats(k, bins, weights, vals);
        v = vals;
    }
    add_list_products(acc->batch_w, acc->batch_s, acc->n, k, bins, v);
    acc->batch_sparse += 1u;
    close_trial(acc);
}

/* A sparse trial that shares a bin with the shift: there s - c may be far
 * smaller than s and c (issue 22: weights of 1e8 on a bin every trial
 * hits), so products of s would cancel at the fold. Its d = s - c instead,
 * over the shift's bins and its own, into batch_d and half of d d^T. 0
 * (nothing written) when the list would not fit: the caller goes densely. */
static int add_sparse_d(mcs_moment *acc, size_t k, const size_t *bins, const double *weights)
{
    const size_t n = acc->n;
    const double *c = acc->shift;
    double *restrict x = acc->work;
    size_t list_bins[LIST_LEN];
    double vals[LIST_LEN];
    size_t len = 0u;
    for (size_t m = 0; m < n; ++m) /* the shift's bins; room left for the trial's */
        if (c[m] != 0.0) {
            if (len + k == LIST_LEN)
                return 0;
            list_bins[len++] = m;
        }
    for (size_t i = 0; i < len; ++i)
        x[list_bins[i]] = 0.0;
    scatter_trial(x, k, bins, weights);
    for (size_t i = 0; i < len; ++i) { /* d on the shift's bins */
        const size_t b = list_bins[i];
        vals[i] = x[b] - c[b];
        x[b] = 0.0;
    }
    memcpy(&list_bins[len], bins, k * sizeof *bins);
    collect_trial(x, k, bins, &vals[len]); /* the trial's other bins: d = s */
    len += k;
    add_list_products(acc->batch_w, acc->batch_d, n, len, list_bins, vals);
    close_trial(acc);
    return 1;
}

/* Bits set in x (SWAR: no loop, no builtin). */
static size_t bit_count(uint64_t x)
{
    x -= (x >> 1) & UINT64_C(0x5555555555555555);
    x = (x & UINT64_C(0x3333333333333333)) + ((x >> 2) & UINT64_C(0x3333333333333333));
    x = (x + (x >> 4)) & UINT64_C(0x0f0f0f0f0f0f0f0f);
    return (size_t)((x * UINT64_C(0x0101010101010101)) >> 56);
}

/* What the scan of a sparse trial finds besides its validity: its total
 * weight, a bit per bin mod 64 (`seen`), and whether a bin of the shift is
 * among its bins (`shared`). */
typedef struct {
    double total;
    uint64_t seen;
    int shared;
} trial_scan;

/* mcs_bins_scan_ (acc_internal.h), with the bins and the shift read in the
 * same pass (a bin out of range reads the shift at bin 0: the trial is
 * refused anyway). 1 when every bin is in range and no weight negative. */
static int scan_trial(const mcs_moment *acc, size_t k, const size_t *b, const double *w,
                      trial_scan *out)
{
    const size_t n = acc->n;
    const double *c = acc->shift;
    size_t bad = 0u, shared = 0u, j = 0;
    uint64_t seen0 = 0u, seen1 = 0u;
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    for (; j + 4u <= k; j += 4u) {
        const size_t b0 = b[j], b1 = b[j + 1u], b2 = b[j + 2u], b3 = b[j + 3u];
        bad |= (size_t)(b0 >= n) | (size_t)(b1 >= n) | (size_t)(b2 >= n) | (size_t)(b3 >= n);
        bad |= (size_t)(w[j] < 0.0) | (size_t)(w[j + 1u] < 0.0) | (size_t)(w[j + 2u] < 0.0) |
               (size_t)(w[j + 3u] < 0.0);
        shared |= (size_t)(c[b0 < n ? b0 : 0u] != 0.0) | (size_t)(c[b1 < n ? b1 : 0u] != 0.0) |
                  (size_t)(c[b2 < n ? b2 : 0u] != 0.0) | (size_t)(c[b3 < n ? b3 : 0u] != 0.0);
        seen0 |= (UINT64_C(1) << (b0 & 63u)) | (UINT64_C(1) << (b1 & 63u));
        seen1 |= (UINT64_C(1) << (b2 & 63u)) | (UINT64_C(1) << (b3 & 63u));
        s0 += w[j];
        s1 += w[j + 1u];
        s2 += w[j + 2u];
        s3 += w[j + 3u];
    }
    for (; j < k; ++j) {
        const size_t bj = b[j];
        bad |= (size_t)(bj >= n) | (size_t)(w[j] < 0.0);
        shared |= (size_t)(c[bj < n ? bj : 0u] != 0.0);
        seen0 |= UINT64_C(1) << (bj & 63u);
        s0 += w[j];
    }
    out->total = (s0 + s1) + (s2 + s3);
    out->seen = seen0 | seen1;
    out->shared = shared != 0u;
    return bad == 0u;
}

/* The checks of mcs_check_add_sparse_ (acc_internal.h: the same statuses in
 * the same order) over scan_trial's pass. */
static mcs_status check_trial(const mcs_moment *acc, size_t k, const size_t *bins,
                              const double *weights, trial_scan *sc)
{
    if (k == 0u || !scan_trial(acc, k, bins, weights, sc) ||
        !(sc->total <= 0.5 * MCS_MOMENT_MAX_TRIAL)) {
        mcs_status st = mcs_check_sparse_(acc->n, k, bins, weights);
        if (st != MCS_OK)
            return st;
        sc->total = mcs_weights_total_(k, weights);
    }
    return mcs_check_add_(acc, sizeof *acc, acc->count, sc->total, MCS_MOMENT_MAX_TRIAL, bins,
                          mcs_bytes_(k, sizeof *bins), weights, mcs_bytes_(k, sizeof *weights));
}

mcs_status mcs_moment_add_bins(mcs_moment *acc, size_t k, const size_t *bins,
                               const double *weights)
{
    mcs_status st = bins == NULL || weights == NULL ? MCS_ERR_NULL : moment_check(acc);
    if (st != MCS_OK)
        return st;
    /* a trial of few samples goes in by its list (the scan also finds its
     * distinct bins and those of the shift); others densely */
    const int sparse = acc->count >= (uint64_t)MCS_MOMENT_SETTLE && k <= LIST_LEN &&
                       k <= acc->n && k * (k + 1u) / 2u <= sparse_terms_max(acc->n);
    trial_scan sc = {0.0, 0u, 0};
    st = sparse ? check_trial(acc, k, bins, weights, &sc)
                : mcs_check_add_sparse_(acc, sizeof *acc, acc->n, acc->count, k, bins, weights,
                                        MCS_MOMENT_MAX_TRIAL);
    if (st != MCS_OK)
        return st;
    if (sparse) {
        if (!sc.shared) { /* bits for distinct bins: exact for N <= 64, else it may miss */
            add_sparse_s(acc, k, bins, weights, bit_count(sc.seen) == k);
            return MCS_OK;
        }
        if (add_sparse_d(acc, k, bins, weights))
            return MCS_OK;
    }
    /* s of the trial: per-bin sums of its weights (eq. 38) */
    memset(acc->work, 0, acc->n * sizeof acc->work[0]);
    for (size_t j = 0; j < k; ++j)
        acc->work[bins[j]] += weights[j];
    add_dense_work(acc);
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
    add_dense_work(acc);
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
    /* sums no trials give would pass into dst: refused (O(N^2), as the merge) */
    if (st == MCS_OK && (!mcs_moment_stored_valid(dst) || !mcs_moment_stored_valid(src)))
        st = MCS_ERR_INVARIANT;
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
    if (!mcs_moment_stored_valid(acc))
        return MCS_ERR_INVARIANT;
    const size_t n = acc->n;
    /* k = 0: the accumulator does not know K, the caller names it */
    *view = (mcs_readout){.n = n,
                          .k = 0u,
                          .scale = 1.0 / (double)acc->count,
                          .first = acc->sum_d,
                          .second = acc->sum_dd,
                          .cos_table = acc->cos_table,
                          .sin_table = acc->sin_table,
                          .shift = acc->shift,
                          .accum = MCS_MOMENT_ROUNDING_};
    if (acc->batch_count != 0u) {
        view->batch_w = acc->batch_w;
        view->batch_s = acc->batch_s;
        view->batch_d = acc->batch_d;
        view->batch_sparse = (double)acc->batch_sparse;
    }
    return MCS_OK;
}

MCS_READOUT_DEFINE(moment, mcs_moment, mcs_readout_open_moment)
