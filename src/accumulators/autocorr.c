#include "mcspec/autocorr.h"
#include "acc_internal.h"

#include <math.h>
#include <string.h>

mcs_status mcs_autocorr_init(mcs_autocorr *acc, size_t n)
{
    mcs_status st = mcs_check_init_(acc, n, (size_t)MCS_MAX_N);
    if (st != MCS_OK)
        return st;
    memset(acc, 0, sizeof *acc);
    acc->n = n; /* last: only a complete object counts as initialised */
    return MCS_OK;
}

static mcs_status autocorr_check(const mcs_autocorr *acc)
{
    mcs_status st = mcs_check_object_(acc, acc != NULL ? acc->n : 0u, (size_t)MCS_MAX_N);
    return st == MCS_OK && acc->count > (uint64_t)MCS_MAX_COUNT ? MCS_ERR_INVARIANT : st;
}

/* The object's arrays as the checks read a record's (acc_internal.h). */
static mcs_autocorr_sums_ object_sums(const mcs_autocorr *acc)
{
    const mcs_autocorr_sums_ s = {acc->n,
                                  acc->count,
                                  mcs_memory_values_(acc->sum_s),
                                  mcs_memory_values_(acc->lo_s),
                                  mcs_memory_values_(acc->sum_lag),
                                  mcs_memory_values_(acc->lo_lag),
                                  acc->sum_dc,
                                  acc->lo_dc};
    return s;
}

int mcs_autocorr_stored_valid(const mcs_autocorr *acc)
{
    const mcs_autocorr_sums_ s = object_sums(acc);
    return mcs_autocorr_sums_ok_(&s);
}

/* Folded lag of an ordered pair of bins: e = min(d, N - d), d = c - b mod N. */
static size_t folded_lag(size_t b, size_t c, size_t n)
{
    const size_t d = c >= b ? c - b : c + n - b;
    return d <= n - d ? d : n - d;
}

/* K < N: every unordered pair {j, j'} at folded lag e adds w w' to sum_lag[e];
 * a sample with itself adds w^2 / 2 to sum_lag[0]. Then A(e) = sum_lag[e]
 * for 0 < e < N/2, and A(0) = 2 sum_lag[0], A(N/2) = 2 sum_lag[N/2]
 * (read-out), because there both orders of a pair land on the same lag. */
static void add_pairs(mcs_autocorr *acc, size_t k, const size_t *bins, const double *weights)
{
    const size_t n = acc->n;
    double *a = acc->sum_lag, *lo = acc->lo_lag;
    for (size_t j = 0; j < k; ++j) {
        const size_t b = bins[j];
        const double w = weights[j];
        mcs_kahan_add_(&acc->sum_s[b], &acc->lo_s[b], w);
        mcs_kahan_add_(&a[0], &lo[0], 0.5 * w * w);
        for (size_t jj = j + 1u; jj < k; ++jj) {
            const size_t e = folded_lag(b, bins[jj], n);
            mcs_kahan_add_(&a[e], &lo[e], w * weights[jj]);
        }
    }
}

/* K >= N: the trial's s, centred on its mean c = S/N, gives A_c(e) =
 * sum_n y_n y_{n+e}, y = s - c, folded as add_pairs folds A (halved at e = 0
 * and e = N/2, where d and N - d are one lag); S^2/N goes to sum_dc. */
static void add_dense(mcs_autocorr *acc, size_t k, const size_t *bins, const double *weights)
{
    const size_t n = acc->n, h = n / 2u;
    double *y = acc->work;
    memset(y, 0, n * sizeof y[0]);
    for (size_t j = 0; j < k; ++j)
        y[bins[j]] += weights[j];
    double total = 0.0, tlo = 0.0;
    for (size_t b = 0; b < n; ++b) {
        mcs_kahan_add_(&acc->sum_s[b], &acc->lo_s[b], y[b]);
        mcs_kahan_add_(&total, &tlo, y[b]);
    }
    const double c = total / (double)n;
    for (size_t b = 0; b < n; ++b)
        y[b] -= c;
    for (size_t e = 0; e <= h; ++e) {
        double lag = 0.0;
        for (size_t b = 0; b + e < n; ++b)
            lag += y[b] * y[b + e];
        for (size_t b = n - e; b < n; ++b)
            lag += y[b] * y[b + e - n];
        const double half = (e == 0u || 2u * e == n) ? 0.5 : 1.0;
        mcs_kahan_add_(&acc->sum_lag[e], &acc->lo_lag[e], half * lag);
    }
    mcs_kahan_add_(&acc->sum_dc, &acc->lo_dc, total * c);
}

mcs_status mcs_autocorr_add_bins(mcs_autocorr *acc, size_t k, const size_t *bins,
                                 const double *weights)
{
    mcs_status st = bins == NULL || weights == NULL ? MCS_ERR_NULL : autocorr_check(acc);
    if (st == MCS_OK)
        st = mcs_check_add_sparse_(acc, sizeof *acc, acc->n, acc->count, k, bins, weights,
                                   MCS_AUTOCORR_MAX_TRIAL);
    if (st != MCS_OK)
        return st;
    if (k >= acc->n)
        add_dense(acc, k, bins, weights);
    else
        add_pairs(acc, k, bins, weights);
    acc->count += 1u;
    return MCS_OK;
}

/* dst's (sum, lo) pairs += src's (dst == src doubles them). */
static void merge_kahan(size_t len, double *sum, double *lo, const double *src_sum,
                        const double *src_lo)
{
    for (size_t j = 0; j < len; ++j)
        mcs_kahan_merge_(&sum[j], &lo[j], src_sum[j], src_lo[j]);
}

mcs_status mcs_autocorr_merge(mcs_autocorr *dst, const mcs_autocorr *src)
{
    mcs_status st = mcs_check_pair_(autocorr_check(dst), autocorr_check(src));
    if (st == MCS_OK)
        st = mcs_check_merge_(dst, src, sizeof *dst, dst->n == src->n, dst->count, src->count);
    /* sums no trials give would pass into dst: refused (O(N), as the merge) */
    if (st == MCS_OK && (!mcs_autocorr_stored_valid(dst) || !mcs_autocorr_stored_valid(src)))
        st = MCS_ERR_INVARIANT;
    if (st != MCS_OK)
        return st;
    const size_t n = dst->n;
    merge_kahan(n, dst->sum_s, dst->lo_s, src->sum_s, src->lo_s);
    merge_kahan(n / 2u + 1u, dst->sum_lag, dst->lo_lag, src->sum_lag, src->lo_lag);
    merge_kahan(1u, &dst->sum_dc, &dst->lo_dc, &src->sum_dc, &src->lo_dc);
    dst->count += src->count;
    return MCS_OK;
}

mcs_status mcs_autocorr_count(const mcs_autocorr *acc, uint64_t *count)
{
    mcs_status st = count == NULL ? MCS_ERR_NULL : autocorr_check(acc);
    if (st == MCS_OK)
        *count = acc->count;
    return st;
}

/* The checks of a read-out writing the n-entry arrays out and out2 (out2
 * NULL for one array), in this order: NULL, UNINIT (acc), MISMATCH, the
 * plan (UNINIT or MISMATCH), EMPTY, INVARIANT (sums no trials give:
 * mcs_autocorr_stored_valid), ALIAS (outputs overlapping each other, the accumulator or the plan:
 * the plan's scratch holds the data mid-transform). */
static mcs_status autocorr_readout(const mcs_autocorr *acc, const mcs_dft *plan, size_t n,
                                   const double *out, const double *out2)
{
    mcs_status st = plan == NULL || out == NULL ? MCS_ERR_NULL : autocorr_check(acc);
    if (st == MCS_OK && n != acc->n)
        st = MCS_ERR_MISMATCH;
    if (st == MCS_OK)
        st = mcs_dft_check(plan, n); /* UNINIT or MISMATCH */
    if (st == MCS_OK && acc->count == 0u)
        st = MCS_ERR_EMPTY;
    if (st == MCS_OK && !mcs_autocorr_stored_valid(acc))
        st = MCS_ERR_INVARIANT;
    const size_t bytes = n * sizeof(double);
    const size_t out2_bytes = out2 != NULL ? bytes : 0u;
    if (st == MCS_OK &&
        (mcs_overlap_(out, bytes, out2, out2_bytes) ||
         mcs_overlap_(out, bytes, acc, sizeof *acc) || mcs_overlap_(out, bytes, plan, sizeof *plan) ||
         mcs_overlap_(out2, out2_bytes, acc, sizeof *acc) ||
         mcs_overlap_(out2, out2_bytes, plan, sizeof *plan)))
        st = MCS_ERR_ALIAS;
    return st;
}

/* The transform's status, then every output finite: a read-out never returns
 * MCS_OK with an untransformed or non-finite result. With the stored values
 * bounded (autocorr_readout) neither can fail; the checks stay as the rule. */
static mcs_status transformed(mcs_status dft_status, size_t n, const double *a, const double *b)
{
    if (dft_status != MCS_OK)
        return dft_status;
    return mcs_all_finite_(n, a) && (b == NULL || mcs_all_finite_(n, b)) ? MCS_OK
                                                                         : MCS_ERR_NOT_FINITE;
}

mcs_status mcs_autocorr_mean(const mcs_autocorr *acc, mcs_dft *plan, size_t n, double *re,
                             double *im)
{
    if (im == NULL)
        return MCS_ERR_NULL;
    mcs_status st = autocorr_readout(acc, plan, n, re, im);
    if (st != MCS_OK)
        return st;
    const double inv = 1.0 / (double)acc->count;
    for (size_t j = 0; j < n; ++j)
        re[j] = acc->sum_s[j] * inv;
    return transformed(mcs_dft_real(plan, n, re, re, im), n, re, im); /* eq. 15 */
}

/* The rounding bound of every power (autocorr.h), mcs_autocorr_power_gamma_
 * (acc_internal.h) times <A(0)> = 2 sum_lag[0] / T, the largest |<A(d)>|:
 * each stored lag sum is within (N + 8 + T N^2 eps) eps of T <A(0)> of its
 * exact value (a trial's lag is a sum of at most N products, or its pair
 * products one at a time, and Kahan's sum of n terms errs by 2u + n u^2 of
 * their magnitudes, n <= T N^2 products), and a transform of N lags of at
 * most <A(0)> each errs by (N + 2) u <A(0)> on the direct path (a sum of N
 * terms) or (8 log2 N + 16) u <A(0)> on the FFT paths (normwise, Higham,
 * Accuracy and Stability, thm 24.2, per stage 8u with twiddles to an ulp,
 * and the real transform's last step); the bound takes these and twice the
 * rounding of the loader's direct sums, so that what it loads reads out. */
static double power_rounding(const mcs_autocorr *acc)
{
    return mcs_autocorr_power_gamma_(acc->n, acc->count, 0) *
               (2.0 * acc->sum_lag[0] / (double)acc->count) +
           mcs_autocorr_power_underflow_(acc->n, 0);
}

/* MCS_POWER_FREQS_ frequencies at a time, the twiddles by rotation (within
 * 40 eps; the gamma allows 64). */
int mcs_autocorr_powers_ok(const mcs_autocorr_sums_ *s)
{
    const size_t n = s->n, h = n / 2u;
    if (s->count == 0u || n == 0u)
        return 1;
    const double nd = (double)n, t = (double)s->count, l0 = MCS_AT_(s->sum_lag, 0u);
    const double floor = -(mcs_autocorr_power_gamma_(n, s->count, 1) * (2.0 * l0 / t) +
                           mcs_autocorr_power_underflow_(n, 1));
    for (size_t k0 = 0; k0 <= h; k0 += MCS_POWER_FREQS_) {
        const size_t len = h + 1u - k0 < MCS_POWER_FREQS_ ? h + 1u - k0 : MCS_POWER_FREQS_;
        double sum[MCS_POWER_FREQS_];
        mcs_rotations_ r;
        mcs_rotations_start_(&r, k0, len, n);
        for (size_t f = 0; f < len; ++f)
            sum[f] = 2.0 * l0;
        for (size_t e = 1; e <= h; ++e) {
            mcs_rotations_step_(&r, e);
            const double x = 2.0 * MCS_AT_(s->sum_lag, e); /* lags e and N - e, or N/2 halved */
            for (size_t f = 0; f < len; ++f)
                sum[f] += x * r.zc[f];
        }
        for (size_t f = 0; f < len; ++f) {
            const double power = sum[f] / (nd * t) + (k0 + f == 0u ? s->sum_dc / t : 0.0);
            if (!(power >= floor))
                return 0;
        }
    }
    return 1;
}

int mcs_autocorr_powers_valid(const mcs_autocorr *acc)
{
    const mcs_autocorr_sums_ s = object_sums(acc);
    return mcs_autocorr_powers_ok(&s);
}

mcs_status mcs_autocorr_power(const mcs_autocorr *acc, mcs_dft *plan, size_t n, double *power)
{
    mcs_status st = autocorr_readout(acc, plan, n, power, NULL);
    if (st != MCS_OK)
        return st;
    /* <A(d)> for every lag, unfolded (see mcs_autocorr_add_bins), less the
     * constant S^2/N of the centred trials; then Wiener-Khinchin:
     * <|S_k|^2> = (1/N) sum_d e^{-2 pi i k d/N} <A(d)>, i.e. N^{-1/2} times
     * eq. 7 applied to <A>. A is even, so the result is real. The constant
     * <S^2/N> on every lag gives exactly itself at k = 0 and 0 elsewhere, so
     * it is added there after the transform instead of cancelling in it. */
    const double inv = 1.0 / (double)acc->count;
    power[0] = 2.0 * acc->sum_lag[0] * inv;
    for (size_t d = 1; d < n; ++d) {
        const size_t e = d <= n - d ? d : n - d;
        const double twice = (2u * e == n) ? 2.0 : 1.0;
        power[d] = twice * acc->sum_lag[e] * inv;
    }
    st = transformed(mcs_dft_real(plan, n, power, power, NULL), n, power, NULL);
    if (st != MCS_OK)
        return st;
    const double scale = 1.0 / sqrt((double)n);
    for (size_t k = 0; k < n; ++k)
        power[k] *= scale;
    power[0] += acc->sum_dc * inv;
    /* A power is a mean of |S_k|^2: one below 0 within the rounding bound
     * is rounding (at the weight limit, -2.7e39 beside 2.5e57 at k = 0) and
     * reads 0; one below that is no spectrum of any trials. */
    const double bound = power_rounding(acc);
    for (size_t k = 0; k < n && st == MCS_OK; ++k)
        if (power[k] < 0.0)
            st = power[k] >= -bound ? MCS_OK : MCS_ERR_INVARIANT;
    for (size_t k = 0; k < n && st == MCS_OK; ++k)
        power[k] = power[k] < 0.0 ? 0.0 : power[k];
    return st;
}
