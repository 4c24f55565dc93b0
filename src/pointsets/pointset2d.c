#include "mcspec/pointset2d.h"
#include "pointset_internal.h"

#include <math.h>
#include <string.h>

/* Layout: wave vector (fx, fy), fy = 0..F, fx = -F..F, at fy (2F+2) + fx + F
 * (column 2F+1 of each row is padding that stays 0 and is never read).
 * The fy = 0 row is stored whole; (fx, fy > 0) stands for itself and for
 * (-fx, -fy), so whole-plane sums weigh the fy = 0 row 1 and the rest 2. */

enum { XR = 0, XI = 1, YR = 2, YI = 3 };

/* An exactly empty annulus (a grid's) measures as rounding residue, around
 * K 1e-32; below this its mean counts as 0. */
#define RING_ZERO 1e-20

/* MCS_ERR_NULL without acc, MCS_ERR_UNINIT unless it came from init. */
static mcs_status check_acc(const mcs_pointset2d *acc)
{
    return mcs_check_object_(acc, acc != NULL ? acc->freq_max : 0u, (size_t)MCS_MAX_FREQ);
}

/* Stored wave vectors: (2F + 2) columns by F + 1 rows. */
static size_t cells_of(size_t fmax)
{
    return (2u * fmax + 2u) * (fmax + 1u);
}

mcs_status mcs_pointset2d_init(mcs_pointset2d *acc, size_t freq_max)
{
    mcs_status st = mcs_ps_check_init(acc, freq_max, (size_t)MCS_MAX_FREQ);
    if (st != MCS_OK)
        return st;
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

/* Phase rows of point slot p for point q of k (a padding slot past the last
 * point contributes 0): x row over fx = -F..F (negative fx by conjugation,
 * exactly), y row over fy = 0..F scaled by the amplitude. */
static void phase_rows(mcs_pointset2d *acc, int p, size_t k, mcs_points_ points, size_t q)
{
    const size_t fmax = acc->freq_max;
    const double x = q < k ? mcs_point_(points, 2u * q) : 0.0;
    const double y = q < k ? mcs_point_(points, 2u * q + 1u) : 0.0;
    double *xr = acc->phase[p][XR], *xi = acc->phase[p][XI];
    mcs_ps_phase_row(x, 1.0, fmax, xr + fmax, xi + fmax);
    for (size_t f = 1; f <= fmax; ++f) {
        xr[fmax - f] = xr[fmax + f];
        xi[fmax - f] = -xi[fmax + f];
    }
    xr[2u * fmax + 1u] = 0.0; /* the padding column */
    xi[2u * fmax + 1u] = 0.0;
    mcs_ps_phase_row(y, q < k ? 1.0 : 0.0, fmax, acc->phase[p][YR], acc->phase[p][YI]);
}

/* S(fx, fy) += sum over the four slots of ex_p(fx) ey_p(fy): one pass over
 * the stored wave vectors per four points. */
static void accumulate_four(mcs_pointset2d *acc)
{
    double (*ph)[4][MCS_POINTSET2D_ROW] = acc->phase;
    const double *const x[8] = {ph[0][XR], ph[0][XI], ph[1][XR], ph[1][XI],
                                ph[2][XR], ph[2][XI], ph[3][XR], ph[3][XI]};
    const double *const y[8] = {ph[0][YR], ph[0][YI], ph[1][YR], ph[1][YI],
                                ph[2][YR], ph[2][YI], ph[3][YR], ph[3][YI]};
    mcs_ps_outer4(acc->freq_max + 1u, 2u * acc->freq_max + 2u, acc->re, acc->im, x, y);
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

/* The body of mcs_pointset2d_add and mcs_pointset2d_add_f, over double or
 * float points (internal.h): the same bits from the widened points. */
static MCS_ALWAYS_INLINE mcs_status add_points(mcs_pointset2d *acc, size_t k, mcs_points_ points)
{
    mcs_status st = mcs_points_addr_(points) == NULL ? MCS_ERR_NULL : check_acc(acc);
    if (st == MCS_OK && k == 0u)
        st = MCS_ERR_K_RANGE;
    if (st == MCS_OK)
        st = k > SIZE_MAX / 2u ? MCS_ERR_POINT_RANGE : mcs_check_points_(2u * k, points, NULL);
    if (st == MCS_OK)
        st = mcs_check_count_(acc->count, 1u);
    if (st != MCS_OK)
        return st;
    mcs_ps_clear(cells_of(acc->freq_max), acc->re, acc->im);
    for (size_t j = 0; j < k; j += 4u) {
        for (int p = 0; p < 4; ++p)
            phase_rows(acc, p, k, points, j + (size_t)p);
        accumulate_four(acc);
    }
    update_statistics(acc, k);
    return MCS_OK;
}

mcs_status mcs_pointset2d_add(mcs_pointset2d *acc, size_t k, const double *points)
{
    return add_points(acc, k, mcs_points_d_(points));
}

mcs_status mcs_pointset2d_add_f(mcs_pointset2d *acc, size_t k, const float *points)
{
    return add_points(acc, k, mcs_points_f_(points));
}

mcs_status mcs_pointset2d_merge(mcs_pointset2d *dst, const mcs_pointset2d *src)
{
    mcs_status st = mcs_check_pair_(check_acc(dst), check_acc(src));
    if (st == MCS_OK)
        st = mcs_check_merge_(dst, src, sizeof *dst, dst->freq_max == src->freq_max, dst->count,
                              src->count);
    if (st != MCS_OK || src->count == 0u)
        return st;
    const uint64_t na = dst->count, nb = src->count;
    const size_t fmax = dst->freq_max;
    mcs_ps_chan_cells(cells_of(fmax), dst->mean, dst->m2, na, src->mean, src->m2, nb);
    mcs_ps_chan_cells(fmax + 1u, dst->ring_mean, dst->ring_m2, na, src->ring_mean, src->ring_m2,
                      nb);
    dst->count = na + nb;
    return MCS_OK;
}

mcs_status mcs_pointset2d_count(const mcs_pointset2d *acc, uint64_t *count)
{
    mcs_status st = count == NULL ? MCS_ERR_NULL : check_acc(acc);
    return mcs_ps_count_out(st, st == MCS_OK ? acc->count : 0u, count);
}

/* <P(fx, fy)> (want_stderr 0) or its standard error (1), read at the stored
 * mirror (-fx, -fy) when fy < 0. */
static mcs_status read_power(const mcs_pointset2d *acc, long fx, long fy, int want_stderr,
                             double *out)
{
    mcs_status st = out == NULL ? MCS_ERR_NULL : check_acc(acc);
    if (st != MCS_OK)
        return st;
    const size_t fmax = acc->freq_max;
    if (mcs_ps_abs(fx) > fmax || mcs_ps_abs(fy) > fmax)
        return MCS_ERR_FREQ_RANGE;
    if (fy < 0) {
        fx = -fx;
        fy = -fy;
    }
    const size_t i = (size_t)fy * (2u * fmax + 2u) + (size_t)(fx + (long)fmax);
    return mcs_ps_read(acc->mean[i], acc->m2[i], acc->count, want_stderr, out);
}

mcs_status mcs_pointset2d_power(const mcs_pointset2d *acc, long freq_x, long freq_y, double *out)
{
    return read_power(acc, freq_x, freq_y, 0, out);
}

mcs_status mcs_pointset2d_power_stderr(const mcs_pointset2d *acc, long freq_x, long freq_y,
                                       double *out)
{
    return read_power(acc, freq_x, freq_y, 1, out);
}

/* The checks of a read-out of annulus radius. */
static mcs_status check_radius(const mcs_pointset2d *acc, size_t radius, const double *out)
{
    mcs_status st = out == NULL ? MCS_ERR_NULL : check_acc(acc);
    return st == MCS_OK && radius > acc->freq_max ? MCS_ERR_FREQ_RANGE : st;
}

mcs_status mcs_pointset2d_radial(const mcs_pointset2d *acc, size_t radius, double *out)
{
    mcs_status st = check_radius(acc, radius, out);
    return st != MCS_OK ? st
                        : mcs_ps_read(acc->ring_mean[radius], 0.0, acc->count, 0, out);
}

mcs_status mcs_pointset2d_radial_stderr(const mcs_pointset2d *acc, size_t radius, double *out)
{
    mcs_status st = check_radius(acc, radius, out);
    return st != MCS_OK ? st
                        : mcs_ps_read(0.0, acc->ring_m2[radius], acc->count, 1, out);
}

/* The mean periodogram over annulus r, the whole plane counted. */
static void ring_moments(const mcs_pointset2d *acc, size_t r, mcs_ps_ring *g)
{
    const size_t fmax = acc->freq_max, row = 2u * fmax + 1u;
    for (int pass = 0; pass < 2; ++pass)
        for (size_t fy = 0; fy <= fmax; ++fy)
            for (size_t c = 0; c < row; ++c)
                if (ring_of(fmax, c, fy) == r)
                    mcs_ps_ring_add(g, pass, fy == 0u ? 1.0 : 2.0, acc->mean[fy * (row + 1u) + c]);
}

mcs_status mcs_pointset2d_anisotropy(const mcs_pointset2d *acc, size_t radius, double *out_db)
{
    mcs_status st = check_radius(acc, radius, out_db);
    if (st == MCS_OK && acc->count == 0u)
        st = MCS_ERR_EMPTY;
    if (st != MCS_OK)
        return st;
    mcs_ps_ring g = {0.0, 0.0, 0.0};
    ring_moments(acc, radius, &g);
    return mcs_ps_ring_db(&g, RING_ZERO, 0.0, out_db);
}

/* Integer wave vectors of the whole plane with |f|^2 < q: row fy (and -fy),
 * fy^2 < q, holds the fx with fx^2 <= q - fy^2 - 1. O(sqrt q) steps. */
static size_t disc_size(size_t q)
{
    size_t n = 0u;
    for (size_t fy = 0; fy * fy < q; ++fy)
        n += (fy > 0u ? 2u : 1u) * (2u * mcs_ps_isqrt(q - fy * fy - 1u) + 1u);
    return n;
}

mcs_status mcs_pointset2d_ring_size(size_t radius, size_t *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    if (radius > (size_t)MCS_MAX_FREQ)
        return MCS_ERR_FREQ_RANGE;
    *out = disc_size((radius + 1u) * (radius + 1u)) - disc_size(radius * radius);
    return MCS_OK;
}
