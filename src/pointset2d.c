#include "mcspec/pointset2d.h"
#include "pointset_internal.h"

#include <math.h>
#include <string.h>

/* Layout: wave vector (fx, fy), fy = 0..F, fx = -F..F, at fy (2F+2) + fx + F
 * (column 2F+1 of each row is padding that stays 0 and is never read).
 * The fy = 0 row is stored whole; (fx, fy > 0) stands for itself and for
 * (-fx, -fy), so whole-plane sums weigh the fy = 0 row 1 and the rest 2. */

enum { XR = 0, XI = 1, YR = 2, YI = 3 };

#define RING_ZERO 1e-20

static int pointset2d_is_valid(const mcs_pointset2d *acc)
{
    return acc->freq_max >= 1u && acc->freq_max <= (size_t)MCS_MAX_FREQ;
}

mcs_status mcs_pointset2d_init(mcs_pointset2d *acc, size_t freq_max)
{
    if (acc == NULL)
        return MCS_ERR_NULL;
    if (freq_max == 0u || freq_max > (size_t)MCS_MAX_FREQ)
        return MCS_ERR_FREQ_RANGE;
    memset(acc, 0, sizeof *acc);
    acc->freq_max = freq_max;
    return MCS_OK;
}

/* Annulus of the stored wave vector at column c (fx = c - F), row fy. */
static size_t ring_of(size_t fmax, size_t c, size_t fy)
{
    size_t ax = c >= fmax ? c - fmax : fmax - c;
    return mcs_ps_isqrt(ax * ax + fy * fy);
}

/* Phase rows of point slot p: x row over fx = -F..F (negative fx by
 * conjugation, exactly), y row over fy = 0..F scaled by amp. */
static void phase_rows(mcs_pointset2d *acc, int p, double x, double y, double amp)
{
    const size_t fmax = acc->freq_max;
    double *xr = acc->phase[p][XR], *xi = acc->phase[p][XI];
    mcs_ps_phase_row(x, 1.0, fmax, xr + fmax, xi + fmax);
    for (size_t f = 1; f <= fmax; ++f) {
        xr[fmax - f] = xr[fmax + f];
        xi[fmax - f] = -xi[fmax + f];
    }
    xr[2u * fmax + 1u] = 0.0; /* the padding column */
    xi[2u * fmax + 1u] = 0.0;
    mcs_ps_phase_row(y, amp, fmax, acc->phase[p][YR], acc->phase[p][YI]);
}

/* S(fx, fy) += sum over the four slots of ex_p(fx) ey_p(fy): one pass over
 * the stored wave vectors per four points. */
static void accumulate_four(mcs_pointset2d *acc)
{
    const size_t fmax = acc->freq_max, stride = 2u * fmax + 2u;
    double (*ph)[4][MCS_POINTSET2D_ROW] = acc->phase;
    for (size_t fy = 0; fy <= fmax; ++fy) {
        double y[8];
        for (size_t p = 0; p < 4u; ++p) {
            y[2u * p] = ph[p][YR][fy];
            y[2u * p + 1u] = ph[p][YI][fy];
        }
        mcs_ps_row_update4(stride, acc->re + fy * stride, acc->im + fy * stride, ph[0][XR],
                           ph[0][XI], ph[1][XR], ph[1][XI], ph[2][XR], ph[2][XI], ph[3][XR],
                           ph[3][XI], y);
    }
}

/* Per-trial P into the Welford means, and the per-trial annulus averages
 * into theirs. The ring sums reuse the phase scratch (free by now). */
static void update_statistics(mcs_pointset2d *acc, size_t k)
{
    const size_t fmax = acc->freq_max, row = 2u * fmax + 1u, stride = row + 1u;
    double *ring_sum = acc->phase[0][XR], *ring_n = acc->phase[0][XI];
    memset(ring_sum, 0, (fmax + 1u) * sizeof *ring_sum);
    memset(ring_n, 0, (fmax + 1u) * sizeof *ring_n);
    acc->count++;
    const double inv_k = 1.0 / (double)k;
    for (size_t fy = 0; fy <= fmax; ++fy) {
        const double w = fy == 0u ? 1.0 : 2.0;
        for (size_t c = 0; c < row; ++c) {
            size_t i = fy * stride + c;
            double p = (acc->re[i] * acc->re[i] + acc->im[i] * acc->im[i]) * inv_k;
            mcs_ps_welford(&acc->mean[i], &acc->m2[i], p, acc->count);
            size_t r = ring_of(fmax, c, fy);
            if (r <= fmax) {
                ring_sum[r] += w * p;
                ring_n[r] += w;
            }
        }
    }
    for (size_t r = 0; r <= fmax; ++r)
        mcs_ps_welford(&acc->ring_mean[r], &acc->ring_m2[r], ring_sum[r] / ring_n[r],
                       acc->count);
}

mcs_status mcs_pointset2d_add(mcs_pointset2d *acc, size_t k, const double *points)
{
    if (acc == NULL || points == NULL)
        return MCS_ERR_NULL;
    if (!pointset2d_is_valid(acc))
        return MCS_ERR_UNINIT;
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    if (k > SIZE_MAX / 2u || !mcs_ps_points_in_range(2u * k, points))
        return MCS_ERR_POINT_RANGE;
    const size_t fmax = acc->freq_max, cells = (2u * fmax + 2u) * (fmax + 1u);
    memset(acc->re, 0, cells * sizeof acc->re[0]);
    memset(acc->im, 0, cells * sizeof acc->im[0]);
    for (size_t j = 0; j < k; j += 4u) {
        for (int p = 0; p < 4; ++p) {
            size_t q = j + (size_t)p;
            if (q < k)
                phase_rows(acc, p, points[2u * q], points[2u * q + 1u], 1.0);
            else
                phase_rows(acc, p, 0.0, 0.0, 0.0); /* padding: contributes 0 */
        }
        accumulate_four(acc);
    }
    update_statistics(acc, k);
    return MCS_OK;
}

mcs_status mcs_pointset2d_merge(mcs_pointset2d *dst, const mcs_pointset2d *src)
{
    if (dst == NULL || src == NULL)
        return MCS_ERR_NULL;
    if (!pointset2d_is_valid(dst) || !pointset2d_is_valid(src))
        return MCS_ERR_UNINIT;
    if (dst->freq_max != src->freq_max)
        return MCS_ERR_MISMATCH;
    if (src->count == 0u)
        return MCS_OK;
    const uint64_t na = dst->count, nb = src->count;
    const size_t fmax = dst->freq_max, cells = (2u * fmax + 2u) * (fmax + 1u);
    for (size_t i = 0; i < cells; ++i)
        mcs_ps_chan(&dst->mean[i], &dst->m2[i], na, src->mean[i], src->m2[i], nb);
    for (size_t r = 0; r <= fmax; ++r)
        mcs_ps_chan(&dst->ring_mean[r], &dst->ring_m2[r], na, src->ring_mean[r], src->ring_m2[r],
                    nb);
    dst->count = na + nb;
    return MCS_OK;
}

mcs_status mcs_pointset2d_count(const mcs_pointset2d *acc, uint64_t *count)
{
    if (acc == NULL || count == NULL)
        return MCS_ERR_NULL;
    if (!pointset2d_is_valid(acc))
        return MCS_ERR_UNINIT;
    *count = acc->count;
    return MCS_OK;
}

static mcs_status read_check(const mcs_pointset2d *acc, const double *out)
{
    if (acc == NULL || out == NULL)
        return MCS_ERR_NULL;
    return pointset2d_is_valid(acc) ? MCS_OK : MCS_ERR_UNINIT;
}

/* Stored index of (fx, fy), mirrored to fy >= 0; MCS_ERR_FREQ_RANGE outside. */
static mcs_status cell_index(const mcs_pointset2d *acc, long fx, long fy, size_t *index)
{
    const size_t fmax = acc->freq_max;
    if (mcs_ps_abs(fx) > fmax || mcs_ps_abs(fy) > fmax)
        return MCS_ERR_FREQ_RANGE;
    if (fy < 0) {
        fx = -fx;
        fy = -fy;
    }
    *index = (size_t)fy * (2u * fmax + 2u) + (size_t)(fx + (long)fmax);
    return MCS_OK;
}

static mcs_status power_read(const mcs_pointset2d *acc, long fx, long fy, const double *out,
                             uint64_t min_count, size_t *index)
{
    mcs_status st = read_check(acc, out);
    if (st == MCS_OK)
        st = cell_index(acc, fx, fy, index);
    if (st == MCS_OK && acc->count < min_count)
        st = MCS_ERR_EMPTY;
    return st;
}

mcs_status mcs_pointset2d_power(const mcs_pointset2d *acc, long freq_x, long freq_y, double *out)
{
    size_t i = 0u;
    mcs_status st = power_read(acc, freq_x, freq_y, out, 1u, &i);
    if (st == MCS_OK)
        *out = acc->mean[i];
    return st;
}

mcs_status mcs_pointset2d_power_stderr(const mcs_pointset2d *acc, long freq_x, long freq_y,
                                       double *out)
{
    size_t i = 0u;
    mcs_status st = power_read(acc, freq_x, freq_y, out, 2u, &i);
    if (st == MCS_OK)
        *out = mcs_ps_stderr(acc->m2[i], acc->count);
    return st;
}

static mcs_status radial_read(const mcs_pointset2d *acc, size_t radius, const double *out,
                              uint64_t min_count)
{
    mcs_status st = read_check(acc, out);
    if (st != MCS_OK)
        return st;
    if (radius > acc->freq_max)
        return MCS_ERR_FREQ_RANGE;
    return acc->count < min_count ? MCS_ERR_EMPTY : MCS_OK;
}

mcs_status mcs_pointset2d_radial(const mcs_pointset2d *acc, size_t radius, double *out)
{
    mcs_status st = radial_read(acc, radius, out, 1u);
    if (st == MCS_OK)
        *out = acc->ring_mean[radius];
    return st;
}

mcs_status mcs_pointset2d_radial_stderr(const mcs_pointset2d *acc, size_t radius, double *out)
{
    mcs_status st = radial_read(acc, radius, out, 2u);
    if (st == MCS_OK)
        *out = mcs_ps_stderr(acc->ring_m2[radius], acc->count);
    return st;
}

/* Whole-plane mean and unbiased variance of the mean periodogram over annulus
 * r, in two passes (the variance of values near a large mean would cancel in
 * one). Returns the whole-plane count. */
static double ring_moments(const mcs_pointset2d *acc, size_t r, double *mean, double *var)
{
    const size_t fmax = acc->freq_max, row = 2u * fmax + 1u;
    double sum = 0.0, n = 0.0, ss = 0.0;
    for (int pass = 0; pass < 2; ++pass) {
        for (size_t fy = 0; fy <= fmax; ++fy)
            for (size_t c = 0; c < row; ++c) {
                if (ring_of(fmax, c, fy) != r)
                    continue;
                double w = fy == 0u ? 1.0 : 2.0, p = acc->mean[fy * (row + 1u) + c];
                if (pass == 0) {
                    sum += w * p;
                    n += w;
                } else {
                    ss += w * (p - sum / n) * (p - sum / n);
                }
            }
    }
    *mean = sum / n;
    *var = n > 1.0 ? ss / (n - 1.0) : 0.0;
    return n;
}

mcs_status mcs_pointset2d_anisotropy(const mcs_pointset2d *acc, size_t radius, double *out_db)
{
    mcs_status st = radial_read(acc, radius, out_db, 1u);
    if (st != MCS_OK)
        return st;
    double mean = 0.0, var = 0.0;
    double n = ring_moments(acc, radius, &mean, &var);
    /* An exactly empty annulus (a grid's) measures as rounding residue,
     * around K 1e-32; below RING_ZERO its mean counts as 0. */
    if (n < 2.0 || !(mean > RING_ZERO) || !(var > 0.0))
        return MCS_ERR_DOMAIN;
    *out_db = 10.0 * log10(var / (mean * mean));
    return MCS_OK;
}

mcs_status mcs_pointset2d_ring_size(size_t radius, size_t *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    const size_t lim = radius + 1u;
    size_t n = 0u;
    for (size_t ay = 0; ay < lim; ++ay)
        for (size_t ax = 0; ax < lim; ++ax) {
            if (mcs_ps_isqrt(ax * ax + ay * ay) != radius)
                continue;
            n += (size_t)(ax > 0u ? 2u : 1u) * (ay > 0u ? 2u : 1u); /* the sign choices */
        }
    *out = n;
    return MCS_OK;
}
