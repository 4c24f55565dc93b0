/* Private helpers shared by the accumulators that keep compensated sums of
 * trials (moment, autocorr; the point-set ones can use the merge check): the
 * bound on stored values, the checks of an add and of a merge, and the merge
 * of two compensated sums. Static inline, as internal.h. */
#ifndef MCSPEC_ACC_INTERNAL_H
#define MCSPEC_ACC_INTERNAL_H

#include "core/internal.h"

#include <float.h>

/* Read-outs refuse a stored value above 2^500 in magnitude, the bound of the
 * record format too (io.h): trials never get there (the sums stay below
 * 2^496, see each header's trial limit), and below it every read-out,
 * squares of transforms of N values included, stays finite on any object. */
#define MCS_STORED_LIMIT_ 3.273390607896142e+150 /* 2^500 */

/* Every x[len] finite and at most limit in magnitude (NaN fails the
 * compare). */
static inline int mcs_all_below_(size_t len, const double *x, double limit)
{
    int ok = 1;
    for (size_t j = 0; j < len; ++j)
        ok &= fabs(x[j]) <= limit;
    return ok;
}

/* Every x[len] finite and at most MCS_STORED_LIMIT_ in magnitude. */
static inline int mcs_all_stored_(size_t len, const double *x)
{
    return mcs_all_below_(len, x, MCS_STORED_LIMIT_);
}

/* The moment accumulator's values of one trial or one batch (moment.h), and
 * the limits its read-outs and records hold them to: a trial's s and the
 * shift are below 2^220 (MCS_MOMENT_MAX_TRIAL), a batch's sums of s and of d
 * below 2^14 of them, its half products below 2^14 * 2^440. Within these,
 * what a batch adds at read-out (up to 2^14 c_m c_n) stays far below
 * MCS_STORED_LIMIT_, so every read-out stays finite as for the other sums. */
#define MCS_MOMENT_LIMIT_S_ 1.7668470647783843e+72  /* 2^240: shift, batch_s, batch_d */
#define MCS_MOMENT_LIMIT_W_ 2.977131414714806e+138  /* 2^460: batch_w */

/* The rounding the moment accumulator's sums carry, relative (moment.h):
 * every entry of the sums of d d^T, closed and open batch together, is
 * within (MCS_MOMENT_BATCH + 64) eps sqrt(D_m D_n) of the exact sum over the
 * trials, D the sums of d_m^2. A batch entry is a plain sum of one product
 * a trial (below MCS_MOMENT_BATCH of them: gamma_B), each product and the
 * fold's terms a few roundings, the compensated sums 2u + F u^2 <= 3u over
 * F <= 2^53 folds and merges, and the moves of the shift as it settles
 * (moment.c, settle_shift) under 32 eps each. */
#define MCS_MOMENT_ROUNDING_ ((double)(MCS_MOMENT_BATCH + 64u) * DBL_EPSILON)

/* The checks every add shares once the object and the trial are valid: the
 * trial's total weight at most max_total (MAGNITUDE), the count (COUNT), and
 * the caller's arrays a and b (b_bytes 0 for none) outside the object
 * (ALIAS). */
static inline mcs_status mcs_check_add_(const void *obj, size_t obj_bytes, uint64_t count,
                                        double total, double max_total, const void *a,
                                        size_t a_bytes, const void *b, size_t b_bytes)
{
    if (!(total <= max_total))
        return MCS_ERR_MAGNITUDE;
    mcs_status st = mcs_check_count_(count, 1u);
    if (st == MCS_OK && (mcs_overlap_(a, a_bytes, obj, obj_bytes) ||
                         mcs_overlap_(b, b_bytes, obj, obj_bytes)))
        st = MCS_ERR_ALIAS;
    return st;
}

/* Bins and weights of a trial without a branch per sample: 0 for any bin
 * out of range or negative weight, else 1 and the weights' sum in *total
 * (NaN and infinities poison it, so the caller's bound on the sum refuses
 * them; four partial sums keep the adds apart). Only a trial that fails is
 * checked again sample by sample, for the status of its first bad sample. */
static inline int mcs_bins_scan_(size_t n, size_t k, const size_t *b, const double *w,
                                 double *total)
{
    size_t bad = 0u, j = 0;
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    for (; j + 4u <= k; j += 4u) {
        bad |= (size_t)(b[j] >= n) | (size_t)(b[j + 1u] >= n) | (size_t)(b[j + 2u] >= n) |
               (size_t)(b[j + 3u] >= n);
        bad |= (size_t)(w[j] < 0.0) | (size_t)(w[j + 1u] < 0.0) | (size_t)(w[j + 2u] < 0.0) |
               (size_t)(w[j + 3u] < 0.0);
        s0 += w[j];
        s1 += w[j + 1u];
        s2 += w[j + 2u];
        s3 += w[j + 3u];
    }
    for (; j < k; ++j) {
        bad |= (size_t)(b[j] >= n) | (size_t)(w[j] < 0.0);
        s0 += w[j];
    }
    *total = (s0 + s1) + (s2 + s3);
    return bad == 0u;
}

/* The same for a sparse trial on an object of N = n bins (checked already):
 * the trial as mcs_check_sparse_, then mcs_check_add_ with its weights'
 * sum. */
static inline mcs_status mcs_check_add_sparse_(const void *obj, size_t obj_bytes, size_t n,
                                               uint64_t count, size_t k, const size_t *bins,
                                               const double *weights, double max_total)
{
    /* The scan's sum differs from the one in sample order by rounding: a
     * trial within half the bound passes either way, any other is checked
     * sample by sample (so NaN, infinities and the bound's edge get the
     * statuses of that check). */
    double total;
    if (k == 0u || !mcs_bins_scan_(n, k, bins, weights, &total) || !(total <= 0.5 * max_total)) {
        mcs_status st = mcs_check_sparse_(n, k, bins, weights);
        if (st != MCS_OK)
            return st;
        total = mcs_weights_total_(k, weights);
    }
    return mcs_check_add_(obj, obj_bytes, count, total, max_total, bins,
                          mcs_bytes_(k, sizeof *bins), weights, mcs_bytes_(k, sizeof *weights));
}

/* The status of a call on two objects (merge) from each one's own check:
 * MCS_ERR_NULL first, as if both had been checked for NULL before anything
 * else, then the first object's status, then the second's. */
static inline mcs_status mcs_check_pair_(mcs_status a, mcs_status b)
{
    if (a == MCS_ERR_NULL || b == MCS_ERR_NULL)
        return MCS_ERR_NULL;
    return a != MCS_OK ? a : b;
}

/* The checks of merging src into dst once both objects passed their own
 * (mcs_check_pair_): MISMATCH unless same_shape, COUNT if the counts would
 * add up past MCS_MAX_COUNT, ALIAS for distinct objects that overlap
 * (dst == src is allowed: it doubles). */
static inline mcs_status mcs_check_merge_(const void *dst, const void *src, size_t bytes,
                                          int same_shape, uint64_t dst_count, uint64_t src_count)
{
    if (!same_shape)
        return MCS_ERR_MISMATCH;
    mcs_status st = mcs_check_count_(dst_count, src_count);
    if (st == MCS_OK && dst != src && mcs_overlap_(dst, bytes, src, bytes))
        st = MCS_ERR_ALIAS;
    return st;
}

/* Adds the compensated sum (src_sum, src_lo), whose total is
 * src_sum - src_lo, to (*sum, *lo). The caller reads both src values before
 * either destination is written, so a merge into itself doubles. */
static inline void mcs_kahan_merge_(double *sum, double *lo, double src_sum, double src_lo)
{
    mcs_kahan_add_(sum, lo, src_sum);
    mcs_kahan_add_(sum, lo, -src_lo);
}

#endif /* MCSPEC_ACC_INTERNAL_H */
