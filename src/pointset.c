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

/* S(f) += sum over four points of amp_p e^{-2 pi i f x_p}, f = 0..F: the four
 * phase recurrences are independent, so they run side by side. */
static void add_four(mcs_pointset *acc, const double *x, const double *amp)
{
    const size_t fmax = acc->freq_max;
    double wr[4], wi[4], zr[4], zi[4];
    for (int p = 0; p < 4; ++p)
        mcs_ps_phase(x[p], 1u, &wr[p], &wi[p]);
    for (size_t c = 0; c <= fmax; c += MCS_PS_ANCHOR) {
        for (int p = 0; p < 4; ++p) {
            mcs_ps_phase(x[p], c, &zr[p], &zi[p]);
            zr[p] *= amp[p];
            zi[p] *= amp[p];
        }
        size_t end = fmax - c < MCS_PS_ANCHOR ? fmax + 1u : c + MCS_PS_ANCHOR;
        for (size_t f = c; f < end; ++f) {
            acc->re[f] += (zr[0] + zr[1]) + (zr[2] + zr[3]);
            acc->im[f] += (zi[0] + zi[1]) + (zi[2] + zi[3]);
            for (int p = 0; p < 4; ++p) {
                double t = zr[p] * wr[p] - zi[p] * wi[p];
                zi[p] = zr[p] * wi[p] + zi[p] * wr[p];
                zr[p] = t;
            }
        }
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
    const size_t fmax = acc->freq_max;
    memset(acc->re, 0, (fmax + 1u) * sizeof acc->re[0]);
    memset(acc->im, 0, (fmax + 1u) * sizeof acc->im[0]);
    for (size_t j = 0; j < k; j += 4u) {
        double x[4] = {0.0, 0.0, 0.0, 0.0}, amp[4] = {0.0, 0.0, 0.0, 0.0};
        for (size_t p = 0; p < 4u && j + p < k; ++p) {
            x[p] = points[j + p];
            amp[p] = 1.0;
        }
        add_four(acc, x, amp);
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
