/* The spectrum accumulator's public calls: set-up, argument checks, the
 * choice of path per trial, and merge. The kernels are in
 * spectrum_kernels.c, the read-outs in spectrum_readout.c, the AUTO model
 * and the batch rule in spectrum_cost.c. */
#include "mcspec/spectrum.h"

#include <math.h>
#include <string.h>

#include "acc_internal.h"
#include "dft/dft_internal.h"
#include "core/simd.h"
#include "spectrum_internal.h"

/* The object's own invariants: a set-up accumulator with a working plan, a
 * known path and counts that add up (every unit holds at least one trial).
 * MCS_ERR_NULL without it, MCS_ERR_UNINIT otherwise. */
static mcs_status spectrum_check(const mcs_spectrum *acc)
{
    if (acc == NULL)
        return MCS_ERR_NULL;
    if (!(acc->n >= 1u && acc->n <= (size_t)MCS_MAX_N &&
          (unsigned)acc->path <= (unsigned)MCS_SPECTRUM_PATH_PAIR && /* enum may be unsigned */
          acc->count <= MCS_SPECTRUM_MAX_COUNT && acc->open_count <= acc->count &&
          acc->units <= acc->count - acc->open_count && acc->batch <= MCS_SPECTRUM_BATCH_LIMIT &&
          (acc->simd == 0 || acc->simd == 1) &&
          (acc->units == 0u) == (acc->count == acc->open_count)))
        return MCS_ERR_UNINIT;
    return mcs_dft_check(&acc->plan, acc->n) == MCS_OK ? MCS_OK : MCS_ERR_UNINIT;
}

mcs_status mcs_spectrum_init(mcs_spectrum *acc, size_t n)
{
    if (acc == NULL)
        return MCS_ERR_NULL;
    if (n == 0u || n > (size_t)MCS_MAX_N)
        return MCS_ERR_N_RANGE;
    /* The plan is the only step that can fail; it leaves acc->plan as it was. */
    mcs_status st = mcs_dft_init(&acc->plan, n);
    if (st != MCS_OK)
        return st;
    /* Everything but the plan to zero (the scratch too: dense s must be 0). */
    const size_t plan_offset = offsetof(mcs_spectrum, plan);
    memset(acc, 0, plan_offset);
    memset((char *)acc + plan_offset + sizeof acc->plan, 0,
           sizeof *acc - plan_offset - sizeof acc->plan);
    acc->n = n;
    acc->path = MCS_SPECTRUM_PATH_AUTO;
    acc->simd = acc->plan.simd; /* the CPU's answer, asked once by the plan */
    mcs_spectrum_cost_init_(acc);
    return MCS_OK;
}

mcs_status mcs_spectrum_set_path(mcs_spectrum *acc, mcs_spectrum_path path)
{
    mcs_status st = spectrum_check(acc);
    if (st == MCS_OK && path != MCS_SPECTRUM_PATH_AUTO && path != MCS_SPECTRUM_PATH_SPARSE &&
        path != MCS_SPECTRUM_PATH_FFT && path != MCS_SPECTRUM_PATH_PAIR)
        st = MCS_ERR_KIND;
    if (st == MCS_OK)
        acc->path = path;
    return st;
}

mcs_status mcs_spectrum_set_batch(mcs_spectrum *acc, uint64_t batch)
{
    mcs_status st = spectrum_check(acc);
    if (st == MCS_OK && batch > MCS_SPECTRUM_BATCH_LIMIT)
        st = MCS_ERR_K_RANGE;
    if (st == MCS_OK) {
        acc->batch = batch;
        acc->auto_k = 0u; /* AUTO's model depends on the batch size */
    }
    return st;
}

mcs_status mcs_spectrum_flush(mcs_spectrum *acc)
{
    mcs_status st = spectrum_check(acc);
    if (st == MCS_OK && acc->open_count > 0u)
        mcs_spectrum_close_(acc);
    return st;
}

/* An input array of `bytes` must not lie inside the accumulator: the paths
 * write its scratch while they read the trial. */
static int inside(const mcs_spectrum *acc, const void *p, size_t bytes)
{
    return p != NULL && mcs_overlap_(p, bytes, acc, sizeof *acc);
}

/* MCS_ERR_MAGNITUDE when the weights (NULL: all 1, a sum of at most
 * MCS_MAX_K) sum above MCS_SPECTRUM_MAX_SUM (spectrum.h: nothing can then
 * overflow, so no later step can fail); the weights are checked already. */
static mcs_status check_sum(size_t k, const double *w)
{
    double sum = 0.0;
    for (size_t j = 0; w != NULL && j < k; ++j)
        sum += w[j];
    return sum <= MCS_SPECTRUM_MAX_SUM ? MCS_OK : MCS_ERR_MAGNITUDE;
}

/* The scan by the object's copy (the baseline one is shared with the other
 * accumulators, acc_internal.h; the AVX2 one is spectrum_kernels.c). */
static mcs_status check_bins(const mcs_spectrum *acc, size_t k, const size_t *b, const double *w)
{
    const size_t n = acc->n;
    double sum;
#if MCS_AVX2_CLONES
    const int ok = acc->simd ? mcs_spectrum_bins_ok_avx2_(n, k, b, w, &sum)
                             : mcs_bins_scan_(n, k, b, w, &sum);
#else
    const int ok = mcs_bins_scan_(n, k, b, w, &sum);
#endif
    if (ok && sum <= MCS_SPECTRUM_MAX_SUM)
        return MCS_OK;
    mcs_status st = mcs_check_sparse_(n, k, b, w);
    return st != MCS_OK ? st : check_sum(k, w);
}

/* The samples of a trial of points (mcs_check_points_, then the weights'
 * sum), one copy of the loop per kind of point (internal.h). */
static mcs_status check_points(const mcs_spectrum_trial_ *t)
{
    const mcs_points_ p = t->points;
    mcs_status st = p.f != NULL ? mcs_check_points_(t->k, mcs_points_f_(p.f), t->weights)
                                : mcs_check_points_(t->k, mcs_points_d_(p.d), t->weights);
    return st != MCS_OK ? st : check_sum(t->k, t->weights);
}

/* The checks of a trial: the object, K, the count, no input array inside
 * the accumulator, then its samples. */
static mcs_status check_trial(const mcs_spectrum *acc, const mcs_spectrum_trial_ *t)
{
    mcs_status st = spectrum_check(acc);
    if (st != MCS_OK)
        return st;
    if (t->k == 0u)
        return MCS_ERR_K_RANGE;
    if (acc->count >= MCS_SPECTRUM_MAX_COUNT)
        return MCS_ERR_COUNT;
    if (inside(acc, t->bins, mcs_bytes_(t->k, sizeof t->bins[0])) ||
        inside(acc, mcs_points_addr_(t->points), mcs_points_bytes_(t->points, t->k)) ||
        inside(acc, t->weights, mcs_bytes_(t->k, sizeof t->weights[0])))
        return MCS_ERR_ALIAS;
    return t->bins != NULL ? check_bins(acc, t->k, t->bins, t->weights) : check_points(t);
}

/* One checked trial down the path the policy gives it. */
static void add_trial(mcs_spectrum *acc, const mcs_spectrum_trial_ *t)
{
    const mcs_spectrum_path path =
        acc->path == MCS_SPECTRUM_PATH_AUTO ? mcs_spectrum_auto_(acc, t->k) : acc->path;
    switch (path) {
    case MCS_SPECTRUM_PATH_SPARSE: mcs_spectrum_sparse_(acc, t); break;
    case MCS_SPECTRUM_PATH_PAIR:
        mcs_spectrum_pairs_(acc, t);
        if (mcs_spectrum_batch_due_(acc))
            mcs_spectrum_close_(acc);
        break;
    default: mcs_spectrum_fft_(acc, t); break;
    }
}

mcs_status mcs_spectrum_add_bins(mcs_spectrum *acc, size_t k, const size_t *bins,
                                 const double *weights)
{
    if (bins == NULL || weights == NULL)
        return MCS_ERR_NULL;
    const mcs_spectrum_trial_ t = {k, bins, {NULL, NULL}, weights};
    mcs_status st = check_trial(acc, &t);
    if (st == MCS_OK)
        add_trial(acc, &t);
    return st;
}

/* Both point calls: the trial carries the points as given (double, or float
 * read in place and widened exactly where a path reads them, internal.h),
 * so every path gives the same bits for float points as for the widened
 * double ones. */
static mcs_status add_points(mcs_spectrum *acc, size_t k, mcs_points_ points,
                             const double *weights)
{
    if (mcs_points_addr_(points) == NULL)
        return MCS_ERR_NULL;
    const mcs_spectrum_trial_ t = {k, NULL, points, weights};
    mcs_status st = check_trial(acc, &t);
    if (st == MCS_OK)
        add_trial(acc, &t);
    return st;
}

mcs_status mcs_spectrum_add_points(mcs_spectrum *acc, size_t k, const double *points,
                                   const double *weights)
{
    return add_points(acc, k, mcs_points_d_(points), weights);
}

mcs_status mcs_spectrum_add_points_f(mcs_spectrum *acc, size_t k, const float *points,
                                     const double *weights)
{
    return add_points(acc, k, mcs_points_f_(points), weights);
}

mcs_status mcs_spectrum_add_dense(mcs_spectrum *acc, size_t n, const double *s)
{
    if (s == NULL)
        return MCS_ERR_NULL;
    mcs_status st = spectrum_check(acc);
    if (st != MCS_OK)
        return st;
    if (n != acc->n)
        return MCS_ERR_MISMATCH;
    if (inside(acc, s, mcs_bytes_(n, sizeof s[0])))
        return MCS_ERR_ALIAS;
    if (acc->count >= MCS_SPECTRUM_MAX_COUNT)
        return MCS_ERR_COUNT;
    double sum = 0.0;
    for (size_t j = 0; j < n; ++j) {
        if (!isfinite(s[j]))
            return MCS_ERR_NOT_FINITE;
        if (s[j] < 0.0)
            return MCS_ERR_NEGATIVE;
        sum += s[j];
    }
    if (!(sum <= MCS_SPECTRUM_MAX_SUM))
        return MCS_ERR_MAGNITUDE;
    mcs_spectrum_dense_(acc, s);
    return MCS_OK;
}

/* Chan, Golub and LeVeque on the closed units: shift each mean by the gap
 * times wb / (wa + wb) and add the gap's share wa wb / (wa + wb) to M2.
 * Reads src[k] before writing dst[k], so dst may be src. */
static void merge_closed(mcs_spectrum *dst, const mcs_spectrum *src, double wa, double wb)
{
    const size_t hpad = mcs_spectrum_blocks_(dst->n) * MCS_SPECTRUM_BLOCK;
    const double f = wb / (wa + wb), g = wa * wb / (wa + wb);
    for (size_t k = 0; k < hpad; ++k) {
        const double dr = src->mean_re[k] - dst->mean_re[k];
        const double di = src->mean_im[k] - dst->mean_im[k];
        const double dp = src->mean_pow[k] - dst->mean_pow[k];
        const double m2s = src->m2_s[k], m2p = src->m2_pow[k];
        dst->mean_re[k] += dr * f;
        dst->mean_im[k] += di * f;
        dst->m2_s[k] += m2s + (dr * dr + di * di) * g;
        dst->mean_pow[k] += dp * f;
        dst->m2_pow[k] += m2p + dp * dp * g;
    }
}

static void copy_closed(mcs_spectrum *dst, const mcs_spectrum *src)
{
    const size_t bytes = mcs_spectrum_blocks_(dst->n) * MCS_SPECTRUM_BLOCK * sizeof(double);
    memcpy(dst->mean_re, src->mean_re, bytes);
    memcpy(dst->mean_im, src->mean_im, bytes);
    memcpy(dst->m2_s, src->m2_s, bytes);
    memcpy(dst->mean_pow, src->mean_pow, bytes);
    memcpy(dst->m2_pow, src->m2_pow, bytes);
}

static mcs_status merge_check(const mcs_spectrum *dst, const mcs_spectrum *src)
{
    mcs_status st = src == NULL ? MCS_ERR_NULL : spectrum_check(dst);
    if (st == MCS_OK)
        st = spectrum_check(src);
    if (st != MCS_OK)
        return st;
    if (dst->n != src->n)
        return MCS_ERR_MISMATCH;
    if (dst != src && mcs_overlap_(dst, sizeof *dst, src, sizeof *src))
        return MCS_ERR_ALIAS;
    return src->count > MCS_SPECTRUM_MAX_COUNT - dst->count ? MCS_ERR_COUNT : MCS_OK;
}

mcs_status mcs_spectrum_merge(mcs_spectrum *dst, const mcs_spectrum *src)
{
    mcs_status st = merge_check(dst, src);
    if (st != MCS_OK || src->count == 0u)
        return st;
    const uint64_t closed_a = mcs_spectrum_closed_(dst), closed_b = mcs_spectrum_closed_(src);
    const uint64_t count = src->count, units = src->units, open = src->open_count;
    const double work = src->open_work;
    if (closed_b > 0u) {
        if (closed_a == 0u)
            copy_closed(dst, src);
        else
            merge_closed(dst, src, (double)closed_a, (double)closed_b);
    }
    if (open > 0u) { /* open batches: their sums add */
        const size_t n = dst->n;
        for (size_t j = 0; j < n; ++j)
            dst->open_sum[j] += src->open_sum[j];
        for (size_t j = 0; j < 2u * n; ++j)
            dst->open_pairs[j] += src->open_pairs[j];
    }
    dst->count += count;
    dst->units += units;
    dst->open_count += open;
    dst->open_work += work;
    if (dst->open_count > 0u && mcs_spectrum_batch_due_(dst))
        mcs_spectrum_close_(dst);
    return MCS_OK;
}

mcs_status mcs_spectrum_count(const mcs_spectrum *acc, uint64_t *count)
{
    mcs_status st = count == NULL ? MCS_ERR_NULL : spectrum_check(acc);
    if (st == MCS_OK)
        *count = acc->count;
    return st;
}

mcs_status mcs_spectrum_units(const mcs_spectrum *acc, uint64_t *units)
{
    mcs_status st = units == NULL ? MCS_ERR_NULL : spectrum_check(acc);
    if (st == MCS_OK)
        *units = acc->units + (acc->open_count > 0u ? 1u : 0u);
    return st;
}
