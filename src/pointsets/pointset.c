#include "mcspec/pointset.h"
#include "pointset_internal.h"

#include <math.h>
#include <string.h>

/* MCS_ERR_NULL without acc, MCS_ERR_UNINIT unless it came from init. */
static mcs_status check_acc(const mcs_pointset *acc)
{
    return mcs_check_object_(acc, acc != NULL ? acc->freq_max : 0u, (size_t)MCS_MAX_FREQ_1D);
}

mcs_status mcs_pointset_init(mcs_pointset *acc, size_t freq_max)
{
    mcs_status st = mcs_ps_check_init(acc, freq_max, (size_t)MCS_MAX_FREQ_1D);
    if (st != MCS_OK)
        return st;
    memset(acc, 0, sizeof *acc);
    acc->freq_max = freq_max;
    return MCS_OK;
}

/* Phase rows of point slot p for point q of k (a padding slot past the
 * last point contributes 0): low[b] = e^{-2 pi i b x}, b < B, and
 * high[a] = e^{-2 pi i a B x}, a < blocks. B x mod 1 is exact (B is a power
 * of two), so the high row is the phase row of that fraction. */
static void phase_rows(mcs_pointset *acc, int p, size_t k, mcs_points_ points, size_t q)
{
    const double x = q < k ? mcs_point_(points, q) : 0.0, amp = q < k ? 1.0 : 0.0;
    const size_t blocks = acc->freq_max / MCS_POINTSET_BLOCK + 1u;
    mcs_ps_phase_row(x, 1.0, MCS_POINTSET_BLOCK - 1u, acc->low[p][0], acc->low[p][1]);
    double xb = (double)MCS_POINTSET_BLOCK * x;
    mcs_ps_phase_row(xb - floor(xb), amp, blocks - 1u, acc->high[p][0], acc->high[p][1]);
}

/* S(a B + b) += sum over the four slots of high_p[a] low_p[b]. */
static void accumulate_four(mcs_pointset *acc)
{
    const double *const x[8] = {acc->low[0][0], acc->low[0][1], acc->low[1][0], acc->low[1][1],
                                acc->low[2][0], acc->low[2][1], acc->low[3][0], acc->low[3][1]};
    const double *const y[8] = {acc->high[0][0], acc->high[0][1], acc->high[1][0],
                                acc->high[1][1], acc->high[2][0], acc->high[2][1],
                                acc->high[3][0], acc->high[3][1]};
    mcs_ps_outer4(acc->freq_max / MCS_POINTSET_BLOCK + 1u, MCS_POINTSET_BLOCK, acc->re, acc->im,
                  x, y);
}

/* The body of mcs_pointset_add and mcs_pointset_add_f, over double or float
 * points (internal.h): the same bits from the widened points. */
static MCS_ALWAYS_INLINE mcs_status add_points(mcs_pointset *acc, size_t k, mcs_points_ points)
{
    mcs_status st = mcs_points_addr_(points) == NULL ? MCS_ERR_NULL : check_acc(acc);
    if (st == MCS_OK)
        st = k == 0u ? MCS_ERR_K_RANGE : mcs_check_points_(k, points, NULL);
    if (st == MCS_OK)
        st = mcs_check_count_(acc->count, 1u);
    if (st != MCS_OK)
        return st;
    const size_t fmax = acc->freq_max, blocks = fmax / MCS_POINTSET_BLOCK + 1u;
    mcs_ps_clear(blocks * MCS_POINTSET_BLOCK, acc->re, acc->im);
    for (size_t j = 0; j < k; j += 4u) {
        for (int p = 0; p < 4; ++p)
            phase_rows(acc, p, k, points, j + (size_t)p);
        accumulate_four(acc);
    }
    acc->count++;
    const double inv_k = 1.0 / (double)k;
    for (size_t f = 0; f <= fmax; ++f) {
        double p = (acc->re[f] * acc->re[f] + acc->im[f] * acc->im[f]) * inv_k;
        mcs_ps_welford(&acc->mean[f], &acc->m2[f], p, acc->count);
    }
    return MCS_OK;
}

mcs_status mcs_pointset_add(mcs_pointset *acc, size_t k, const double *points)
{
    return add_points(acc, k, mcs_points_d_(points));
}

mcs_status mcs_pointset_add_f(mcs_pointset *acc, size_t k, const float *points)
{
    return add_points(acc, k, mcs_points_f_(points));
}

mcs_status mcs_pointset_merge(mcs_pointset *dst, const mcs_pointset *src)
{
    mcs_status st = mcs_check_pair_(check_acc(dst), check_acc(src));
    if (st == MCS_OK)
        st = mcs_check_merge_(dst, src, sizeof *dst, dst->freq_max == src->freq_max, dst->count,
                              src->count);
    if (st != MCS_OK || src->count == 0u)
        return st;
    mcs_ps_chan_cells(dst->freq_max + 1u, dst->mean, dst->m2, dst->count, src->mean, src->m2,
                      src->count);
    dst->count += src->count;
    return MCS_OK;
}

mcs_status mcs_pointset_count(const mcs_pointset *acc, uint64_t *count)
{
    mcs_status st = count == NULL ? MCS_ERR_NULL : check_acc(acc);
    return mcs_ps_count_out(st, st == MCS_OK ? acc->count : 0u, count);
}

/* <P(freq)> (want_stderr 0) or its standard error (1). */
static mcs_status read_power(const mcs_pointset *acc, long freq, int want_stderr, double *out)
{
    mcs_status st = out == NULL ? MCS_ERR_NULL : check_acc(acc);
    if (st != MCS_OK)
        return st;
    const size_t f = mcs_ps_abs(freq);
    if (f > acc->freq_max)
        return MCS_ERR_FREQ_RANGE;
    return mcs_ps_read(acc->mean[f], acc->m2[f], acc->count, want_stderr, out);
}

mcs_status mcs_pointset_power(const mcs_pointset *acc, long freq, double *out)
{
    return read_power(acc, freq, 0, out);
}

mcs_status mcs_pointset_power_stderr(const mcs_pointset *acc, long freq, double *out)
{
    return read_power(acc, freq, 1, out);
}

mcs_status mcs_pointset_exact_power(mcs_pattern_kind kind, size_t k, long freq, double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    if (kind != MCS_PATTERN_RANDOM && kind != MCS_PATTERN_STRATIFIED &&
        kind != MCS_PATTERN_UNIFORM && kind != MCS_PATTERN_JITTER)
        return MCS_ERR_KIND;
    const double kd = (double)k;
    const size_t f = mcs_ps_abs(freq);
    if (f == 0u) {
        *out = kd;
        return MCS_OK;
    }
    switch (kind) {
    case MCS_PATTERN_RANDOM: *out = 1.0; break;
    case MCS_PATTERN_STRATIFIED: *out = 1.0 - mcs_ps_sinc2(f, k); break;
    default: /* a comb: all K phases agree exactly when K divides f */
        *out = f % k == 0u ? kd : 0.0;
        break;
    }
    return MCS_OK;
}
