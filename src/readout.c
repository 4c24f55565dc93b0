/* The read-out of first and second moments, for measured and exact moments
 * alike (see readout.h). Every frame stays small (the library's `make stack`
 * limit is 1 KiB): transforms are taken one coefficient at a time. */
#include "readout.h"
#include "internal.h"

#include <float.h>
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

/* Rounding bound of a form over the moments: (2N + 16) DBL_EPSILON times the
 * sum of the magnitudes of its terms, (1/K^2) sum |f_m| |g_n| (|<s_m s_n>| +
 * |<s_m>| |<s_n>|). Each term carries the few roundings of the moments and of
 * its product, and a sum of N terms at most N more (twice: rows, then the
 * sum of rows). */
double mcs_readout_form_bound(const mcs_readout *view, size_t k, const double *f,
                              const double *g)
{
    const size_t n = view->n;
    const double sc = view->scale;
    double sum = 0.0;
    for (size_t m = 0; m < n; ++m) {
        const double *row = &view->second[m * n];
        const double mean_m = fabs(view->first[m] * sc);
        double acc = 0.0;
        for (size_t b = 0; b < n; ++b)
            acc += (fabs(row[b] * sc) + mean_m * fabs(view->first[b] * sc)) * fabs(g[b]);
        sum += fabs(f[m]) * acc;
    }
    const double kd = (double)k;
    return (2.0 * (double)n + 16.0) * DBL_EPSILON * sum / (kd * kd);
}

double mcs_readout_nonnegative(const mcs_readout *view, double value, double bound)
{
    return view->k != 0u && value < 0.0 && -value <= bound ? 0.0 : value;
}

/* The bound of <|S_k|^2> = (1/N) sum e^{..} <s_m s_n>: |e^{..}| = 1. */
static double power_bound(const mcs_readout *view)
{
    double sum = 0.0;
    for (size_t j = 0; j < view->n * view->n; ++j)
        sum += fabs(view->second[j] * view->scale);
    return (2.0 * (double)view->n + 16.0) * DBL_EPSILON * sum / (double)view->n;
}

/* ---- checked read-outs ---------------------------------------------------- */

/* Opens obj for a read-out: outputs given (else NULL), the object's own
 * checks (UNINIT, EMPTY), then indices a, b below N (else range). */
static mcs_status open_for(int outputs, const mcs_readout_source *src, size_t a,
                           size_t b, mcs_status range, mcs_readout *view)
{
    if (!outputs || src->obj == NULL)
        return MCS_ERR_NULL;
    mcs_status st = src->open(src->obj, view);
    if (st == MCS_OK && (a >= view->n || b >= view->n))
        st = range;
    return st;
}

mcs_status mcs_readout_bin_mean(const mcs_readout_source *src, size_t bin, double *out)
{
    mcs_readout v;
    mcs_status st = open_for(out != NULL, src, bin, bin, MCS_ERR_BIN_RANGE, &v);
    return st == MCS_OK ? mcs_set_(out, v.first[bin] * v.scale) : st;
}

mcs_status mcs_readout_bin_second(const mcs_readout_source *src, size_t bin_m,
                                  size_t bin_n, double *out)
{
    mcs_readout v;
    mcs_status st = open_for(out != NULL, src, bin_m, bin_n, MCS_ERR_BIN_RANGE, &v);
    return st == MCS_OK ? mcs_set_(out, v.second[bin_m * v.n + bin_n] * v.scale) : st;
}

/* A complex read-out at frequencies freq_k, freq_l, the value from at. */
typedef void (*complex_at)(const mcs_readout *view, size_t freq_k, size_t freq_l, double *re,
                           double *im);

static mcs_status read_complex(const mcs_readout_source *src, size_t freq_k,
                               size_t freq_l, double *re, double *im, complex_at at)
{
    mcs_readout v;
    int outputs = re != NULL && im != NULL;
    mcs_status st = open_for(outputs, src, freq_k, freq_l, MCS_ERR_FREQ_RANGE, &v);
    if (st == MCS_OK)
        at(&v, freq_k, freq_l, re, im);
    return st;
}

/* <S_k> as a complex_at: one frequency, freq_l == freq_k. */
static void mean_at_k(const mcs_readout *view, size_t freq_k, size_t freq_l, double *re,
                      double *im)
{
    (void)freq_l;
    mean_at(view, freq_k, re, im);
}

mcs_status mcs_readout_mean(const mcs_readout_source *src, size_t freq, double *re,
                            double *im)
{
    return read_complex(src, freq, freq, re, im, mean_at_k);
}

mcs_status mcs_readout_power(const mcs_readout_source *src, size_t freq, double *out)
{
    mcs_readout v;
    mcs_status st = open_for(out != NULL, src, freq, freq, MCS_ERR_FREQ_RANGE, &v);
    if (st != MCS_OK)
        return st;
    double re = 0.0, im = 0.0; /* im is 0 up to rounding: <s s^T> is symmetric */
    mcs_readout_cross_at(&v, freq, freq, &re, &im);
    if (re < 0.0) /* a second moment: never negative but for rounding */
        re = mcs_readout_nonnegative(&v, re, power_bound(&v));
    *out = re;
    return MCS_OK;
}

mcs_status mcs_readout_cross(const mcs_readout_source *src, size_t freq_k,
                             size_t freq_l, double *re, double *im)
{
    return read_complex(src, freq_k, freq_l, re, im, mcs_readout_cross_at);
}

mcs_status mcs_readout_covariance(const mcs_readout_source *src, size_t freq_k,
                                  size_t freq_l, double *re, double *im)
{
    return read_complex(src, freq_k, freq_l, re, im, covariance_at);
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

/* Opens obj for an array of its N: outputs given (else NULL), the object's
 * checks (UNINIT, EMPTY), n equal to its N (else MISMATCH). */
static mcs_status open_n(int outputs, const mcs_readout_source *src, size_t n,
                         mcs_readout *view)
{
    if (!outputs || src->obj == NULL)
        return MCS_ERR_NULL;
    mcs_status st = src->open(src->obj, view);
    if (st == MCS_OK && n != view->n)
        st = MCS_ERR_MISMATCH;
    return st;
}

mcs_status mcs_readout_cross_matrix(const mcs_readout_source *src, size_t n,
                                    double *re, double *im)
{
    mcs_readout v;
    mcs_status st = open_n(re != NULL && im != NULL, src, n, &v);
    if (st == MCS_OK)
        cross_matrix_at(&v, re, im);
    return st;
}

mcs_status mcs_readout_covariance_matrix(const mcs_readout_source *src, size_t n,
                                         double *re, double *im)
{
    mcs_readout v;
    mcs_status st = open_n(re != NULL && im != NULL, src, n, &v);
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

mcs_status mcs_readout_check_integrand(const mcs_readout_source *src, size_t n, size_t k,
                                       const double *f, mcs_readout *view)
{
    mcs_status st = open_n(f != NULL, src, n, view);
    if (st != MCS_OK)
        return st;
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    if (view->k != 0u && k != view->k) /* exact moments are for one K */
        return MCS_ERR_MISMATCH;
    if (!mcs_all_finite_(n, f))
        return MCS_ERR_NOT_FINITE;
    return MCS_OK;
}

mcs_status mcs_readout_check_integrands(const mcs_readout_source *src, size_t n, size_t k,
                                        const double *f, const double *g, mcs_readout *view)
{
    mcs_status st = g == NULL ? MCS_ERR_NULL : mcs_readout_check_integrand(src, n, k, f, view);
    return st == MCS_OK ? mcs_readout_check_integrand(src, n, k, g, view) : st;
}

/* <I> = (1/K) sum_n f_n <s_n>. */
static double estimator_mean_at(const mcs_readout *view, size_t k, const double *f)
{
    double sum = 0.0;
    for (size_t b = 0; b < view->n; ++b)
        sum += f[b] * (view->first[b] * view->scale);
    return sum / (double)k;
}

mcs_status mcs_readout_integrand_value(const mcs_readout_source *src, size_t n,
                                       size_t k, const double *f, mcs_readout_value value,
                                       double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    mcs_readout v;
    mcs_status st = mcs_readout_check_integrand(src, n, k, f, &v);
    return st == MCS_OK ? mcs_set_(out, value(&v, k, f)) : st;
}

mcs_status mcs_readout_estimator_mean(const mcs_readout_source *src, size_t n,
                                      size_t k, const double *f, double *out)
{
    return mcs_readout_integrand_value(src, n, k, f, estimator_mean_at, out);
}

mcs_status mcs_readout_variance(const mcs_readout_source *src, size_t n, size_t k,
                                const double *f, double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    mcs_readout v;
    mcs_status st = mcs_readout_check_integrand(src, n, k, f, &v);
    if (st != MCS_OK)
        return st;
    double var = mcs_readout_form(&v, k, f, f);
    if (var < 0.0) /* f^T Cov f: never negative but for rounding */
        var = mcs_readout_nonnegative(&v, var, mcs_readout_form_bound(&v, k, f, f));
    *out = var;
    return MCS_OK;
}

mcs_status mcs_readout_estimator_covariance(const mcs_readout_source *src, size_t n,
                                            size_t k, const double *f, const double *g,
                                            double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    mcs_readout v;
    mcs_status st = mcs_readout_check_integrands(src, n, k, f, g, &v);
    return st == MCS_OK ? mcs_set_(out, mcs_readout_form(&v, k, f, g)) : st;
}
