/* Exact discrete moments of every pattern kind, and the note's closed forms.
 * See include/mcspec/theory.h for the model; DESIGN.md for the formulas. */
#include "mcspec/theory.h"

#include <math.h>

#define MCS_PI 3.14159265358979323846

/* H comes from a computed harmonic mean whose exact value is <= 1; allow
 * rounding above 1 but reject anything that is not a harmonic mean of p. */
#define MCS_H_SLACK 1e-9

/* ---- shared validation --------------------------------------------------- */

static int kind_is_valid(mcs_pattern_kind kind)
{
    return kind == MCS_PATTERN_RANDOM || kind == MCS_PATTERN_STRATIFIED ||
           kind == MCS_PATTERN_HOMOGENIZED || kind == MCS_PATTERN_UNIFORM ||
           kind == MCS_PATTERN_JITTER;
}

static int theory_is_valid(const mcs_theory *th)
{
    return th->n >= 1u && th->n <= (size_t)MCS_MAX_COV_N && th->k >= 1u &&
           kind_is_valid(th->kind);
}

static int all_finite(size_t n, const double *x)
{
    for (size_t i = 0; i < n; ++i)
        if (!isfinite(x[i]))
            return 0;
    return 1;
}

/* Checks shared by every read-out that takes a per-bin array of th->n. */
static mcs_status check_theory_array(const mcs_theory *th, size_t n, const double *f)
{
    if (!theory_is_valid(th))
        return MCS_ERR_UNINIT;
    if (n != th->n)
        return MCS_ERR_MISMATCH;
    if (!all_finite(n, f))
        return MCS_ERR_NOT_FINITE;
    return MCS_OK;
}

/* imp NULL is "no importance function": the importance formulas are not
 * defined there (the note reduces them to section 3 by p = 1 instead). */
static mcs_status check_importance(const mcs_importance *imp)
{
    if (imp == NULL)
        return MCS_ERR_DOMAIN;
    if (imp->n == 0u || imp->n > (size_t)MCS_MAX_N)
        return MCS_ERR_UNINIT;
    return MCS_OK;
}

static mcs_status check_h(double h)
{
    if (!isfinite(h))
        return MCS_ERR_NOT_FINITE;
    if (!(h > 0.0 && h <= 1.0 + MCS_H_SLACK))
        return MCS_ERR_DOMAIN;
    return MCS_OK;
}

static mcs_status check_n_k(size_t n, size_t cap, size_t k)
{
    if (n == 0u || n > cap)
        return MCS_ERR_N_RANGE;
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    return MCS_OK;
}

/* ---- small direct DFTs (no dft module needed) ------------------------------
 * No work arrays: every frame stays small (the library's stack check allows
 * 1 KiB per frame), so transforms are taken one coefficient at a time. */

/* cos, sin of 2 pi t / n for t in [0, n): exact index reduction keeps every
 * twiddle within an ulp, whatever k * n is. */
static void twiddles(size_t n, double *c, double *s)
{
    for (size_t t = 0; t < n; ++t) {
        double a = 2.0 * MCS_PI * (double)t / (double)n;
        c[t] = cos(a);
        s[t] = sin(a);
    }
}

/* Eq. 7 at one frequency: X_k = N^{-1/2} sum_t e^{-2 pi i k t / N} x_t, with
 * the twiddle computed per term from the reduced index (k t mod N). */
static void dft_coefficient(size_t n, const double *x, size_t k, double *re, double *im)
{
    double r = 0.0, i = 0.0;
    for (size_t t = 0; t < n; ++t) {
        double a = 2.0 * MCS_PI * (double)((k * t) % n) / (double)n;
        r += cos(a) * x[t];
        i -= sin(a) * x[t];
    }
    double scale = 1.0 / sqrt((double)n);
    *re = r * scale;
    *im = i * scale;
}

/* ---- exact moments -------------------------------------------------------- */

/* Samples of a shared beta in [0,1) that put j + beta in [a, b), summed over
 * j: r(beta) = ceil(b - beta) - ceil(a - beta) (t = u K units). */
static double jitter_count(double a, double b, double beta)
{
    return ceil(b - beta) - ceil(a - beta);
}

static double frac_part(double x)
{
    double f = x - floor(x);
    return f < 1.0 ? f : 0.0;
}

/* <r_m r_n> for jitter: the integral over beta in [0,1) of r_m(beta) r_n(beta).
 * Each r is constant between the fractional parts of its two edges, so the
 * integral is exact as a sum over the (at most 5) pieces. */
static double jitter_pair(double am, double bm, double an, double bn)
{
    double pts[6] = {0.0, frac_part(am), frac_part(bm), frac_part(an), frac_part(bn), 1.0};
    for (int i = 1; i < 5; ++i) /* insertion sort of the four inner points */
        for (int j = i; j > 0 && pts[j] < pts[j - 1]; --j) {
            double t = pts[j];
            pts[j] = pts[j - 1];
            pts[j - 1] = t;
        }
    double sum = 0.0;
    for (int i = 0; i < 5; ++i) {
        double w = pts[i + 1] - pts[i];
        if (w > 0.0) {
            double mid = pts[i] + 0.5 * w;
            sum += jitter_count(am, bm, mid) * jitter_count(an, bn, mid) * w;
        }
    }
    return sum;
}

/* |[a, b) intersect [j, j + 1)| in t units: P(u_j in the bin) for stratum j. */
static double stratum_overlap(double a, double b, double j)
{
    double lo = a > j ? a : j;
    double hi = b < j + 1.0 ? b : j + 1.0;
    return hi > lo ? hi - lo : 0.0;
}

/* sum_j P(u_j in I_m) P(u_j in I_n) over strata j: the same-stratum pairs that
 * independent sampling would count but stratification forbids. Strata meeting
 * both bins run from j_lo to j_hi; the inner ones lie inside both bins (only
 * possible for m = n) and contribute 1 each, so the cost is O(1) for any K. */
static double strat_pair(double am, double bm, double an, double bn)
{
    if (!(bm > am) || !(bn > an))
        return 0.0;
    double j_lo = fmax(floor(am), floor(an));
    double j_hi = fmin(ceil(bm), ceil(bn)) - 1.0;
    if (j_hi < j_lo)
        return 0.0;
    double sum = stratum_overlap(am, bm, j_lo) * stratum_overlap(an, bn, j_lo);
    if (j_hi > j_lo)
        sum += stratum_overlap(am, bm, j_hi) * stratum_overlap(an, bn, j_hi) +
               (j_hi - j_lo - 1.0);
    return sum;
}

/* Bin of the uniform pattern's u_j = (j + 1/2)/K, by the generator's own
 * arithmetic (src/pattern.c: stratum_point, then place), so a u_j on a bin
 * edge lands in the same bin. Without importance that is the exact
 * floor((2j + 1) N / (2K)); with importance it is the CDF search of the
 * correctly rounded u_j. */
static size_t uniform_bin(const mcs_pattern *pat, size_t j)
{
    if (pat->importance != NULL) {
        double u = ((double)j + 0.5) / (double)pat->k;
        if (!(u < 1.0))
            u = nextafter(1.0, 0.0);
        size_t bin = 0;
        (void)mcs_importance_warp(pat->importance, u, NULL, &bin);
        return bin;
    }
    size_t b = (size_t)(((double)j + 0.5) * (double)pat->n / (double)pat->k);
    return b < pat->n ? b : pat->n - 1u;
}

/* Homogenized: the generator shifts the stratified bins by d uniform in [0, N),
 * so <s_m s_n> = (1/N) sum_d strat<s_{m-d} s_{n-d}>, a function of n - m only. */
static void homogenize(mcs_theory *th)
{
    size_t n = th->n;
    double mean = 0.0;
    for (size_t d = 0; d < n; ++d)
        mean += th->mean_s[d];
    mean /= (double)n;
    /* The lag averages go through mean_s as scratch (no stack array), then
     * fill every row; mean_s gets the (constant) homogenized mean last. */
    for (size_t d = 0; d < n; ++d) {
        double acc = 0.0;
        for (size_t a = 0; a < n; ++a)
            acc += th->second[a * n + (a + d) % n];
        th->mean_s[d] = acc / (double)n;
    }
    for (size_t m = 0; m < n; ++m)
        for (size_t b = 0; b < n; ++b)
            th->second[m * n + b] = th->mean_s[(b + n - m) % n];
    for (size_t m = 0; m < n; ++m)
        th->mean_s[m] = mean;
}

/* Bin b of the pattern is [edge(b), edge(b + 1)) in t = u K units (its CDF
 * interval with importance, [b/N, (b+1)/N) without); its length in u is the
 * probability one uniform u lands in it; 1/p_b its weight. */
static double bin_edge(const mcs_pattern *pat, size_t b)
{
    double kd = (double)pat->k;
    if (pat->importance != NULL)
        return pat->importance->cdf[b] * kd;
    return ((double)b * kd) / (double)pat->n; /* exact product, one rounding */
}

static double bin_length(const mcs_pattern *pat, size_t b)
{
    if (pat->importance != NULL)
        return pat->importance->cdf[b + 1u] - pat->importance->cdf[b];
    return 1.0 / (double)pat->n;
}

static double bin_inv_p(const mcs_pattern *pat, size_t b)
{
    return pat->importance != NULL ? 1.0 / pat->importance->p[b] : 1.0;
}

static mcs_status check_pattern(const mcs_pattern *pat)
{
    if (pat->n == 0u || pat->k == 0u || !kind_is_valid(pat->kind))
        return MCS_ERR_UNINIT;
    if (pat->n > (size_t)MCS_MAX_COV_N)
        return MCS_ERR_N_RANGE;
    if (pat->importance != NULL) {
        if (pat->kind == MCS_PATTERN_HOMOGENIZED)
            return MCS_ERR_KIND;
        if (pat->importance->n != pat->n)
            return MCS_ERR_UNINIT;
    }
    return MCS_OK;
}

mcs_status mcs_theory_init(mcs_theory *th, const mcs_pattern *pat)
{
    if (th == NULL || pat == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_pattern(pat);
    if (st != MCS_OK)
        return st;

    const size_t n = pat->n;
    const double kd = (double)pat->k;
    th->kind = pat->kind;
    th->n = n;
    th->k = pat->k;
    th->has_importance = pat->importance != NULL;
    twiddles(n, th->cos_table, th->sin_table);

    if (pat->kind == MCS_PATTERN_UNIFORM) {
        /* mean_s holds the bin counts r_n until the weights are applied */
        for (size_t b = 0; b < n; ++b)
            th->mean_s[b] = 0.0;
        for (size_t j = 0; j < pat->k; ++j)
            th->mean_s[uniform_bin(pat, j)] += 1.0;
        for (size_t m = 0; m < n; ++m)
            th->mean_s[m] *= bin_inv_p(pat, m);
        for (size_t m = 0; m < n; ++m)
            for (size_t b = 0; b < n; ++b)
                th->second[m * n + b] = th->mean_s[m] * th->mean_s[b];
        return MCS_OK;
    }

    for (size_t m = 0; m < n; ++m) {
        double len_m = bin_length(pat, m), inv_pm = bin_inv_p(pat, m);
        double am = bin_edge(pat, m), bm = bin_edge(pat, m + 1u);
        /* sum_j P(u_j in I_m) = K |I_m| for random, stratified and jitter alike. */
        th->mean_s[m] = kd * len_m * inv_pm;
        for (size_t b = 0; b < n; ++b) {
            double len_b = bin_length(pat, b);
            double diag = m == b ? kd * len_m : 0.0; /* j = j': P(u_j in I_m cap I_n) */
            double rr;
            switch (pat->kind) {
            case MCS_PATTERN_RANDOM: /* j != j' independent: K (K - 1) |I_m| |I_n| */
                rr = diag + kd * (kd - 1.0) * len_m * len_b;
                break;
            case MCS_PATTERN_JITTER: /* one shared beta: exact integral */
                rr = jitter_pair(am, bm, bin_edge(pat, b), bin_edge(pat, b + 1u));
                break;
            default: /* stratified, homogenized: independent across strata only */
                rr = diag + kd * kd * len_m * len_b -
                     strat_pair(am, bm, bin_edge(pat, b), bin_edge(pat, b + 1u));
                break;
            }
            th->second[m * n + b] = rr * inv_pm * bin_inv_p(pat, b);
        }
    }
    if (pat->kind == MCS_PATTERN_HOMOGENIZED)
        homogenize(th);
    return MCS_OK;
}

/* ---- read-outs ------------------------------------------------------------ */

mcs_status mcs_theory_mean_s(const mcs_theory *th, size_t bin, double *out)
{
    if (th == NULL || out == NULL)
        return MCS_ERR_NULL;
    if (!theory_is_valid(th))
        return MCS_ERR_UNINIT;
    if (bin >= th->n)
        return MCS_ERR_BIN_RANGE;
    *out = th->mean_s[bin];
    return MCS_OK;
}

mcs_status mcs_theory_second(const mcs_theory *th, size_t m, size_t n, double *out)
{
    if (th == NULL || out == NULL)
        return MCS_ERR_NULL;
    if (!theory_is_valid(th))
        return MCS_ERR_UNINIT;
    if (m >= th->n || n >= th->n)
        return MCS_ERR_BIN_RANGE;
    *out = th->second[m * th->n + n];
    return MCS_OK;
}

/* Eq. 7 at one frequency from the theory's twiddle table; the index k t mod N
 * is stepped, not divided (k < N). */
static void table_dft(const mcs_theory *th, const double *x, size_t freq, double *re,
                      double *im)
{
    size_t n = th->n, idx = 0;
    double r = 0.0, i = 0.0;
    for (size_t t = 0; t < n; ++t) {
        r += th->cos_table[idx] * x[t];
        i -= th->sin_table[idx] * x[t];
        idx += freq;
        if (idx >= n)
            idx -= n;
    }
    double scale = 1.0 / sqrt((double)n);
    *re = r * scale;
    *im = i * scale;
}

static void spectrum_mean(const mcs_theory *th, size_t freq, double *re, double *im)
{
    table_dft(th, th->mean_s, freq, re, im);
}

/* Eq. 16, separably: inner sum over n with e^{+2 pi i l n/N}, outer over m
 * with e^{-2 pi i k m/N}. O(N^2). */
static void cross(const mcs_theory *th, size_t fk, size_t fl, double *re, double *im)
{
    size_t n = th->n, idx_m = 0;
    double r = 0.0, i = 0.0;
    for (size_t m = 0; m < n; ++m) {
        const double *row = &th->second[m * n];
        double rr = 0.0, ri = 0.0;
        size_t idx = 0;
        for (size_t b = 0; b < n; ++b) {
            rr += th->cos_table[idx] * row[b];
            ri += th->sin_table[idx] * row[b];
            idx += fl;
            if (idx >= n)
                idx -= n;
        }
        double c = th->cos_table[idx_m], s = th->sin_table[idx_m];
        r += c * rr + s * ri;
        i += c * ri - s * rr;
        idx_m += fk;
        if (idx_m >= n)
            idx_m -= n;
    }
    *re = r / (double)n;
    *im = i / (double)n;
}

static mcs_status check_freq_pair(const mcs_theory *th, size_t fk, size_t fl)
{
    if (!theory_is_valid(th))
        return MCS_ERR_UNINIT;
    if (fk >= th->n || fl >= th->n)
        return MCS_ERR_FREQ_RANGE;
    return MCS_OK;
}

mcs_status mcs_theory_spectrum_mean(const mcs_theory *th, size_t freq, double *re, double *im)
{
    if (th == NULL || re == NULL || im == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_freq_pair(th, freq, freq);
    if (st != MCS_OK)
        return st;
    spectrum_mean(th, freq, re, im);
    return MCS_OK;
}

mcs_status mcs_theory_cross(const mcs_theory *th, size_t freq_k, size_t freq_l, double *re,
                            double *im)
{
    if (th == NULL || re == NULL || im == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_freq_pair(th, freq_k, freq_l);
    if (st != MCS_OK)
        return st;
    cross(th, freq_k, freq_l, re, im);
    return MCS_OK;
}

mcs_status mcs_theory_covariance(const mcs_theory *th, size_t freq_k, size_t freq_l, double *re,
                                 double *im)
{
    if (th == NULL || re == NULL || im == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_freq_pair(th, freq_k, freq_l);
    if (st != MCS_OK)
        return st;
    double cr, ci, kr, ki, lr, li;
    cross(th, freq_k, freq_l, &cr, &ci);
    spectrum_mean(th, freq_k, &kr, &ki);
    spectrum_mean(th, freq_l, &lr, &li);
    /* <S_k><S_l>* = (kr + i ki)(lr - i li) */
    *re = cr - (kr * lr + ki * li);
    *im = ci - (ki * lr - kr * li);
    return MCS_OK;
}

mcs_status mcs_theory_power(const mcs_theory *th, size_t freq, double *out)
{
    if (th == NULL || out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_freq_pair(th, freq, freq);
    if (st != MCS_OK)
        return st;
    double re, im;
    cross(th, freq, freq, &re, &im);
    *out = re; /* im is 0 up to rounding: <s_m s_n> is real and symmetric */
    return MCS_OK;
}

mcs_status mcs_theory_estimator_mean(const mcs_theory *th, size_t n, const double *f,
                                     double *out)
{
    if (th == NULL || f == NULL || out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_theory_array(th, n, f);
    if (st != MCS_OK)
        return st;
    double sum = 0.0;
    for (size_t b = 0; b < n; ++b)
        sum += f[b] * th->mean_s[b];
    *out = sum / (double)th->k;
    return MCS_OK;
}

/* (1/K^2) f^T Cov(s) g, Cov(s)_mn = <s_m s_n> - <s_m><s_n>. */
static double primal_form(const mcs_theory *th, const double *f, const double *g)
{
    size_t n = th->n;
    double sum = 0.0;
    for (size_t m = 0; m < n; ++m) {
        double row = 0.0;
        for (size_t b = 0; b < n; ++b)
            row += (th->second[m * n + b] - th->mean_s[m] * th->mean_s[b]) * g[b];
        sum += f[m] * row;
    }
    double kd = (double)th->k;
    return sum / (kd * kd);
}

/* (1/K^2) sum_{k,l >= first} F_k* F_l X_kl, with X = Cov(S) (centred) or
 * <S S*> (raw), every X_kl through eq. 16: O(N^4), about 17 M multiply-adds
 * at N = 64, and no work arrays (frames stay small). */
static double spectral_form(const mcs_theory *th, const double *f, int centred, size_t first)
{
    size_t n = th->n;
    double total = 0.0;
    for (size_t k = first; k < n; ++k) {
        double fkr, fki, mkr = 0.0, mki = 0.0;
        table_dft(th, f, k, &fkr, &fki);
        if (centred)
            spectrum_mean(th, k, &mkr, &mki);
        for (size_t l = first; l < n; ++l) {
            double flr, fli, cr, ci;
            table_dft(th, f, l, &flr, &fli);
            cross(th, k, l, &cr, &ci);
            if (centred) { /* Cov = <S_k S_l*> - <S_k><S_l>* */
                double mlr, mli;
                spectrum_mean(th, l, &mlr, &mli);
                cr -= mkr * mlr + mki * mli;
                ci -= mki * mlr - mkr * mli;
            }
            /* F_k* F_l = (fkr - i fki)(flr + i fli); the real part of the product */
            double ar = fkr * flr + fki * fli;
            double ai = fkr * fli - fki * flr;
            total += ar * cr - ai * ci;
        }
    }
    double kd = (double)th->k;
    return total / (kd * kd);
}

mcs_status mcs_theory_variance(const mcs_theory *th, size_t n, const double *f, double *out)
{
    if (th == NULL || f == NULL || out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_theory_array(th, n, f);
    if (st != MCS_OK)
        return st;
    *out = primal_form(th, f, f);
    return MCS_OK;
}

mcs_status mcs_theory_variance_spectral(const mcs_theory *th, size_t n, const double *f,
                                        double *out)
{
    if (th == NULL || f == NULL || out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_theory_array(th, n, f);
    if (st != MCS_OK)
        return st;
    *out = spectral_form(th, f, 1, 0u);
    return MCS_OK;
}

mcs_status mcs_theory_estimator_covariance(const mcs_theory *th, size_t n, const double *f,
                                           const double *g, double *out)
{
    if (th == NULL || f == NULL || g == NULL || out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_theory_array(th, n, f);
    if (st == MCS_OK)
        st = check_theory_array(th, n, g);
    if (st != MCS_OK)
        return st;
    *out = primal_form(th, f, g);
    return MCS_OK;
}

/* N^{-1/2} sum_b e^{-2 pi i freq b/N} / p_b; trig per term (N up to MCS_MAX_N,
 * so no table), with exact index reduction. */
static void q_coefficient(const mcs_importance *imp, size_t freq, double *re, double *im)
{
    size_t n = imp->n;
    double r = 0.0, i = 0.0;
    for (size_t b = 0; b < n; ++b) {
        double a = 2.0 * MCS_PI * (double)((freq * b) % n) / (double)n;
        double q = 1.0 / imp->p[b];
        r += cos(a) * q;
        i -= sin(a) * q;
    }
    double scale = 1.0 / sqrt((double)n);
    *re = r * scale;
    *im = i * scale;
}

mcs_status mcs_theory_q(const mcs_importance *imp, size_t freq, double *re, double *im)
{
    if (re == NULL || im == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_importance(imp);
    if (st != MCS_OK)
        return st;
    if (freq >= imp->n)
        return MCS_ERR_FREQ_RANGE;
    q_coefficient(imp, freq, re, im);
    return MCS_OK;
}

/* ---- Section 1 ------------------------------------------------------------ */

mcs_status mcs_eq2_uncorrelated_variance(double var_f, double var_g, double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    if (!isfinite(var_f) || !isfinite(var_g))
        return MCS_ERR_NOT_FINITE;
    if (var_f < 0.0 || var_g < 0.0)
        return MCS_ERR_NEGATIVE;
    *out = var_f + var_g; /* independent trials: Cov[f, g] = 0 */
    return MCS_OK;
}

mcs_status mcs_eq2_uncorrelated_variance_fg(const mcs_theory *th, size_t n, const double *f,
                                            const double *g, double *out)
{
    if (th == NULL || f == NULL || g == NULL || out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_theory_array(th, n, f);
    if (st == MCS_OK)
        st = check_theory_array(th, n, g);
    if (st != MCS_OK)
        return st;
    *out = primal_form(th, f, f) + primal_form(th, g, g);
    return MCS_OK;
}

mcs_status mcs_eq4_correlated_variance(const mcs_theory *th, size_t n, const double *f,
                                       const double *g, double *out)
{
    if (th == NULL || f == NULL || g == NULL || out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_theory_array(th, n, f);
    if (st == MCS_OK)
        st = check_theory_array(th, n, g);
    if (st != MCS_OK)
        return st;
    for (size_t b = 0; b < n; ++b)
        if (!isfinite(f[b] - g[b])) /* f - g can overflow */
            return MCS_ERR_NOT_FINITE;
    /* (f - g)^T Cov (f - g), expanded so no difference array is needed */
    *out = primal_form(th, f, f) + primal_form(th, g, g) - 2.0 * primal_form(th, f, g);
    return MCS_OK;
}

/* ---- Section 2 ------------------------------------------------------------ */

mcs_status mcs_eq11_unbiased_mean(size_t n, const double *f, double *out)
{
    if (f == NULL || out == NULL)
        return MCS_ERR_NULL;
    if (n == 0u || n > (size_t)MCS_MAX_N)
        return MCS_ERR_N_RANGE;
    if (!all_finite(n, f))
        return MCS_ERR_NOT_FINITE;
    double sum = 0.0;
    for (size_t b = 0; b < n; ++b)
        sum += f[b];
    *out = sum / (double)n; /* (1/K)(K/sqrt N) F_0* = (1/N) sum f */
    return MCS_OK;
}

mcs_status mcs_eq13_variance(const mcs_theory *th, size_t n, const double *f, double *out)
{
    if (th == NULL || f == NULL || out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_theory_array(th, n, f);
    if (st != MCS_OK)
        return st;
    *out = spectral_form(th, f, 0, 1u);
    return MCS_OK;
}

mcs_status mcs_eq14_variance(size_t n, size_t k, const double *f, const double *power,
                             double *out)
{
    if (f == NULL || power == NULL || out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_n_k(n, (size_t)MCS_MAX_COV_N, k);
    if (st != MCS_OK)
        return st;
    if (!all_finite(n, f) || !all_finite(n - 1u, power + 1))
        return MCS_ERR_NOT_FINITE;
    double sum = 0.0;
    for (size_t b = 1; b < n; ++b) {
        double fr, fi;
        dft_coefficient(n, f, b, &fr, &fi);
        sum += (fr * fr + fi * fi) * power[b];
    }
    double kd = (double)k;
    *out = sum / (kd * kd);
    return MCS_OK;
}

/* ---- Section 3 ------------------------------------------------------------ */

/* Common checks for a closed form at one frequency. */
static mcs_status check_freq_form(size_t n, size_t k, size_t freq)
{
    mcs_status st = check_n_k(n, (size_t)MCS_MAX_N, k);
    if (st != MCS_OK)
        return st;
    if (freq >= n)
        return MCS_ERR_FREQ_RANGE;
    return MCS_OK;
}

/* Stratified forms of the note put N/K bins in each stratum. */
static int k_divides_n(size_t n, size_t k)
{
    return k <= n && n % k == 0u;
}

mcs_status mcs_eq23_random_power(size_t n, size_t k, size_t freq, double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_freq_form(n, k, freq);
    if (st != MCS_OK)
        return st;
    if (freq == 0u)
        return MCS_ERR_DOMAIN;
    *out = (double)k / (double)n;
    return MCS_OK;
}

/* Sum over k >= 1 of |F_k|^2 by a direct DFT. */
static double ac_energy(size_t n, const double *f)
{
    double sum = 0.0;
    for (size_t b = 1; b < n; ++b) {
        double fr, fi;
        dft_coefficient(n, f, b, &fr, &fi);
        sum += fr * fr + fi * fi;
    }
    return sum;
}

mcs_status mcs_eq24_random_variance(size_t n, size_t k, const double *f, double *out)
{
    if (f == NULL || out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_n_k(n, (size_t)MCS_MAX_COV_N, k);
    if (st != MCS_OK)
        return st;
    if (!all_finite(n, f))
        return MCS_ERR_NOT_FINITE;
    *out = ac_energy(n, f) / ((double)k * (double)n);
    return MCS_OK;
}

mcs_status mcs_eq25_random_variance(size_t n, size_t k, const double *f, double *out)
{
    if (f == NULL || out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_n_k(n, (size_t)MCS_MAX_N, k);
    if (st != MCS_OK)
        return st;
    if (!all_finite(n, f))
        return MCS_ERR_NOT_FINITE;
    double mean = 0.0;
    for (size_t b = 0; b < n; ++b)
        mean += f[b];
    mean /= (double)n;
    double ss = 0.0; /* two passes: no cancellation of sum f^2 against N fbar^2 */
    for (size_t b = 0; b < n; ++b)
        ss += (f[b] - mean) * (f[b] - mean);
    *out = ss / ((double)n * (double)k);
    return MCS_OK;
}

/* The printed bracket of eq. 30: (1 - e^{-2 pi i k/K}) / (1 - e^{-2 pi i k/N})
 * for k not a multiple of N. */
static void eq30_ratio(size_t n, size_t k, size_t freq, double *re, double *im)
{
    double a = 2.0 * MCS_PI * (double)(freq % k) / (double)k;
    double b = 2.0 * MCS_PI * (double)freq / (double)n;
    double nr = 1.0 - cos(a), ni = sin(a); /* 1 - e^{-ia} */
    double dr = 1.0 - cos(b), di = sin(b);
    double d2 = dr * dr + di * di;
    *re = (nr * dr + ni * di) / d2;
    *im = (ni * dr - nr * di) / d2;
}

/* Geometric sum over one stratum, sum_{a < N/K} e^{-2 pi i freq a/N}, summed
 * directly so it is defined at freq = 0 too. */
static void stratum_sum(size_t n, size_t k, size_t freq, double *re, double *im)
{
    double r = 0.0, i = 0.0;
    for (size_t a = 0; a < n / k; ++a) {
        double t = 2.0 * MCS_PI * (double)((freq * a) % n) / (double)n;
        r += cos(t);
        i -= sin(t);
    }
    *re = r;
    *im = i;
}

static mcs_status check_pair_form(size_t n, size_t k, size_t fk, size_t fl)
{
    mcs_status st = check_n_k(n, (size_t)MCS_MAX_N, k);
    if (st != MCS_OK)
        return st;
    if (fk >= n || fl >= n)
        return MCS_ERR_FREQ_RANGE;
    if (!k_divides_n(n, k))
        return MCS_ERR_DOMAIN;
    return MCS_OK;
}

static void eq30_printed(size_t n, size_t k, size_t fk, size_t fl, double *re, double *im)
{
    double ar, ai, br, bi;
    eq30_ratio(n, k, fk, &ar, &ai);
    eq30_ratio(n, k, fl, &br, &bi);
    bi = -bi; /* the second bracket is the conjugate ratio at l */
    double c = (double)k / (double)n;
    c = -c * c * c;
    *re = c * (ar * br - ai * bi);
    *im = c * (ar * bi + ai * br);
}

mcs_status mcs_eq30_stratified_delta_printed(size_t n, size_t k, size_t freq_k, size_t freq_l,
                                             double *re, double *im)
{
    if (re == NULL || im == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_pair_form(n, k, freq_k, freq_l);
    if (st != MCS_OK)
        return st;
    if (freq_k == 0u || freq_l == 0u)
        return MCS_ERR_DOMAIN;
    eq30_printed(n, k, freq_k, freq_l, re, im);
    return MCS_OK;
}

/* Delta_kl with the strata phase sum: the K strata at offsets q N/K add
 * e^{-2 pi i (k - l) q/K}, which sums to K for k = l (mod K) and to 0 else. */
static void eq30_corrected(size_t n, size_t k, size_t fk, size_t fl, double *re, double *im)
{
    if ((fk + n - fl) % n % k != 0u) {
        *re = 0.0;
        *im = 0.0;
        return;
    }
    double ar, ai, br, bi;
    stratum_sum(n, k, fk, &ar, &ai);
    stratum_sum(n, k, fl, &br, &bi);
    bi = -bi;
    double c = (double)k / (double)n;
    c = -c * c * c;
    *re = c * (ar * br - ai * bi);
    *im = c * (ar * bi + ai * br);
}

mcs_status mcs_eq30_stratified_delta_corrected(size_t n, size_t k, size_t freq_k,
                                               size_t freq_l, double *re, double *im)
{
    if (re == NULL || im == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_pair_form(n, k, freq_k, freq_l);
    if (st != MCS_OK)
        return st;
    eq30_corrected(n, k, freq_k, freq_l, re, im);
    return MCS_OK;
}

mcs_status mcs_eq30_stratified_cross(size_t n, size_t k, size_t freq_k, size_t freq_l,
                                     double *re, double *im)
{
    if (re == NULL || im == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_pair_form(n, k, freq_k, freq_l);
    if (st != MCS_OK)
        return st;
    double dr, di;
    eq30_corrected(n, k, freq_k, freq_l, &dr, &di);
    double kn = (double)k / (double)n;
    if (freq_k == freq_l)
        dr += kn; /* eq. 28's delta term, as for random */
    if (freq_k == 0u && freq_l == 0u)
        dr += (double)k * kn; /* eq. 28's constant K^2/N^2 term */
    *re = dr;
    *im = di;
    return MCS_OK;
}

/* Checks for the one-frequency stratified/jitter forms: K | N and, when
 * positive_freq, freq >= 1. */
static mcs_status check_strat_form(size_t n, size_t k, size_t freq, int positive_freq)
{
    mcs_status st = check_freq_form(n, k, freq);
    if (st != MCS_OK)
        return st;
    if (!k_divides_n(n, k) || (positive_freq && freq == 0u))
        return MCS_ERR_DOMAIN;
    return MCS_OK;
}

/* sin^2(pi freq / K) has period K in freq: reducing first makes it exactly 0
 * on multiples of K. */
static double sin2_over_k(size_t k, size_t freq)
{
    double s = sin(MCS_PI * (double)(freq % k) / (double)k);
    return s * s;
}

static double eq32(size_t n, size_t k, size_t freq)
{
    double kn = (double)k / (double)n;
    double sn = sin(MCS_PI * (double)freq / (double)n);
    return -kn * kn * kn * sin2_over_k(k, freq) / (sn * sn);
}

mcs_status mcs_eq31_stratified_delta_printed(size_t n, size_t k, size_t freq, double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_strat_form(n, k, freq, 1);
    if (st != MCS_OK)
        return st;
    double kn = (double)k / (double)n;
    double num = 1.0 - cos(2.0 * MCS_PI * (double)(freq % k) / (double)k);
    double den = 1.0 - cos(2.0 * MCS_PI * (double)freq / (double)n);
    double ratio = num / den;
    *out = -kn * kn * kn * ratio * ratio;
    return MCS_OK;
}

mcs_status mcs_eq32_stratified_delta(size_t n, size_t k, size_t freq, double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_strat_form(n, k, freq, 1);
    if (st != MCS_OK)
        return st;
    *out = eq32(n, k, freq);
    return MCS_OK;
}

mcs_status mcs_eq33_stratified_power_exact(size_t n, size_t k, size_t freq, double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_strat_form(n, k, freq, 1);
    if (st != MCS_OK)
        return st;
    *out = (double)k / (double)n + eq32(n, k, freq);
    return MCS_OK;
}

/* sinc^2(pi freq / K) with sinc x = sin x / x, freq in [1, N). The limit
 * forms are functions of the signed frequency: index freq > N/2 is freq - N,
 * and sinc^2 is even, so fold it to min(freq, N - freq) (sin^2(pi freq/K) is
 * unchanged by the fold because K divides N). */
static double sinc2(size_t n, size_t k, size_t freq)
{
    size_t folded = freq <= n - freq ? freq : n - freq;
    double x = MCS_PI * (double)folded / (double)k;
    return sin2_over_k(k, folded) / (x * x);
}

mcs_status mcs_eq33_stratified_power_limit(size_t n, size_t k, size_t freq, double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_strat_form(n, k, freq, 1);
    if (st != MCS_OK)
        return st;
    *out = (double)k / (double)n * (1.0 - sinc2(n, k, freq));
    return MCS_OK;
}

mcs_status mcs_eq34_uniform_spectrum(size_t n, size_t k, size_t freq, double *re, double *im)
{
    if (re == NULL || im == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_strat_form(n, k, freq, 0);
    if (st != MCS_OK)
        return st;
    if ((n / k) % 2u != 0u) /* (alpha + 1/2) N/K must be a whole bin */
        return MCS_ERR_DOMAIN;
    if (freq % k != 0u) {
        *re = 0.0;
        *im = 0.0;
        return MCS_OK;
    }
    /* e^{-2 pi i k beta/K} at k = mu K, beta = 1/2: (-1)^mu */
    double mag = (double)k / sqrt((double)n);
    *re = (freq / k) % 2u == 0u ? mag : -mag;
    *im = 0.0;
    return MCS_OK;
}

mcs_status mcs_eq35_jitter_mean(size_t n, size_t k, size_t freq, double *re, double *im)
{
    if (re == NULL || im == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_strat_form(n, k, freq, 0);
    if (st != MCS_OK)
        return st;
    *re = freq == 0u ? (double)k / sqrt((double)n) : 0.0;
    *im = 0.0;
    return MCS_OK;
}

mcs_status mcs_eq37_jitter_power(size_t n, size_t k, size_t freq, double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_strat_form(n, k, freq, 0);
    if (st != MCS_OK)
        return st;
    *out = freq % k == 0u ? (double)k * (double)k / (double)n : 0.0;
    return MCS_OK;
}

/* ---- Section 4 ------------------------------------------------------------ */

mcs_status mcs_eq41_importance_second(const mcs_importance *imp, size_t k, size_t m, size_t n,
                                      double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_importance(imp);
    if (st != MCS_OK)
        return st;
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    if (m >= imp->n || n >= imp->n)
        return MCS_ERR_BIN_RANGE;
    double kd = (double)k, nd = (double)imp->n;
    double v = (kd * kd - kd) / (nd * nd);
    if (m == n)
        v += kd / nd / imp->p[n];
    *out = v;
    return MCS_OK;
}

mcs_status mcs_eq43_importance_cross(const mcs_importance *imp, size_t k, size_t freq_k,
                                     size_t freq_l, double *re, double *im)
{
    if (re == NULL || im == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_importance(imp);
    if (st != MCS_OK)
        return st;
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    size_t n = imp->n;
    if (freq_k >= n || freq_l >= n)
        return MCS_ERR_FREQ_RANGE;
    if (freq_k == 0u && freq_l == 0u) /* the constant (K^2 - K)/N^2 adds there */
        return MCS_ERR_DOMAIN;
    double qr, qi;
    q_coefficient(imp, (freq_k + n - freq_l) % n, &qr, &qi);
    double c = (double)k / (double)n / sqrt((double)n);
    *re = c * qr;
    *im = c * qi;
    return MCS_OK;
}

mcs_status mcs_eq44_inverse_harmonic_mean(const mcs_importance *imp, double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_importance(imp);
    if (st != MCS_OK)
        return st;
    double sum = 0.0;
    for (size_t b = 0; b < imp->n; ++b)
        sum += 1.0 / imp->p[b];
    *out = sum / (double)imp->n;
    return MCS_OK;
}

static mcs_status check_h_form(size_t n, size_t k, double h, size_t freq, int positive_freq,
                               int need_divides)
{
    mcs_status st = check_freq_form(n, k, freq);
    if (st != MCS_OK)
        return st;
    st = check_h(h);
    if (st != MCS_OK)
        return st;
    if ((positive_freq && freq == 0u) || (need_divides && !k_divides_n(n, k)))
        return MCS_ERR_DOMAIN;
    return MCS_OK;
}

mcs_status mcs_eq45_importance_power(size_t n, size_t k, double h, size_t freq, double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_h_form(n, k, h, freq, 1, 0);
    if (st != MCS_OK)
        return st;
    *out = (double)k / (double)n / h;
    return MCS_OK;
}

static double eq46(size_t n, size_t k, double h)
{
    double kn = (double)k / (double)n;
    return (double)k * kn + kn * (1.0 / h - 1.0);
}

mcs_status mcs_eq46_importance_power0(size_t n, size_t k, double h, double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_h_form(n, k, h, 0u, 0, 0);
    if (st != MCS_OK)
        return st;
    *out = eq46(n, k, h);
    return MCS_OK;
}

mcs_status mcs_eq49_importance_stratified_cross(const mcs_importance *imp, size_t k,
                                                size_t freq_k, size_t freq_l, double *re,
                                                double *im)
{
    if (re == NULL || im == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_importance(imp);
    if (st != MCS_OK)
        return st;
    size_t n = imp->n;
    st = check_pair_form(n, k, freq_k, freq_l);
    if (st != MCS_OK)
        return st;
    if (freq_k == 0u || freq_l == 0u)
        return MCS_ERR_DOMAIN;
    double qr, qi, dr, di;
    q_coefficient(imp, (freq_k + n - freq_l) % n, &qr, &qi);
    eq30_printed(n, k, freq_k, freq_l, &dr, &di);
    double c = (double)k / (double)n / sqrt((double)n);
    *re = c * qr + dr;
    *im = c * qi + di;
    return MCS_OK;
}

mcs_status mcs_eq50_importance_stratified_power(size_t n, size_t k, double h, size_t freq,
                                                double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_h_form(n, k, h, freq, 1, 1);
    if (st != MCS_OK)
        return st;
    *out = (double)k / (double)n * (1.0 / h - sinc2(n, k, freq));
    return MCS_OK;
}

mcs_status mcs_eq51_importance_stratified_power0(size_t n, size_t k, double h, double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_h_form(n, k, h, 0u, 0, 1);
    if (st != MCS_OK)
        return st;
    *out = eq46(n, k, h);
    return MCS_OK;
}

/* Checks for the forms taking imp, k and f[imp->n] with a DFT of f. */
static mcs_status check_imp_f(const mcs_importance *imp, size_t k, const double *f, size_t cap)
{
    mcs_status st = check_importance(imp);
    if (st != MCS_OK)
        return st;
    st = check_n_k(imp->n, cap, k);
    if (st != MCS_OK)
        return st;
    if (!all_finite(imp->n, f))
        return MCS_ERR_NOT_FINITE;
    return MCS_OK;
}

/* Re sum_{k >= k0, l >= l0} F_k* F_l Q_{k-l}: F of f, Q of 1/p, both eq. 7,
 * each coefficient computed where it is used (O(N^3) trig, no work arrays). */
static double fq_form(const mcs_importance *imp, const double *f, size_t k0, size_t l0)
{
    size_t n = imp->n;
    double sum = 0.0;
    for (size_t a = k0; a < n; ++a) {
        double far, fai;
        dft_coefficient(n, f, a, &far, &fai);
        for (size_t b = l0; b < n; ++b) {
            double fbr, fbi, qr, qi;
            dft_coefficient(n, f, b, &fbr, &fbi);
            q_coefficient(imp, (a + n - b) % n, &qr, &qi);
            double ar = far * fbr + fai * fbi; /* F_a* F_b */
            double ai = far * fbi - fai * fbr;
            sum += ar * qr - ai * qi;
        }
    }
    return sum;
}

mcs_status mcs_eq52_variance_printed(const mcs_importance *imp, size_t k, const double *f,
                                     double *out)
{
    if (f == NULL || out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_imp_f(imp, k, f, (size_t)MCS_MAX_COV_N);
    if (st != MCS_OK)
        return st;
    double nd = (double)imp->n;
    *out = fq_form(imp, f, 1u, 1u) / ((double)k * nd * sqrt(nd));
    return MCS_OK;
}

mcs_status mcs_eq52_variance_corrected(const mcs_importance *imp, size_t k, const double *f,
                                       double *out)
{
    if (f == NULL || out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_imp_f(imp, k, f, (size_t)MCS_MAX_COV_N);
    if (st != MCS_OK)
        return st;
    size_t n = imp->n;
    double nd = (double)n;
    double sum = 0.0;
    for (size_t b = 0; b < n; ++b)
        sum += f[b];
    double f0_sq = sum * sum / nd; /* |F_0|^2 */
    *out = (fq_form(imp, f, 0u, 0u) / (nd * sqrt(nd)) - f0_sq / nd) / (double)k;
    return MCS_OK;
}

mcs_status mcs_eq52_variance_corrected_primal(const mcs_importance *imp, size_t k,
                                              const double *f, double *out)
{
    if (f == NULL || out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_imp_f(imp, k, f, (size_t)MCS_MAX_N);
    if (st != MCS_OK)
        return st;
    size_t n = imp->n;
    double mean = 0.0, m2 = 0.0;
    for (size_t b = 0; b < n; ++b) {
        mean += f[b];
        m2 += f[b] * f[b] / imp->p[b];
    }
    mean /= (double)n;
    m2 /= (double)n;
    *out = (m2 - mean * mean) / (double)k;
    return MCS_OK;
}

mcs_status mcs_eq55_variance_convolution(const mcs_importance *imp, size_t k, const double *f,
                                         double *out)
{
    if (f == NULL || out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_imp_f(imp, k, f, (size_t)MCS_MAX_COV_N);
    if (st != MCS_OK)
        return st;
    double nd = (double)imp->n;
    /* sum_{k >= 1} F_k* (F (x) Q)_k with the convolution over every l */
    *out = fq_form(imp, f, 1u, 0u) / ((double)k * nd * sqrt(nd));
    return MCS_OK;
}

mcs_status mcs_eq58_bound_printed(size_t n, size_t k, double h, const double *f, double *out)
{
    if (f == NULL || out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_n_k(n, (size_t)MCS_MAX_COV_N, k);
    if (st != MCS_OK)
        return st;
    st = check_h(h);
    if (st != MCS_OK)
        return st;
    if (!all_finite(n, f))
        return MCS_ERR_NOT_FINITE;
    *out = ac_energy(n, f) / h / (double)k;
    return MCS_OK;
}

mcs_status mcs_eq58_bound_corrected(size_t n, size_t k, double h, const double *f, double *out)
{
    if (f == NULL || out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_n_k(n, (size_t)MCS_MAX_N, k);
    if (st != MCS_OK)
        return st;
    st = check_h(h);
    if (st != MCS_OK)
        return st;
    if (!all_finite(n, f))
        return MCS_ERR_NOT_FINITE;
    double energy = 0.0; /* sum_{all n} |F_n|^2 = sum f_n^2 (Parseval, eq. 7 is unitary) */
    for (size_t b = 0; b < n; ++b)
        energy += f[b] * f[b];
    *out = energy * (1.0 / h - 1.0 / (double)n) / (double)k;
    return MCS_OK;
}
