#include "mcspec/spectrum2d.h"
#include "mcspec/spectrum.h"
#include "pointset_internal.h"

#include <math.h>
#include <string.h>

/* Layout: wave vector (k1, k2), k2 = 0..N2/2, at k2 * stride + k1 with
 * stride = N1 rounded up to even (the pad column stays 0, never read). */

enum { XR = 0, XI = 1, YR = 2, YI = 3 };

static size_t stride_of(size_t n_x)
{
    return n_x + n_x % 2u;
}

/* Stored wave vectors of an N1 x N2 plane: rows k2 = 0..N2/2. */
static size_t cells_of(const mcs_spectrum2d *acc)
{
    return stride_of(acc->n_x) * (acc->n_y / 2u + 1u);
}

static int side_ok(size_t n)
{
    return n >= 1u && n <= (size_t)MCS_MAX_SIDE;
}

/* MCS_ERR_NULL without acc, MCS_ERR_UNINIT unless it came from init,
 * MCS_ERR_INVARIANT for a count past the largest. O(1). */
static mcs_status check_acc(const mcs_spectrum2d *acc)
{
    if (acc == NULL)
        return MCS_ERR_NULL;
    if (!side_ok(acc->n_x) || !side_ok(acc->n_y))
        return MCS_ERR_UNINIT;
    return acc->count <= MCS_SPECTRUM_MAX_COUNT ? MCS_OK : MCS_ERR_INVARIANT;
}

/* What trials within MCS_SPECTRUM_MAX_SUM give (spectrum2d.h): |S_k| <=
 * 2^100, so |<S_k>| <= 2^100 and <|S_k|^2> in [0, 2^200], and over c
 * trials each M2 is at most (c - 1) times the square of the largest gap
 * from the mean (2^202 for S_k, 2^400 for |S_k|^2, as for welford), here
 * with room for rounding: no mean without a trial, no spread with one. */
#define MAX_ABS_S 0x1p101
#define MAX_POWER 0x1p202
#define SPREAD_S 0x1p204
#define SPREAD_POWER 0x1p404

static int in_range(double x, double lo, double hi)
{
    return x >= lo && x <= hi; /* NaN is in no range */
}

/* The twiddles init builds: in [-1, 1]. O(N1 + N2). */
static int twiddles_sound(const mcs_spectrum2d *acc)
{
    int sound = 1;
    for (size_t t = 0; t < acc->n_x; ++t)
        sound &= in_range(acc->cos_x[t], -1.0, 1.0) & in_range(acc->sin_x[t], -1.0, 1.0);
    for (size_t t = 0; t < acc->n_y; ++t)
        sound &= in_range(acc->cos_y[t], -1.0, 1.0) & in_range(acc->sin_y[t], -1.0, 1.0);
    return sound;
}

/* The statistics of stored cell i within the bounds above. O(1). */
static int cell_sound(const mcs_spectrum2d *acc, size_t i)
{
    const double some = acc->count > 0u ? 1.0 : 0.0;
    const double spread = acc->count > 0u ? (double)(acc->count - 1u) : 0.0;
    return fabs(acc->mean_re[i]) <= some * MAX_ABS_S &&
           fabs(acc->mean_im[i]) <= some * MAX_ABS_S &&
           in_range(acc->mean_pow[i], 0.0, some * MAX_POWER) &&
           in_range(acc->m2_s[i], 0.0, spread * SPREAD_S) &&
           in_range(acc->m2_pow[i], 0.0, spread * SPREAD_POWER);
}

/* check_acc, then every stored cell, the pad column 0 (no call writes it)
 * and the twiddles: what an add or a merge reads. O(N1 N2). */
static mcs_status check_body(const mcs_spectrum2d *acc)
{
    mcs_status st = check_acc(acc);
    if (st != MCS_OK)
        return st;
    const size_t stride = stride_of(acc->n_x);
    int sound = twiddles_sound(acc);
    for (size_t k2 = 0; k2 <= acc->n_y / 2u; ++k2) {
        for (size_t k1 = 0; k1 < acc->n_x; ++k1)
            sound &= cell_sound(acc, k2 * stride + k1);
        if (stride > acc->n_x) {
            const size_t pad = k2 * stride + acc->n_x;
            sound &= acc->mean_re[pad] == 0.0 && acc->mean_im[pad] == 0.0 &&
                     acc->mean_pow[pad] == 0.0 && acc->m2_s[pad] == 0.0 &&
                     acc->m2_pow[pad] == 0.0;
        }
    }
    return sound ? MCS_OK : MCS_ERR_INVARIANT;
}

mcs_status mcs_spectrum2d_init(mcs_spectrum2d *acc, size_t n_x, size_t n_y)
{
    if (acc == NULL)
        return MCS_ERR_NULL;
    if (!side_ok(n_x) || !side_ok(n_y))
        return MCS_ERR_N_RANGE;
    memset(acc, 0, sizeof *acc);
    acc->n_x = n_x;
    acc->n_y = n_y;
    mcs_twiddles_(n_x, acc->cos_x, acc->sin_x);
    mcs_twiddles_(n_y, acc->cos_y, acc->sin_y);
    return MCS_OK;
}

/* Twiddle rows of point slot p for point q of k, binned at (b1, b2), with its
 * weight (a padding slot past the last point has weight 0):
 * x row e^{-2 pi i k1 b1/N1}, k1 < N1; y row w e^{-2 pi i k2 b2/N2}, k2 <= N2/2.
 * Table indices advance by b mod N, so every twiddle is an exact entry. */
static void twiddle_rows(mcs_spectrum2d *acc, int p, size_t k, mcs_points_ points,
                         const double *weights, size_t q)
{
    const size_t n1 = acc->n_x, n2 = acc->n_y;
    const size_t b1 = q < k ? mcs_point_bin_(mcs_point_(points, 2u * q), n1) : 0u;
    const size_t b2 = q < k ? mcs_point_bin_(mcs_point_(points, 2u * q + 1u), n2) : 0u;
    const double w = q >= k ? 0.0 : weights != NULL ? weights[q] : 1.0;
    double *xr = acc->rows[p][XR], *xi = acc->rows[p][XI];
    for (size_t k1 = 0, t = 0; k1 < n1; ++k1) {
        xr[k1] = acc->cos_x[t];
        xi[k1] = -acc->sin_x[t];
        t += b1;
        t = t >= n1 ? t - n1 : t;
    }
    if (n1 % 2u) { /* the pad column */
        xr[n1] = 0.0;
        xi[n1] = 0.0;
    }
    for (size_t k2 = 0, t = 0; k2 <= n2 / 2u; ++k2) {
        acc->rows[p][YR][k2] = w * acc->cos_y[t];
        acc->rows[p][YI][k2] = -w * acc->sin_y[t];
        t += b2;
        t = t >= n2 ? t - n2 : t;
    }
}

static void accumulate_four(mcs_spectrum2d *acc)
{
    double (*r)[4][MCS_SPECTRUM2D_STRIDE] = acc->rows;
    const double *const x[8] = {r[0][XR], r[0][XI], r[1][XR], r[1][XI],
                                r[2][XR], r[2][XI], r[3][XR], r[3][XI]};
    const double *const y[8] = {r[0][YR], r[0][YI], r[1][YR], r[1][YI],
                                r[2][YR], r[2][YI], r[3][YR], r[3][YI]};
    mcs_ps_outer4(acc->n_y / 2u + 1u, stride_of(acc->n_x), acc->re, acc->im, x, y);
}

/* Normalise the trial's S_k (eq. 7's N^{-1/2}) and update the statistics. */
static void update_statistics(mcs_spectrum2d *acc)
{
    const size_t n1 = acc->n_x, stride = stride_of(n1);
    const double scale = 1.0 / sqrt((double)n1 * (double)acc->n_y);
    acc->count++;
    const double c = (double)acc->count;
    for (size_t k2 = 0; k2 <= acc->n_y / 2u; ++k2)
        for (size_t k1 = 0; k1 < n1; ++k1) {
            size_t i = k2 * stride + k1;
            double sr = acc->re[i] * scale, si = acc->im[i] * scale;
            double dr = sr - acc->mean_re[i], di = si - acc->mean_im[i];
            acc->mean_re[i] += dr / c;
            acc->mean_im[i] += di / c;
            acc->m2_s[i] += dr * (sr - acc->mean_re[i]) + di * (si - acc->mean_im[i]);
            mcs_ps_welford(&acc->mean_pow[i], &acc->m2_pow[i], sr * sr + si * si, acc->count);
        }
}

/* The checks of a trial: K >= 1, points[2 k] in [0,1), weights[k] (if any)
 * finite and >= 0, in that order, then their sum at most
 * MCS_SPECTRUM_MAX_SUM: |S_k| <= 2^100 then, so no square or fourth power
 * of the statistics can overflow (as for the 1D accumulator, spectrum.h). */
static mcs_status check_trial(size_t k, mcs_points_ points, const double *weights)
{
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    if (k > SIZE_MAX / 2u)
        return MCS_ERR_POINT_RANGE;
    mcs_status st = mcs_check_points_(2u * k, points, NULL);
    double sum = 0.0;
    for (size_t j = 0; st == MCS_OK && weights != NULL && j < k; ++j) {
        st = mcs_check_weight_(weights[j]);
        sum += weights[j];
    }
    return st == MCS_OK && !(sum <= MCS_SPECTRUM_MAX_SUM) ? MCS_ERR_MAGNITUDE : st;
}

/* The body of mcs_spectrum2d_add_points and its _f twin, over double or
 * float points (internal.h): the same bits from the widened points. Not
 * inlined: a point costs O(N1 + N2) here, far more than the test of its
 * kind, and the inlined copies would realign their frames. */
static mcs_status add_points(mcs_spectrum2d *acc, size_t k, mcs_points_ points,
                             const double *weights)
{
    mcs_status st = mcs_points_addr_(points) == NULL ? MCS_ERR_NULL : check_body(acc);
    if (st == MCS_OK && acc->count >= MCS_SPECTRUM_MAX_COUNT)
        st = MCS_ERR_COUNT;
    if (st == MCS_OK)
        st = check_trial(k, points, weights);
    if (st != MCS_OK)
        return st;
    mcs_ps_clear(cells_of(acc), acc->re, acc->im);
    for (size_t j = 0; j < k; j += 4u) {
        for (int p = 0; p < 4; ++p)
            twiddle_rows(acc, p, k, points, weights, j + (size_t)p);
        accumulate_four(acc);
    }
    update_statistics(acc);
    return MCS_OK;
}

mcs_status mcs_spectrum2d_add_points(mcs_spectrum2d *acc, size_t k, const double *points,
                                     const double *weights)
{
    return add_points(acc, k, mcs_points_d_(points), weights);
}

mcs_status mcs_spectrum2d_add_points_f(mcs_spectrum2d *acc, size_t k, const float *points,
                                       const double *weights)
{
    return add_points(acc, k, mcs_points_f_(points), weights);
}

mcs_status mcs_spectrum2d_merge(mcs_spectrum2d *dst, const mcs_spectrum2d *src)
{
    mcs_status st = mcs_check_pair_(check_body(dst), check_body(src));
    if (st == MCS_OK)
        st = mcs_check_merge_(dst, src, sizeof *dst, dst->n_x == src->n_x && dst->n_y == src->n_y,
                              dst->count, src->count);
    if (st != MCS_OK || src->count == 0u)
        return st;
    const uint64_t na = dst->count, nb = src->count;
    const double n = (double)na + (double)nb, fb = (double)nb / n;
    const double cross = (double)na * (double)nb / n;
    const size_t cells = cells_of(dst);
    /* Chan et al. for the complex mean: the squared gap is |d|^2. */
    for (size_t i = 0; i < cells; ++i) {
        double dr = src->mean_re[i] - dst->mean_re[i], di = src->mean_im[i] - dst->mean_im[i];
        dst->mean_re[i] += dr * fb;
        dst->mean_im[i] += di * fb;
        dst->m2_s[i] += src->m2_s[i] + (dr * dr + di * di) * cross;
    }
    mcs_ps_chan_cells(cells, dst->mean_pow, dst->m2_pow, na, src->mean_pow, src->m2_pow, nb);
    dst->count = na + nb;
    return MCS_OK;
}

mcs_status mcs_spectrum2d_count(const mcs_spectrum2d *acc, uint64_t *count)
{
    mcs_status st = count == NULL ? MCS_ERR_NULL : check_acc(acc);
    return mcs_ps_count_out(st, st == MCS_OK ? acc->count : 0u, count);
}

/* The checks of a read-out at k = (k1, k2) with output out, and the stored
 * index of k; *conj = 1 when it is the mirror -k's entry. */
static mcs_status lookup(const mcs_spectrum2d *acc, size_t k1, size_t k2, const double *out,
                         size_t *index, int *conj)
{
    mcs_status st = out == NULL ? MCS_ERR_NULL : check_acc(acc);
    if (st != MCS_OK)
        return st;
    const size_t n1 = acc->n_x, n2 = acc->n_y;
    if (k1 >= n1 || k2 >= n2)
        return MCS_ERR_FREQ_RANGE;
    *conj = k2 > n2 / 2u;
    if (*conj) {
        k2 = n2 - k2;
        k1 = (n1 - k1) % n1;
    }
    *index = k2 * stride_of(n1) + k1;
    return cell_sound(acc, *index) ? MCS_OK : MCS_ERR_INVARIANT;
}

mcs_status mcs_spectrum2d_mean(const mcs_spectrum2d *acc, size_t freq_k, size_t freq_l,
                               double *re, double *im)
{
    size_t i = 0u;
    int conj = 0;
    mcs_status st = im == NULL ? MCS_ERR_NULL : lookup(acc, freq_k, freq_l, re, &i, &conj);
    if (st == MCS_OK && re == im)
        st = MCS_ERR_ALIAS; /* one place cannot hold both parts */
    if (st == MCS_OK)
        st = mcs_ps_read(acc->mean_re[i], 0.0, acc->count, 0, re);
    if (st == MCS_OK)
        *im = conj ? -acc->mean_im[i] : acc->mean_im[i];
    return st;
}

/* <|S_k|^2> (what 0), its standard error (1), or that of <S_k> (2). */
static mcs_status read_stat(const mcs_spectrum2d *acc, size_t k1, size_t k2, int what,
                            double *out)
{
    size_t i = 0u;
    int conj = 0;
    mcs_status st = lookup(acc, k1, k2, out, &i, &conj);
    if (st != MCS_OK)
        return st;
    if (what == 2)
        return mcs_ps_read(0.0, acc->m2_s[i], acc->count, 1, out);
    return mcs_ps_read(acc->mean_pow[i], acc->m2_pow[i], acc->count, what, out);
}

mcs_status mcs_spectrum2d_power(const mcs_spectrum2d *acc, size_t freq_k, size_t freq_l,
                                double *out)
{
    return read_stat(acc, freq_k, freq_l, 0, out);
}

mcs_status mcs_spectrum2d_power_stderr(const mcs_spectrum2d *acc, size_t freq_k, size_t freq_l,
                                       double *out)
{
    return read_stat(acc, freq_k, freq_l, 1, out);
}

mcs_status mcs_spectrum2d_mean_stderr(const mcs_spectrum2d *acc, size_t freq_k, size_t freq_l,
                                      double *out)
{
    return read_stat(acc, freq_k, freq_l, 2, out);
}

/* S_k over k2 <= N2/2 by direct sums over the non-zero s_n (exact table
 * indices), then the rest by S_{-k} = conj(S_k). */
mcs_status mcs_spectrum2d_transform(const mcs_spectrum2d *acc, const double *s, double *re,
                                    double *im)
{
    mcs_status st = s == NULL || re == NULL || im == NULL ? MCS_ERR_NULL : check_acc(acc);
    if (st == MCS_OK && !twiddles_sound(acc))
        st = MCS_ERR_INVARIANT; /* a NaN twiddle made every output NaN */
    if (st != MCS_OK)
        return st;
    const size_t n1 = acc->n_x, n2 = acc->n_y, n = n1 * n2, bytes = n * sizeof(double);
    /* The outputs are written while s is read: no two may overlap. */
    if (mcs_overlap_(s, bytes, re, bytes) || mcs_overlap_(s, bytes, im, bytes) ||
        mcs_overlap_(re, bytes, im, bytes))
        return MCS_ERR_ALIAS;
    double total = 0.0; /* sum |s_n| bounds every partial sum (dft.h) */
    for (size_t j = 0; j < n; ++j)
        total += fabs(s[j]);
    if (!(total <= MCS_DFT_MAX_ABS_SUM))
        return mcs_all_finite_(n, s) ? MCS_ERR_MAGNITUDE : MCS_ERR_NOT_FINITE;
    memset(re, 0, n * sizeof *re);
    memset(im, 0, n * sizeof *im);
    for (size_t b2 = 0; b2 < n2; ++b2)
        for (size_t b1 = 0; b1 < n1; ++b1) {
            const double v = s[b2 * n1 + b1];
            if (v == 0.0)
                continue;
            for (size_t k2 = 0, t2 = 0; k2 <= n2 / 2u; ++k2, t2 = (t2 + b2) % n2) {
                const double cy = acc->cos_y[t2], sy = acc->sin_y[t2];
                for (size_t k1 = 0, t1 = 0; k1 < n1; ++k1, t1 = (t1 + b1) % n1) {
                    const double cx = acc->cos_x[t1], sx = acc->sin_x[t1];
                    re[k2 * n1 + k1] += v * (cx * cy - sx * sy);
                    im[k2 * n1 + k1] -= v * (sx * cy + cx * sy);
                }
            }
        }
    const double scale = 1.0 / sqrt((double)n);
    for (size_t i = 0; i < (n2 / 2u + 1u) * n1; ++i) {
        re[i] *= scale;
        im[i] *= scale;
    }
    for (size_t k2 = n2 / 2u + 1u; k2 < n2; ++k2)
        for (size_t k1 = 0; k1 < n1; ++k1) {
            size_t mirror = (n2 - k2) * n1 + (n1 - k1) % n1;
            re[k2 * n1 + k1] = re[mirror];
            im[k2 * n1 + k1] = -im[mirror];
        }
    return MCS_OK;
}

mcs_status mcs_spectrum2d_variance14(const mcs_spectrum2d *acc, size_t k, const double *f_re,
                                     const double *f_im, double *out)
{
    mcs_status st = f_re == NULL || f_im == NULL || out == NULL ? MCS_ERR_NULL : check_body(acc);
    if (st == MCS_OK && k == 0u)
        st = MCS_ERR_K_RANGE;
    if (st == MCS_OK && acc->count == 0u)
        st = MCS_ERR_EMPTY;
    if (st != MCS_OK)
        return st;
    const size_t n1 = acc->n_x, n2 = acc->n_y;
    if (!mcs_all_finite_(n1 * n2, f_re) || !mcs_all_finite_(n1 * n2, f_im))
        return MCS_ERR_NOT_FINITE;
    double sum = 0.0;
    for (size_t k2 = 0; k2 < n2 && st == MCS_OK; ++k2)
        for (size_t k1 = 0; k1 < n1 && st == MCS_OK; ++k1) {
            if (k1 == 0u && k2 == 0u)
                continue;
            double p = 0.0;
            st = mcs_spectrum2d_power(acc, k1, k2, &p); /* cannot fail: checked above */
            size_t i = k2 * n1 + k1;
            sum += (f_re[i] * f_re[i] + f_im[i] * f_im[i]) * p;
        }
    if (st != MCS_OK)
        return st;
    /* |F_k|^2 of a finite f can overflow: refused, never returned as inf. */
    const double v = sum / ((double)k * (double)k);
    return isfinite(v) ? mcs_set_(out, v) : MCS_ERR_MAGNITUDE;
}
