#include "mcspec/spectrum2d.h"
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

static int side_ok(size_t n)
{
    return n >= 1u && n <= (size_t)MCS_MAX_SIDE;
}

static int spectrum2d_is_valid(const mcs_spectrum2d *acc)
{
    return side_ok(acc->n_x) && side_ok(acc->n_y);
}

static void twiddles(size_t n, double *c, double *s)
{
    for (size_t t = 0; t < n; ++t) {
        double a = MCS_PS_TWO_PI * (double)t / (double)n;
        c[t] = cos(a);
        s[t] = sin(a);
    }
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
    twiddles(n_x, acc->cos_x, acc->sin_x);
    twiddles(n_y, acc->cos_y, acc->sin_y);
    return MCS_OK;
}

static size_t bin_of(double x, size_t n)
{
    size_t b = (size_t)(x * (double)n);
    return b < n ? b : n - 1u;
}

/* Twiddle rows of point slot p in bin (b1, b2) with weight w:
 * x row e^{-2 pi i k1 b1/N1}, k1 < N1; y row w e^{-2 pi i k2 b2/N2}, k2 <= N2/2.
 * Table indices advance by b mod N, so every twiddle is an exact entry. */
static void twiddle_rows(mcs_spectrum2d *acc, int p, size_t b1, size_t b2, double w)
{
    const size_t n1 = acc->n_x, n2 = acc->n_y;
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
    const size_t stride = stride_of(acc->n_x);
    double (*r)[4][MCS_SPECTRUM2D_STRIDE] = acc->rows;
    for (size_t k2 = 0; k2 <= acc->n_y / 2u; ++k2) {
        double y[8];
        for (size_t p = 0; p < 4u; ++p) {
            y[2u * p] = r[p][YR][k2];
            y[2u * p + 1u] = r[p][YI][k2];
        }
        mcs_ps_row_update4(stride, acc->re + k2 * stride, acc->im + k2 * stride, r[0][XR],
                           r[0][XI], r[1][XR], r[1][XI], r[2][XR], r[2][XI], r[3][XR], r[3][XI],
                           y);
    }
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

static mcs_status check_weights(size_t k, const double *w)
{
    for (size_t j = 0; w != NULL && j < k; ++j) {
        if (!isfinite(w[j]))
            return MCS_ERR_NOT_FINITE;
        if (w[j] < 0.0)
            return MCS_ERR_NEGATIVE;
    }
    return MCS_OK;
}

mcs_status mcs_spectrum2d_add_points(mcs_spectrum2d *acc, size_t k, const double *points,
                                     const double *weights)
{
    if (acc == NULL || points == NULL)
        return MCS_ERR_NULL;
    if (!spectrum2d_is_valid(acc))
        return MCS_ERR_UNINIT;
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    if (k > SIZE_MAX / 2u || !mcs_ps_points_in_range(2u * k, points))
        return MCS_ERR_POINT_RANGE;
    mcs_status st = check_weights(k, weights);
    if (st != MCS_OK)
        return st;
    const size_t cells = stride_of(acc->n_x) * (acc->n_y / 2u + 1u);
    memset(acc->re, 0, cells * sizeof acc->re[0]);
    memset(acc->im, 0, cells * sizeof acc->im[0]);
    for (size_t j = 0; j < k; j += 4u) {
        for (int p = 0; p < 4; ++p) {
            size_t q = j + (size_t)p;
            if (q < k)
                twiddle_rows(acc, p, bin_of(points[2u * q], acc->n_x),
                             bin_of(points[2u * q + 1u], acc->n_y),
                             weights != NULL ? weights[q] : 1.0);
            else
                twiddle_rows(acc, p, 0u, 0u, 0.0); /* padding: contributes 0 */
        }
        accumulate_four(acc);
    }
    update_statistics(acc);
    return MCS_OK;
}

mcs_status mcs_spectrum2d_merge(mcs_spectrum2d *dst, const mcs_spectrum2d *src)
{
    if (dst == NULL || src == NULL)
        return MCS_ERR_NULL;
    if (!spectrum2d_is_valid(dst) || !spectrum2d_is_valid(src))
        return MCS_ERR_UNINIT;
    if (dst->n_x != src->n_x || dst->n_y != src->n_y)
        return MCS_ERR_MISMATCH;
    if (src->count == 0u)
        return MCS_OK;
    const uint64_t na = dst->count, nb = src->count;
    const double n = (double)na + (double)nb, fb = (double)nb / n;
    const double cross = (double)na * (double)nb / n;
    const size_t cells = stride_of(dst->n_x) * (dst->n_y / 2u + 1u);
    for (size_t i = 0; i < cells; ++i) {
        double dr = src->mean_re[i] - dst->mean_re[i], di = src->mean_im[i] - dst->mean_im[i];
        dst->mean_re[i] += dr * fb;
        dst->mean_im[i] += di * fb;
        dst->m2_s[i] += src->m2_s[i] + (dr * dr + di * di) * cross;
        mcs_ps_chan(&dst->mean_pow[i], &dst->m2_pow[i], na, src->mean_pow[i], src->m2_pow[i], nb);
    }
    dst->count = na + nb;
    return MCS_OK;
}

mcs_status mcs_spectrum2d_count(const mcs_spectrum2d *acc, uint64_t *count)
{
    if (acc == NULL || count == NULL)
        return MCS_ERR_NULL;
    if (!spectrum2d_is_valid(acc))
        return MCS_ERR_UNINIT;
    *count = acc->count;
    return MCS_OK;
}

/* Stored index of (k1, k2); *conj = 1 when it is the mirror -k's entry. */
static mcs_status lookup(const mcs_spectrum2d *acc, size_t k1, size_t k2, uint64_t min_count,
                         size_t *index, int *conj)
{
    if (!spectrum2d_is_valid(acc))
        return MCS_ERR_UNINIT;
    const size_t n1 = acc->n_x, n2 = acc->n_y;
    if (k1 >= n1 || k2 >= n2)
        return MCS_ERR_FREQ_RANGE;
    if (acc->count < min_count)
        return MCS_ERR_EMPTY;
    *conj = k2 > n2 / 2u;
    if (*conj) {
        k2 = n2 - k2;
        k1 = (n1 - k1) % n1;
    }
    *index = k2 * stride_of(n1) + k1;
    return MCS_OK;
}

mcs_status mcs_spectrum2d_mean(const mcs_spectrum2d *acc, size_t freq_k, size_t freq_l,
                               double *re, double *im)
{
    if (acc == NULL || re == NULL || im == NULL)
        return MCS_ERR_NULL;
    size_t i = 0u;
    int conj = 0;
    mcs_status st = lookup(acc, freq_k, freq_l, 1u, &i, &conj);
    if (st != MCS_OK)
        return st;
    *re = acc->mean_re[i];
    *im = conj ? -acc->mean_im[i] : acc->mean_im[i];
    return MCS_OK;
}

mcs_status mcs_spectrum2d_power(const mcs_spectrum2d *acc, size_t freq_k, size_t freq_l,
                                double *out)
{
    if (acc == NULL || out == NULL)
        return MCS_ERR_NULL;
    size_t i = 0u;
    int conj = 0;
    mcs_status st = lookup(acc, freq_k, freq_l, 1u, &i, &conj);
    if (st == MCS_OK)
        *out = acc->mean_pow[i];
    return st;
}

mcs_status mcs_spectrum2d_power_stderr(const mcs_spectrum2d *acc, size_t freq_k, size_t freq_l,
                                       double *out)
{
    if (acc == NULL || out == NULL)
        return MCS_ERR_NULL;
    size_t i = 0u;
    int conj = 0;
    mcs_status st = lookup(acc, freq_k, freq_l, 2u, &i, &conj);
    if (st == MCS_OK)
        *out = mcs_ps_stderr(acc->m2_pow[i], acc->count);
    return st;
}

mcs_status mcs_spectrum2d_mean_stderr(const mcs_spectrum2d *acc, size_t freq_k, size_t freq_l,
                                      double *out)
{
    if (acc == NULL || out == NULL)
        return MCS_ERR_NULL;
    size_t i = 0u;
    int conj = 0;
    mcs_status st = lookup(acc, freq_k, freq_l, 2u, &i, &conj);
    if (st == MCS_OK)
        *out = mcs_ps_stderr(acc->m2_s[i], acc->count);
    return st;
}

static int all_finite(size_t n, const double *v)
{
    for (size_t i = 0; i < n; ++i)
        if (!isfinite(v[i]))
            return 0;
    return 1;
}

/* S_k over k2 <= N2/2 by direct sums over the non-zero s_n (exact table
 * indices), then the rest by S_{-k} = conj(S_k). */
mcs_status mcs_spectrum2d_transform(const mcs_spectrum2d *acc, const double *s, double *re,
                                    double *im)
{
    if (acc == NULL || s == NULL || re == NULL || im == NULL)
        return MCS_ERR_NULL;
    if (!spectrum2d_is_valid(acc))
        return MCS_ERR_UNINIT;
    const size_t n1 = acc->n_x, n2 = acc->n_y, n = n1 * n2;
    if (!all_finite(n, s))
        return MCS_ERR_NOT_FINITE;
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
    if (acc == NULL || f_re == NULL || f_im == NULL || out == NULL)
        return MCS_ERR_NULL;
    if (!spectrum2d_is_valid(acc))
        return MCS_ERR_UNINIT;
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    if (acc->count == 0u)
        return MCS_ERR_EMPTY;
    const size_t n1 = acc->n_x, n2 = acc->n_y;
    if (!all_finite(n1 * n2, f_re) || !all_finite(n1 * n2, f_im))
        return MCS_ERR_NOT_FINITE;
    double sum = 0.0;
    for (size_t k2 = 0; k2 < n2; ++k2)
        for (size_t k1 = 0; k1 < n1; ++k1) {
            if (k1 == 0u && k2 == 0u)
                continue;
            double p = 0.0;
            (void)mcs_spectrum2d_power(acc, k1, k2, &p);
            size_t i = k2 * n1 + k1;
            sum += (f_re[i] * f_re[i] + f_im[i] * f_im[i]) * p;
        }
    *out = sum / ((double)k * (double)k);
    return MCS_OK;
}
