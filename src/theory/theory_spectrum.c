/* Exact spectra and estimator moments at any N with O(N) memory (see
 * include/mcspec/theory.h, "Exact spectra at any N"); the covariances are in
 * src/theory/theory_cov.c. */
#include "theory_internal.h"
#include "accumulators/readout.h"

#include <float.h>

/* ---- set-up ---------------------------------------------------------------- */

/* The bins as mcs_theory sees them (the same inline arithmetic), and <s_n> as
 * mcs_theory_init forms it: K L_n / p_n, the uniform pattern's counts over
 * p_n, the homogenized mean of the stratified ones. */
static void fill_bins(mcs_theory_spectrum *ts, const mcs_pattern *pat)
{
    const size_t n = pat->n;
    for (size_t b = 0; b <= n; ++b) {
        ts->edge[b] = mcs_theory_edge_(pat, b);
        ts->edge_lo[b] = mcs_theory_edge_lo_(pat, b);
    }
    for (size_t b = 0; b < n; ++b) {
        ts->length[b] = mcs_theory_length_(pat, b);
        ts->inv_p[b] = mcs_theory_inv_p_(pat, b);
        ts->mean_s[b] = (double)pat->k * ts->length[b] * ts->inv_p[b];
    }
    if (pat->kind == MCS_PATTERN_UNIFORM) {
        mcs_theory_uniform_counts_(pat, ts->mean_s);
        for (size_t b = 0; b < n; ++b)
            ts->mean_s[b] *= ts->inv_p[b];
    } else if (pat->kind == MCS_PATTERN_HOMOGENIZED) {
        double mean = 0.0;
        for (size_t b = 0; b < n; ++b)
            mean += ts->mean_s[b];
        mean /= (double)n;
        for (size_t b = 0; b < n; ++b)
            ts->mean_s[b] = mean;
    }
}

mcs_status mcs_theory_spectrum_init(mcs_theory_spectrum *ts, const mcs_pattern *pat)
{
    if (ts == NULL || pat == NULL)
        return MCS_ERR_NULL;
    mcs_status st = mcs_theory_check_pattern_(pat, (size_t)MCS_MAX_N);
    if (st != MCS_OK)
        return st;
    ts->kind = pat->kind;
    ts->k = pat->k;
    ts->has_importance = pat->importance != NULL;
    fill_bins(ts, pat);
    mcs_twiddles_(pat->n, ts->cos_table, ts->sin_table);
    ts->n = pat->n;
    if (pat->kind == MCS_PATTERN_JITTER && pat->n >= 2u)
        mcs_theory_sort_breakpoints_(ts);
    return MCS_OK;
}

/* ---- checks ---------------------------------------------------------------- */

/* Bounds every body mcs_theory_spectrum_init writes keeps: 1/p_b <= 2^32
 * (p_b >= N g_b with g_b >= MCS_IMPORTANCE_MIN_G = 2^-32 but for the 2^-53
 * rounding of the CDF), |<s_b>| <= K max 1/p_b < 2^63. */
#define MAX_INV_P 0x1p33
#define MAX_MEAN_S 0x1p64

static int in_range(double x, double lo, double hi)
{
    return x >= lo && x <= hi; /* NaN is in no range */
}

/* The body as mcs_theory_spectrum_init writes it: edges rising from 0 to K,
 * lengths in [0, 1], weights 1/p_b in (0, 2^33] (0 for a bin of length 0:
 * outside the support), means and twiddles
 * bounded. Then every covariance term is a weight >= 0 times a squared
 * deviation (the strata overlaps are >= 0 because the edges rise), so
 * variances and powers are sums of non-negative finite terms: >= 0 with no
 * rounding to clamp, and finite. O(N): checked where N results are written
 * (mcs_theory_power_spectrum); a single read-out checks its result instead
 * (set_real, set_complex), which costs nothing beside its O(N) sums. */
static int body_is_sound(const mcs_theory_spectrum *ts)
{
    const size_t n = ts->n;
    int sound = ts->edge[0] == 0.0 && ts->edge[n] == (double)ts->k;
    for (size_t b = 0; b <= n; ++b) /* an edge's rounding: at most half its ulp */
        sound &= fabs(ts->edge_lo[b]) <= 0x1p-52 * fabs(ts->edge[b]);
    for (size_t b = 0; b < n; ++b) {
        sound &= ts->edge[b] <= ts->edge[b + 1u];
        sound &= in_range(ts->length[b], 0.0, 1.0);
        /* 0 only outside the support, where no sample lands (length 0) */
        sound &= in_range(ts->inv_p[b], DBL_MIN, MAX_INV_P) |
                 (ts->inv_p[b] == 0.0 && ts->length[b] == 0.0);
        sound &= in_range(ts->mean_s[b], -MAX_MEAN_S, MAX_MEAN_S);
        sound &= in_range(ts->cos_table[b], -1.0, 1.0) & in_range(ts->sin_table[b], -1.0, 1.0);
    }
    return sound;
}

/* Jitter's breakpoints index the edges: each in [1, N), or a read would
 * leave the object (a corrupted entry read far outside it). */
static int order_is_sound(const mcs_theory_spectrum *ts)
{
    int sound = 1;
    for (size_t i = 0; ts->kind == MCS_PATTERN_JITTER && i + 1u < ts->n; ++i)
        sound &= ts->order[i] - 1u < ts->n - 1u; /* 1 <= order < N, one unsigned compare */
    return sound;
}

/* The edges rise from 0 to K: the strata overlaps and jitter pieces are
 * read from them (a bin inside a stratum by its length, so edges out of
 * order would not show as a negative overlap). O(N). */
static int edges_are_sound(const mcs_theory_spectrum *ts)
{
    int sound = ts->edge[0] == 0.0 && ts->edge[ts->n] == (double)ts->k;
    for (size_t b = 0; b < ts->n; ++b)
        sound &= ts->edge[b] <= ts->edge[b + 1u];
    return sound;
}

/* Outputs given (else NULL), ts set up (else UNINIT), its indices inside
 * the object and its edges in order (else INVARIANT: a corrupted object,
 * refused before a read). */
static mcs_status check_ts(int outputs, const mcs_theory_spectrum *ts)
{
    if (!outputs || ts == NULL)
        return MCS_ERR_NULL;
    if (ts->n == 0u || ts->n > (size_t)MCS_MAX_N || ts->k == 0u || !mcs_kind_is_valid_(ts->kind))
        return MCS_ERR_UNINIT;
    return order_is_sound(ts) && edges_are_sound(ts) ? MCS_OK : MCS_ERR_INVARIANT;
}

/* check_ts, then frequencies below N (else FREQ_RANGE). */
static mcs_status check_freqs(int outputs, const mcs_theory_spectrum *ts, size_t freq_k,
                              size_t freq_l)
{
    mcs_status st = check_ts(outputs, ts);
    if (st == MCS_OK && (freq_k >= ts->n || freq_l >= ts->n))
        st = MCS_ERR_FREQ_RANGE;
    return st;
}

/* check_freqs for a complex output: re and im given and two different
 * doubles (one double cannot hold both parts: ALIAS). */
static mcs_status check_complex(const mcs_theory_spectrum *ts, size_t freq_k, size_t freq_l,
                                const double *re, const double *im)
{
    mcs_status st = check_freqs(re != NULL && im != NULL, ts, freq_k, freq_l);
    if (st == MCS_OK && mcs_overlap_(re, sizeof *re, im, sizeof *im))
        st = MCS_ERR_ALIAS;
    return st;
}

/* Writes a complex result computed into locals: last, so re and im may lie
 * anywhere (but on each other), even in the object just read. A result
 * that is not finite, or a negative variance or power (real: nonneg), comes
 * only from a body init does not write (see body_is_sound): INVARIANT, and
 * nothing is written. */
static mcs_status set_complex(double *re, double *im, double r, double i, int nonneg)
{
    if (!(isfinite(r) && isfinite(i)) || (nonneg && !(r >= 0.0)))
        return MCS_ERR_INVARIANT;
    *re = r;
    *im = i;
    return MCS_OK;
}

/* A real result, checked as set_complex. */
static mcs_status set_real(double *out, double v, int nonneg)
{
    double zero = 0.0;
    return set_complex(out, &zero, v, 0.0, nonneg);
}

/* check_ts, then n (MISMATCH), k (K_RANGE, MISMATCH), f and g finite
 * (NOT_FINITE) and within MCS_ESTIMATE_MAX_ABS (MAGNITUDE); g may be NULL
 * when not wanted. */
static mcs_status check_integrands(int outputs, const mcs_theory_spectrum *ts, size_t n,
                                   size_t k, const double *f, const double *g)
{
    mcs_status st = check_ts(outputs && f != NULL, ts);
    if (st != MCS_OK)
        return st;
    if (n != ts->n)
        return MCS_ERR_MISMATCH;
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    if (k != ts->k)
        return MCS_ERR_MISMATCH;
    st = mcs_check_integrand_(n, f);
    return st == MCS_OK && g != NULL ? mcs_check_integrand_(n, g) : st;
}

/* ---- spectra ---------------------------------------------------------------- */

/* Eq. 15 from <s> with the object's twiddles: the read-out shared with the
 * N x N moments, so both give <S_k> to the last bit. */
static mcs_theory_zeros zeros_of(const mcs_theory_spectrum *ts)
{
    return mcs_theory_zeros_of_(ts->kind, ts->n, ts->k, ts->has_importance, ts->mean_s);
}

/* Eq. 15 from <s>, with the zeros theory proves (theory_internal.h). */
static void mean_at(const mcs_theory_spectrum *ts, size_t freq, double *re, double *im)
{
    const mcs_readout view = {.n = ts->n,
                              .k = ts->k,
                              .scale = 1.0,
                              .first = ts->mean_s,
                              .cos_table = ts->cos_table,
                              .sin_table = ts->sin_table};
    const mcs_theory_zeros z = zeros_of(ts);
    mcs_readout_dft(&view, ts->mean_s, freq, re, im);
    if (mcs_theory_mean_zero_(&z, freq))
        *re = *im = 0.0;
    if (mcs_theory_real_freq_(&z, freq))
        *im = 0.0;
}

/* Cov(S_k, S_l). The homogenized covariance is circulant (a function of the
 * lag only), so its transform is diagonal; there the variance is the
 * stratified one, since a shift changes S_k by a phase only. */
static void covariance_at(const mcs_theory_spectrum *ts, size_t freq_k, size_t freq_l,
                          double *re, double *im)
{
    const double scale = 1.0 / sqrt((double)ts->n);
    const mcs_theory_weight x = {NULL, freq_k, scale, 0u}, y = {NULL, freq_l, scale, 0u};
    const mcs_theory_weight *yp = freq_k == freq_l ? &x : &y; /* the same: a variance */
    if (ts->kind == MCS_PATTERN_HOMOGENIZED) {
        *re = *im = 0.0;
        if (freq_k == freq_l)
            mcs_theory_strat_cov_(ts, &x, yp, re, im);
    } else {
        mcs_theory_cov_(ts, &x, yp, re, im);
    }
    const mcs_theory_zeros z = zeros_of(ts);
    if (mcs_theory_cov_zero_(&z, freq_k, freq_l))
        *re = *im = 0.0;
    if (mcs_theory_im_zero_(&z, freq_k, freq_l))
        *im = 0.0; /* a variance, or two real S: real (the parts cancel to rounding) */
}

static double power_at(const mcs_theory_spectrum *ts, size_t freq)
{
    double var, zero, mr, mi;
    covariance_at(ts, freq, freq, &var, &zero);
    mean_at(ts, freq, &mr, &mi);
    return var + (mr * mr + mi * mi);
}

mcs_status mcs_theory_spectrum_mean(const mcs_theory_spectrum *ts, size_t freq, double *re,
                                    double *im)
{
    mcs_status st = check_complex(ts, freq, freq, re, im);
    if (st != MCS_OK)
        return st;
    double r, i;
    mean_at(ts, freq, &r, &i);
    return set_complex(re, im, r, i, 0);
}

mcs_status mcs_theory_spectrum_power(const mcs_theory_spectrum *ts, size_t freq, double *out)
{
    mcs_status st = check_freqs(out != NULL, ts, freq, freq);
    return st == MCS_OK ? set_real(out, power_at(ts, freq), 1) : st;
}

mcs_status mcs_theory_power_spectrum(const mcs_theory_spectrum *ts, size_t n, double *power)
{
    mcs_status st = check_ts(power != NULL, ts);
    if (st == MCS_OK && n != ts->n)
        st = MCS_ERR_MISMATCH;
    if (st == MCS_OK && !body_is_sound(ts))
        st = MCS_ERR_INVARIANT; /* N results: the body, before any is written */
    if (st != MCS_OK)
        return st;
    for (size_t q = 0; q < n; ++q)
        power[q] = power_at(ts, q);
    return MCS_OK;
}

mcs_status mcs_theory_spectrum_covariance(const mcs_theory_spectrum *ts, size_t freq_k,
                                          size_t freq_l, double *re, double *im)
{
    mcs_status st = check_complex(ts, freq_k, freq_l, re, im);
    if (st != MCS_OK)
        return st;
    double r, i;
    covariance_at(ts, freq_k, freq_l, &r, &i);
    return set_complex(re, im, r, i, freq_k == freq_l);
}

mcs_status mcs_theory_spectrum_cross(const mcs_theory_spectrum *ts, size_t freq_k,
                                     size_t freq_l, double *re, double *im)
{
    mcs_status st = check_complex(ts, freq_k, freq_l, re, im);
    if (st != MCS_OK)
        return st;
    if (freq_k == freq_l) /* <|S_k|^2>: the power read-out itself, real */
        return set_complex(re, im, power_at(ts, freq_k), 0.0, 1);
    double cr, ci, kr, ki, lr, li;
    covariance_at(ts, freq_k, freq_l, &cr, &ci);
    mean_at(ts, freq_k, &kr, &ki);
    mean_at(ts, freq_l, &lr, &li);
    /* + <S_k><S_l>* = (kr + i ki)(lr - i li); the zeros exactly (above) */
    const mcs_theory_zeros z = zeros_of(ts);
    double r = cr + (kr * lr + ki * li), i = ci + (ki * lr - kr * li);
    if (mcs_theory_cross_zero_(&z, freq_k, freq_l))
        r = i = 0.0;
    if (mcs_theory_im_zero_(&z, freq_k, freq_l))
        i = 0.0;
    return set_complex(re, im, r, i, 0);
}

/* Every stored frequency at once: the per-frequency values (mean_at,
 * covariance_at, power_at: the same bits), for a body checked once
 * (body_is_sound: every value is then finite and no variance or power
 * negative, so nothing needs checking per value before the writes). */
mcs_status mcs_theory_spectrum_read_all(const mcs_theory_spectrum *ts, size_t n_out,
                                        double *mean_re, double *mean_im, double *variance,
                                        double *power)
{
    double *const out[4] = {mean_re, mean_im, variance, power};
    int any = 0;
    for (int a = 0; a < 4; ++a)
        any |= out[a] != NULL;
    mcs_status st = check_ts(any, ts);
    if (st != MCS_OK)
        return st;
    if (n_out != ts->n / 2u + 1u)
        return MCS_ERR_MISMATCH;
    const size_t bytes = mcs_bytes_(n_out, sizeof(double));
    for (int a = 0; a < 4; ++a)
        for (int b = a; b < 4; ++b)
            if (out[a] != NULL &&
                (b == a ? mcs_overlap_(out[a], bytes, ts, sizeof *ts)
                        : out[b] != NULL && mcs_overlap_(out[a], bytes, out[b], bytes)))
                return MCS_ERR_ALIAS;
    if (!body_is_sound(ts))
        return MCS_ERR_INVARIANT;
    for (size_t q = 0; q < n_out; ++q) {
        if (mean_re != NULL || mean_im != NULL) {
            double r, i;
            mean_at(ts, q, &r, &i);
            if (mean_re != NULL)
                mean_re[q] = r;
            if (mean_im != NULL)
                mean_im[q] = i;
        }
        if (variance != NULL) {
            double zero;
            covariance_at(ts, q, q, &variance[q], &zero);
        }
        if (power != NULL)
            power[q] = power_at(ts, q);
    }
    return MCS_OK;
}

/* ---- the estimator ---------------------------------------------------------- */

mcs_status mcs_theory_spectrum_estimator_mean(const mcs_theory_spectrum *ts, size_t n,
                                              size_t k, const double *f, double *out)
{
    mcs_status st = check_integrands(out != NULL, ts, n, k, f, NULL);
    if (st != MCS_OK)
        return st;
    double sum = 0.0;
    for (size_t b = 0; b < n; ++b)
        sum += f[b] * ts->mean_s[b];
    return set_real(out, sum / (double)k, 0);
}

mcs_status mcs_theory_spectrum_bias(const mcs_theory_spectrum *ts, size_t n, size_t k,
                                    const double *f, double *out)
{
    mcs_status st = check_integrands(out != NULL, ts, n, k, f, NULL);
    return st == MCS_OK ? set_real(out, mcs_theory_bias_of_(ts->kind, n, k, ts->mean_s, f), 0)
                        : st;
}

/* (1/K^2) Cov(sum f s, sum g s): I = (1/K) sum f s; 0 where theory says so. */
static double estimator_cov(const mcs_theory_spectrum *ts, const double *f, const double *g)
{
    const mcs_theory_zeros z = zeros_of(ts);
    if (mcs_theory_estimator_zero_(&z, ts->n, f, g))
        return 0.0;
    const mcs_theory_weight x = {f, 0u, 1.0, 0u}, y = {g, 0u, 1.0, 0u};
    double re, im;
    mcs_theory_cov_(ts, &x, f == g ? &x : &y, &re, &im);
    const double kd = (double)ts->k;
    return re / (kd * kd);
}

mcs_status mcs_theory_spectrum_variance(const mcs_theory_spectrum *ts, size_t n, size_t k,
                                        const double *f, double *out)
{
    mcs_status st = check_integrands(out != NULL, ts, n, k, f, NULL);
    return st == MCS_OK ? set_real(out, estimator_cov(ts, f, f), 1) : st;
}

mcs_status mcs_theory_spectrum_estimator_covariance(const mcs_theory_spectrum *ts, size_t n,
                                                    size_t k, const double *f, const double *g,
                                                    double *out)
{
    mcs_status st = check_integrands(out != NULL && g != NULL, ts, n, k, f, g);
    return st == MCS_OK ? set_real(out, estimator_cov(ts, f, g), 0) : st;
}
