/* The read-out of first and second moments, for measured and exact moments
 * alike (see readout.h). Every frame stays small (the library's `make stack`
 * limit is 1 KiB): transforms are taken one coefficient at a time. */
#include "readout.h"
#include "internal.h"

#include <math.h>

void mcs_readout_dft(const mcs_readout *view, const double *x, size_t freq, double *re,
                     double *im)
{
    /* Eq. 7 at one frequency; the index freq t mod N is stepped, not divided
     * (freq < N), so every twiddle is an exact table entry. */
    const size_t n = view->n;
    size_t idx = 0;
    double r = 0.0, i = 0.0;
    for (size_t t = 0; t < n; ++t) {
        r += view->cos_table[idx] * x[t];
        i -= view->sin_table[idx] * x[t];
        idx += freq;
        if (idx >= n)
            idx -= n;
    }
    const double scale = 1.0 / sqrt((double)n);
    *re = r * scale;
    *im = i * scale;
}

/* Eq. 15: <S_k> = N^{-1/2} sum_n e^{-2 pi i k n/N} <s_n>. */
static void mean_at(const mcs_readout *view, size_t freq, double *re, double *im)
{
    mcs_readout_dft(view, view->first, freq, re, im);
    *re *= view->scale;
    *im *= view->scale;
}

void mcs_readout_cross_at(const mcs_readout *view, size_t freq_k, size_t freq_l, double *re,
                          double *im)
{
    /* Eq. 16 separably: the inner sum over n with e^{+2 pi i l n/N}, the
     * outer over m with e^{-2 pi i k m/N}. O(N^2). */
    const size_t n = view->n;
    const double *ct = view->cos_table, *st = view->sin_table;
    size_t idx_m = 0;
    double r = 0.0, i = 0.0;
    for (size_t m = 0; m < n; ++m) {
        const double *row = &view->second[m * n];
        double rr = 0.0, ri = 0.0;
        size_t idx = 0;
        for (size_t b = 0; b < n; ++b) {
            rr += ct[idx] * row[b];
            ri += st[idx] * row[b];
            idx += freq_l;
            if (idx >= n)
                idx -= n;
        }
        const double c = ct[idx_m], s = st[idx_m];
        r += c * rr + s * ri;
        i += c * ri - s * rr;
        idx_m += freq_k;
        if (idx_m >= n)
            idx_m -= n;
    }
    *re = r / (double)n * view->scale;
    *im = i / (double)n * view->scale;
}

/* Cov(S_k, S_l) = <S_k S_l*> - <S_k><S_l>*. */
static void covariance_at(const mcs_readout *view, size_t freq_k, size_t freq_l, double *re,
                          double *im)
{
    double cr, ci, kr, ki, lr, li;
    mcs_readout_cross_at(view, freq_k, freq_l, &cr, &ci);
    mean_at(view, freq_k, &kr, &ki);
    mean_at(view, freq_l, &lr, &li);
    /* <S_k><S_l>* = (kr + i ki)(lr - i li) */
    *re = cr - (kr * lr + ki * li);
    *im = ci - (ki * lr - kr * li);
}

double mcs_readout_form(const mcs_readout *view, size_t k, const double *f, const double *g)
{
    /* Cov(s)_mn = <s_m s_n> - <s_m><s_n>, summed row by row. */
    const size_t n = view->n;
    const double sc = view->scale;
    double sum = 0.0;
    for (size_t m = 0; m < n; ++m) {
        const double *row = &view->second[m * n];
        const double mean_m = view->first[m] * sc;
        double acc = 0.0;
        for (size_t b = 0; b < n; ++b)
            acc += (row[b] * sc - mean_m * (view->first[b] * sc)) * g[b];
        sum += f[m] * acc;
    }
    const double kd = (double)k;
    return sum / (kd * kd);
}

/* ---- checked read-outs ---------------------------------------------------- */

mcs_status mcs_readout_bin_mean(const void *obj, mcs_readout_open open, size_t bin, double *out)
{
    if (obj == NULL || out == NULL)
        return MCS_ERR_NULL;
    mcs_readout v;
    mcs_status st = open(obj, &v);
    if (st != MCS_OK)
        return st;
    if (bin >= v.n)
        return MCS_ERR_BIN_RANGE;
    *out = v.first[bin] * v.scale;
    return MCS_OK;
}

mcs_status mcs_readout_bin_second(const void *obj, mcs_readout_open open, size_t bin_m,
                                  size_t bin_n, double *out)
{
    if (obj == NULL || out == NULL)
        return MCS_ERR_NULL;
    mcs_readout v;
    mcs_status st = open(obj, &v);
    if (st != MCS_OK)
        return st;
    if (bin_m >= v.n || bin_n >= v.n)
        return MCS_ERR_BIN_RANGE;
    *out = v.second[bin_m * v.n + bin_n] * v.scale;
    return MCS_OK;
}

/* Opens obj for a read-out at frequencies freq_k, freq_l (both < N). */
static mcs_status open_at(const void *obj, mcs_readout_open open, size_t freq_k, size_t freq_l,
                          mcs_readout *view)
{
    mcs_status st = open(obj, view);
    if (st != MCS_OK)
        return st;
    if (freq_k >= view->n || freq_l >= view->n)
        return MCS_ERR_FREQ_RANGE;
    return MCS_OK;
}

mcs_status mcs_readout_mean(const void *obj, mcs_readout_open open, size_t freq, double *re,
                            double *im)
{
    if (obj == NULL || re == NULL || im == NULL)
        return MCS_ERR_NULL;
    mcs_readout v;
    mcs_status st = open_at(obj, open, freq, freq, &v);
    if (st == MCS_OK)
        mean_at(&v, freq, re, im);
    return st;
}

mcs_status mcs_readout_power(const void *obj, mcs_readout_open open, size_t freq, double *out)
{
    if (obj == NULL || out == NULL)
        return MCS_ERR_NULL;
    mcs_readout v;
    mcs_status st = open_at(obj, open, freq, freq, &v);
    if (st != MCS_OK)
        return st;
    double re, im;
    mcs_readout_cross_at(&v, freq, freq, &re, &im);
    *out = re; /* im is 0 up to rounding: <s_m s_n> is real and symmetric */
    return MCS_OK;
}

mcs_status mcs_readout_cross(const void *obj, mcs_readout_open open, size_t freq_k,
                             size_t freq_l, double *re, double *im)
{
    if (obj == NULL || re == NULL || im == NULL)
        return MCS_ERR_NULL;
    mcs_readout v;
    mcs_status st = open_at(obj, open, freq_k, freq_l, &v);
    if (st == MCS_OK)
        mcs_readout_cross_at(&v, freq_k, freq_l, re, im);
    return st;
}

mcs_status mcs_readout_covariance(const void *obj, mcs_readout_open open, size_t freq_k,
                                  size_t freq_l, double *re, double *im)
{
    if (obj == NULL || re == NULL || im == NULL)
        return MCS_ERR_NULL;
    mcs_readout v;
    mcs_status st = open_at(obj, open, freq_k, freq_l, &v);
    if (st == MCS_OK)
        covariance_at(&v, freq_k, freq_l, re, im);
    return st;
}

/* ---- matrices ------------------------------------------------------------- */

/* Rows of G = <s s^T> F^H are formed a chunk at a time and pushed straight
 * into C = F G / N: per column l, G[m][l] = sum_c <s_m s_c> e^{+2 pi i l c/N}
 * for MATRIX_CHUNK values of m, then C[k][l] += e^{-2 pi i k m/N} G[m][l] for
 * every k. O(N^3) with a few hundred bytes of stack. */
#define MATRIX_CHUNK 16u

/* G[m0 + q][l] for q < len into gr, gi. */
static void chunk_of_g(const mcs_readout *view, size_t l, size_t m0, size_t len, double *gr,
                       double *gi)
{
    const size_t n = view->n;
    for (size_t q = 0; q < len; ++q) {
        const double *row = &view->second[(m0 + q) * n];
        double ar = 0.0, ai = 0.0;
        size_t idx = 0u;
        for (size_t c = 0; c < n; ++c) {
            ar += row[c] * view->cos_table[idx];
            ai += row[c] * view->sin_table[idx];
            idx += l;
            idx = idx >= n ? idx - n : idx;
        }
        gr[q] = ar;
        gi[q] = ai;
    }
}

static void cross_matrix_at(const mcs_readout *view, double *re, double *im)
{
    const size_t n = view->n;
    const double *ct = view->cos_table, *st = view->sin_table;
    for (size_t j = 0; j < n * n; ++j) {
        re[j] = 0.0;
        im[j] = 0.0;
    }
    double gr[MATRIX_CHUNK], gi[MATRIX_CHUNK];
    for (size_t l = 0; l < n; ++l) {
        for (size_t m0 = 0; m0 < n; m0 += MATRIX_CHUNK) {
            const size_t len = n - m0 < MATRIX_CHUNK ? n - m0 : MATRIX_CHUNK;
            chunk_of_g(view, l, m0, len, gr, gi);
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
    const double scale = view->scale / (double)n;
    for (size_t j = 0; j < n * n; ++j) {
        re[j] *= scale;
        im[j] *= scale;
    }
}

static mcs_status open_matrix(const void *obj, mcs_readout_open open, size_t n, const double *re,
                              const double *im, mcs_readout *view)
{
    if (obj == NULL || re == NULL || im == NULL)
        return MCS_ERR_NULL;
    mcs_status st = open(obj, view);
    if (st != MCS_OK)
        return st;
    if (n != view->n)
        return MCS_ERR_MISMATCH;
    return MCS_OK;
}

mcs_status mcs_readout_cross_matrix(const void *obj, mcs_readout_open open, size_t n,
                                    double *re, double *im)
{
    mcs_readout v;
    mcs_status st = open_matrix(obj, open, n, re, im, &v);
    if (st == MCS_OK)
        cross_matrix_at(&v, re, im);
    return st;
}

mcs_status mcs_readout_covariance_matrix(const void *obj, mcs_readout_open open, size_t n,
                                         double *re, double *im)
{
    mcs_readout v;
    mcs_status st = open_matrix(obj, open, n, re, im, &v);
    if (st != MCS_OK)
        return st;
    cross_matrix_at(&v, re, im);
    for (size_t k = 0; k < n; ++k) {
        double ar, ai;
        mean_at(&v, k, &ar, &ai);
        for (size_t l = 0; l < n; ++l) {
            double br, bi;
            mean_at(&v, l, &br, &bi);
            /* (ar + i ai)(br - i bi) */
            re[k * n + l] -= ar * br + ai * bi;
            im[k * n + l] -= ai * br - ar * bi;
        }
    }
    return MCS_OK;
}

/* ---- the estimator -------------------------------------------------------- */

mcs_status mcs_readout_check_integrand(const void *obj, mcs_readout_open open, size_t n,
                                       size_t k, const double *f, mcs_readout *view)
{
    mcs_status st = open(obj, view);
    if (st != MCS_OK)
        return st;
    if (n != view->n)
        return MCS_ERR_MISMATCH;
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    if (view->k != 0u && k != view->k) /* exact moments are for one K */
        return MCS_ERR_MISMATCH;
    if (!mcs_all_finite_(n, f))
        return MCS_ERR_NOT_FINITE;
    return MCS_OK;
}

mcs_status mcs_readout_estimator_mean(const void *obj, mcs_readout_open open, size_t n,
                                      size_t k, const double *f, double *out)
{
    if (obj == NULL || f == NULL || out == NULL)
        return MCS_ERR_NULL;
    mcs_readout v;
    mcs_status st = mcs_readout_check_integrand(obj, open, n, k, f, &v);
    if (st != MCS_OK)
        return st;
    double sum = 0.0;
    for (size_t b = 0; b < n; ++b)
        sum += f[b] * (v.first[b] * v.scale);
    *out = sum / (double)k; /* <I> = (1/K) sum_n f_n <s_n> */
    return MCS_OK;
}

mcs_status mcs_readout_variance(const void *obj, mcs_readout_open open, size_t n, size_t k,
                                const double *f, double *out)
{
    return mcs_readout_estimator_covariance(obj, open, n, k, f, f, out);
}

mcs_status mcs_readout_estimator_covariance(const void *obj, mcs_readout_open open, size_t n,
                                            size_t k, const double *f, const double *g,
                                            double *out)
{
    if (obj == NULL || f == NULL || g == NULL || out == NULL)
        return MCS_ERR_NULL;
    mcs_readout v;
    mcs_status st = mcs_readout_check_integrand(obj, open, n, k, f, &v);
    if (st == MCS_OK)
        st = mcs_readout_check_integrand(obj, open, n, k, g, &v);
    if (st != MCS_OK)
        return st;
    *out = mcs_readout_form(&v, k, f, g);
    return MCS_OK;
}
