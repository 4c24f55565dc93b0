/* Section 3 of the note: spectra of common sampling patterns (eq. 15-37).
 * Random, stratified (fixed strata), homogenized stratified, uniform and
 * uniform jitter: power spectra at chosen frequencies, the off-diagonal
 * <S_k S_l*> that makes fixed strata non-stationary, and what that does to
 * the estimator variance of eq. 14. */
#include "exact.h"
#include "mcspec.h"
#include "measure.h"
#include "readout.h"
#include "report.h"

#include <math.h>
#include <stdio.h>

static const char help_text[] =
    "Section 3: spectra of random, stratified, homogenized stratified, uniform\n"
    "and uniform jitter sampling (eq. 15-37).\n"
    "Per pattern it draws T trials of K samples over N bins and measures, with\n"
    "mcs_spectrum, the power <|S_k|^2> at k in {1, K/2, K, K+1, 2K, N/2}; with\n"
    "direct sums over the samples, <S_k> and the cross moments <S_k S_l*>\n"
    "(Re and Im, each with its own standard error); and the estimator\n"
    "I = (1/K) sum f_n s_n of f(x) = 0.5 + 0.3 sin(2 pi x) + 0.4 [x >= 0.3]\n"
    "(a smooth part and an edge) at the bin centres. Exact predictions come\n"
    "from mcspec theory, closed forms from the note (mcs_eqNN_*).\n"
    "Eq. 33 as printed (sinc^2) is an N -> infinity form: its limit check\n"
    "compares it with the exact finite-N form at 16 N (or the largest multiple\n"
    "of N within MCS_MAX_N; none above MCS_MAX_N / 2). Any N up to MCS_MAX_N:\n"
    "above MCS_MAX_COV_N the exact values come from mcs_theory_spectrum, and the\n"
    "check against the N x N moment accumulator is skipped.\n";

enum { P_RANDOM, P_STRAT, P_HOMOG, P_UNIFORM, P_JITTER, P_COUNT };

static const mcs_pattern_kind kinds[P_COUNT] = {MCS_PATTERN_RANDOM, MCS_PATTERN_STRATIFIED,
                                                MCS_PATTERN_HOMOGENIZED, MCS_PATTERN_UNIFORM,
                                                MCS_PATTERN_JITTER};

static ex_run runs[P_COUNT];
static mcs_spectrum spectra[P_COUNT];
static ex_exact exacts[P_COUNT];
static mcs_moment moment_strat;
static mcs_dft big_plan;
static double f[MCS_MAX_N];
static double f_big[MCS_MAX_N], big_re[MCS_MAX_N], big_im[MCS_MAX_N];

/* What the summary reads from the rows above it. */
typedef struct {
    double fixed_gap, fixed_z;  /* eq. 14 with eq. 33 against fixed strata's measured Var[I] */
    double homog_gap, homog_z;  /* ... against homogenized strata's */
    double strat_offdiag_z;     /* largest |z| of a fixed-strata <S_1 S_l*> against 0 */
} sec3_summary;

/* The chosen frequencies, deduplicated, each in [1, N). */
static size_t pick_freqs(size_t n, size_t k, size_t *out)
{
    const size_t cand[6] = {1u, k / 2u, k, k + 1u, 2u * k, n / 2u};
    return ex_pick_freqs(n, cand, 6u, out);
}

/* The l of the probed pair (1, l): the same residue mod K as 1, so eq. 30 is
 * non-zero there. */
static size_t pair_l(const ex_options *opt)
{
    return opt->k + 1u;
}

/* Eq. 33's sinc^2 form against the exact finite-N form at M bins, relative
 * (EX_NA for M = 0, no larger N). */
static double eq33_gap(size_t m, size_t k, size_t freq)
{
    double lim = 0.0, ex = 0.0;
    if (m == 0u || mcs_eq33_stratified_power_limit(m, k, freq, &lim) != MCS_OK ||
        mcs_eq33_stratified_power_exact(m, k, freq, &ex) != MCS_OK)
        return EX_NA;
    return ex_rel_gap(lim, ex, 1e-12 * (double)k / (double)m);
}

/* Eq. 14 at M bins for f sampled at M bin centres, with the stratified power of
 * eq. 33 (exact finite-N form if exact_form, else the sinc^2 form). */
static double eq14_stratified_at(size_t m, size_t k, int exact_form)
{
    if (m == 0u || m > MCS_MAX_N || mcs_dft_init(&big_plan, m) != MCS_OK)
        return EX_NA;
    ex_integrand_bins(m, f_big);
    if (mcs_dft_real(&big_plan, m, f_big, big_re, big_im) != MCS_OK)
        return EX_NA;
    double sum = 0.0;
    for (size_t q = 1; q < m; ++q) {
        double p = 0.0;
        mcs_status st = exact_form ? mcs_eq33_stratified_power_exact(m, k, q, &p)
                                   : mcs_eq33_stratified_power_limit(m, k, ex_fold(m, q), &p);
        if (st != MCS_OK)
            return EX_NA;
        sum += (big_re[q] * big_re[q] + big_im[q] * big_im[q]) * p;
    }
    return sum / ((double)k * (double)k);
}

/* f at the bin centres, then every pattern's run (fixed strata also into
 * the moment accumulator). */
static int measure_spectra(const ex_options *opt)
{
    ex_integrand_bins(opt->n, f);
    size_t freqs[6];
    size_t nfreq = pick_freqs(opt->n, opt->k, freqs);
    for (int p = 0; p < P_COUNT; ++p) {
        ex_run *run = &runs[p];
        mcs_status st = ex_run_setup(run, &exacts[p], &spectra[p], kinds[p], opt->n, opt->k,
                                     NULL, opt->seed, 0x300u + (uint64_t)kinds[p]);
        if (st != MCS_OK) {
            fprintf(stderr, "sec3: %s: %s\n", mcs_pattern_kind_str(kinds[p]), mcs_status_str(st));
            return 0;
        }
        for (size_t i = 0; i < nfreq; ++i)
            ex_run_probe(run, freqs[i]);
        ex_run_probe(run, opt->k);
        ex_run_probe_pair(run, 1u, pair_l(opt));
        ex_run_probe_pair(run, 1u, 2u);
        ex_run_integrand(run, f);
        mcs_moment *mom = NULL;
        if (p == P_STRAT && mcs_moment_init(&moment_strat, opt->n) == MCS_OK)
            mom = &moment_strat;
        st = ex_run_go(run, opt->trials, &spectra[p], mom);
        if (st != MCS_OK) {
            fprintf(stderr, "sec3: measuring %s: %s\n", mcs_pattern_kind_str(kinds[p]),
                    mcs_status_str(st));
            return 0;
        }
    }
    return 1;
}

/* Power rows for one pattern at the chosen frequencies. */
static void power_rows(const ex_options *opt, int p, const size_t *freqs, size_t nfreq)
{
    const char *name = mcs_pattern_kind_str(kinds[p]);
    double kn = (double)opt->k / (double)opt->n;
    double floor_ = 1e-10 * kn * (double)opt->k;
    for (size_t i = 0; i < nfreq; ++i) {
        size_t q = freqs[i];
        double closed = EX_NA, gap_big = EX_NA, v = 0.0;
        const char *eq = "";
        double se, meas = ex_spectrum_power(&spectra[p], q, &se);
        double exact = ex_exact_power(&exacts[p], q);
        switch (p) {
        case P_RANDOM:
            eq = "eq. 23";
            closed = ex_or_na(mcs_eq23_random_power(opt->n, opt->k, q, &v), &v);
            break;
        case P_STRAT:
        case P_HOMOG:
            eq = "eq. 33";
            closed = ex_or_na(mcs_eq33_stratified_power_limit(opt->n, opt->k, q, &v), &v);
            gap_big = eq33_gap(ex_large_n(opt->n), opt->k, q);
            break;
        default:
            eq = "eq. 37";
            closed = ex_or_na(mcs_eq37_jitter_power(opt->n, opt->k, q, &v), &v);
            break;
        }
        ex_row r = ex_row_of("sec3", "<|S_k|^2>", eq, name, (long)q, EX_NO_FREQ, closed, exact,
                             meas, se, floor_);
        r.limit_gap = gap_big;
        ex_row_print(opt, &r);
    }
}

/* Eq. 33's sinc^2 form against its exact finite-N form, and mcs_theory's
 * stratified power against that form. */
static void eq33_notes(const ex_options *opt, const size_t *freqs, size_t nfreq)
{
    const size_t n = opt->n, k = opt->k;
    double worst = 0.0, worst_big = 0.0;
    size_t at = 0;
    for (size_t i = 0; i < nfreq; ++i) {
        double g = eq33_gap(n, k, freqs[i]);
        if (!isnan(g) && g > worst) {
            worst = g;
            at = freqs[i];
            worst_big = eq33_gap(ex_large_n(n), k, freqs[i]);
        }
    }
    double th_vs_exact = 0.0, v = 0.0, w = 0.0;
    for (size_t q = 1; q < n; ++q)
        if (!isnan(v = ex_exact_power(&exacts[P_STRAT], q)) &&
            mcs_eq33_stratified_power_exact(n, k, q, &w) == MCS_OK)
            th_vs_exact = fmax(th_vs_exact, fabs(v - w) / ((double)k / (double)n));
    if (worst > 0.0)
        ex_notef(opt,
                 "eq. 33 sinc^2 vs the exact finite-N form K/N - (K/N)^3 sin^2(pi k/K) / "
                 "sin^2(pi k/N): largest gap %.3g (relative) at k = %zu for N = %zu, %.3g "
                 "at N = %zu",
                 worst, at, n, worst_big, ex_large_n(n));
    else
        ex_note(opt, "eq. 33: K does not divide N, or no probed frequency separates the forms");
    if (n % k == 0u) /* the exact finite-N form needs K dividing N */
        ex_notef(opt,
                 "mcspec theory's stratified power equals that exact finite-N form to %.2g K/N "
                 "over all k",
                 th_vs_exact);
}

/* ---- power spectra ---- */
static void power_section(const ex_options *opt)
{
    size_t freqs[6];
    size_t nfreq = pick_freqs(opt->n, opt->k, freqs);
    ex_heading(opt, "power spectra <|S_k|^2>: random eq. 23, stratified eq. 33 (sinc^2 form), "
                    "uniform and jitter eq. 37");
    for (int p = 0; p < P_COUNT; ++p)
        power_rows(opt, p, freqs, nfreq);
    eq33_notes(opt, freqs, nfreq);
}

/* ---- eq. 31 and 32: the stratified correction Delta_kk ---- */
static void delta_section(const ex_options *opt)
{
    const size_t n = opt->n, k = opt->k;
    const double kn = (double)k / (double)n;
    ex_heading(opt, "stratified correction Delta_kk = <|S_k|^2> - K/N: eq. 31 as printed "
                    "(squared bracket) and eq. 32");
    const size_t dk[3] = {1u, k / 2u, k + 1u};
    for (int i = 0; i < 3; ++i) {
        size_t q = dk[i];
        if (q == 0u || q >= n || (i > 0 && q == dk[i - 1]) || (i == 2 && q == dk[0]))
            continue;
        double v = 0.0;
        double exact = ex_exact_power(&exacts[P_STRAT], q) - kn;
        /* K/N is a constant: the stderr is the power's */
        double se, meas = ex_spectrum_power(&spectra[P_STRAT], q, &se) - kn;
        double p31 = ex_or_na(mcs_eq31_stratified_delta_printed(n, k, q, &v), &v);
        double p32 = ex_or_na(mcs_eq32_stratified_delta(n, k, q, &v), &v);
        ex_row r = ex_row_of("sec3", "Delta_kk as printed", "eq. 31", "stratified", (long)q,
                             EX_NO_FREQ, p31, exact, meas, se, 1e-10 * kn);
        ex_row_print(opt, &r);
        r = ex_row_of("sec3", "Delta_kk", "eq. 32", "stratified", (long)q, EX_NO_FREQ, p32, exact,
                      meas, se, 1e-10 * kn);
        ex_row_print(opt, &r);
    }
}

/* <S_K> of pattern p: uniform against eq. 34 (after the unbiasedness the
 * estimator needs), jitter against eq. 35, fixed strata against eq. 10. */
static void mean_rows(const ex_options *opt, int p)
{
    const size_t n = opt->n, k = opt->k;
    const double floor_ = 1e-10 * ((double)k / (double)n);
    int idx = ex_run_probe(&runs[p], k);
    if (idx < 0)
        return;
    double a = 0.0, b = 0.0;
    ex_complex se, meas = ex_run_mean(&runs[p], idx, &se);
    ex_complex exact = ex_exact_mean(&exacts[p], k);
    ex_complex closed = {0.0, 0.0};
    const char *eq = "eq. 10";
    if (p == P_UNIFORM) {
        /* First the unbiasedness the estimator needs (eq. 10, as eq. 35
         * states for jitter), then the note's own eq. 34 for uniform. */
        ex_row r = ex_row_of("sec3", "Re <S_k> unbiased=0", "eq. 10", "uniform", (long)k,
                             EX_NO_FREQ, 0.0, exact.re, meas.re, se.re, floor_);
        ex_row_print(opt, &r);
        eq = "eq. 34";
        closed = ex_complex_or_na(mcs_eq34_uniform_spectrum(n, k, k, &a, &b), &a, &b);
    } else if (p == P_JITTER) {
        eq = "eq. 35";
        closed = ex_complex_or_na(mcs_eq35_jitter_mean(n, k, k, &a, &b), &a, &b);
    }
    ex_row_print_complex(opt, "sec3", "<S_k>", eq, mcs_pattern_kind_str(kinds[p]), (long)k,
                         EX_NO_FREQ, closed, exact, meas, se, floor_);
}

/* ---- means: bias of uniform ---- */
static void mean_section(const ex_options *opt)
{
    ex_heading(opt, "means <S_k> at k = K: uniform is biased (eq. 34), jitter is not (eq. 35)");
    const int pats[3] = {P_UNIFORM, P_JITTER, P_STRAT};
    for (int i = 0; i < 3; ++i)
        mean_rows(opt, pats[i]);
}

/* <S_1 S_l*> of pattern p against 0 (stationarity); for fixed strata also
 * against eq. 30 as printed and corrected. Returns |z| against 0 (fixed
 * strata only, else 0). */
static double cross_rows(const ex_options *opt, int p, size_t l)
{
    const size_t n = opt->n, k = opt->k;
    const double floor_ = 1e-10 * ((double)k / (double)n);
    const char *name = mcs_pattern_kind_str(kinds[p]);
    int idx = ex_run_probe_pair(&runs[p], 1u, l);
    if (idx < 0)
        return 0.0;
    double a = 0.0, b = 0.0;
    ex_complex se, meas = ex_run_mean_pair(&runs[p], idx, &se);
    ex_complex exact = ex_exact_cross(&exacts[p], 1u, l);
    ex_complex zero = {0.0, 0.0};
    ex_row_print_complex(opt, "sec3", "<S_k S_l*> if stationary", "eq. 14", name, 1, (long)l,
                         zero, exact, meas, se, floor_);
    if (p != P_STRAT)
        return 0.0;
    ex_complex printed =
        ex_complex_or_na(mcs_eq30_stratified_delta_printed(n, k, 1u, l, &a, &b), &a, &b);
    ex_complex corrected = ex_complex_or_na(mcs_eq30_stratified_cross(n, k, 1u, l, &a, &b), &a, &b);
    ex_row_print_complex(opt, "sec3", "<S_k S_l*> as printed", "eq. 30", name, 1, (long)l,
                         printed, exact, meas, se, floor_);
    ex_row_print_complex(opt, "sec3", "<S_k S_l*> corrected", "eq. 30c", name, 1, (long)l,
                         corrected, exact, meas, se, floor_);
    return ex_z_complex(meas, zero, se, floor_);
}

/* The moment accumulator on the same trials gives the same cross moment. */
static void moment_check_note(const ex_options *opt)
{
    if (opt->n > (size_t)MCS_MAX_COV_N) {
        ex_notef(opt, "check against mcs_moment (N x N sums): skipped above MCS_MAX_COV_N = %d",
                 MCS_MAX_COV_N);
        return;
    }
    size_t l = pair_l(opt);
    int idx = ex_run_probe_pair(&runs[P_STRAT], 1u, l);
    double a = 0.0, b = 0.0;
    if (idx >= 0 && mcs_moment_cross(&moment_strat, 1u, l, &a, &b) == MCS_OK) {
        ex_complex direct = ex_run_mean_pair(&runs[P_STRAT], idx, NULL);
        ex_notef(opt,
                 "check: mcs_moment on the same stratified trials gives <S_1 S_%zu*> = "
                 "%.9g %+.9gi (direct sums: %.9g %+.9gi)",
                 l, a, b, direct.re, direct.im);
    }
}

/* ---- off-diagonal: non-stationarity of fixed strata ---- */
static void cross_section(const ex_options *opt, sec3_summary *s)
{
    ex_heading(opt, "cross moments <S_k S_l*>, k != l (= Cov(S_k, S_l), since <S_k> = 0 for "
                    "k >= 1): eq. 14 assumes 0");
    const int pats[3] = {P_STRAT, P_HOMOG, P_RANDOM};
    const size_t ls[2] = {pair_l(opt), 2u};
    s->strat_offdiag_z = 0.0;
    for (int i = 0; i < 3; ++i)
        for (int li = 0; li < 2; ++li)
            s->strat_offdiag_z = fmax(s->strat_offdiag_z, cross_rows(opt, pats[i], ls[li]));
    moment_check_note(opt);
}

/* Eq. 14's Var[I] with the note's power spectra as the power (EX_NA where a
 * form is undefined, e.g. eq. 33 when K does not divide N). */
typedef struct {
    double strat_exact; /* eq. 33, exact finite-N form */
    double strat_limit; /* eq. 33, sinc^2 form at the signed frequency */
    double random;      /* eq. 23 */
    double jitter;      /* eq. 37 */
} eq14_forms;

static eq14_forms eq14_with_closed_forms(size_t n, size_t k)
{
    static double pw_exact[MCS_MAX_N], pw_limit[MCS_MAX_N], pw_random[MCS_MAX_N],
        pw_jitter[MCS_MAX_N];
    int ok33 = n % k == 0u, ok37 = n % k == 0u; /* both need K dividing N */
    for (size_t q = 1; q < n; ++q) {
        ok33 = ok33 && mcs_eq33_stratified_power_exact(n, k, q, &pw_exact[q]) == MCS_OK &&
               mcs_eq33_stratified_power_limit(n, k, ex_fold(n, q), &pw_limit[q]) == MCS_OK;
        ok37 = ok37 && mcs_eq37_jitter_power(n, k, q, &pw_jitter[q]) == MCS_OK;
        mcs_eq23_random_power(n, k, q, &pw_random[q]);
    }
    eq14_forms e = {EX_NA, EX_NA, EX_NA, EX_NA};
    double v = 0.0;
    if (ok33 && mcs_eq14_variance(n, k, f, pw_exact, &v) == MCS_OK)
        e.strat_exact = v;
    if (ok33 && mcs_eq14_variance(n, k, f, pw_limit, &v) == MCS_OK)
        e.strat_limit = v;
    if (ok37 && mcs_eq14_variance(n, k, f, pw_jitter, &v) == MCS_OK)
        e.jitter = v;
    if (mcs_eq14_variance(n, k, f, pw_random, &v) == MCS_OK)
        e.random = v;
    return e;
}

/* Exact (mcs_theory) and measured Var[I] per pattern. */
typedef struct {
    double exact[P_COUNT], measured[P_COUNT], se[P_COUNT];
} variances;

/* A Var[I] row of pattern p with closed form `closed` (limit_gap as given). */
static void variance_row(const ex_options *opt, const char *quantity, const char *eq, int p,
                         double closed, const variances *var, double limit_gap)
{
    ex_row r = ex_row_of("sec3", quantity, eq, mcs_pattern_kind_str(kinds[p]), EX_NO_FREQ,
                         EX_NO_FREQ, closed, var->exact[p], var->measured[p], var->se[p], 1e-12);
    r.limit_gap = limit_gap;
    ex_row_print(opt, &r);
}

/* ---- estimator variance ---- */
static void variance_section(const ex_options *opt, sec3_summary *s)
{
    const size_t n = opt->n, k = opt->k;
    ex_heading(opt, "estimator variance Var[I]: eq. 14 with a power spectrum, against the "
                    "exact and measured variance");
    eq14_forms e = eq14_with_closed_forms(n, k);
    /* The homogenized pattern is stationary, so its exact variance at 16 N is
     * eq. 14 with the exact finite-N power there. */
    size_t big = ex_large_n(n);
    double vb_exact = eq14_stratified_at(big, k, 1), vb_limit = eq14_stratified_at(big, k, 0);
    double limit_gap_big = ex_rel_gap(vb_limit, vb_exact, 1e-300);
    variances var;
    double v = 0.0;
    for (int p = 0; p < P_COUNT; ++p) {
        var.exact[p] = ex_exact_variance(&exacts[p], f);
        var.measured[p] = ex_variance(&runs[p].estimate[0], &var.se[p]);
    }
    double v25 = ex_or_na(mcs_eq25_random_variance(n, k, f, &v), &v);
    variance_row(opt, "Var[I]", "eq. 25", P_RANDOM, v25, &var, EX_NA);
    variance_row(opt, "Var[I] eq.14 with eq.23", "eq. 14", P_RANDOM, e.random, &var, EX_NA);
    variance_row(opt, "Var[I] eq.14 with eq.37", "eq. 14", P_JITTER, e.jitter, &var, EX_NA);
    variance_row(opt, "Var[I] eq.14 with eq.37", "eq. 14", P_UNIFORM, e.jitter, &var, EX_NA);
    /* A limit only where eq. 14 itself is exact (stationary, homogenized);
     * for fixed strata no larger-N exact value is claimed. */
    variance_row(opt, "Var[I] eq.14 with eq.33 exact", "eq. 14", P_STRAT, e.strat_exact, &var,
                 EX_NA);
    variance_row(opt, "Var[I] eq.14 with eq.33 sinc2", "eq. 14", P_STRAT, e.strat_limit, &var,
                 EX_NA);
    variance_row(opt, "Var[I] eq.14 with eq.33 exact", "eq. 14", P_HOMOG, e.strat_exact, &var,
                 EX_NA);
    variance_row(opt, "Var[I] eq.14 with eq.33 sinc2", "eq. 14", P_HOMOG, e.strat_limit, &var,
                 limit_gap_big);
    const double *meas = var.measured, *se = var.se;
    s->fixed_gap = (e.strat_exact - meas[P_STRAT]) / meas[P_STRAT];
    s->fixed_z = ex_z(meas[P_STRAT], e.strat_exact, se[P_STRAT], 1e-12);
    s->homog_gap = (e.strat_exact - meas[P_HOMOG]) / meas[P_HOMOG];
    s->homog_z = ex_z(meas[P_HOMOG], e.strat_exact, se[P_HOMOG], 1e-12);
    ex_notef(opt,
             "fixed strata: measured Var[I] = %.4g +- %.2g; homogenized: %.4g +- %.2g; "
             "random: %.4g +- %.2g",
             meas[P_STRAT], se[P_STRAT], meas[P_HOMOG], se[P_HOMOG], meas[P_RANDOM], se[P_RANDOM]);
    if (!isnan(e.strat_limit) && !isnan(e.strat_exact) && !isnan(limit_gap_big))
        ex_notef(opt,
                 "eq. 14 with eq. 33 (sinc^2) vs with the exact finite-N power: %.3g relative "
                 "at N = %zu, %.3g at N = %zu (homogenized, where eq. 14 is exact)",
                 ex_rel_gap(e.strat_limit, e.strat_exact, 1e-300), n, limit_gap_big, big);
}

static void summary_notes(const ex_options *opt, const sec3_summary *s)
{
    ex_heading(opt, "summary (computed from the rows above)");
    if (isnan(s->fixed_gap) || isnan(s->homog_gap))
        ex_note(opt, "eq. 33 is defined only when K divides N: no eq. 14 comparison here");
    else
        ex_notef(opt,
                 "eq. 14 with eq. 33 misses the fixed-strata variance by %.0f%% (z = %.1f); with "
                 "homogenized strata it is off by %.2g%% (z = %.2f)",
                 100.0 * s->fixed_gap, s->fixed_z, 100.0 * s->homog_gap, s->homog_z);
    if (opt->n < 3u) /* the probed pairs (1, 2) and (1, K + 1) need N >= 3 */
        ex_note(opt, "N < 3: no pair k != l >= 1 to show the non-stationarity of fixed strata");
    else
        ex_notef(opt,
                 "fixed strata are not stationary: an off-diagonal <S_1 S_l*> lies %.0f stderr "
                 "from 0; homogenizing removes it",
                 s->strat_offdiag_z);
}

int main(int argc, char **argv)
{
    ex_options opt = {64u, 8u, 200000ul, 1u, 0};
    int rc = ex_parse_options(argc, argv, &opt, MCS_MAX_N, EX_MAX_K, help_text);
    if (rc != EX_PARSE_OK)
        return rc;
    if (!measure_spectra(&opt))
        return 1;

    sec3_summary summary;
    ex_begin(&opt, "Section 3: spectra of common sampling patterns (eq. 15-37)");
    power_section(&opt);               /* eq. 23, 33, 37 */
    delta_section(&opt);               /* eq. 31, 32 */
    mean_section(&opt);                /* eq. 34, 35 */
    cross_section(&opt, &summary);     /* eq. 30, and eq. 14's assumption */
    variance_section(&opt, &summary);  /* eq. 14, 25 */
    summary_notes(&opt, &summary);
    ex_end(&opt);
    return 0;
}
