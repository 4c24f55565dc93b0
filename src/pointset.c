#include "mcspec/pointset.h"
#include "pointset_internal.h"

#include <math.h>
#include <string.h>

static int pointset_is_valid(const mcs_pointset *acc)
{
    return acc->freq_max >= 1u && acc->freq_max <= (size_t)MCS_MAX_FREQ_1D;
}

mcs_status mcs_pointset_init(mcs_pointset *acc, size_t freq_max)
{
    if (acc == NULL)
        return MCS_ERR_NULL;
    if (freq_max == 0u || freq_max > (size_t)MCS_MAX_FREQ_1D)
        return MCS_ERR_FREQ_RANGE;
    memset(acc, 0, sizeof *acc);
    acc->freq_max = freq_max;
    return MCS_OK;
}

/* Phase rows of point slot p: low[b] = e^{-2 pi i b x}, b < B, and
 * high[a] = amp e^{-2 pi i a B x}, a < blocks. B x mod 1 is exact (B is a
 * power of two), so the high row is the phase row of that fraction. */
static void phase_rows(mcs_pointset *acc, int p, double x, double amp, size_t blocks)
{
    mcs_ps_phase_row(x, 1.0, MCS_POINTSET_BLOCK - 1u, acc->low[p][0], acc->low[p][1]);
    double xb = (double)MCS_POINTSET_BLOCK * x;
    mcs_ps_phase_row(xb - floor(xb), amp, blocks - 1u, acc->high[p][0], acc->high[p][1]);
}

/* S(a B + b) += sum over the four slots of high_p[a] low_p[b]. */
static void accumulate_four(mcs_pointset *acc, size_t blocks)
{
    for (size_t a = 0; a < blocks; ++a) {
        double y[8];
        for (size_t p = 0; p < 4u; ++p) {
            y[2u * p] = acc->high[p][0][a];
            y[2u * p + 1u] = acc->high[p][1][a];
        }
        size_t off = a * MCS_POINTSET_BLOCK;
        mcs_ps_row_update4(MCS_POINTSET_BLOCK, acc->re + off, acc->im + off, acc->low[0][0],
                           acc->low[0][1], acc->low[1][0], acc->low[1][1], acc->low[2][0],
                           acc->low[2][1], acc->low[3][0], acc->low[3][1], y);
    }
}

mcs_status mcs_pointset_add(mcs_pointset *acc, size_t k, const double *points)
{
    if (acc == NULL || points == NULL)
        return MCS_ERR_NULL;
    if (!pointset_is_valid(acc))
        return MCS_ERR_UNINIT;
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    if (!mcs_ps_points_in_range(k, points))
        return MCS_ERR_POINT_RANGE;
    const size_t fmax = acc->freq_max, blocks = fmax / MCS_POINTSET_BLOCK + 1u;
    memset(acc->re, 0, blocks * MCS_POINTSET_BLOCK * sizeof acc->re[0]);
    memset(acc->im, 0, blocks * MCS_POINTSET_BLOCK * sizeof acc->im[0]);
    for (size_t j = 0; j < k; j += 4u) {
        for (int p = 0; p < 4; ++p) {
            size_t q = j + (size_t)p;
            phase_rows(acc, p, q < k ? points[q] : 0.0, q < k ? 1.0 : 0.0, blocks);
        }
        accumulate_four(acc, blocks);
    }
    acc->count++;
    const double inv_k = 1.0 / (double)k;
    for (size_t f = 0; f <= fmax; ++f) {
        double p = (acc->re[f] * acc->re[f] + acc->im[f] * acc->im[f]) * inv_k;
        mcs_ps_welford(&acc->mean[f], &acc->m2[f], p, acc->count);
    }
    return MCS_OK;
}

mcs_status mcs_pointset_merge(mcs_pointset *dst, const mcs_pointset *src)
{
    if (dst == NULL || src == NULL)
        return MCS_ERR_NULL;
    if (!pointset_is_valid(dst) || !pointset_is_valid(src))
        return MCS_ERR_UNINIT;
    if (dst->freq_max != src->freq_max)
        return MCS_ERR_MISMATCH;
    if (src->count == 0u)
        return MCS_OK;
    const uint64_t na = dst->count, nb = src->count;
    for (size_t f = 0; f <= dst->freq_max; ++f)
        mcs_ps_chan(&dst->mean[f], &dst->m2[f], na, src->mean[f], src->m2[f], nb);
    dst->count = na + nb;
    return MCS_OK;
}

mcs_status mcs_pointset_count(const mcs_pointset *acc, uint64_t *count)
{
    if (acc == NULL || count == NULL)
        return MCS_ERR_NULL;
    if (!pointset_is_valid(acc))
        return MCS_ERR_UNINIT;
    *count = acc->count;
    return MCS_OK;
}

static mcs_status read_check(const mcs_pointset *acc, long freq, const double *out,
                             uint64_t min_count, size_t *index)
{
    if (acc == NULL || out == NULL)
        return MCS_ERR_NULL;
    if (!pointset_is_valid(acc))
        return MCS_ERR_UNINIT;
    size_t f = mcs_ps_abs(freq);
    if (f > acc->freq_max)
        return MCS_ERR_FREQ_RANGE;
    if (acc->count < min_count)
        return MCS_ERR_EMPTY;
    *index = f;
    return MCS_OK;
}

mcs_status mcs_pointset_power(const mcs_pointset *acc, long freq, double *out)
{
    size_t f = 0u;
    mcs_status st = read_check(acc, freq, out, 1u, &f);
    if (st == MCS_OK)
        *out = acc->mean[f];
    return st;
}

mcs_status mcs_pointset_power_stderr(const mcs_pointset *acc, long freq, double *out)
{
    size_t f = 0u;
    mcs_status st = read_check(acc, freq, out, 2u, &f);
    if (st == MCS_OK)
        *out = mcs_ps_stderr(acc->m2[f], acc->count);
    return st;
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
