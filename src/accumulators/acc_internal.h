/* Private helpers shared by the accumulators that keep compensated sums of
 * trials (moment, autocorr; the point-set ones can use the merge check): the
 * bound on stored values, the checks of an add and of a merge, and the merge
 * of two compensated sums. Static inline, as internal.h. */
#ifndef MCSPEC_ACC_INTERNAL_H
#define MCSPEC_ACC_INTERNAL_H

#include "core/internal.h"
#include "mcspec/autocorr.h"
#include "mcspec/moment.h"

#include <float.h>

/* Read-outs refuse a stored value above 2^500 in magnitude, the bound of the
 * record format too (io.h): trials never get there (the sums stay below
 * 2^496, see each header's trial limit), and below it every read-out,
 * squares of transforms of N values included, stays finite on any object. */
#define MCS_STORED_LIMIT_ 3.273390607896142e+150 /* 2^500 */

/* Every x[len] finite and at most limit in magnitude (NaN fails the
 * compare). */
static inline int mcs_all_below_(size_t len, const double *x, double limit)
{
    int ok = 1;
    for (size_t j = 0; j < len; ++j)
        ok &= fabs(x[j]) <= limit;
    return ok;
}

/* Every x[len] finite and at most MCS_STORED_LIMIT_ in magnitude. */
static inline int mcs_all_stored_(size_t len, const double *x)
{
    return mcs_all_below_(len, x, MCS_STORED_LIMIT_);
}

/* The moment accumulator's values of one trial or one batch (moment.h), and
 * the limits its read-outs and records hold them to: a trial's s and the
 * shift are below 2^220 (MCS_MOMENT_MAX_TRIAL), a batch's sums of s and of d
 * below 2^14 of them, its half products below 2^14 * 2^440. Within these,
 * what a batch adds at read-out (up to 2^14 c_m c_n) stays far below
 * MCS_STORED_LIMIT_, so every read-out stays finite as for the other sums. */
#define MCS_MOMENT_LIMIT_S_ 1.7668470647783843e+72  /* 2^240: shift, batch_s, batch_d */
#define MCS_MOMENT_LIMIT_W_ 2.977131414714806e+138  /* 2^460: batch_w */

/* The rounding the moment accumulator's sums carry, relative (moment.h):
 * every entry of the sums of d d^T, closed and open batch together, is
 * within (MCS_MOMENT_BATCH + 64) eps sqrt(D_m D_n) of the exact sum over the
 * trials, D the sums of d_m^2. A batch entry is a plain sum of one product
 * a trial (below MCS_MOMENT_BATCH of them: gamma_B), each product and the
 * fold's terms a few roundings, the compensated sums 2u + F u^2 <= 3u over
 * F <= 2^53 folds and merges, and the moves of the shift as it settles
 * (moment.c, settle_shift) under 32 eps each. */
#define MCS_MOMENT_ROUNDING_ ((double)(MCS_MOMENT_BATCH + 64u) * DBL_EPSILON)

/* ---- Stored sums that no trials produce ----------------------------------
 *
 * One check per accumulator of everything its sums obey (the invariants of
 * docs/format.md), run by its read-outs and merges on the object and by
 * the loader on a record before anything is written: the two cannot
 * disagree, so a loaded object is as trustworthy as a built one. The values
 * are read through mcs_values_, from memory or from a record's payload
 * (src/io/io_kinds.c); written once here, static inline, so that each use
 * reads its own values directly. Tolerances are the stated rounding bounds
 * (moment.h, autocorr.h), and DBL_TRUE_MIN per operation for sums of
 * products that underflow. */

/* One array of stored values: value i is mem[i] in memory, else read by
 * at() (a record). */
typedef struct mcs_values_ {
    const double *mem; /* the doubles in memory, or NULL */
    double (*at)(const struct mcs_values_ *v, size_t i);
    const void *base; /* the record (io_values) */
    size_t first;     /* record: the payload index of value 0 */
    size_t upper;     /* record: N of an N x N array kept as its upper triangle, else 0 */
} mcs_values_;

/* An array of doubles in memory. */
static inline mcs_values_ mcs_memory_values_(const double *x)
{
    const mcs_values_ v = {x, NULL, NULL, 0u, 0u};
    return v;
}

#define MCS_AT_(v, i) ((v).mem != NULL ? (v).mem[(i)] : (v).at(&(v), (i)))

/* A compensation of a Kahan sum (core/internal.h) is its last add's
 * rounding error, at most an ulp of the sum (not half: the add's own error
 * is half an ulp, its computation of the error adds up to as much again;
 * 2^-52 |sum| >= 1 ulp), and 0 when the sum is 0. */
static inline int mcs_compensation_ok_(double lo, double sum)
{
    return fabs(lo) <= DBL_EPSILON * fabs(sum);
}

/* A moment accumulator's counts and arrays (moment.h), N = n. */
typedef struct {
    size_t n;
    uint64_t count, batch, sparse;
    mcs_values_ shift, sum_d, lo_d, sum_dd, lo_dd, batch_s, batch_d, batch_w;
} mcs_moment_sums_;

/* Entry (m, q) of the open batch's sums of d d^T, or value m of its sums of
 * d (q = SIZE_MAX), as readout.h's mcs_batch_second_ and mcs_batch_first_
 * form them. */
static inline double mcs_moment_batch_at_(const mcs_moment_sums_ *s, size_t m, size_t q)
{
    const double sparse = (double)s->sparse, cm = MCS_AT_(s->shift, m);
    const double bm = MCS_AT_(s->batch_s, m);
    if (q == SIZE_MAX)
        return MCS_AT_(s->batch_d, m) + (bm - sparse * cm);
    const size_t n = s->n;
    const double cq = MCS_AT_(s->shift, q), bq = MCS_AT_(s->batch_s, q);
    return (MCS_AT_(s->batch_w, m * n + q) + MCS_AT_(s->batch_w, q * n + m)) -
           (bm * cq + cm * bq) + sparse * (cm * cq);
}

/* 1 when the sums are those of some trials: the counts (a batch below
 * MCS_MOMENT_BATCH trials and below the count, its sparse trials among
 * them); every value finite and within its limit; shift and batch_s >= 0,
 * no batch_s on a bin of the shift, no batch_s without sparse trials, no
 * batch_d without others, no sums before two trials or batch sums without
 * a batch; every compensation within an ulp of its sum; and, the sums of
 * d d^T being sums of squares and products (gamma = MCS_MOMENT_ROUNDING_,
 * D_m a diagonal plus T DBL_TRUE_MIN, F_m a first sum, over T trials):
 * diagonals >= 0 (closed, batch), F_m^2 <= (1 + 4 gamma) T D_m for the
 * closed sums, the batch and both, |D_mn| <= (1 + 3 gamma) sqrt(D_m D_n) for
 * both, and T c_m + F_m (the sum of s_m) >= 0 within its rounding. */
#define MCS_CHECK_CHUNK_ 8u

static inline int mcs_moment_sums_ok_(const mcs_moment_sums_ *s)
{
    const size_t n = s->n;
    const double t = (double)s->count, b = (double)s->batch, tc = t - b;
    const double sparse = (double)s->sparse;
    const double g = MCS_MOMENT_ROUNDING_ + 8.0 * DBL_EPSILON;
    const double tiny = t * DBL_TRUE_MIN * 4.0;
    if (s->count > (uint64_t)MCS_MAX_COUNT || s->batch >= (uint64_t)MCS_MOMENT_BATCH ||
        s->sparse > s->batch || (s->batch != 0u && s->batch >= s->count))
        return 0;
    int ok = 1;
    for (size_t m = 0; m < n && ok; ++m) {
        const double c = MCS_AT_(s->shift, m), bs = MCS_AT_(s->batch_s, m);
        const double bd = MCS_AT_(s->batch_d, m), f = MCS_AT_(s->sum_d, m);
        const double dd = MCS_AT_(s->sum_dd, m * n + m), w = MCS_AT_(s->batch_w, m * n + m);
        ok = c >= 0.0 && c <= MCS_MOMENT_LIMIT_S_ && bs >= 0.0 && bs <= MCS_MOMENT_LIMIT_S_ &&
             fabs(bd) <= MCS_MOMENT_LIMIT_S_ && w >= 0.0 && w <= MCS_MOMENT_LIMIT_W_ &&
             dd >= 0.0 && dd <= MCS_STORED_LIMIT_ && fabs(f) <= MCS_STORED_LIMIT_ &&
             mcs_compensation_ok_(MCS_AT_(s->lo_d, m), f) &&
             (bs == 0.0 || (c == 0.0 && s->sparse != 0u)) && (bd == 0.0 || s->sparse < s->batch) &&
             (s->count >= 2u || (f == 0.0 && dd == 0.0));
        if (!ok)
            break;
        const double bdiag = mcs_moment_batch_at_(s, m, m), bfirst = mcs_moment_batch_at_(s, m, SIZE_MAX);
        const double dm = dd + bdiag, fm = f + bfirst;
        ok = f * f <= (1.0 + 4.0 * g) * tc * (dd + tiny) &&
             bfirst * bfirst <= (1.0 + 4.0 * g) * b * (bdiag + tiny) &&
             fm * fm <= (1.0 + 4.0 * g) * t * (dm + tiny) &&
             t * c + fm >= -(2.0 * g * sqrt(t * (dm + tiny)) + 4.0 * DBL_EPSILON * (t * c + fabs(fm)));
    }
    /* Every pair m <= q (the sums are symmetric: a record keeps one
     * triangle, an object's other one is checked equal to it), by chunks
     * of columns whose diagonals are formed once. */
    for (size_t q0 = 0; q0 < n && ok; q0 += MCS_CHECK_CHUNK_) {
        const size_t len = n - q0 < MCS_CHECK_CHUNK_ ? n - q0 : MCS_CHECK_CHUNK_;
        double root_q[MCS_CHECK_CHUNK_], c_q[MCS_CHECK_CHUNK_], bs_q[MCS_CHECK_CHUNK_];
        for (size_t j = 0; j < len; ++j) {
            const size_t q = q0 + j;
            root_q[j] = sqrt(MCS_AT_(s->sum_dd, q * n + q) + mcs_moment_batch_at_(s, q, q) + tiny);
            c_q[j] = MCS_AT_(s->shift, q);
            bs_q[j] = MCS_AT_(s->batch_s, q);
        }
        for (size_t m = 0; m < q0 + len; ++m) {
            const double cm = MCS_AT_(s->shift, m), bm = MCS_AT_(s->batch_s, m);
            const double root_m = (1.0 + 3.0 * g) *
                                  sqrt(MCS_AT_(s->sum_dd, m * n + m) + mcs_moment_batch_at_(s, m, m) + tiny);
            for (size_t j = m > q0 ? m - q0 : 0u; j < len; ++j) {
                const size_t q = q0 + j, i = m * n + q;
                const double v = MCS_AT_(s->sum_dd, i);
                const double w = MCS_AT_(s->batch_w, i), wt = MCS_AT_(s->batch_w, q * n + m);
                /* the batch's entry as mcs_moment_batch_at_ forms it */
                const double batch = (w + wt) - (bm * c_q[j] + cm * bs_q[j]) + sparse * (cm * c_q[j]);
                ok &= (fabs(w) <= MCS_MOMENT_LIMIT_W_) & (fabs(wt) <= MCS_MOMENT_LIMIT_W_) &
                      mcs_compensation_ok_(MCS_AT_(s->lo_dd, i), v) &
                      (fabs(v + batch) <= root_m * root_q[j]); /* NaN fails, and |v| <= 2^500 */
            }
        }
    }
    /* nothing in the second sums before two trials, none in an empty batch */
    for (size_t i = 0; i < n * n && (s->count < 2u || s->batch == 0u); ++i)
    {
        ok &= s->count >= 2u || MCS_AT_(s->sum_dd, i) == 0.0;
        ok &= s->batch != 0u || MCS_AT_(s->batch_w, i) == 0.0;
    }
    return ok;
}

/* An autocorrelation accumulator's count and arrays (autocorr.h), N = n. */
typedef struct {
    size_t n;
    uint64_t count;
    mcs_values_ sum_s, lo_s, sum_lag, lo_lag;
    double sum_dc, lo_dc;
} mcs_autocorr_sums_;

/* 1 when the sums are those of some trials: the count; every value finite
 * and at most 2^500; sum_s, sum_dc and the lag-0 sum >= 0 (sums of weights
 * and of squares); every compensation within an ulp of its sum; nothing
 * with no trials; and within the rounding of autocorr.h (gamma = (N + 8 +
 * T N^2 eps) eps of T <A(0)> = 2 L_0 for a lag sum L_e): |A(d)| <= A(0) for
 * every trial, so |L_e| <= 2 L_0 for 0 < e < N/2 and |L_{N/2}| <= L_0 (both
 * halved: autocorr.h); and with S_t a trial's total weight and sum_d A(d) =
 * S_t^2 (its centred lags sum to 0, its S^2/N goes to sum_dc), T sum_t
 * S_t^2 >= (sum_t S_t)^2 >= sum_t S_t^2 >= N sum_dc. */
static inline int mcs_autocorr_sums_ok_(const mcs_autocorr_sums_ *s)
{
    const size_t n = s->n, h = n / 2u;
    const double nd = (double)n, t = (double)s->count;
    const double gamma = ((nd + 8.0) + t * nd * nd * DBL_EPSILON) * DBL_EPSILON;
    const double l0 = MCS_AT_(s->sum_lag, 0u);
    const double tiny = 4.0 * t * nd * nd * DBL_TRUE_MIN;
    if (s->count > (uint64_t)MCS_MAX_COUNT || !(l0 >= 0.0 && l0 <= MCS_STORED_LIMIT_) ||
        !(s->sum_dc >= 0.0 && s->sum_dc <= MCS_STORED_LIMIT_) ||
        !mcs_compensation_ok_(s->lo_dc, s->sum_dc))
        return 0;
    int ok = s->count != 0u || s->sum_dc == 0.0;
    /* no early exit, and four partial sums (any order is within the rounding
     * allowed below): no chain of adds through the loops */
    double total[4] = {0.0, 0.0, 0.0, 0.0}, lag_sum[4] = {0.0, 0.0, 0.0, 0.0};
    for (size_t j = 0; j < n; ++j) {
        const double x = MCS_AT_(s->sum_s, j);
        ok &= (x >= 0.0) & (x <= MCS_STORED_LIMIT_) &
              mcs_compensation_ok_(MCS_AT_(s->lo_s, j), x) & (s->count != 0u || x == 0.0);
        total[j % 4u] += x;
    }
    const double grow = 1.0 + 4.0 * gamma + 8.0 * DBL_EPSILON;
    for (size_t e = 0; e <= h; ++e) {
        const double x = MCS_AT_(s->sum_lag, e);
        const double most = (e == 0u || 2u * e == n ? 1.0 : 2.0) * l0;
        ok &= (fabs(x) <= MCS_STORED_LIMIT_) & mcs_compensation_ok_(MCS_AT_(s->lo_lag, e), x) &
              (fabs(x) <= most * grow + tiny);
        lag_sum[e % 4u] += x;
    }
    /* every folded lag stands for two: d and N - d, or a halved one */
    const double sum_s = (total[0] + total[1]) + (total[2] + total[3]);
    const double lags = 2.0 * ((lag_sum[0] + lag_sum[1]) + (lag_sum[2] + lag_sum[3]));
    if (!ok)
        return 0;
    /* sum_t S_t^2 = sum_d <A(d)> T + N sum_dc, to the lags' rounding */
    const double squares = lags + nd * s->sum_dc;
    const double slack = (2.0 * nd * gamma + 2.0 * nd * nd * DBL_EPSILON) * l0 +
                         4.0 * DBL_EPSILON * nd * s->sum_dc + tiny;
    const double sq_total = sum_s * sum_s, rel = 2.0 * (nd + 4.0) * DBL_EPSILON;
    return (1.0 - rel) * sq_total <= t * (squares + slack) &&
           squares <= (1.0 + rel) * sq_total + 2.0 * slack &&
           nd * s->sum_dc <= (1.0 + rel) * sq_total + slack;
}

/* ---- Spectra the stored sums imply ----------------------------------------
 *
 * A power is a mean of |S_k|^2, so >= 0: its read-out refuses one below
 * minus its rounding bound (readout.c, autocorr.c). The checks above see one
 * bin or two; sums can pass them and still have a power below that (three
 * bins that are no covariance, lags that are no autocorrelation). The
 * loader computes every power once more, directly, and refuses a record
 * with one below a tighter threshold, so that whatever it loads reads out:
 * with E the direct sum's rounding and A what the stored sums may carry,
 * a valid object's direct power is >= -(A + E) (its exact one >= -A), and
 * a record passing that has exact powers >= -(A + 2E), which a read-out
 * with its own rounding E' computes >= -(A + 2E + E'), within the bound the
 * read-out refuses beyond. */

/* cos and sin of 2 pi j / n, j reduced mod n first (core/internal.h). */
static inline void mcs_twiddle_pair_(size_t j, size_t n, double *c, double *s)
{
    const size_t nn = n != 0u ? n : 1u; /* no object has N = 0; stated for the analyser */
    const double a = mcs_twiddle_angle_(j % nn, nn);
    *c = cos(a);
    *s = sin(a);
}

/* Entry (m, q) of the whole sums of d d^T (closed and open batch). */
static inline double mcs_moment_total_at_(const mcs_moment_sums_ *s, size_t m, size_t q)
{
    return MCS_AT_(s->sum_dd, m * s->n + q) + mcs_moment_batch_at_(s, m, q);
}

/* Entry m of the whole first sums. */
static inline double mcs_moment_first_at_(const mcs_moment_sums_ *s, size_t m)
{
    return MCS_AT_(s->sum_d, m) + mcs_moment_batch_at_(s, m, SIZE_MAX);
}

/* The rounding of a moment power read from the sums, R, in the units of the
 * power: (2N + 64) eps (1/N) sum |<D_mn>| for the transform of the second
 * sums and 4 (N + 32) eps (1/N) ((sum |<d>|)^2 + (sum c + sum |<d>|)^2) for
 * the squares of the transforms of the first sums and of <s> = c + <d>;
 * R bounds both the read-out's (readout.c) and the loader's direct sums.
 * *acc gets A = 3 gamma (sum sqrt(<D_m>))^2 / N, what the sums may carry;
 * *var (may be NULL) R_v, the same without <s> = c + <d>: the rounding of a
 * variance Cov(S_k, S_k), which the shift leaves out. */
static inline double mcs_moment_power_rounding_(const mcs_moment_sums_ *s, double *acc,
                                                double *var)
{
    const size_t n = s->n;
    const double nd = (double)n, t = (double)s->count;
    double second = 0.0, first = 0.0, shift = 0.0, root = 0.0;
    for (size_t m = 0; m < n; ++m) {
        const double dm = mcs_moment_total_at_(s, m, m) / t;
        root += sqrt(dm > 0.0 ? dm : 0.0);
        first += fabs(mcs_moment_first_at_(s, m)) / t;
        shift += fabs(MCS_AT_(s->shift, m));
        for (size_t q = 0; q < n; ++q)
            second += fabs(mcs_moment_total_at_(s, m, q)) / t;
    }
    *acc = 3.0 * MCS_MOMENT_ROUNDING_ * root * root / nd;
    if (var != NULL)
        *var = ((2.0 * nd + 64.0) * DBL_EPSILON * second +
                4.0 * (nd + 32.0) * DBL_EPSILON * first * first) /
               nd;
    return ((2.0 * nd + 64.0) * DBL_EPSILON * second +
            4.0 * (nd + 32.0) * DBL_EPSILON * (first * first + (shift + first) * (shift + first))) /
           nd;
}

/* What underflow adds to a moment power or variance whatever the sums'
 * scale (as mcs_autocorr_power_underflow_): near the smallest doubles each
 * operation errs by up to DBL_TRUE_MIN / 2 absolutely, and a read-out sums
 * about N^2 products, scaled by 1/N (fuzz_load: sums of a few DBL_TRUE_MIN
 * over 2^52 trials made every bound 0 and a variance of -4.9e-324 was
 * refused); the read-outs allow 64 (N^2 + 8) DBL_TRUE_MIN, the loader 16. */
static inline double mcs_moment_underflow_(size_t n, int load)
{
    return (load ? 16.0 : 64.0) * ((double)n * (double)n + 8.0) * DBL_TRUE_MIN;
}

/* Frequencies a power check forms at once: each value of the sums is read
 * once per this many (a record's values are decoded at every read). */
#define MCS_POWER_FREQS_ 8u

/* Twiddles by rotation for the frequencies k0 .. k0 + len - 1 of N: z_k =
 * e^{i 2 pi k j / N} stepped in j, set afresh from cos and sin every 16
 * steps, so each is within 40 eps (16 rotations of a few roundings). */
typedef struct {
    size_t k0, len, n;
    double wc[MCS_POWER_FREQS_], ws[MCS_POWER_FREQS_];
    double zc[MCS_POWER_FREQS_], zs[MCS_POWER_FREQS_];
} mcs_rotations_;

static inline void mcs_rotations_start_(mcs_rotations_ *r, size_t k0, size_t len, size_t n)
{
    r->k0 = k0;
    r->len = len;
    r->n = n;
    for (size_t f = 0; f < len; ++f) {
        mcs_twiddle_pair_(k0 + f, n, &r->wc[f], &r->ws[f]);
        r->zc[f] = 1.0;
        r->zs[f] = 0.0;
    }
}

/* From z at step j - 1 to step j. */
static inline void mcs_rotations_step_(mcs_rotations_ *r, size_t j)
{
    if (j % 16u == 0u) {
        for (size_t f = 0; f < r->len; ++f)
            mcs_twiddle_pair_((r->k0 + f) * j, r->n, &r->zc[f], &r->zs[f]);
        return;
    }
    for (size_t f = 0; f < r->len; ++f) {
        const double c = r->zc[f] * r->wc[f] - r->zs[f] * r->ws[f];
        r->zs[f] = r->zc[f] * r->ws[f] + r->zs[f] * r->wc[f];
        r->zc[f] = c;
    }
}

/* 1 when every power <|S_k|^2> of the sums, computed directly, is >= -(A +
 * 4 R) and every variance Cov(S_k, S_k) >= -(A + 4 R_v)
 * (mcs_moment_power_rounding_; the read-outs refuse below -(A + 8 R) and
 * -(A + 8 R_v)). O(N^3) (moment_check.c): for the loader and the record
 * writer. */
int mcs_moment_powers_ok(const mcs_moment_sums_ *s);

/* The autocorrelation's powers, in units of eps <A(0)> = eps 2 L_0 / T: the
 * read-out refuses one below -(2N + 16 log2 N + 192 + T N^2 eps) (autocorr.h:
 * the lags' T N^2 eps + N + 8, twice the direct sum's N/4 + 72, the FFT's
 * 4 log2 N + 8 or the direct path's N/2 + 1), the loader one whose direct
 * sum is below -(5N/4 + 80 + T N^2 eps). */
static inline double mcs_autocorr_power_gamma_(size_t n, uint64_t count, int load)
{
    const double nd = (double)n, t = (double)count;
    double log2n = 0.0;
    for (size_t m = 1u; m < n; m *= 2u)
        log2n += 1.0;
    const double lags = t * nd * nd * DBL_EPSILON;
    return (load ? 1.25 * nd + 80.0 + lags : 2.0 * nd + 16.0 * log2n + 192.0 + lags) *
           DBL_EPSILON;
}

/* What underflow adds to a power whatever its scale: near the smallest
 * doubles rounding is absolute, at most DBL_TRUE_MIN / 2 an operation, so a
 * transform of N lags and its scalings err by up to about (N + 8)
 * DBL_TRUE_MIN however small <A(0)> is (fuzz_load: lag sums of a few
 * DBL_TRUE_MIN over 4.8e15 trials made <A(0)> 0 and powers of
 * -4.9e-324); the read-out allows 64 times that, the loader 16 times. */
static inline double mcs_autocorr_power_underflow_(size_t n, int load)
{
    return (load ? 16.0 : 64.0) * ((double)n + 8.0) * DBL_TRUE_MIN;
}

/* 1 when every power of the lag sums, computed directly (k = 0..N/2; the
 * rest mirror them), is >= -(mcs_autocorr_power_gamma_(load) <A(0)> +
 * mcs_autocorr_power_underflow_(load)). O(N^2)
 * and O(1) memory (autocorr.c): for the loader and the record writer. */
int mcs_autocorr_powers_ok(const mcs_autocorr_sums_ *s);

/* The checks above on an object, with those of its own copy of the data
 * (moment: both triangles of its sums equal, its twiddle table that of its
 * N): 1 when valid. The sums' checks are those of the read-outs and merges,
 * the powers' those of the record writer (with the sums'). */
int mcs_moment_stored_valid(const mcs_moment *acc);
int mcs_moment_powers_valid(const mcs_moment *acc);
int mcs_autocorr_stored_valid(const mcs_autocorr *acc);
int mcs_autocorr_powers_valid(const mcs_autocorr *acc);

/* The checks every add shares once the object and the trial are valid: the
 * trial's total weight at most max_total (MAGNITUDE), the count (COUNT), and
 * the caller's arrays a and b (b_bytes 0 for none) outside the object
 * (ALIAS). */
static inline mcs_status mcs_check_add_(const void *obj, size_t obj_bytes, uint64_t count,
                                        double total, double max_total, const void *a,
                                        size_t a_bytes, const void *b, size_t b_bytes)
{
    if (!(total <= max_total))
        return MCS_ERR_MAGNITUDE;
    mcs_status st = mcs_check_count_(count, 1u);
    if (st == MCS_OK && (mcs_overlap_(a, a_bytes, obj, obj_bytes) ||
                         mcs_overlap_(b, b_bytes, obj, obj_bytes)))
        st = MCS_ERR_ALIAS;
    return st;
}

/* Bins and weights of a trial without a branch per sample: 0 for any bin
 * out of range or negative weight, else 1 and the weights' sum in *total
 * (NaN and infinities poison it, so the caller's bound on the sum refuses
 * them; four partial sums keep the adds apart). Only a trial that fails is
 * checked again sample by sample, for the status of its first bad sample. */
static inline int mcs_bins_scan_(size_t n, size_t k, const size_t *b, const double *w,
                                 double *total)
{
    size_t bad = 0u, j = 0;
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    for (; j + 4u <= k; j += 4u) {
        bad |= (size_t)(b[j] >= n) | (size_t)(b[j + 1u] >= n) | (size_t)(b[j + 2u] >= n) |
               (size_t)(b[j + 3u] >= n);
        bad |= (size_t)(w[j] < 0.0) | (size_t)(w[j + 1u] < 0.0) | (size_t)(w[j + 2u] < 0.0) |
               (size_t)(w[j + 3u] < 0.0);
        s0 += w[j];
        s1 += w[j + 1u];
        s2 += w[j + 2u];
        s3 += w[j + 3u];
    }
    for (; j < k; ++j) {
        bad |= (size_t)(b[j] >= n) | (size_t)(w[j] < 0.0);
        s0 += w[j];
    }
    *total = (s0 + s1) + (s2 + s3);
    return bad == 0u;
}

/* The same for a sparse trial on an object of N = n bins (checked already):
 * the trial as mcs_check_sparse_, then mcs_check_add_ with its weights'
 * sum. */
static inline mcs_status mcs_check_add_sparse_(const void *obj, size_t obj_bytes, size_t n,
                                               uint64_t count, size_t k, const size_t *bins,
                                               const double *weights, double max_total)
{
    /* The scan's sum differs from the one in sample order by rounding: a
     * trial within half the bound passes either way, any other is checked
     * sample by sample (so NaN, infinities and the bound's edge get the
     * statuses of that check). */
    double total;
    if (k == 0u || !mcs_bins_scan_(n, k, bins, weights, &total) || !(total <= 0.5 * max_total)) {
        mcs_status st = mcs_check_sparse_(n, k, bins, weights);
        if (st != MCS_OK)
            return st;
        total = mcs_weights_total_(k, weights);
    }
    return mcs_check_add_(obj, obj_bytes, count, total, max_total, bins,
                          mcs_bytes_(k, sizeof *bins), weights, mcs_bytes_(k, sizeof *weights));
}

/* The status of a call on two objects (merge) from each one's own check:
 * MCS_ERR_NULL first, as if both had been checked for NULL before anything
 * else, then the first object's status, then the second's. */
static inline mcs_status mcs_check_pair_(mcs_status a, mcs_status b)
{
    if (a == MCS_ERR_NULL || b == MCS_ERR_NULL)
        return MCS_ERR_NULL;
    return a != MCS_OK ? a : b;
}

/* The checks of merging src into dst once both objects passed their own
 * (mcs_check_pair_): MISMATCH unless same_shape, COUNT if the counts would
 * add up past MCS_MAX_COUNT, ALIAS for distinct objects that overlap
 * (dst == src is allowed: it doubles). */
static inline mcs_status mcs_check_merge_(const void *dst, const void *src, size_t bytes,
                                          int same_shape, uint64_t dst_count, uint64_t src_count)
{
    if (!same_shape)
        return MCS_ERR_MISMATCH;
    mcs_status st = mcs_check_count_(dst_count, src_count);
    if (st == MCS_OK && dst != src && mcs_overlap_(dst, bytes, src, bytes))
        st = MCS_ERR_ALIAS;
    return st;
}

/* Adds the compensated sum (src_sum, src_lo), whose total is
 * src_sum - src_lo, to (*sum, *lo). The caller reads both src values before
 * either destination is written, so a merge into itself doubles. */
static inline void mcs_kahan_merge_(double *sum, double *lo, double src_sum, double src_lo)
{
    mcs_kahan_add_(sum, lo, src_sum);
    mcs_kahan_add_(sum, lo, -src_lo);
}

#endif /* MCSPEC_ACC_INTERNAL_H */
