/* Section 4 of the note: importance sampling (eq. 38-58). Random and
 * stratified sampling warped through an importance function g, with
 * s_n = r_n / p_n (eq. 38): the power at k = 0 (eq. 46, 51) and k > 0
 * (eq. 45, 50), the cross spectrum Q_{k-l} (eq. 43, 49), the harmonic-mean
 * claim that importance sampling raises the power spectrum, the variance of
 * eq. 52 as printed and corrected, and the bound of eq. 58 as printed and
 * corrected; and an importance function with bins of g = 0 (outside the
 * support), whose estimator misses f there. */
#include "exact.h"
#include "importance.h"
#include "mcspec.h"
#include "measure.h"
#include "outside.h"
#include "readout.h"
#include "report.h"

#include <math.h>
#include <stdio.h>

static const char help_text[] =
    "Section 4: importance sampling (eq. 38-58).\n"
    "Integrand f(x) = 0.5 + 0.3 sin(2 pi x) + 0.4 [x >= 0.3] at the bin centres,\n"
    "and the constant f = 1 (for eq. 58). Importance functions (weights at the\n"
    "bin centres, normalised): g1 = 0.45 + 0.3 sin(2 pi x) + 0.3 [x >= 0.35]\n"
    "roughly follows f; g2 = 0.2 + (1 - x)^2 does not (it is high where f is\n"
    "low); 'flat' is the uniform g (p_n = 1), where the stratified forms should\n"
    "reduce to section 3; g1b is g1 with each block of N/K bins rescaled to mass\n"
    "1/K, so that every warped stratum is N/K whole bins (the condition under\n"
    "which eq. 49-51 can hold) though g1b is far from uniform. Runs: random and\n"
    "stratified without importance, random warped through g1 and g2, and\n"
    "stratified warped through g1, g2, flat and g1b; and, apart, random and\n"
    "stratified warped through g1z, g1 with g = 0 on the bins whose centre lies in\n"
    "[0.6, 0.75) (never drawn: the estimator's bias is -(1/N) sum of f there).\n"
    "Measured per run (T trials each, its own PCG32 stream): the power spectrum\n"
    "(mcs_spectrum), S_k and S_k S_l* at a few frequencies by direct sums\n"
    "(Welford, Re and Im each with its standard error), the estimator I of both\n"
    "integrands (Welford: mean, variance and the variance's standard error)\n"
    "and the Parseval sum sum_{k>=1} |S_k|^2 per trial (the mean power over\n"
    "k >= 1 with an honest standard error).\n"
    "Bound rows (eq. 58) put the bound in the closed column; their verdict is\n"
    "the bound rule below. Eq. 50 is an N -> infinity form when the strata are\n"
    "whole bins (flat g, g1b): its limit check uses the exact finite-N form\n"
    "there, eq. 33's exact form + (K/N)(1/H - 1), at 16 N (the largest multiple\n"
    "of N within MCS_MAX_N if smaller; none above MCS_MAX_N / 2), checked\n"
    "against mcspec theory at N in the notes. Any N up to MCS_MAX_N: above\n"
    "MCS_MAX_COV_N the exact values come from mcs_theory_spectrum, and eq. 52\n"
    "and 55 are taken by their Parseval equals. The note's N -> infinity forms are\n"
    "evaluated at the signed frequency min(k, N - k) wherever a sum over all k\n"
    "is formed.\n";

enum { R_RANDOM, R_STRAT, R_RANDOM_G1, R_RANDOM_G2, R_STRAT_G1, R_STRAT_G2, R_STRAT_FLAT,
       R_STRAT_BAL, R_COUNT };

typedef struct {
    mcs_pattern_kind kind;
    int g;
    const char *name;
} run_spec;

_Static_assert(0x400u + R_COUNT == EX_OUTSIDE_STREAM, "the support runs' streams follow ours");
static const run_spec specs[R_COUNT] = {
    {MCS_PATTERN_RANDOM, EX_G_NONE, "random"},
    {MCS_PATTERN_STRATIFIED, EX_G_NONE, "stratified"},
    {MCS_PATTERN_RANDOM, EX_G_FOLLOW, "random+g1"},
    {MCS_PATTERN_RANDOM, EX_G_MISMATCH, "random+g2"},
    {MCS_PATTERN_STRATIFIED, EX_G_FOLLOW, "stratified+g1"},
    {MCS_PATTERN_STRATIFIED, EX_G_MISMATCH, "stratified+g2"},
    {MCS_PATTERN_STRATIFIED, EX_G_FLAT, "stratified+flat"},
    {MCS_PATTERN_STRATIFIED, EX_G_BALANCED, "stratified+g1b"},
};

static mcs_importance imps[EX_G_COUNT];
static ex_run runs[R_COUNT];
static mcs_spectrum spectra[R_COUNT];
static ex_exact exacts[R_COUNT];
static double f[MCS_MAX_N], f_const[MCS_MAX_N];
static size_t n_bins, k_samples;
static double kn, pfloor; /* K/N, and the rounding scale of a power: 1e-10 K/N K */

static const mcs_importance *imp_of(int r)
{
    return specs[r].g == EX_G_NONE ? NULL : &imps[specs[r].g];
}

static double h_of(int r)
{
    return specs[r].g == EX_G_NONE ? 1.0 : imps[specs[r].g].harmonic_mean;
}

/* Eq. 52 corrected in the primal domain, (1/K)[(1/N) sum f^2/p - fbar^2]: the
 * Parseval twin of mcs_eq52_variance_corrected, printed as a cross-check. */
static mcs_status eq52_corrected_primal(const mcs_importance *imp, size_t k, const double *ff,
                                        double *out)
{
    if (imp == NULL)
        return MCS_ERR_DOMAIN;
    double mean = 0.0, m2 = 0.0;
    for (size_t b = 0; b < imp->n; ++b) {
        mean += ff[b];
        m2 += ff[b] * ff[b] / imp->p[b];
    }
    mean /= (double)imp->n;
    m2 /= (double)imp->n;
    *out = (m2 - mean * mean) / (double)k;
    return MCS_OK;
}

/* The chosen frequencies, deduplicated, each in [1, N). */
static size_t pick_freqs(size_t n, size_t k, size_t *out)
{
    const size_t cand[5] = {1u, k / 2u, k, 2u * k, n / 2u};
    return ex_pick_freqs(n, cand, 5u, out);
}

/* Importance functions, the runs (each with its pattern's exact moments and
 * a spectrum accumulator), and the integrands f and f = 1. */
static int setup_and_measure(const ex_options *opt)
{
    size_t freqs[5];
    size_t nfreq = pick_freqs(opt->n, opt->k, freqs);
    n_bins = opt->n;
    k_samples = opt->k;
    kn = (double)opt->k / (double)opt->n;
    pfloor = 1e-10 * kn * (double)opt->k;
    ex_integrand_bins(opt->n, f);
    for (size_t b = 0; b < opt->n; ++b)
        f_const[b] = 1.0;
    for (int g = EX_G_FOLLOW; g < EX_G_COUNT; ++g)
        if (ex_importance_for(g, opt->n, opt->k, &imps[g]) != MCS_OK)
            return 0;
    for (int r = 0; r < R_COUNT; ++r) {
        ex_run *run = &runs[r];
        mcs_status st = ex_run_setup(run, &exacts[r], &spectra[r], specs[r].kind, opt->n,
                                     opt->k, imp_of(r), opt->seed, 0x400u + (uint64_t)r);
        if (st == MCS_OK) {
            ex_run_probe(run, 0u);
            for (size_t i = 0; i < nfreq; ++i)
                ex_run_probe(run, freqs[i]);
            ex_run_probe_pair(run, 1u, 2u);
            ex_run_probe_pair(run, 3u, 1u);
            ex_run_probe_pair(run, 1u, opt->k + 1u);
            ex_run_integrand(run, f);
            ex_run_integrand(run, f_const);
            st = ex_run_go(run, opt->trials, &spectra[r], NULL);
        }
        if (st != MCS_OK) {
            fprintf(stderr, "sec4: %s: %s\n", specs[r].name, mcs_status_str(st));
            return 0;
        }
    }
    return 1;
}

/* Mean over k >= 1 of the exact power. */
static double theory_mean_power(int r)
{
    double sum = 0.0;
    for (size_t q = 1; q < n_bins; ++q)
        sum += ex_exact_power(&exacts[r], q);
    return sum / (double)(n_bins - 1u);
}

/* Run r for the limit checks of examples/support/importance.c. */
static ex_imp_run imp_run(int r)
{
    ex_imp_run run = {specs[r].kind, specs[r].g, n_bins, k_samples};
    return run;
}

/* The exact power of a stratified run at m bins where it is known in closed
 * form (strata of m/K whole bins; the notes below check it at N), else EX_NA. */
static double exact_power_at(int r, size_t m, size_t q)
{
    const ex_imp_run run = imp_run(r);
    return ex_imp_exact_power(&run, m, q);
}

/* Relative gap of the closed form to the exact value at the larger N, at
 * index q, or of their means over k >= 1 if q == 0. */
static double gap_at_large_n(int r, size_t q, double floor_)
{
    const ex_imp_run run = imp_run(r);
    return ex_imp_limit_gap(&run, q, floor_);
}

/* A row of run r (its name in the pattern column), no limit check. */
static ex_row run_row(const char *quantity, const char *equation, int r, long freq, long freq2,
                      double closed, double exact, double measured, double se, double floor_)
{
    return ex_row_of("sec4", quantity, equation, specs[r].name, freq, freq2, closed, exact,
                     measured, se, floor_);
}

static void harmonic_mean_note(const ex_options *opt)
{
    ex_notef(opt,
             "harmonic means of p = N g: H(g1) = %.6f, H(g2) = %.6f, H(flat) = %.6f, "
             "H(g1b) = %.6f",
             imps[EX_G_FOLLOW].harmonic_mean, imps[EX_G_MISMATCH].harmonic_mean,
             imps[EX_G_FLAT].harmonic_mean, imps[EX_G_BALANCED].harmonic_mean);
}

/* ---- unbiasedness ---- */
static void unbiasedness_section(const ex_options *opt)
{
    ex_heading(opt, "unbiasedness under importance sampling: <s_n> = K/N, so <I> = mean of f "
                    "(eq. 11)");
    for (int r = R_RANDOM_G1; r < R_COUNT; ++r)
        ex_estimator_mean_row(opt, "sec4", specs[r].name, &exacts[r], &runs[r], f);
}

/* <|S_q|^2> of run r: eq. 46 (random) or eq. 51 (stratified) at q = 0, where
 * S_0 is random under importance sampling; eq. 45 or eq. 50 above, with the
 * limit check of eq. 50 where the strata are whole bins. */
static void power_row(const ex_options *opt, int r, size_t q)
{
    const size_t n = opt->n, k = opt->k;
    int is_random = specs[r].kind == MCS_PATTERN_RANDOM;
    double v = 0.0, se;
    mcs_status st;
    if (q == 0u) /* eq. 51 is eq. 46, on eq. 51's domain: K dividing N */
        st = is_random || n % k == 0u ? mcs_eq46_importance_power0(imp_of(r), k, &v)
                                      : MCS_ERR_DOMAIN;
    else
        st = is_random ? mcs_eq45_importance_power(imp_of(r), k, q, &v)
                       : mcs_eq50_importance_stratified_power(imp_of(r), k, q, &v);
    double closed = ex_or_na(st, &v);
    double meas = ex_spectrum_power(&spectra[r], q, &se);
    const char *eq =
        q == 0u ? (is_random ? "eq. 46" : "eq. 51") : (is_random ? "eq. 45" : "eq. 50");
    ex_row row = run_row(q == 0u ? "<|S_0|^2>" : "<|S_k|^2>", eq, r, (long)q, EX_NO_FREQ, closed,
                         ex_exact_power(&exacts[r], q), meas, se, pfloor);
    if (q > 0u)
        row.limit_gap = gap_at_large_n(r, q, pfloor);
    ex_row_print(opt, &row);
}

/* ---- <|S_0|^2> ---- */
static void power0_section(const ex_options *opt)
{
    ex_heading(opt, "<|S_0|^2>: S_0 is random under importance sampling; eq. 46 (random), "
                    "eq. 51 (stratified)");
    for (int r = R_RANDOM_G1; r < R_COUNT; ++r)
        power_row(opt, r, 0u);
}

/* Strata of N/K whole bins (none, flat, g1b): mcs_theory's power against
 * eq. 33's exact form + (K/N)(1/H - 1), largest gap over all k in K/N. */
static double whole_bin_check(void)
{
    const int wr[3] = {R_STRAT, R_STRAT_FLAT, R_STRAT_BAL};
    double worst = 0.0;
    for (size_t q = 1; q < n_bins; ++q) {
        for (int i = 0; i < 3; ++i) {
            double e = exact_power_at(wr[i], n_bins, q);
            if (!isnan(e))
                worst = fmax(worst, fabs(ex_exact_power(&exacts[wr[i]], q) - e) / kn);
        }
    }
    return worst;
}

/* ---- <|S_k|^2>, k >= 1 ---- */
static void power_section(const ex_options *opt)
{
    const int rs[5] = {R_RANDOM_G1, R_RANDOM_G2, R_STRAT_G1, R_STRAT_FLAT, R_STRAT_BAL};
    size_t freqs[5];
    size_t nfreq = pick_freqs(opt->n, opt->k, freqs);
    ex_heading(opt, "<|S_k|^2>, k >= 1: eq. 45 (random, K/(N H)) and eq. 50 (stratified, "
                    "(K/N)(1/H - sinc^2(pi k/K)))");
    double check = whole_bin_check();
    for (int i = 0; i < 5; ++i)
        for (size_t j = 0; j < nfreq; ++j)
            power_row(opt, rs[i], freqs[j]);
    const size_t big = ex_large_n(opt->n);
    if (big > 0u)
        ex_notef(opt,
                 "strata of N/K whole bins (none, flat, g1b): mcspec theory's spectrum equals "
                 "eq. 33's exact finite-N form + (K/N)(1/H - 1) to %.2g K/N over all k; the "
                 "limit checks use that form at %u N",
                 check, (unsigned)(big / opt->n));
    else
        ex_notef(opt,
                 "strata of N/K whole bins (none, flat, g1b): mcspec theory's spectrum equals "
                 "eq. 33's exact finite-N form + (K/N)(1/H - 1) to %.2g K/N over all k; no "
                 "larger N within MCS_MAX_N for the limit checks",
                 check);
}

/* <S_k S_l*> of run r against eq. 43 (random) or eq. 49 (stratified).
 * Returns the larger |z| of its parts against 0 (random runs; else 0). */
static double cross_rows(const ex_options *opt, int r, size_t freq_k, size_t freq_l)
{
    int is_random = specs[r].kind == MCS_PATTERN_RANDOM;
    int idx = ex_run_probe_pair(&runs[r], freq_k, freq_l);
    if (idx < 0)
        return 0.0;
    const size_t k = opt->k;
    double a = 0.0, b = 0.0;
    mcs_status st =
        is_random ? mcs_eq43_importance_cross(imp_of(r), k, freq_k, freq_l, &a, &b)
                  : mcs_eq49_importance_stratified_cross(imp_of(r), k, freq_k, freq_l, &a, &b);
    ex_complex closed = ex_complex_or_na(st, &a, &b);
    ex_complex exact = ex_exact_cross(&exacts[r], freq_k, freq_l);
    ex_complex se, meas = ex_run_mean_pair(&runs[r], idx, &se);
    double floor_ = 1e-10 * kn;
    ex_row_print_complex(opt, "sec4", "<S_k S_l*>", is_random ? "eq. 43" : "eq. 49",
                         specs[r].name, (long)freq_k, (long)freq_l, closed, exact, meas, se,
                         floor_);
    ex_complex zero = {0.0, 0.0};
    return is_random ? ex_z_complex(meas, zero, se, floor_) : 0.0;
}

/* ---- cross spectrum Q_{k-l} ---- */
static void cross_section(const ex_options *opt)
{
    const int rs[4] = {R_RANDOM_G1, R_RANDOM_G2, R_STRAT_G1, R_STRAT_BAL};
    const size_t pk[3] = {1u, 3u, 1u}, pl[3] = {2u, 1u, opt->k + 1u};
    ex_heading(opt, "<S_k S_l*>, k != l (= Cov(S_k, S_l): <S_k> = 0 for k >= 1): eq. 43 "
                    "(K/N) N^{-1/2} Q_{k-l} (random), eq. 49 (stratified)");
    double worst_z = 0.0;
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 3; ++j) {
            if (j == 2 && rs[i] != R_STRAT_BAL)
                continue; /* k = l (mod K): where eq. 49 can hold */
            worst_z = fmax(worst_z, cross_rows(opt, rs[i], pk[j], pl[j]));
        }
    }
    ex_notef(opt,
             "random with importance is not stationary: an off-diagonal <S_k S_l*> lies %.0f "
             "stderr from 0",
             worst_z);
}

/* What the later sections and the summary read from the rows above them. */
typedef struct {
    /* mean over k >= 1 of <|S_k|^2>: measured (Parseval), its stderr, exact */
    double mean_meas[R_COUNT], mean_se[R_COUNT], mean_exact[R_COUNT];
    int rises_everywhere[R_COUNT]; /* exact power above no-IS at every k >= 1 */
    size_t worst_q;                /* where stratified+g1 rises least (0: none) */
    double worst_diff;             /* and by how much */
    double var_meas[R_COUNT], var_se[R_COUNT], var_exact[R_COUNT]; /* Var[I] of f */
} sec4_summary;

/* The run without importance that run r is compared with. */
static int base_of(int r)
{
    return specs[r].kind == MCS_PATTERN_RANDOM ? R_RANDOM : R_STRAT;
}

/* Where the exact rise of stratified+g1 over plain stratified is smallest
 * (k <= N/2; the rest mirror it), and whether any k falls. */
static void rise_scan(sec4_summary *s)
{
    s->worst_q = 0;
    s->worst_diff = (double)INFINITY;
    for (int r = R_RANDOM_G1; r <= R_STRAT_G2; ++r) {
        int b = base_of(r);
        s->rises_everywhere[r] = 1;
        for (size_t q = 1; q < n_bins; ++q) {
            double d = ex_exact_power(&exacts[r], q) - ex_exact_power(&exacts[b], q);
            s->rises_everywhere[r] = s->rises_everywhere[r] && d > 0.0;
            if (r == R_STRAT_G1 && q <= n_bins / 2u && d < s->worst_diff) {
                s->worst_diff = d;
                s->worst_q = q;
            }
        }
    }
}

/* A row of run a's rise over its base run: eq. 45 - eq. 23 = eq. 50 - eq. 33
 * claim (K/N)(1/H - 1), against the exact and the measured difference. The
 * runs are independent, so the standard errors add in quadrature. */
static void rise_row(const ex_options *opt, const char *quantity, int a, long freq,
                     double exact_diff, double meas_diff, double se_a, double se_b)
{
    int is_random = specs[a].kind == MCS_PATTERN_RANDOM;
    double claim = kn * (1.0 / h_of(a) - 1.0);
    ex_row row = run_row(quantity, is_random ? "eq. 45" : "eq. 50", a, freq, EX_NO_FREQ, claim,
                         exact_diff, meas_diff, sqrt(se_a * se_a + se_b * se_b), pfloor);
    ex_row_print(opt, &row);
}

/* Importance minus none, same base pattern: the means over k >= 1, then the
 * power where stratified+g1 rises least. */
static void rise_rows(const ex_options *opt, const sec4_summary *s)
{
    const int rs[5] = {R_RANDOM_G1, R_RANDOM_G2, R_STRAT_G1, R_STRAT_G2, R_STRAT_BAL};
    for (int i = 0; i < 5; ++i) {
        int a = rs[i], b = base_of(a);
        rise_row(opt, "mean power rise vs no IS", a, EX_NO_FREQ,
                 s->mean_exact[a] - s->mean_exact[b], s->mean_meas[a] - s->mean_meas[b],
                 s->mean_se[a], s->mean_se[b]);
    }
    if (s->worst_q == 0u)
        return;
    const int at[2] = {R_RANDOM_G1, R_STRAT_G1};
    size_t q = s->worst_q;
    for (int i = 0; i < 2; ++i) {
        int a = at[i], b = base_of(a);
        double sa, ma = ex_spectrum_power(&spectra[a], q, &sa);
        double sb, mb = ex_spectrum_power(&spectra[b], q, &sb);
        rise_row(opt, "power rise vs no IS", a, (long)q,
                 ex_exact_power(&exacts[a], q) - ex_exact_power(&exacts[b], q), ma - mb, sa,
                 sb);
    }
}

/* ---- the harmonic-mean claim ---- */
static void mean_power_section(const ex_options *opt, sec4_summary *s)
{
    ex_heading(opt, "does importance sampling raise the power spectrum? mean of <|S_k|^2> over "
                    "k >= 1 (Parseval, per trial)");
    for (int r = 0; r < R_COUNT; ++r) {
        double scale = 1.0 / (double)(n_bins - 1u);
        s->mean_meas[r] = ex_mean(&runs[r].parseval, &s->mean_se[r]) * scale;
        s->mean_se[r] *= scale;
        s->mean_exact[r] = theory_mean_power(r);
        int is_random = specs[r].kind == MCS_PATTERN_RANDOM;
        const char *eq = is_random ? (specs[r].g == EX_G_NONE ? "eq. 23" : "eq. 45")
                                   : (specs[r].g == EX_G_NONE ? "eq. 33" : "eq. 50");
        const ex_imp_run run = imp_run(r);
        ex_row row = run_row("mean_k>=1 <|S_k|^2>", eq, r, EX_NO_FREQ, EX_NO_FREQ,
                             ex_imp_mean_power(&run, n_bins, 0), s->mean_exact[r],
                             s->mean_meas[r], s->mean_se[r], pfloor);
        /* EX_NA unless strata are whole bins */
        row.limit_gap = gap_at_large_n(r, 0u, pfloor);
        ex_row_print(opt, &row);
    }
    rise_scan(s);
    rise_rows(opt, s);
}

/* A Var[I] row of run r for f, beside its exact and measured variance. */
static void variance_row(const ex_options *opt, const char *quantity, const char *eq, int r,
                         double closed, const sec4_summary *s, double floor_)
{
    ex_row row = run_row(quantity, eq, r, EX_NO_FREQ, EX_NO_FREQ, closed, s->var_exact[r],
                         s->var_meas[r], s->var_se[r], floor_);
    ex_row_print(opt, &row);
}

/* ---- eq. 52 ---- */
static void eq52_section(const ex_options *opt, sec4_summary *s)
{
    const size_t n = opt->n, k = opt->k;
    ex_heading(opt, "variance of random sampling with importance: eq. 52 as printed (k, l >= 1) "
                    "and corrected (all k, l minus |F_0|^2/N)");
    double v = 0.0;
    for (int r = 0; r < R_COUNT; ++r) {
        s->var_meas[r] = ex_variance(&runs[r].estimate[0], &s->var_se[r]);
        s->var_exact[r] = ex_exact_variance(&exacts[r], f);
    }
    double primal_vs_spectral = 0.0;
    for (int r = R_RANDOM_G1; r <= R_RANDOM_G2; ++r) {
        double fl = 1e-12 * fmax(fabs(s->var_exact[r]), 1e-12);
        double printed = ex_or_na(mcs_eq52_variance_printed(imp_of(r), k, f, &v), &v);
        double corrected = ex_or_na(mcs_eq52_variance_corrected(imp_of(r), k, f, &v), &v);
        double primal = ex_or_na(eq52_corrected_primal(imp_of(r), k, f, &v), &v);
        double conv = ex_or_na(mcs_eq55_variance_convolution(imp_of(r), k, f, &v), &v);
        primal_vs_spectral = fmax(primal_vs_spectral, ex_rel_gap(primal, corrected, 1e-300));
        variance_row(opt, "Var[I] as printed", "eq. 52", r, printed, s, fl);
        variance_row(opt, "Var[I] corrected", "eq. 52c", r, corrected, s, fl);
        variance_row(opt, "Var[I] convolution form", "eq. 55", r, conv, s, fl);
    }
    double v25 = ex_or_na(mcs_eq25_random_variance(n, k, f, &v), &v);
    variance_row(opt, "Var[I] no importance", "eq. 25", R_RANDOM, v25, s,
                 1e-12 * fmax(fabs(v25), 1e-12));
    ex_notef(opt,
             "eq. 52 corrected, spectral and primal forms ((1/K)[(1/N) sum f^2/p - fbar^2]) "
             "agree to %.2g",
             primal_vs_spectral);
}

/* The two bound rows of run r for integrand `which` (0: f, 1: f = 1), and
 * how the measurement compares, appended to above. */
static void eq58_rows(const ex_options *opt, int r, int which, char *above, size_t *used,
                      size_t size)
{
    const size_t k = opt->k;
    const double *ff = which == 0 ? f : f_const;
    double v = 0.0, se = 0.0;
    double exact = ex_exact_variance(&exacts[r], ff);
    double meas = ex_variance(&runs[r].estimate[which], &se);
    double printed = ex_or_na(mcs_eq58_bound_printed(imp_of(r), k, ff, &v), &v);
    double corrected = ex_or_na(mcs_eq58_bound_corrected(imp_of(r), k, ff, &v), &v);
    double fl = 1e-12 * fmax(fabs(exact), 1e-12);
    const char *qn = which == 0 ? "Var[I] bound f" : "Var[I] bound f = 1";
    const char *qc = which == 0 ? "Var[I] bound f corrected" : "Var[I] bound f=1 corrected";
    ex_row row = run_row(qn, "eq. 58", r, EX_NO_FREQ, EX_NO_FREQ, printed, exact, meas, se, fl);
    ex_row_print_bound(opt, &row);
    row = run_row(qc, "eq. 58c", r, EX_NO_FREQ, EX_NO_FREQ, corrected, exact, meas, se, fl);
    ex_row_print_bound(opt, &row);
    if (*used < size) {
        int wrote = snprintf(above + *used, size - *used,
                             "%s %s: measured %s printed, %s corrected; ", specs[r].name,
                             which == 0 ? "f" : "f=1", meas <= printed ? "<=" : ">",
                             meas <= corrected ? "<=" : ">");
        if (wrote > 0)
            *used += (size_t)wrote;
    }
}

/* ---- eq. 58 ---- */
static void eq58_section(const ex_options *opt)
{
    ex_heading(opt, "upper bound on Var[I], random with importance: eq. 58 as printed and "
                    "corrected ((1/K) sum_all |F_n|^2 (1/H - 1/N)); bound rows");
    char above[256] = "";
    size_t used = 0;
    for (int r = R_RANDOM_G1; r <= R_RANDOM_G2; ++r)
        for (int which = 0; which < 2; ++which)
            eq58_rows(opt, r, which, above, &used, sizeof above);
    ex_notef(opt, "measured Var[I] against the bounds: %s", above);
}

/* The power part of the summary: does importance raise it, and by how much. */
static void power_summary(const ex_options *opt, const sec4_summary *s)
{
    const double *mm = s->mean_meas, *ms = s->mean_se;
    ex_notef(opt,
             "random: the exact power %s at every k >= 1 with g1 and %s with g2; mean power "
             "%.4g -> %.4g with g1 (ratio %.4f, 1/H = %.4f), %.4g with g2 (ratio %.4f, 1/H = "
             "%.4f)",
             s->rises_everywhere[R_RANDOM_G1] ? "rises" : "does NOT rise",
             s->rises_everywhere[R_RANDOM_G2] ? "rises" : "does NOT rise", mm[R_RANDOM],
             mm[R_RANDOM_G1], mm[R_RANDOM_G1] / mm[R_RANDOM], 1.0 / h_of(R_RANDOM_G1),
             mm[R_RANDOM_G2], mm[R_RANDOM_G2] / mm[R_RANDOM], 1.0 / h_of(R_RANDOM_G2));
    for (int r = R_STRAT_G1; r <= R_STRAT_G2; ++r)
        ex_notef(opt,
                 "%s: the mean power over k >= 1 rises by %.4g +- %.2g (eq. 50's claim %.4g, "
                 "exact %.4g); the exact power %s at every k >= 1",
                 specs[r].name, mm[r] - mm[R_STRAT],
                 sqrt(ms[r] * ms[r] + ms[R_STRAT] * ms[R_STRAT]), kn * (1.0 / h_of(r) - 1.0),
                 s->mean_exact[r] - s->mean_exact[R_STRAT],
                 s->rises_everywhere[r] ? "rises" : "does NOT rise");
    if (s->worst_q > 0u)
        ex_notef(opt,
                 "stratified+g1: smallest exact change at k = %zu: %+.4g (eq. 50 claims %+.4g at "
                 "every k)",
                 s->worst_q, s->worst_diff, kn * (1.0 / h_of(R_STRAT_G1) - 1.0));
}

static void summary_notes(const ex_options *opt, const sec4_summary *s)
{
    ex_heading(opt, "summary (computed from the rows above)");
    if (opt->n < 2u || !(s->var_exact[R_RANDOM_G2] > 0.0)) {
        ex_note(opt, "(no summary: N = 1 has no frequency k >= 1)");
        return;
    }
    power_summary(opt, s);
    const double *vm = s->var_meas, *vs = s->var_se, *ve = s->var_exact;
    ex_notef(opt,
             "yet Var[I] = %.4g with g1 and %.4g with g2 against %.4g without: the gain or loss "
             "is in the off-diagonal Q_{k-l} terms",
             vm[R_RANDOM_G1], vm[R_RANDOM_G2], vm[R_RANDOM]);
    double v = 0.0;
    double pr = ex_or_na(mcs_eq52_variance_printed(imp_of(R_RANDOM_G2), opt->k, f, &v), &v);
    ex_notef(opt,
             "eq. 52 as printed is off by %.1f%% for g2 (z = %.1f against the measurement); "
             "the corrected form is within %.1f stderr",
             100.0 * (pr - ve[R_RANDOM_G2]) / ve[R_RANDOM_G2],
             ex_z(vm[R_RANDOM_G2], pr, vs[R_RANDOM_G2], 1e-300),
             fabs(ex_z(vm[R_RANDOM_G2], ve[R_RANDOM_G2], vs[R_RANDOM_G2], 1e-300)));
}

int main(int argc, char **argv)
{
    ex_options opt = {64u, 8u, 200000ul, 1u, 0};
    int rc = ex_parse_options(argc, argv, &opt, MCS_MAX_N, EX_MAX_K, help_text);
    if (rc != EX_PARSE_OK)
        return rc;
    if (!setup_and_measure(&opt))
        return 1;

    sec4_summary summary = {0};
    ex_begin(&opt, "Section 4: importance sampling (eq. 38-58)");
    harmonic_mean_note(&opt);
    unbiasedness_section(&opt);              /* eq. 11 */
    ex_outside_section(&opt, f);             /* eq. 11 over the support */
    power0_section(&opt);                    /* eq. 46, 51 */
    power_section(&opt);                     /* eq. 45, 50 */
    cross_section(&opt);                     /* eq. 43, 49 */
    mean_power_section(&opt, &summary);      /* eq. 23, 33, 45, 50: the harmonic-mean claim */
    eq52_section(&opt, &summary);            /* eq. 52, 55, 25 */
    eq58_section(&opt);                      /* eq. 58 */
    summary_notes(&opt, &summary);
    ex_end(&opt);
    return 0;
}
