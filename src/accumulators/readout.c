/* The read-out of first and second moments, for measured and exact moments
 * alike (see readout.h). Every frame stays small (the library's `make stack`
 * limit is 1 KiB): transforms are taken one coefficient at a time. */
#include "readout.h"
#include "acc_internal.h"
#include "core/internal.h"

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

/* Eq. 7 of first_entry at one frequency (as mcs_readout_dft). */
static void first_dft(const mcs_readout *view, size_t freq, double *re, double *im)
{
    if (!mcs_readout_has_batch(view)) {
        mcs_readout_dft(view, view->first, freq, re, im);
        return;
    }
    const size_t n = view->n;
    size_t idx = 0;
    double r = 0.0, i = 0.0;
    for (size_t t = 0; t < n; ++t) {
        const double x = mcs_readout_first(view, t);
        r += view->cos_table[idx] * x;
        i -= view->sin_table[idx] * x;
        idx += freq;
        if (idx >= n)
            idx -= n;
    }
    const double scale = 1.0 / sqrt((double)n);
    *re = r * scale;
    *im = i * scale;
}

/* sum_m |g_m| sqrt(<D_m>) (g NULL: 1), <D_m> the average of the diagonal of
 * second (a sum of squares, read as 0 if rounding left it below). */
static double root_weight(const mcs_readout *view, const double *g)
{
    double r = 0.0;
    for (size_t m = 0; m < view->n; ++m) {
        const double dm = mcs_readout_second(view, m, m) * view->scale;
        r += (g != NULL ? fabs(g[m]) : 1.0) * sqrt(dm > 0.0 ? dm : 0.0);
    }
    return r;
}

/* Entry (m, n) of second errs by at most accum sqrt(D_m D_n) (Cauchy-Schwarz
 * on sum_t |d_m d_n|), entry m of first by accum sqrt(T D_m); in a form the
 * second moments' errors sum to accum (sum |g| sqrt(<D>)) (sum |h| sqrt(<D>))
 * and those of the products of first averages to twice that. */
double mcs_readout_accumulated(const mcs_readout *view, const double *g, const double *h)
{
    if (view->accum == 0.0 || view->shift == NULL) /* exact moments (no shift either) */
        return 0.0;
    return 3.0 * view->accum * root_weight(view, g) * root_weight(view, h);
}

/* The transform of first * scale: <S_k> without a shift, <D_k> (d = s - c)
 * with one. */
static void first_mean_at(const mcs_readout *view, size_t freq, double *re, double *im)
{
    first_dft(view, freq, re, im);
    *re *= view->scale;
    *im *= view->scale;
}

/* Eq. 15: <S_k> = N^{-1/2} sum_n e^{-2 pi i k n/N} <s_n>, with <s> = c + <d>
 * for a shifted view (the transform is linear). */
static void mean_at(const mcs_readout *view, size_t freq, double *re, double *im)
{
    first_mean_at(view, freq, re, im);
    if (view->shift != NULL) {
        double cr, ci;
        mcs_readout_dft(view, view->shift, freq, &cr, &ci);
        *re += cr;
        *im += ci;
    }
}

/* <s_bin>. */
double mcs_readout_mean_entry(const mcs_readout *view, size_t bin)
{
    const double m = mcs_readout_first(view, bin) * view->scale;
    return view->shift != NULL ? view->shift[bin] + m : m;
}

/* a b* for a = (ar, ai), b = (br, bi), added to (*re, *im) with sign. */
static void add_product(double ar, double ai, double br, double bi, double sign, double *re,
                        double *im)
{
    *re += sign * (ar * br + ai * bi);
    *im += sign * (ai * br - ar * bi);
}

/* Eq. 16 applied to second * scale: <S_k S_l*> without a shift, <D_k D_l*>
 * with one. */
static void second_at(const mcs_readout *view, size_t freq_k, size_t freq_l, double *re,
                      double *im)
{
    /* Eq. 16 separably: the inner sum over n with e^{+2 pi i l n/N}, the
     * outer over m with e^{-2 pi i k m/N}. O(N^2). */
    const size_t n = view->n;
    const double *ct = view->cos_table, *st = view->sin_table;
    size_t idx_m = 0;
    double r = 0.0, i = 0.0;
    for (size_t m = 0; m < n; ++m) {
        double rr = 0.0, ri = 0.0;
        size_t idx = 0;
        for (size_t b = 0; b < n; ++b) {
            const double x = mcs_readout_second(view, m, b);
            rr += ct[idx] * x;
            ri += st[idx] * x;
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

void mcs_readout_cross_at(const mcs_readout *view, size_t freq_k, size_t freq_l, double *re,
                          double *im)
{
    second_at(view, freq_k, freq_l, re, im);
    if (view->shift != NULL) { /* <S_k S_l*> = <D_k D_l*> - <D_k><D_l>* + <S_k><S_l>* */
        double ar, ai, br, bi;
        first_mean_at(view, freq_k, &ar, &ai);
        first_mean_at(view, freq_l, &br, &bi);
        add_product(ar, ai, br, bi, -1.0, re, im);
        mean_at(view, freq_k, &ar, &ai);
        mean_at(view, freq_l, &br, &bi);
        add_product(ar, ai, br, bi, 1.0, re, im);
    }
}

/* Cov(S_k, S_l) = <S_k S_l*> - <S_k><S_l>*, which a shift leaves unchanged:
 * the transform of second minus the product of the transforms of first. */
static void covariance_at(const mcs_readout *view, size_t freq_k, size_t freq_l, double *re,
                          double *im)
{
    double kr, ki, lr, li;
    second_at(view, freq_k, freq_l, re, im);
    first_mean_at(view, freq_k, &kr, &ki);
    first_mean_at(view, freq_l, &lr, &li);
    add_product(kr, ki, lr, li, -1.0, re, im);
}

/* The rounding bound of a variance Cov(S_k, S_k) read as above: the O(N^2)
 * transform of second errs by at most (2N + 2) u sum |second| scale / N, the
 * square of the O(N) transform of first by N u (sum |first| scale)^2 / N
 * (u = eps / 2): twice their sum; and the rounding the stored sums carry
 * (mcs_readout_accumulated, |e^{..}| = 1 / N in eq. 16). Measured moments
 * take 8 R_v + A (acc_internal.h, mcs_moment_power_rounding_), so that a
 * variance the loader accepts at -(4 R_v + A) reads out. */
static double variance_rounding(const mcs_readout *view)
{
    const size_t n = view->n;
    double a = 0.0, b = 0.0;
    for (size_t m = 0; m < n; ++m)
        for (size_t c = 0; c < n; ++c)
            a += fabs(mcs_readout_second(view, m, c));
    for (size_t j = 0; j < n; ++j)
        b += fabs(mcs_readout_first(view, j));
    a *= view->scale;
    b *= view->scale;
    const double nd = (double)n;
    if (view->shift != NULL) /* measured: 8 R_v + A, whatever the loader accepts at 4 R_v + A */
        return 8.0 * ((2.0 * nd + 64.0) * DBL_EPSILON * a + 4.0 * (nd + 32.0) * DBL_EPSILON * b * b) /
                   nd +
               mcs_readout_accumulated(view, NULL, NULL) / nd + mcs_moment_underflow_(n, 0);
    return (4.0 * ((double)n + 2.0) * DBL_EPSILON * (a + b * b) +
            mcs_readout_accumulated(view, NULL, NULL) + view->exact_rounding) /
           (double)n;
}

double mcs_readout_nonnegative(const mcs_readout *view, double value, double bound)
{
    (void)view;
    return value < 0.0 && -value <= bound ? 0.0 : value;
}

mcs_status mcs_readout_clamp(double bound, double *value)
{
    if (*value >= 0.0)
        return MCS_OK;
    if (!(*value >= -bound)) /* beyond rounding (or NaN) */
        return MCS_ERR_INVARIANT;
    *value = 0.0;
    return MCS_OK;
}

/* sum_m |x_m| of an array of the view's N. */
static double abs_sum(size_t n, const double *x)
{
    double sum = 0.0;
    for (size_t m = 0; m < n; ++m)
        sum += fabs(x[m]);
    return sum;
}

/* The bound of <|S_k|^2> = (1/N) sum e^{..} <s_m s_n>: |e^{..}| = 1, (2N + 16)
 * eps times the sum of |<s_m s_n>| for exact moments. Measured ones (a
 * shift) add the squares of the transforms of <d> and of <s> = c + <d>, and
 * take 8 R + A (acc_internal.h, mcs_moment_power_rounding_: R the rounding
 * of a power read from the sums, A what the sums carry), so that whatever
 * the loader accepts at -(4 R + A) reads out. */
static double power_bound(const mcs_readout *view)
{
    const size_t n = view->n;
    const double nd = (double)n;
    double sum = 0.0;
    for (size_t m = 0; m < n; ++m)
        for (size_t c = 0; c < n; ++c)
            sum += fabs(mcs_readout_second(view, m, c) * view->scale);
    if (view->shift == NULL)
        return ((2.0 * nd + 16.0) * DBL_EPSILON * sum + view->exact_rounding) / nd;
    double d = 0.0;
    for (size_t m = 0; m < n; ++m)
        d += fabs(mcs_readout_first(view, m) * view->scale);
    const double s = d + abs_sum(n, view->shift);
    const double r = ((2.0 * nd + 64.0) * DBL_EPSILON * sum +
                      4.0 * (nd + 32.0) * DBL_EPSILON * (d * d + s * s)) /
                     nd;
    return 8.0 * r + mcs_readout_accumulated(view, NULL, NULL) / nd + mcs_moment_underflow_(n, 0);
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
    return st == MCS_OK ? mcs_set_(out, mcs_readout_mean_entry(&v, bin)) : st;
}

mcs_status mcs_readout_bin_second(const mcs_readout_source *src, size_t bin_m,
                                  size_t bin_n, double *out)
{
    mcs_readout v;
    mcs_status st = open_for(out != NULL, src, bin_m, bin_n, MCS_ERR_BIN_RANGE, &v);
    if (st != MCS_OK)
        return st;
    double x = mcs_readout_second(&v, bin_m, bin_n) * v.scale;
    double bound = 4.0 * DBL_EPSILON * fabs(x) + mcs_readout_accumulated(&v, NULL, NULL);
    if (v.shift != NULL) { /* <s_m s_n> = Cov(d)_mn + <s_m><s_n> */
        const double sm = mcs_readout_mean_entry(&v, bin_m), sn = mcs_readout_mean_entry(&v, bin_n);
        const double dm = mcs_readout_first(&v, bin_m) * v.scale;
        const double dn = mcs_readout_first(&v, bin_n) * v.scale;
        x += sm * sn - dm * dn;
        bound += 8.0 * DBL_EPSILON * (fabs(sm * sn) + fabs(dm * dn));
    }
    /* <s_m^2> is never negative: as mcs_readout_power (bound: the sums' and
     * this sum's rounding) */
    if (bin_m == bin_n && x < 0.0) {
        st = mcs_readout_clamp(bound, &x);
        if (st != MCS_OK)
            return st;
    }
    return mcs_set_(out, x);
}

/* A complex read-out at frequencies freq_k, freq_l: the value into re, im,
 * and a status (only a variance or a power can fail, see mcs_readout_clamp). */
typedef mcs_status (*complex_at)(const mcs_readout *view, size_t freq_k, size_t freq_l,
                                 double *re, double *im);

/* The value is computed into locals and written only when finite; re and im
 * must be two different doubles (one double cannot hold both parts). Six
 * arguments at most (see readout.h). */
static mcs_status read_complex(const mcs_readout_source *src, size_t freq_k, size_t freq_l,
                               double *re, double *im, complex_at at)
{
    mcs_readout v;
    int outputs = re != NULL && im != NULL;
    mcs_status st = open_for(outputs, src, freq_k, freq_l, MCS_ERR_FREQ_RANGE, &v);
    if (st == MCS_OK && mcs_overlap_(re, sizeof *re, im, sizeof *im))
        st = MCS_ERR_ALIAS;
    double r = 0.0, i = 0.0;
    if (st == MCS_OK)
        st = at(&v, freq_k, freq_l, &r, &i);
    if (st == MCS_OK && !(isfinite(r) && isfinite(i)))
        st = MCS_ERR_NOT_FINITE;
    if (st == MCS_OK) {
        *re = r;
        *im = i;
    }
    return st;
}

/* <S_k> as a complex_at: one frequency, freq_l == freq_k. */
static mcs_status mean_value(const mcs_readout *view, size_t freq_k, size_t freq_l, double *re,
                             double *im)
{
    (void)freq_l;
    mean_at(view, freq_k, re, im);
    if (freq_k == 0u || 2u * freq_k == view->n) /* s is real: S_0 and S_{N/2} are real */
        *im = 0.0;
    return MCS_OK;
}

/* <S_k S_l*> as a complex_at. */
static mcs_status cross_value(const mcs_readout *view, size_t freq_k, size_t freq_l,
                              double *re, double *im)
{
    mcs_readout_cross_at(view, freq_k, freq_l, re, im);
    return MCS_OK;
}

/* <|S_k|^2> as a complex_at (k = l): real, and a second moment, never
 * negative but for rounding. A value below minus the rounding bound is no
 * moment of any data, measured or exact: the object holds values no call
 * produced (MCS_ERR_INVARIANT, as the cross matrix's diagonal reads it). */
static mcs_status power_value(const mcs_readout *view, size_t freq_k, size_t freq_l,
                              double *re, double *im)
{
    mcs_readout_cross_at(view, freq_k, freq_l, re, im);
    *im = 0.0; /* <s s^T> is symmetric: the imaginary part is rounding */
    return *re < 0.0 ? mcs_readout_clamp(power_bound(view), re) : MCS_OK;
}

/* Cov(S_k, S_l) as a complex_at: a variance (k = l) is never negative. */
static mcs_status covariance_value(const mcs_readout *view, size_t freq_k, size_t freq_l,
                                   double *re, double *im)
{
    covariance_at(view, freq_k, freq_l, re, im);
    return freq_k == freq_l ? mcs_readout_clamp(variance_rounding(view), re) : MCS_OK;
}

mcs_status mcs_readout_mean(const mcs_readout_source *src, size_t freq, double *re,
                            double *im)
{
    return read_complex(src, freq, freq, re, im, mean_value);
}

mcs_status mcs_readout_power(const mcs_readout_source *src, size_t freq, double *out)
{
    double re = 0.0, im = 0.0; /* im is 0 up to rounding: <s s^T> is symmetric */
    mcs_status st = read_complex(src, freq, freq, out != NULL ? &re : NULL, &im, power_value);
    return st == MCS_OK ? mcs_set_(out, re) : st;
}

/* At k = l the cross moment is the power <|S_k|^2>, clamped as
 * mcs_readout_power (fuzz_api found -1.5e-17 there). */
mcs_status mcs_readout_cross(const mcs_readout_source *src, size_t freq_k,
                             size_t freq_l, double *re, double *im)
{
    return read_complex(src, freq_k, freq_l, re, im,
                        freq_k == freq_l ? power_value : cross_value);
}

mcs_status mcs_readout_covariance(const mcs_readout_source *src, size_t freq_k,
                                  size_t freq_l, double *re, double *im)
{
    return read_complex(src, freq_k, freq_l, re, im, covariance_value);
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
        double ar = 0.0, ai = 0.0;
        size_t idx = 0u;
        for (size_t c = 0; c < n; ++c) {
            const double x = mcs_readout_second(view, m0 + q, c);
            ar += x * view->cos_table[idx];
            ai += x * view->sin_table[idx];
            idx += l;
            idx = idx >= n ? idx - n : idx;
        }
        gr[q] = ar;
        gi[q] = ai;
    }
}

/* Eq. 16 for every k, l, applied to second * scale (see second_at). */
static void second_matrix_at(const mcs_readout *view, double *re, double *im)
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
mcs_status mcs_readout_open_n(int outputs, const mcs_readout_source *src, size_t n,
                               mcs_readout *view)
{
    if (!outputs || src->obj == NULL)
        return MCS_ERR_NULL;
    mcs_status st = src->open(src->obj, view);
    if (st == MCS_OK && n != view->n)
        st = MCS_ERR_MISMATCH;
    return st;
}

/* A matrix read-out opens the source for n; its outputs (n * n doubles
 * each) are written while the object is read, and zeroed first: they must
 * overlap neither each other nor any array of the view (MCS_ERR_ALIAS). */
static mcs_status open_matrix(const mcs_readout_source *src, size_t n, const double *re,
                              const double *im, mcs_readout *view)
{
    mcs_status st = mcs_readout_open_n(re != NULL && im != NULL, src, n, view);
    if (st != MCS_OK)
        return st;
    const size_t nn = n * n * sizeof(double), n1 = n * sizeof(double);
    const int open = view->batch_w != NULL;
    const void *in[8] = {view->first,   view->second,  view->cos_table, view->sin_table,
                         view->shift,   view->batch_w, view->batch_s,   view->batch_d};
    const size_t len[8] = {n1, nn, n1, n1, view->shift != NULL ? n1 : 0u,
                           open ? nn : 0u, open ? n1 : 0u, open ? n1 : 0u};
    int alias = mcs_overlap_(re, nn, im, nn);
    for (size_t a = 0; a < 8u; ++a)
        alias |= mcs_overlap_(re, nn, in[a], len[a]) || mcs_overlap_(im, nn, in[a], len[a]);
    return alias ? MCS_ERR_ALIAS : MCS_OK;
}

/* Adds sign a_k b_l* to every entry, a and b the mean transforms `am`, `bm`
 * (O(N^3): each is taken one coefficient at a time, as everywhere here). */
typedef void (*mean_fn)(const mcs_readout *view, size_t freq, double *re, double *im);

static void add_mean_products(const mcs_readout *view, mean_fn am, mean_fn bm, double sign,
                              double *re, double *im)
{
    const size_t n = view->n;
    for (size_t k = 0; k < n; ++k) {
        double ar, ai;
        am(view, k, &ar, &ai);
        for (size_t l = 0; l < n; ++l) {
            double br, bi;
            bm(view, l, &br, &bi);
            add_product(ar, ai, br, bi, sign, &re[k * n + l], &im[k * n + l]);
        }
    }
}

mcs_status mcs_readout_cross_matrix(const mcs_readout_source *src, size_t n,
                                    double *re, double *im)
{
    mcs_readout v;
    mcs_status st = open_matrix(src, n, re, im, &v);
    if (st != MCS_OK)
        return st;
    /* The diagonal is checked before anything is written (power_value). */
    const double tol = power_bound(&v);
    for (size_t k = 0; k < n && st == MCS_OK; ++k) {
        double pr, pi;
        mcs_readout_cross_at(&v, k, k, &pr, &pi);
        st = mcs_readout_clamp(tol, &pr);
    }
    if (st != MCS_OK)
        return st;
    second_matrix_at(&v, re, im);
    if (v.shift != NULL) { /* as mcs_readout_cross_at */
        add_mean_products(&v, first_mean_at, first_mean_at, -1.0, re, im);
        add_mean_products(&v, mean_at, mean_at, 1.0, re, im);
    }
    /* The diagonal is <|S_k|^2>, clamped as mcs_readout_power: two sums of N
     * terms, within power_bound (checked before anything was written). */
    for (size_t k = 0; k < n; ++k)
        (void)mcs_readout_clamp(tol, &re[k * n + k]);
    return MCS_OK;
}

mcs_status mcs_readout_covariance_matrix(const mcs_readout_source *src, size_t n,
                                         double *re, double *im)
{
    mcs_readout v;
    mcs_status st = open_matrix(src, n, re, im, &v);
    if (st != MCS_OK)
        return st;
    /* The diagonal is checked before anything is written (covariance_value). */
    const double tol = variance_rounding(&v);
    for (size_t k = 0; k < n && st == MCS_OK; ++k) {
        double vr, vi;
        covariance_at(&v, k, k, &vr, &vi);
        st = mcs_readout_clamp(tol, &vr);
    }
    if (st != MCS_OK)
        return st;
    second_matrix_at(&v, re, im);
    add_mean_products(&v, first_mean_at, first_mean_at, -1.0, re, im);
    for (size_t k = 0; k < n; ++k)
        (void)mcs_readout_clamp(tol, &re[k * n + k]);
    return MCS_OK;
}
