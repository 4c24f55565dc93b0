#include "mcspec/moment.h"
#include "internal.h"
#include "readout.h"

#include <string.h>

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
    mcs_twiddles_(n, acc->cos_table, acc->sin_table);
    return MCS_OK;
}

/* Adds sample pair contributions. s_m s_n = sum over ordered pairs (j, j')
 * with n_j = m, n_j' = n of w_j w_j': a pair in two bins adds w w' to both
 * mirrored entries (so the matrix stays exactly symmetric), a pair in one
 * bin 2 w w' to its diagonal entry. */
static void add_sample_pairs(mcs_moment *acc, size_t k, const size_t *bins,
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
            if (b == c) {
                ss[b * n + b] += 2.0 * ww;
            } else {
                ss[b * n + c] += ww;
                ss[c * n + b] += ww;
            }
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
    mcs_status st = mcs_check_sparse_(acc->n, k, bins, weights);
    if (st != MCS_OK)
        return st;
    add_sample_pairs(acc, k, bins, weights);
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
    mcs_status st = mcs_check_weights_(n, s);
    if (st != MCS_OK)
        return st;
    /* Each non-zero bin as one sample of weight s_m: the diagonal gets s_m^2
     * and each pair of distinct bins s_m s_c in both mirrored entries. */
    double *ss = acc->sum_ss;
    for (size_t m = 0; m < n; ++m) {
        const double a = s[m];
        if (a == 0.0)
            continue;
        acc->sum_s[m] += a;
        ss[m * n + m] += a * a;
        for (size_t c = m + 1u; c < n; ++c) {
            const double v = a * s[c];
            ss[m * n + c] += v;
            ss[c * n + m] += v;
        }
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

/* ---- read-out (src/readout.c): the trial averages are the sums / count ---- */

mcs_status mcs_readout_open_moment(const void *obj, mcs_readout *view)
{
    const mcs_moment *acc = (const mcs_moment *)obj;
    if (!moment_is_valid(acc))
        return MCS_ERR_UNINIT;
    if (acc->count == 0u)
        return MCS_ERR_EMPTY;
    view->n = acc->n;
    view->k = 0u; /* the caller names K */
    view->scale = 1.0 / (double)acc->count;
    view->first = acc->sum_s;
    view->second = acc->sum_ss;
    view->cos_table = acc->cos_table;
    view->sin_table = acc->sin_table;
    return MCS_OK;
}

static const mcs_readout_open trial_averages = mcs_readout_open_moment;

mcs_status mcs_moment_bin_mean(const mcs_moment *acc, size_t bin, double *out)
{
    return mcs_readout_bin_mean(acc, trial_averages, bin, out);
}

mcs_status mcs_moment_bin_second(const mcs_moment *acc, size_t bin_m, size_t bin_n,
                                 double *out)
{
    return mcs_readout_bin_second(acc, trial_averages, bin_m, bin_n, out);
}

mcs_status mcs_moment_mean(const mcs_moment *acc, size_t freq, double *re, double *im)
{
    return mcs_readout_mean(acc, trial_averages, freq, re, im);
}

mcs_status mcs_moment_power(const mcs_moment *acc, size_t freq, double *out)
{
    return mcs_readout_power(acc, trial_averages, freq, out);
}

mcs_status mcs_moment_cross(const mcs_moment *acc, size_t freq_k, size_t freq_l, double *re,
                            double *im)
{
    return mcs_readout_cross(acc, trial_averages, freq_k, freq_l, re, im);
}

mcs_status mcs_moment_covariance(const mcs_moment *acc, size_t freq_k, size_t freq_l,
                                 double *re, double *im)
{
    return mcs_readout_covariance(acc, trial_averages, freq_k, freq_l, re, im);
}

mcs_status mcs_moment_cross_matrix(const mcs_moment *acc, size_t n, double *re, double *im)
{
    return mcs_readout_cross_matrix(acc, trial_averages, n, re, im);
}

mcs_status mcs_moment_covariance_matrix(const mcs_moment *acc, size_t n, double *re,
                                        double *im)
{
    return mcs_readout_covariance_matrix(acc, trial_averages, n, re, im);
}

mcs_status mcs_moment_estimator_mean(const mcs_moment *acc, size_t n, size_t k, const double *f,
                                     double *out)
{
    return mcs_readout_estimator_mean(acc, trial_averages, n, k, f, out);
}

mcs_status mcs_moment_variance(const mcs_moment *acc, size_t n, size_t k, const double *f,
                               double *out)
{
    return mcs_readout_variance(acc, trial_averages, n, k, f, out);
}

mcs_status mcs_moment_estimator_covariance(const mcs_moment *acc, size_t n, size_t k,
                                           const double *f, const double *g, double *out)
{
    return mcs_readout_estimator_covariance(acc, trial_averages, n, k, f, g, out);
}
