/* Private: the one read-out of first and second moments, shared by the
 * measured moments (mcs_moment, sums over trials) and the exact ones
 * (mcs_theory, expectations), so "measured vs exact" is the same code on two
 * objects. Each object is reached through an open function that checks it
 * and describes where its moments are (a view); everything from there on,
 * eq. 15, eq. 16, covariances and Var[I], is written once below. */
#ifndef MCSPEC_READOUT_H
#define MCSPEC_READOUT_H

#include <stddef.h>
#include "mcspec/status.h"

/* Where an object's moments are: <s_bin> = first[bin] * scale and
 * <s_bin_m s_bin_n> = second[bin_m * N + bin_n] * scale (both triangles,
 * symmetric). With a shift c (the moment accumulator), first and second are
 * sums of d = s - c instead: <s> = c + first * scale, and every covariance
 * is read from them directly (it does not depend on c), without cancelling
 * <s_m s_n> against <s_m><s_n>. */
typedef struct {
    size_t n;              /* N */
    size_t k;              /* K of exact moments; 0: any K >= 1 the caller names */
    double scale;          /* 1 / trials for sums, 1 for expectations */
    const double *first;   /* [n] */
    const double *second;  /* [n * n] */
    const double *cos_table; /* cos(2 pi j / N), j < N */
    const double *sin_table; /* sin(2 pi j / N), j < N */
    const double *shift;   /* [n] c, or NULL: first and second are of s itself */
    /* The open batch of a moment accumulator, added to first and second at
     * read-out (mcs_batch_first_, mcs_batch_second_); batch_w NULL: none. */
    const double *batch_w; /* [n * n] half products */
    const double *batch_s; /* [n] sum of s over the batch's sparse trials */
    const double *batch_d; /* [n] sum of d over its other trials */
    double batch_sparse;   /* its sparse trials */
    /* The rounding the stored sums carry, relative (moment.h): every entry
     * of second (closed and open batch) is within accum sqrt(D_m D_n) of
     * the exact sum over the trials, D the diagonal of second. 0 for exact
     * moments. */
    double accum;
    /* The rounding exact moments carry from their computation (theory's
     * init, mcs_theory_init_rounding_), absolute, on N times a power: the
     * power and variance bounds add it / N. 0 for measured moments. */
    double exact_rounding;
} mcs_readout;

/* What an open batch adds to the sums of d (moment.h): its dense trials
 * gave d and half of d d^T directly; its B sparse trials gave s and half of
 * s s^T, whose d sums are sum s - B c and sum s s^T - (sum s) c^T
 * - c (sum s)^T + B c c^T. Written so that (m, q) and (q, m) round alike:
 * the sums stay exactly symmetric. */
static inline double mcs_batch_first_(const double *bs, const double *bd, const double *c,
                                      double sparse, size_t m)
{
    return bd[m] + (bs[m] - sparse * c[m]);
}

static inline double mcs_batch_second_(const double *w, const double *bs, const double *c,
                                       double sparse, size_t n, size_t m, size_t q)
{
    return (w[m * n + q] + w[q * n + m]) - (bs[m] * c[q] + c[m] * bs[q]) +
           sparse * (c[m] * c[q]);
}

/* An open batch to add (it comes with a shift: the accumulator's view). */
static inline int mcs_readout_has_batch(const mcs_readout *view)
{
    return view->batch_w != NULL && view->shift != NULL;
}

/* first[bin] and second[bin_m * N + bin_n] with a moment accumulator's open
 * batch added (above): the sums a fold would give, read without writing. */
static inline double mcs_readout_first(const mcs_readout *view, size_t bin)
{
    const double x = view->first[bin];
    return !mcs_readout_has_batch(view)
               ? x
               : x + mcs_batch_first_(view->batch_s, view->batch_d, view->shift,
                                      view->batch_sparse, bin);
}

static inline double mcs_readout_second(const mcs_readout *view, size_t bin_m, size_t bin_n)
{
    const double x = view->second[bin_m * view->n + bin_n];
    return !mcs_readout_has_batch(view)
               ? x
               : x + mcs_batch_second_(view->batch_w, view->batch_s, view->shift,
                                       view->batch_sparse, view->n, bin_m, bin_n);
}

/* <s_bin>. */
double mcs_readout_mean_entry(const mcs_readout *view, size_t bin);

/* The rounding the stored sums carry (view->accum) in a form over the
 * averages, sum_{m,n} |g_m| |h_n| |error of <d_m d_n>| and the matching
 * products of first averages (g, h NULL: 1): 3 accum (sum_m |g_m|
 * sqrt(<D_m>)) (sum_n |h_n| sqrt(<D_n>)), by Cauchy-Schwarz (readout.c).
 * 0 for exact moments. */
double mcs_readout_accumulated(const mcs_readout *view, const double *g, const double *h);

/* Checks obj and fills *view: MCS_ERR_UNINIT, MCS_ERR_EMPTY (no trials yet). */
typedef mcs_status (*mcs_readout_open)(const void *obj, mcs_readout *view);

/* An object and how to open it (obj may be NULL: MCS_ERR_NULL). Every
 * read-out below takes one, so no call needs more than six arguments: past
 * six, x86-64 passes them on the stack, and GCC's -fstack-usage reports the
 * frame that pushes them as dynamic, which `make stack` refuses. */
typedef struct {
    const void *obj;
    mcs_readout_open open;
} mcs_readout_source;

/* Opens src's object for an array of its N: outputs given (else NULL), the
 * object's checks (UNINIT, EMPTY), n equal to its N (else MISMATCH). */
mcs_status mcs_readout_open_n(int outputs, const mcs_readout_source *src, size_t n,
                              mcs_readout *view);

/* The two objects (obj not NULL): a mcs_moment, a mcs_theory. */
mcs_status mcs_readout_open_moment(const void *obj, mcs_readout *view);
mcs_status mcs_readout_open_theory(const void *obj, mcs_readout *view);

/* The public read-outs of moment.h and theory.h, for the object of src;
 * arguments and statuses as documented there. */
mcs_status mcs_readout_bin_mean(const mcs_readout_source *src, size_t bin, double *out);
mcs_status mcs_readout_bin_second(const mcs_readout_source *src, size_t bin_m,
                                  size_t bin_n, double *out);
mcs_status mcs_readout_mean(const mcs_readout_source *src, size_t freq, double *re,
                            double *im);
mcs_status mcs_readout_power(const mcs_readout_source *src, size_t freq, double *out);
mcs_status mcs_readout_cross(const mcs_readout_source *src, size_t freq_k,
                             size_t freq_l, double *re, double *im);
mcs_status mcs_readout_covariance(const mcs_readout_source *src, size_t freq_k,
                                  size_t freq_l, double *re, double *im);
mcs_status mcs_readout_cross_matrix(const mcs_readout_source *src, size_t n,
                                    double *re, double *im);
mcs_status mcs_readout_covariance_matrix(const mcs_readout_source *src, size_t n,
                                         double *re, double *im);
mcs_status mcs_readout_estimator_mean(const mcs_readout_source *src, size_t n,
                                      size_t k, const double *f, double *out);
mcs_status mcs_readout_variance(const mcs_readout_source *src, size_t n, size_t k,
                                const double *f, double *out);
mcs_status mcs_readout_estimator_covariance(const mcs_readout_source *src, size_t n,
                                            size_t k, const double *f, const double *g,
                                            double *out);

/* For the closed forms built on a read-out (eq. 2, 4, 13). */

/* Opens src's object and checks an integrand for it: obj and f not NULL
 * (else MCS_ERR_NULL), the object's checks (MCS_ERR_UNINIT, MCS_ERR_EMPTY),
 * n equal to its N (MCS_ERR_MISMATCH), k >= 1 (MCS_ERR_K_RANGE) and, for
 * exact moments, equal to their K (MCS_ERR_MISMATCH), f[n] finite
 * (MCS_ERR_NOT_FINITE). The caller checks its outputs first. */
mcs_status mcs_readout_check_integrand(const mcs_readout_source *src, size_t n, size_t k,
                                       const double *f, mcs_readout *view);

/* The same for two integrands f, g: g not NULL, then f, then g. */
mcs_status mcs_readout_check_integrands(const mcs_readout_source *src, size_t n, size_t k,
                                        const double *f, const double *g, mcs_readout *view);

/* A value computed from the moments for one integrand f and K = k. */
typedef double (*mcs_readout_value)(const mcs_readout *view, size_t k, const double *f);

/* Checks as mcs_readout_check_integrand (out too), then *out = value(view, k, f). */
mcs_status mcs_readout_integrand_value(const mcs_readout_source *src, size_t n,
                                       size_t k, const double *f, mcs_readout_value value,
                                       double *out);

/* (1/K^2) f^T Cov(s) g, K = k, both checked. */
double mcs_readout_form(const mcs_readout *view, size_t k, const double *f, const double *g);

/* The rounding bound of mcs_readout_form(view, k, f, g): (2N + 16)
 * DBL_EPSILON (1/K^2) sum_{m,n} |f_m| |g_n| (|<s_m s_n>| + |<s_m>| |<s_n>|). */
double mcs_readout_form_bound(const mcs_readout *view, size_t k, const double *f,
                              const double *g);

/* A value that cannot be negative (a variance, a power): in [-bound, 0) it
 * is rounding and reads 0, from exact and measured moments alike (a
 * deterministic pattern's zero variances come out as +-1e-16); below -bound
 * it is returned as it is, for the caller to refuse (mcs_readout_clamp). */
double mcs_readout_nonnegative(const mcs_readout *view, double value, double bound);

/* The same as a status: *value in [-bound, 0) reads 0 and MCS_OK; below
 * -bound (or NaN) it is no value any data give, MCS_ERR_INVARIANT with
 * *value unchanged. */
mcs_status mcs_readout_clamp(double bound, double *value);

/* Eq. 7 at one frequency, freq < N, of any x[N] from the view's twiddle table. */
void mcs_readout_dft(const mcs_readout *view, const double *x, size_t freq, double *re,
                     double *im);

/* <S_k S_l*> (eq. 16), freq_k and freq_l < N. */
void mcs_readout_cross_at(const mcs_readout *view, size_t freq_k, size_t freq_l, double *re,
                          double *im);

/* Defines the public read-out of one object type as declared in its header
 * (include/mcspec/moment.h, theory.h), every call forwarding to the code
 * above with the object and its open function: MCS_READOUT_DEFINE(moment,
 * mcs_moment, open) defines mcs_moment_bin_mean ... mcs_moment_estimator_covariance.
 * One definition for both objects keeps their argument lists identical. */
#define MCS_READOUT_DEFINE(module, type, open)                                                 \
    mcs_status mcs_##module##_bin_mean(const type *obj, size_t bin, double *out)               \
    {                                                                                          \
        const mcs_readout_source src_ = {obj, open};                                           \
        return mcs_readout_bin_mean(&src_, bin, out);                                          \
    }                                                                                          \
    mcs_status mcs_##module##_bin_second(const type *obj,                                      \
        size_t bin_m, size_t bin_n, double *out)                                               \
    {                                                                                          \
        const mcs_readout_source src_ = {obj, open};                                           \
        return mcs_readout_bin_second(&src_, bin_m, bin_n, out);                               \
    }                                                                                          \
    mcs_status mcs_##module##_mean(const type *obj, size_t freq, double *re, double *im)       \
    {                                                                                          \
        const mcs_readout_source src_ = {obj, open};                                           \
        return mcs_readout_mean(&src_, freq, re, im);                                          \
    }                                                                                          \
    mcs_status mcs_##module##_power(const type *obj, size_t freq, double *out)                 \
    {                                                                                          \
        const mcs_readout_source src_ = {obj, open};                                           \
        return mcs_readout_power(&src_, freq, out);                                            \
    }                                                                                          \
    mcs_status mcs_##module##_cross(const type *obj,                                           \
        size_t freq_k, size_t freq_l, double *re, double *im)                                  \
    {                                                                                          \
        const mcs_readout_source src_ = {obj, open};                                           \
        return mcs_readout_cross(&src_, freq_k, freq_l, re, im);                               \
    }                                                                                          \
    mcs_status mcs_##module##_covariance(const type *obj,                                      \
        size_t freq_k, size_t freq_l, double *re, double *im)                                  \
    {                                                                                          \
        const mcs_readout_source src_ = {obj, open};                                           \
        return mcs_readout_covariance(&src_, freq_k, freq_l, re, im);                          \
    }                                                                                          \
    mcs_status mcs_##module##_cross_matrix(const type *obj,                                    \
        size_t n, double *re, double *im)                                                      \
    {                                                                                          \
        const mcs_readout_source src_ = {obj, open};                                           \
        return mcs_readout_cross_matrix(&src_, n, re, im);                                     \
    }                                                                                          \
    mcs_status mcs_##module##_covariance_matrix(const type *obj,                               \
        size_t n, double *re, double *im)                                                      \
    {                                                                                          \
        const mcs_readout_source src_ = {obj, open};                                           \
        return mcs_readout_covariance_matrix(&src_, n, re, im);                                \
    }                                                                                          \
    mcs_status mcs_##module##_estimator_mean(const type *obj,                                  \
        size_t n, size_t k, const double *f, double *out)                                      \
    {                                                                                          \
        const mcs_readout_source src_ = {obj, open};                                           \
        return mcs_readout_estimator_mean(&src_, n, k, f, out);                                \
    }                                                                                          \
    mcs_status mcs_##module##_variance(const type *obj,                                        \
        size_t n, size_t k, const double *f, double *out)                                      \
    {                                                                                          \
        const mcs_readout_source src_ = {obj, open};                                           \
        return mcs_readout_variance(&src_, n, k, f, out);                                      \
    }                                                                                          \
    mcs_status mcs_##module##_estimator_covariance(const type *obj,                            \
        size_t n, size_t k, const double *f, const double *g, double *out)                     \
    {                                                                                          \
        const mcs_readout_source src_ = {obj, open};                                           \
        return mcs_readout_estimator_covariance(&src_, n, k, f, g, out);                       \
    }

#endif /* MCSPEC_READOUT_H */
