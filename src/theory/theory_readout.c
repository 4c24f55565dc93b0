/* The read-outs of exact moments (include/mcspec/theory.h): the shared
 * read-out of src/accumulators/readout.c over the expectations themselves,
 * with the zeros theory proves and the tolerances of init's rounding; the
 * moments and their checks are theory.c. */
#include "mcspec/theory.h"
#include "core/internal.h"
#include "accumulators/readout.h"
#include "theory_internal.h"

#include <float.h>
#include <math.h>

/* ---- read-out (src/accumulators/readout.c): the expectations themselves -------------- */

static void fill_view(const mcs_theory *th, mcs_readout *view)
{
    *view = (mcs_readout){.n = th->n,
                          .k = th->k,
                          .scale = 1.0,
                          .first = th->mean_s,
                          .second = th->second,
                          .cos_table = th->cos_table,
                          .sin_table = th->sin_table,
                          .exact_rounding = mcs_theory_init_rounding_(th, NULL, 0.0)};
}

/* The zeros theory proves for th (theory_internal.h), formed before a
 * read-out writes (its outputs may lie in *th); 0 for an object that is not
 * set up (the read-out then refuses it). */
static int zeros_of(const mcs_theory *th, mcs_theory_zeros *z)
{
    if (th == NULL || !mcs_theory_valid_(th))
        return 0;
    *z = mcs_theory_zeros_of_(th->kind, th->n, th->k, th->has_importance == 1, th->mean_s);
    return 1;
}

/* A complex read-out at (k, l) with the zeros of z applied: all of it where
 * zero says so, its imaginary part where both S are real (or k = l). */
static void apply_zeros(const mcs_theory_zeros *z, int zero, size_t k, size_t l, double *re,
                        double *im)
{
    if (zero)
        *re = *im = 0.0;
    if (mcs_theory_im_zero_(z, k, l))
        *im = 0.0;
}

/* Opens th for a read-out of <s> alone (bin_mean, mean, estimator_mean):
 * MCS_ERR_UNINIT, then MCS_ERR_INVARIANT for the O(N) part. */
static mcs_status open_first(const void *obj, mcs_readout *view)
{
    const mcs_theory *th = (const mcs_theory *)obj;
    if (!mcs_theory_valid_(th))
        return MCS_ERR_UNINIT;
    if (!mcs_theory_first_sound_(th))
        return MCS_ERR_INVARIANT;
    fill_view(th, view);
    return MCS_OK;
}

/* For every read-out of the second moments: open_first, then all of them
 * (O(N^2), the order of the read-out's own cost or less). */
mcs_status mcs_readout_open_theory(const void *obj, mcs_readout *view)
{
    mcs_status st = open_first(obj, view);
    if (st == MCS_OK && !mcs_theory_second_sound_((const mcs_theory *)obj))
        st = MCS_ERR_INVARIANT;
    return st;
}


/* Opens th for a read-out at bins or frequencies a, b (range the status of
 * one outside [0, N)), outputs given: MCS_ERR_NULL, the checks of
 * mcs_readout_open_theory, then range. */
static mcs_status open_at(int outputs, const mcs_theory *th, size_t a, size_t b,
                          mcs_status range, mcs_readout *view)
{
    if (!outputs || th == NULL)
        return MCS_ERR_NULL;
    mcs_status st = mcs_readout_open_theory(th, view);
    return st == MCS_OK && (a >= th->n || b >= th->n) ? range : st;
}

/* The two bounds of the shared read-out for exact moments (readout.c:
 * power_bound, variance_rounding), each plus init's rounding (above), which
 * the read-out does not know of: a power or a variance in [-bound, 0) is
 * rounding and reads 0; one below -bound comes from no moments init writes. */
static double sum_abs_second(const mcs_readout *view)
{
    double a = 0.0;
    for (size_t j = 0; j < view->n * view->n; ++j)
        a += fabs(view->second[j]);
    return a;
}

static double power_tolerance(const mcs_theory *th, const mcs_readout *view)
{
    const double n = (double)th->n;
    return ((2.0 * n + 16.0) * DBL_EPSILON * sum_abs_second(view) +
            mcs_theory_init_rounding_(th, NULL, 0.0)) /
           n;
}

static double variance_tolerance(const mcs_theory *th, const mcs_readout *view)
{
    const double n = (double)th->n;
    double b = 0.0;
    for (size_t j = 0; j < th->n; ++j)
        b += fabs(th->mean_s[j]);
    return (4.0 * (n + 2.0) * DBL_EPSILON * (sum_abs_second(view) + b * b) +
            mcs_theory_init_rounding_(th, NULL, 0.0)) /
           n;
}

/* A value that cannot be negative, judged against its tolerance. */
static mcs_status clamp_nonnegative(double tol, double *v)
{
    if (*v >= 0.0)
        return MCS_OK;
    if (!(*v >= -tol))
        return MCS_ERR_INVARIANT;
    *v = 0.0;
    return MCS_OK;
}

/* <|S_freq|^2> from the shared eq. 16, real (as mcs_readout_power); 0 where
 * S_freq is 0 in every trial. */
static mcs_status power_at(const mcs_theory *th, const mcs_readout *view, size_t freq, double *p)
{
    double im;
    mcs_theory_zeros z;
    mcs_readout_cross_at(view, freq, freq, p, &im);
    mcs_status st = clamp_nonnegative(*p < 0.0 ? power_tolerance(th, view) : 0.0, p);
    if (st == MCS_OK && zeros_of(th, &z) && mcs_theory_s_zero_(&z, freq))
        *p = 0.0;
    return st;
}

/* Cov(S_freq, S_freq) with the arithmetic of the shared covariance_at
 * (readout.c): <S_k S_k*> less |<S_k>|^2. */
static mcs_status variance_at(const mcs_theory *th, const mcs_readout *view, size_t freq,
                              double *re, double *im)
{
    double kr, ki;
    mcs_readout_cross_at(view, freq, freq, re, im);
    mcs_readout_dft(view, view->first, freq, &kr, &ki);
    *re += -1.0 * (kr * kr + ki * ki);
    *im += -1.0 * (ki * kr - kr * ki);
    mcs_status st = clamp_nonnegative(*re < 0.0 ? variance_tolerance(th, view) : 0.0, re);
    mcs_theory_zeros z;
    if (st == MCS_OK && zeros_of(th, &z))
        apply_zeros(&z, mcs_theory_cov_zero_(&z, freq, freq), freq, freq, re, im);
    return st;
}

mcs_status mcs_theory_bin_mean(const mcs_theory *th, size_t bin, double *out)
{
    const mcs_readout_source src = {th, open_first};
    return mcs_readout_bin_mean(&src, bin, out);
}

/* The O(N) part, then the entry read and the two diagonals it is judged by. */
mcs_status mcs_theory_bin_second(const mcs_theory *th, size_t bin_m, size_t bin_n,
                                 double *out)
{
    mcs_readout v;
    mcs_status st = out == NULL || th == NULL ? MCS_ERR_NULL : open_first(th, &v);
    if (st == MCS_OK && (bin_m >= th->n || bin_n >= th->n))
        st = MCS_ERR_BIN_RANGE;
    if (st == MCS_OK && !(mcs_theory_diagonal_sound_(th, bin_m) && mcs_theory_diagonal_sound_(th, bin_n) &&
                          mcs_theory_entry_sound_(th, bin_m, bin_n)))
        st = MCS_ERR_INVARIANT;
    const mcs_readout_source src = {th, open_first};
    return st == MCS_OK ? mcs_readout_bin_second(&src, bin_m, bin_n, out) : st;
}

mcs_status mcs_theory_mean(const mcs_theory *th, size_t freq, double *re, double *im)
{
    const mcs_readout_source src = {th, open_first};
    mcs_theory_zeros z;
    const int known = zeros_of(th, &z);
    mcs_status st = mcs_readout_mean(&src, freq, re, im);
    if (st == MCS_OK && known) {
        if (mcs_theory_mean_zero_(&z, freq))
            *re = *im = 0.0;
        if (mcs_theory_real_freq_(&z, freq))
            *im = 0.0;
    }
    return st;
}

mcs_status mcs_theory_power(const mcs_theory *th, size_t freq, double *out)
{
    mcs_readout v;
    double p = 0.0;
    mcs_status st = open_at(out != NULL, th, freq, freq, MCS_ERR_FREQ_RANGE, &v);
    if (st == MCS_OK)
        st = power_at(th, &v, freq, &p);
    return st == MCS_OK ? mcs_set_(out, p) : st;
}

/* A complex read-out at k = l (power or variance): computed first, written
 * last into two different doubles. */
typedef mcs_status (*diagonal_at)(const mcs_theory *th, const mcs_readout *view, size_t freq,
                                  double *re, double *im);

static mcs_status power_im(const mcs_theory *th, const mcs_readout *view, size_t freq,
                           double *re, double *im)
{
    *im = 0.0; /* <s s^T> is symmetric: the imaginary part is rounding */
    return power_at(th, view, freq, re);
}

static mcs_status read_diagonal(const mcs_theory *th, size_t freq, double *re, double *im,
                                diagonal_at at)
{
    mcs_readout v;
    mcs_status st = open_at(re != NULL && im != NULL, th, freq, freq, MCS_ERR_FREQ_RANGE, &v);
    if (st == MCS_OK && mcs_overlap_(re, sizeof *re, im, sizeof *im))
        st = MCS_ERR_ALIAS;
    double r = 0.0, i = 0.0;
    if (st == MCS_OK)
        st = at(th, &v, freq, &r, &i);
    if (st == MCS_OK) {
        *re = r;
        *im = i;
    }
    return st;
}

mcs_status mcs_theory_cross(const mcs_theory *th, size_t freq_k, size_t freq_l, double *re,
                            double *im)
{
    if (freq_k == freq_l)
        return read_diagonal(th, freq_k, re, im, power_im);
    const mcs_readout_source src = {th, mcs_readout_open_theory};
    mcs_theory_zeros z;
    const int known = zeros_of(th, &z);
    mcs_status st = mcs_readout_cross(&src, freq_k, freq_l, re, im);
    if (st == MCS_OK && known)
        apply_zeros(&z, mcs_theory_cross_zero_(&z, freq_k, freq_l), freq_k, freq_l, re, im);
    return st;
}

mcs_status mcs_theory_covariance(const mcs_theory *th, size_t freq_k, size_t freq_l,
                                 double *re, double *im)
{
    if (freq_k == freq_l)
        return read_diagonal(th, freq_k, re, im, variance_at);
    const mcs_readout_source src = {th, mcs_readout_open_theory};
    mcs_theory_zeros z;
    const int known = zeros_of(th, &z);
    mcs_status st = mcs_readout_covariance(&src, freq_k, freq_l, re, im);
    if (st == MCS_OK && known)
        apply_zeros(&z, mcs_theory_cov_zero_(&z, freq_k, freq_l), freq_k, freq_l, re, im);
    return st;
}

/* Every entry of a matrix read-out (re, im of n * n, not in *th) with the
 * zeros of z; cov picks the covariance's rule, else the cross moment's. */
static void matrix_zeros(const mcs_theory_zeros *z, size_t n, int cov, double *re, double *im)
{
    for (size_t k = 0; k < n; ++k)
        for (size_t l = 0; l < n; ++l) {
            const int zero = cov ? mcs_theory_cov_zero_(z, k, l) : mcs_theory_cross_zero_(z, k, l);
            apply_zeros(z, zero, k, l, &re[k * n + l], &im[k * n + l]);
        }
}

/* The matrices: every diagonal judged first (O(N^3), as the matrix), so a
 * refused one leaves the outputs unwritten; then the shared matrix. */
static mcs_status check_diagonals(const mcs_theory *th, size_t n, const double *re,
                                  const double *im, diagonal_at at)
{
    const mcs_readout_source src = {th, mcs_readout_open_theory};
    mcs_readout v;
    mcs_status st = mcs_readout_open_n(re != NULL && im != NULL, &src, n, &v);
    for (size_t k = 0; st == MCS_OK && k < n; ++k) {
        double r, i;
        st = at(th, &v, k, &r, &i);
    }
    return st;
}

mcs_status mcs_theory_cross_matrix(const mcs_theory *th, size_t n, double *re, double *im)
{
    mcs_status st = check_diagonals(th, n, re, im, power_im);
    const mcs_readout_source src = {th, mcs_readout_open_theory};
    if (st == MCS_OK)
        st = mcs_readout_cross_matrix(&src, n, re, im);
    for (size_t k = 0; st == MCS_OK && k < n; ++k) /* rounding, as power_at found */
        re[k * n + k] = fmax(re[k * n + k], 0.0);
    mcs_theory_zeros z;
    if (st == MCS_OK && zeros_of(th, &z))
        matrix_zeros(&z, n, 0, re, im);
    return st;
}

mcs_status mcs_theory_covariance_matrix(const mcs_theory *th, size_t n, double *re,
                                        double *im)
{
    mcs_status st = check_diagonals(th, n, re, im, variance_at);
    if (st != MCS_OK)
        return st;
    const mcs_readout_source src = {th, mcs_readout_open_theory};
    st = mcs_readout_covariance_matrix(&src, n, re, im); /* its bounds hold init's rounding */
    for (size_t k = 0; st == MCS_OK && k < n; ++k) /* rounding, as variance_at found */
        re[k * n + k] = fmax(re[k * n + k], 0.0);
    mcs_theory_zeros z;
    if (st == MCS_OK && zeros_of(th, &z))
        matrix_zeros(&z, n, 1, re, im);
    return st;
}

mcs_status mcs_theory_estimator_mean(const mcs_theory *th, size_t n, size_t k, const double *f,
                                     double *out)
{
    const mcs_readout_source src = {th, open_first};
    return mcs_readout_estimator_mean(&src, n, k, f, out);
}

mcs_status mcs_theory_bias(const mcs_theory *th, size_t n, size_t k, const double *f,
                           double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    const mcs_readout_source src = {th, open_first};
    mcs_readout v;
    mcs_status st = mcs_readout_check_integrand(&src, n, k, f, &v);
    if (st == MCS_OK)
        st = mcs_check_integrand_(n, f);
    if (st != MCS_OK)
        return st;
    const double bias = mcs_theory_bias_of_(th->kind, n, k, th->mean_s, f);
    return isfinite(bias) ? mcs_set_(out, bias) : MCS_ERR_INVARIANT;
}

double mcs_theory_form_tolerance_(const mcs_theory *th, const mcs_readout *view,
                                  const double *f)
{
    const double kd = (double)th->k;
    return mcs_readout_form_bound(view, th->k, f, f) +
           mcs_theory_init_rounding_(th, f, 0.0) / (kd * kd);
}

/* As mcs_readout_variance, with a variance below minus its tolerance
 * refused. */
mcs_status mcs_theory_variance(const mcs_theory *th, size_t n, size_t k, const double *f,
                               double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    const mcs_readout_source src = {th, mcs_readout_open_theory};
    mcs_readout v;
    mcs_status st = mcs_readout_check_integrand(&src, n, k, f, &v);
    if (st != MCS_OK)
        return st;
    double var = mcs_readout_form(&v, k, f, f);
    if (!isfinite(var)) /* f so large that the form overflows */
        return MCS_ERR_MAGNITUDE;
    st = clamp_nonnegative(var < 0.0 ? mcs_theory_form_tolerance_(th, &v, f) : 0.0, &var);
    mcs_theory_zeros z;
    if (st == MCS_OK && zeros_of(th, &z) && mcs_theory_estimator_zero_(&z, n, f, f))
        var = 0.0;
    return st == MCS_OK ? mcs_set_(out, var) : st;
}

mcs_status mcs_theory_estimator_covariance(const mcs_theory *th, size_t n, size_t k,
                                           const double *f, const double *g, double *out)
{
    const mcs_readout_source src = {th, mcs_readout_open_theory};
    /* judged before the read-out writes: out may be an element of f or g */
    mcs_theory_zeros z;
    const int zero = f != NULL && g != NULL && zeros_of(th, &z) && n == th->n &&
                     mcs_theory_estimator_zero_(&z, n, f, g);
    mcs_status st = mcs_readout_estimator_covariance(&src, n, k, f, g, out);
    if (st == MCS_OK && zero)
        *out = 0.0;
    return st;
}
