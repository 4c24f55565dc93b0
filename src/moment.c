#include "mcspec/moment.h"

#include <math.h>
#include <string.h>

static mcs_status check_weight(double w)
{
    if (!isfinite(w))
        return MCS_ERR_NOT_FINITE;
    if (w < 0.0)
        return MCS_ERR_NEGATIVE;
    return MCS_OK;
}

/* bins[k] < n, weights finite and >= 0. */
static mcs_status check_sparse(size_t n, size_t k, const size_t *bins, const double *weights)
{
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    for (size_t j = 0; j < k; ++j) {
        if (bins[j] >= n)
            return MCS_ERR_BIN_RANGE;
        mcs_status st = check_weight(weights[j]);
        if (st != MCS_OK)
            return st;
    }
    return MCS_OK;
}

static mcs_status check_dense(size_t n, const double *s)
{
    for (size_t j = 0; j < n; ++j) {
        mcs_status st = check_weight(s[j]);
        if (st != MCS_OK)
            return st;
    }
    return MCS_OK;
}

/* ---- mcs_moment: full second moment, N <= MCS_MAX_COV_N ---- */

static int moment_is_valid(const mcs_moment *acc)
{
    return acc->n >= 1u && acc->n <= (size_t)MCS_MAX_COV_N;
}

mcs_status mcs_moment_init(mcs_moment *acc, size_t n)
{
    if (acc == NULL)
        return MCS_ERR_NULL;
    if (n == 0u || n > (size_t)MCS_MAX_COV_N)
        return MCS_ERR_N_RANGE;
    memset(acc, 0, sizeof *acc);
    acc->n = n;
    const double two_pi_over_n = 6.283185307179586476925286766559 / (double)n;
    for (size_t j = 0; j < n; ++j) {
        acc->cos_table[j] = cos(two_pi_over_n * (double)j);
        acc->sin_table[j] = sin(two_pi_over_n * (double)j);
    }
    return MCS_OK;
}

/* Adds sample pair contributions. s_m s_n = sum over ordered pairs (j, j')
 * with n_j = m, n_j' = n of w_j w_j'; only m <= n is stored, so an unordered
 * pair of distinct bins adds w w' once and a pair in the same bin twice. */
static void moment_add_sample_pairs(mcs_moment *acc, size_t k, const size_t *bins,
                                    const double *weights)
{
    const size_t n = acc->n;
    double *ss = acc->sum_ss;
    for (size_t j = 0; j < k; ++j) {
        const size_t b = bins[j];
        const double w = weights[j];
        acc->sum_s[b] += w;
        ss[b * n + b] += w * w;
        for (size_t jj = j + 1u; jj < k; ++jj) {
            const size_t c = bins[jj];
            const double ww = w * weights[jj];
            if (b == c)
                ss[b * n + b] += 2.0 * ww;
            else if (b < c)
                ss[b * n + c] += ww;
            else
                ss[c * n + b] += ww;
        }
    }
    acc->count += 1u;
}

mcs_status mcs_moment_add_bins(mcs_moment *acc, size_t k, const size_t *bins,
                               const double *weights)
{
    if (acc == NULL || bins == NULL || weights == NULL)
        return MCS_ERR_NULL;
    if (!moment_is_valid(acc))
        return MCS_ERR_UNINIT;
    mcs_status st = check_sparse(acc->n, k, bins, weights);
    if (st != MCS_OK)
        return st;
    moment_add_sample_pairs(acc, k, bins, weights);
    return MCS_OK;
}

mcs_status mcs_moment_add_dense(mcs_moment *acc, size_t n, const double *s)
{
    if (acc == NULL || s == NULL)
        return MCS_ERR_NULL;
    if (!moment_is_valid(acc))
        return MCS_ERR_UNINIT;
    if (n != acc->n)
        return MCS_ERR_MISMATCH;
    mcs_status st = check_dense(n, s);
    if (st != MCS_OK)
        return st;
    /* Each non-zero bin as one sample of weight s_m: the diagonal gets s_m^2
     * and each pair of distinct bins s_m s_c once (upper triangle). */
    double *ss = acc->sum_ss;
    for (size_t m = 0; m < n; ++m) {
        const double a = s[m];
        if (a == 0.0)
            continue;
        acc->sum_s[m] += a;
        ss[m * n + m] += a * a;
        for (size_t c = m + 1u; c < n; ++c)
            ss[m * n + c] += a * s[c];
    }
    acc->count += 1u;
    return MCS_OK;
}

mcs_status mcs_moment_merge(mcs_moment *dst, const mcs_moment *src)
{
    if (dst == NULL || src == NULL)
        return MCS_ERR_NULL;
    if (!moment_is_valid(dst) || !moment_is_valid(src))
        return MCS_ERR_UNINIT;
    if (dst->n != src->n)
        return MCS_ERR_MISMATCH;
    const size_t n = dst->n;
    for (size_t j = 0; j < n; ++j)
        dst->sum_s[j] += src->sum_s[j];
    for (size_t j = 0; j < n * n; ++j)
        dst->sum_ss[j] += src->sum_ss[j];
    dst->count += src->count;
    return MCS_OK;
}

mcs_status mcs_moment_count(const mcs_moment *acc, uint64_t *count)
{
    if (acc == NULL || count == NULL)
        return MCS_ERR_NULL;
    if (!moment_is_valid(acc))
        return MCS_ERR_UNINIT;
    *count = acc->count;
    return MCS_OK;
}

static mcs_status moment_readout(const mcs_moment *acc, const void *out)
{
    if (acc == NULL || out == NULL)
        return MCS_ERR_NULL;
    if (!moment_is_valid(acc))
        return MCS_ERR_UNINIT;
    if (acc->count == 0u)
        return MCS_ERR_EMPTY;
    return MCS_OK;
}

static double ss_at(const mcs_moment *acc, size_t m, size_t n)
{
    return m <= n ? acc->sum_ss[m * acc->n + n] : acc->sum_ss[n * acc->n + m];
}

mcs_status mcs_moment_mean_s(const mcs_moment *acc, size_t bin, double *mean)
{
    mcs_status st = moment_readout(acc, mean);
    if (st != MCS_OK)
        return st;
    if (bin >= acc->n)
        return MCS_ERR_BIN_RANGE;
    *mean = acc->sum_s[bin] / (double)acc->count;
    return MCS_OK;
}

mcs_status mcs_moment_second(const mcs_moment *acc, size_t m, size_t n, double *value)
{
    mcs_status st = moment_readout(acc, value);
    if (st != MCS_OK)
        return st;
    if (m >= acc->n || n >= acc->n)
        return MCS_ERR_BIN_RANGE;
    *value = ss_at(acc, m, n) / (double)acc->count;
    return MCS_OK;
}

/* Eq. 15: <S_k> = N^{-1/2} sum_n e^{-2 pi i k n/N} <s_n>. */
static void spectrum_mean_unchecked(const mcs_moment *acc, size_t freq, double *re, double *im)
{
    const size_t n = acc->n;
    double ar = 0.0, ai = 0.0;
    size_t idx = 0u;
    for (size_t b = 0; b < n; ++b) {
        ar += acc->sum_s[b] * acc->cos_table[idx];
        ai -= acc->sum_s[b] * acc->sin_table[idx];
        idx += freq;
        idx = idx >= n ? idx - n : idx;
    }
    const double scale = 1.0 / (sqrt((double)n) * (double)acc->count);
    *re = ar * scale;
    *im = ai * scale;
}

mcs_status mcs_moment_spectrum_mean(const mcs_moment *acc, size_t freq, double *re, double *im)
{
    if (im == NULL)
        return MCS_ERR_NULL;
    mcs_status st = moment_readout(acc, re);
    if (st != MCS_OK)
        return st;
    if (freq >= acc->n)
        return MCS_ERR_FREQ_RANGE;
    spectrum_mean_unchecked(acc, freq, re, im);
    return MCS_OK;
}

mcs_status mcs_moment_power(const mcs_moment *acc, size_t freq, double *power)
{
    mcs_status st = moment_readout(acc, power);
    if (st != MCS_OK)
        return st;
    if (freq >= acc->n)
        return MCS_ERR_FREQ_RANGE;
    /* Eq. 16 with l = k and <s_m s_n> symmetric: the diagonal plus twice the
     * upper triangle times cos(2 pi k (n - m)/N), real by construction. */
    const size_t n = acc->n;
    double diag = 0.0, off = 0.0;
    for (size_t m = 0; m < n; ++m) {
        const double *row = acc->sum_ss + m * n;
        diag += row[m];
        size_t idx = 0u; /* k (c - m) mod N, starting at c = m */
        for (size_t c = m + 1u; c < n; ++c) {
            idx += freq;
            idx = idx >= n ? idx - n : idx;
            off += row[c] * acc->cos_table[idx];
        }
    }
    *power = (diag + 2.0 * off) / ((double)n * (double)acc->count);
    return MCS_OK;
}

/* Eq. 16: <S_k S_l*> = (1/N) sum_{m,n} e^{-2 pi i (k m - l n)/N} <s_m s_n>. */
static void cross_unchecked(const mcs_moment *acc, size_t k, size_t l, double *re, double *im)
{
    const size_t n = acc->n;
    double ar = 0.0, ai = 0.0;
    size_t km = 0u; /* k m mod N */
    for (size_t m = 0; m < n; ++m) {
        size_t idx = km; /* (k m - l c) mod N, starting at c = 0 */
        const size_t step = (n - l % n) % n;
        for (size_t c = 0; c < n; ++c) {
            const double v = ss_at(acc, m, c);
            ar += v * acc->cos_table[idx];
            ai -= v * acc->sin_table[idx];
            idx += step;
            idx = idx >= n ? idx - n : idx;
        }
        km += k;
        km = km >= n ? km - n : km;
    }
    const double scale = 1.0 / ((double)n * (double)acc->count);
    *re = ar * scale;
    *im = ai * scale;
}

mcs_status mcs_moment_cross(const mcs_moment *acc, size_t k, size_t l, double *re, double *im)
{
    if (im == NULL)
        return MCS_ERR_NULL;
    mcs_status st = moment_readout(acc, re);
    if (st != MCS_OK)
        return st;
    if (k >= acc->n || l >= acc->n)
        return MCS_ERR_FREQ_RANGE;
    cross_unchecked(acc, k, l, re, im);
    return MCS_OK;
}

mcs_status mcs_moment_covariance(const mcs_moment *acc, size_t k, size_t l, double *re,
                                 double *im)
{
    if (im == NULL)
        return MCS_ERR_NULL;
    mcs_status st = moment_readout(acc, re);
    if (st != MCS_OK)
        return st;
    if (k >= acc->n || l >= acc->n)
        return MCS_ERR_FREQ_RANGE;
    double cr, ci, ar, ai, br, bi;
    cross_unchecked(acc, k, l, &cr, &ci);
    spectrum_mean_unchecked(acc, k, &ar, &ai);
    spectrum_mean_unchecked(acc, l, &br, &bi);
    /* (ar + i ai)(br - i bi) */
    *re = cr - (ar * br + ai * bi);
    *im = ci - (ai * br - ar * bi);
    return MCS_OK;
}

static mcs_status matrix_readout(const mcs_moment *acc, size_t n, const double *re,
                                 const double *im)
{
    if (im == NULL)
        return MCS_ERR_NULL;
    mcs_status st = moment_readout(acc, re);
    if (st != MCS_OK)
        return st;
    if (n != acc->n)
        return MCS_ERR_MISMATCH;
    return MCS_OK;
}

/* Rows of G = <s s^T> F^H are formed a chunk at a time and pushed straight
 * into C = F G / N: per column l, G[m][l] = sum_c <s_m s_c> e^{+2 pi i l c/N}
 * for MATRIX_CHUNK values of m, then C[k][l] += e^{-2 pi i k m/N} G[m][l] for
 * every k. O(N^3) with a few hundred bytes of stack. */
#define MATRIX_CHUNK 16u

static void cross_matrix_unchecked(const mcs_moment *acc, double *re, double *im)
{
    const size_t n = acc->n;
    const double *ct = acc->cos_table, *st = acc->sin_table;
    for (size_t j = 0; j < n * n; ++j) {
        re[j] = 0.0;
        im[j] = 0.0;
    }
    double gr[MATRIX_CHUNK], gi[MATRIX_CHUNK];
    for (size_t l = 0; l < n; ++l) {
        for (size_t m0 = 0; m0 < n; m0 += MATRIX_CHUNK) {
            const size_t len = n - m0 < MATRIX_CHUNK ? n - m0 : MATRIX_CHUNK;
            for (size_t q = 0; q < len; ++q) {
                double ar = 0.0, ai = 0.0;
                size_t idx = 0u;
                for (size_t c = 0; c < n; ++c) {
                    const double v = ss_at(acc, m0 + q, c);
                    ar += v * ct[idx];
                    ai += v * st[idx];
                    idx += l;
                    idx = idx >= n ? idx - n : idx;
                }
                gr[q] = ar;
                gi[q] = ai;
            }
            for (size_t k = 0; k < n; ++k) {
                double ar = 0.0, ai = 0.0;
                size_t idx = (k * m0) % n;
                for (size_t q = 0; q < len; ++q) {
                    /* (c - i s)(gr + i gi) */
                    ar += ct[idx] * gr[q] + st[idx] * gi[q];
                    ai += ct[idx] * gi[q] - st[idx] * gr[q];
                    idx += k;
                    idx = idx >= n ? idx - n : idx;
                }
                re[k * n + l] += ar;
                im[k * n + l] += ai;
            }
        }
    }
    const double scale = 1.0 / ((double)n * (double)acc->count);
    for (size_t j = 0; j < n * n; ++j) {
        re[j] *= scale;
        im[j] *= scale;
    }
}

mcs_status mcs_moment_cross_matrix(const mcs_moment *acc, size_t n, double *re, double *im)
{
    mcs_status st = matrix_readout(acc, n, re, im);
    if (st != MCS_OK)
        return st;
    cross_matrix_unchecked(acc, re, im);
    return MCS_OK;
}

mcs_status mcs_moment_covariance_matrix(const mcs_moment *acc, size_t n, double *re,
                                        double *im)
{
    mcs_status st = matrix_readout(acc, n, re, im);
    if (st != MCS_OK)
        return st;
    cross_matrix_unchecked(acc, re, im);
    for (size_t k = 0; k < n; ++k) {
        double ar, ai;
        spectrum_mean_unchecked(acc, k, &ar, &ai);
        for (size_t l = 0; l < n; ++l) {
            double br, bi;
            spectrum_mean_unchecked(acc, l, &br, &bi);
            /* (ar + i ai)(br - i bi) */
            re[k * n + l] -= ar * br + ai * bi;
            im[k * n + l] -= ai * br - ar * bi;
        }
    }
    return MCS_OK;
}

/* ---- mcs_autocorr: circular autocorrelation, N <= MCS_MAX_N ---- */

static int autocorr_is_valid(const mcs_autocorr *acc)
{
    return acc->n >= 1u && acc->n <= (size_t)MCS_MAX_N;
}

mcs_status mcs_autocorr_init(mcs_autocorr *acc, size_t n)
{
    if (acc == NULL)
        return MCS_ERR_NULL;
    if (n == 0u || n > (size_t)MCS_MAX_N)
        return MCS_ERR_N_RANGE;
    memset(acc, 0, sizeof *acc);
    acc->n = n;
    return MCS_OK;
}

mcs_status mcs_autocorr_add_bins(mcs_autocorr *acc, size_t k, const size_t *bins,
                                 const double *weights)
{
    if (acc == NULL || bins == NULL || weights == NULL)
        return MCS_ERR_NULL;
    if (!autocorr_is_valid(acc))
        return MCS_ERR_UNINIT;
    mcs_status st = check_sparse(acc->n, k, bins, weights);
    if (st != MCS_OK)
        return st;
    /* Folded storage: an unordered pair {j, j'} at circular distance
     * e = min(d, N - d) adds w w' to sum_a[e]; a sample with itself adds
     * w^2 / 2 to sum_a[0]. Then A(e) = sum_a[e] for 0 < e < N/2, and
     * A(0) = 2 sum_a[0], A(N/2) = 2 sum_a[N/2] (read-out), because there both
     * orders of a pair land on the same lag. */
    const size_t n = acc->n;
    double *a = acc->sum_a;
    for (size_t j = 0; j < k; ++j) {
        const size_t b = bins[j];
        const double w = weights[j];
        acc->sum_s[b] += w;
        a[0] += 0.5 * w * w;
        for (size_t jj = j + 1u; jj < k; ++jj) {
            const size_t c = bins[jj];
            const size_t d = c >= b ? c - b : c + n - b;
            const size_t e = d <= n - d ? d : n - d;
            a[e] += w * weights[jj];
        }
    }
    acc->count += 1u;
    return MCS_OK;
}

mcs_status mcs_autocorr_merge(mcs_autocorr *dst, const mcs_autocorr *src)
{
    if (dst == NULL || src == NULL)
        return MCS_ERR_NULL;
    if (!autocorr_is_valid(dst) || !autocorr_is_valid(src))
        return MCS_ERR_UNINIT;
    if (dst->n != src->n)
        return MCS_ERR_MISMATCH;
    const size_t n = dst->n, h = n / 2u;
    for (size_t j = 0; j < n; ++j)
        dst->sum_s[j] += src->sum_s[j];
    for (size_t j = 0; j <= h; ++j)
        dst->sum_a[j] += src->sum_a[j];
    dst->count += src->count;
    return MCS_OK;
}

mcs_status mcs_autocorr_count(const mcs_autocorr *acc, uint64_t *count)
{
    if (acc == NULL || count == NULL)
        return MCS_ERR_NULL;
    if (!autocorr_is_valid(acc))
        return MCS_ERR_UNINIT;
    *count = acc->count;
    return MCS_OK;
}

static mcs_status autocorr_readout(const mcs_autocorr *acc, const mcs_dft *plan, size_t n,
                                   const double *out)
{
    if (acc == NULL || plan == NULL || out == NULL)
        return MCS_ERR_NULL;
    if (!autocorr_is_valid(acc))
        return MCS_ERR_UNINIT;
    if (n != acc->n)
        return MCS_ERR_MISMATCH;
    mcs_status st = mcs_dft_check(plan, n); /* UNINIT or MISMATCH */
    if (st != MCS_OK)
        return st;
    if (acc->count == 0u)
        return MCS_ERR_EMPTY;
    return MCS_OK;
}

mcs_status mcs_autocorr_mean(const mcs_autocorr *acc, mcs_dft *plan, size_t n, double *re,
                             double *im)
{
    if (im == NULL)
        return MCS_ERR_NULL;
    mcs_status st = autocorr_readout(acc, plan, n, re);
    if (st != MCS_OK)
        return st;
    if (check_dense(n, acc->sum_s) != MCS_OK) /* an overflowed sum: refuse before writing */
        return MCS_ERR_NOT_FINITE;
    const double inv = 1.0 / (double)acc->count;
    for (size_t j = 0; j < n; ++j)
        re[j] = acc->sum_s[j] * inv;
    return mcs_dft_real(plan, n, re, re, im); /* eq. 15 */
}

mcs_status mcs_autocorr_power(const mcs_autocorr *acc, mcs_dft *plan, size_t n, double *power)
{
    mcs_status st = autocorr_readout(acc, plan, n, power);
    if (st != MCS_OK)
        return st;
    const size_t h = n / 2u;
    for (size_t j = 0; j <= h; ++j)
        if (!isfinite(acc->sum_a[j]))
            return MCS_ERR_NOT_FINITE;
    /* <A(d)> for every lag, unfolded (see mcs_autocorr_add_bins), then
     * Wiener-Khinchin: <|S_k|^2> = (1/N) sum_d e^{-2 pi i k d/N} <A(d)>, i.e.
     * N^{-1/2} times eq. 7 applied to <A>. A is even, so the result is real. */
    const double inv = 1.0 / (double)acc->count;
    power[0] = 2.0 * acc->sum_a[0] * inv;
    for (size_t d = 1; d < n; ++d) {
        const size_t e = d <= n - d ? d : n - d;
        const double twice = (2u * e == n) ? 2.0 : 1.0;
        power[d] = twice * acc->sum_a[e] * inv;
    }
    (void)mcs_dft_real(plan, n, power, power, NULL);
    const double scale = 1.0 / sqrt((double)n);
    for (size_t k = 0; k < n; ++k)
        power[k] *= scale;
    return MCS_OK;
}
