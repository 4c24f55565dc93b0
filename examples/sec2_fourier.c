/* Section 2 of the note: discrete Fourier analysis of sampling (eq. 7-14).
 * The estimator as a dot product in the Fourier domain (eq. 8), its mean
 * (eq. 9-11) and its variance as the full double sum over frequencies
 * (eq. 13) or only the diagonal, the power spectrum (eq. 14), for stationary
 * patterns (random, uniform jitter), a non-stationary one (stratified with
 * fixed strata) and a biased one (uniform). */
#include "exact.h"
#include "mcspec.h"
#include "measure.h"
#include "readout.h"
#include "report.h"

#include <math.h>
#include <stdio.h>

static const char help_text[] =
    "Section 2: discrete Fourier analysis of sampling (eq. 7-14).\n"
    "Per pattern (random and uniform jitter: stationary; stratified with fixed\n"
    "strata: not stationary; uniform: deterministic and biased) it draws T\n"
    "trials of K samples over N bins and measures Re <S_0>, Re <S_1>, Re <S_K>\n"
    "(direct sums over the samples, Welford, each with its standard error),\n"
    "every <S_k> (mcs_spectrum, for the eq. 9 check) and the estimator\n"
    "I = (1/K) sum f_n s_n of f(x) = 0.5 + 0.3 sin(2 pi x) + 0.4 [x >= 0.3] at\n"
    "the bin centres (Welford: mean, variance and the variance's standard error).\n"
    "Eq. 8 is checked trial by trial with mcs_dft on 1000 extra trials.\n"
    "Eq. 10-11 (unbiasedness) and eq. 13 and 14 (variance) are put beside the\n"
    "exact values from mcspec theory and the measurement. Eq. 13 is evaluated\n"
    "with the exact <S_m S_n*>, eq. 14 with the exact power spectrum, so any gap\n"
    "is the formula's, not a closed form's for the spectrum. Any N up to\n"
    "MCS_MAX_N; eq. 13 needs the N x N moments and is skipped above\n"
    "MCS_MAX_COV_N. A variance's rounding floor is 1e-12 of its size, and at\n"
    "least 1e-15 of E[f^2]/K (the size of the second moments it is formed\n"
    "from), so a variance that is 0 reads 0 however it was rounded.\n";

enum { P_RANDOM, P_JITTER, P_STRAT, P_UNIFORM, P_COUNT };

static const mcs_pattern_kind kinds[P_COUNT] = {MCS_PATTERN_RANDOM, MCS_PATTERN_JITTER,
                                                MCS_PATTERN_STRATIFIED, MCS_PATTERN_UNIFORM};

static ex_run runs[P_COUNT];
static mcs_spectrum spectra[P_COUNT];
static ex_exact exacts[P_COUNT];
static mcs_dft plan;
static double f[MCS_MAX_N], f_re[MCS_MAX_N], f_im[MCS_MAX_N];

/* What the summary reads from the rows above it. */
typedef struct {
    double bias_uniform, bias_z; /* <I> - mean of f for uniform, and its z */
    double v13[P_COUNT], v14[P_COUNT], vex[P_COUNT], vme[P_COUNT], vse[P_COUNT];
    double floor_[P_COUNT];      /* the rounding floor of the variance rows */
} sec2_summary;

/* f at the bin centres and its DFT, then every pattern's run. */
static int measure_all(const ex_options *opt)
{
    ex_integrand_bins(opt->n, f);
    if (mcs_dft_init(&plan, opt->n) != MCS_OK ||
        mcs_dft_real(&plan, opt->n, f, f_re, f_im) != MCS_OK)
        return 0;
    for (int p = 0; p < P_COUNT; ++p) {
        ex_run *run = &runs[p];
        mcs_status st = ex_run_setup(run, &exacts[p], &spectra[p], kinds[p], opt->n, opt->k,
                                     NULL, opt->seed, 0x200u + (uint64_t)kinds[p]);
        if (st == MCS_OK) {
            ex_run_probe(run, 0u);
            ex_run_probe(run, 1u);
            ex_run_probe(run, opt->k);
            ex_run_integrand(run, f);
            st = ex_run_go(run, opt->trials, &spectra[p], NULL);
        }
        if (st != MCS_OK) {
            fprintf(stderr, "sec2: %s: %s\n", mcs_pattern_kind_str(kinds[p]), mcs_status_str(st));
            return 0;
        }
    }
    return 1;
}

/* Eq. 8 trial by trial: the primal dot product against (1/K) sum_n F_n* S_n
 * with S from mcs_dft of the dense s. Returns the largest |difference|. */
static double eq8_check(const ex_options *opt, mcs_pattern_kind kind, unsigned long trials)
{
    static size_t bins[EX_MAX_K];
    static double w[EX_MAX_K], s[MCS_MAX_N], s_re[MCS_MAX_N], s_im[MCS_MAX_N];
    mcs_pattern pat;
    mcs_rng rng;
    double worst = 0.0;
    if (mcs_pattern_init(&pat, kind, opt->n, opt->k, NULL) != MCS_OK)
        return EX_NA;
    mcs_rng_seed(&rng, opt->seed, 0x2f0u + (uint64_t)kind);
    for (unsigned long t = 0; t < trials; ++t) {
        double primal = 0.0, fourier = 0.0;
        if (mcs_pattern_draw(&pat, &rng, opt->k, bins, w, NULL) != MCS_OK ||
            mcs_estimate_bins(opt->n, opt->k, f, bins, w, &primal) != MCS_OK ||
            mcs_pattern_dense(opt->n, opt->k, bins, w, s) != MCS_OK ||
            mcs_dft_real(&plan, opt->n, s, s_re, s_im) != MCS_OK)
            return EX_NA;
        for (size_t q = 0; q < opt->n; ++q) /* Re(F* S); the imaginary parts cancel */
            fourier += f_re[q] * s_re[q] + f_im[q] * s_im[q];
        fourier /= (double)opt->k;
        worst = fmax(worst, fabs(primal - fourier));
    }
    return worst;
}

/* Eq. 9 on one pattern's trials: (1/K) sum_n F_n* <S_n> from mcs_spectrum's
 * means against the mean of I over the same trials; |difference|. */
static double eq9_gap(const ex_options *opt, int p)
{
    double acc = 0.0, re = 0.0, im = 0.0;
    for (size_t q = 0; q < opt->n; ++q)
        if (mcs_spectrum_mean(&spectra[p], q, &re, &im) == MCS_OK)
            acc += f_re[q] * re + f_im[q] * im;
    double mean_i = ex_mean(&runs[p].estimate[0], NULL);
    return fabs(acc / (double)opt->k - mean_i);
}

/* ---- eq. 8 and 9: identities on the measured data ---- */
static void identity_notes(const ex_options *opt)
{
    ex_heading(opt, "eq. 8 and 9 are identities: checked on the trials themselves");
    double worst = 0.0;
    for (int p = 0; p < P_COUNT; ++p)
        worst = fmax(worst, eq8_check(opt, kinds[p], 1000ul));
    ex_notef(opt,
             "eq. 8: (1/K) sum_n f_n s_n = (1/K) sum_n F_n* S_n on 1000 trials per pattern, "
             "largest difference %.2g",
             worst);
    double worst9 = 0.0;
    for (int p = 0; p < P_COUNT; ++p)
        worst9 = fmax(worst9, eq9_gap(opt, p));
    ex_notef(opt,
             "eq. 9: (1/K) sum_n F_n* <S_n> from mcs_spectrum's means = the mean of I over "
             "the same trials, largest difference %.2g",
             worst9);
}

/* Re <S_freq> of pattern p (eq. 10): closed form, mcs_theory, measured. */
static void mean_row(const ex_options *opt, int p, const char *quantity, size_t freq,
                     double closed)
{
    double se = 0.0;
    double kn = (double)opt->k / (double)opt->n;
    int idx = ex_run_probe(&runs[p], freq);
    double exact = ex_exact_mean(&exacts[p], freq).re;
    double meas = ex_mean(&runs[p].s_re[idx], &se);
    ex_row r = ex_row_of("sec2", quantity, "eq. 10", mcs_pattern_kind_str(kinds[p]), (long)freq,
                         EX_NO_FREQ, closed, exact, meas, se, 1e-12 * kn);
    ex_row_print(opt, &r);
}

/* Eq. 10 at k = 0, 1 and K, and eq. 11, for pattern p. */
static void unbiasedness_rows(const ex_options *opt, int p, sec2_summary *s)
{
    const size_t n = opt->n, k = opt->k;
    mean_row(opt, p, "<S_0>", 0u, (double)k / sqrt((double)n));
    if (ex_run_probe(&runs[p], 1u) >= 0)
        mean_row(opt, p, "Re <S_k>", 1u, 0.0);
    if (ex_run_probe(&runs[p], k) >= 0 && k != 1u)
        mean_row(opt, p, "Re <S_k>", k, 0.0);
    ex_row r = ex_estimator_mean_row(opt, "sec2", mcs_pattern_kind_str(kinds[p]), &exacts[p],
                                     &runs[p], f);
    if (p == P_UNIFORM) {
        s->bias_uniform = r.measured - r.closed_form;
        s->bias_z = ex_z(r.measured, r.closed_form, r.stderr_, 1e-12);
    }
}

/* ---- eq. 10 and 11: unbiasedness ---- */
static void unbiasedness_section(const ex_options *opt, sec2_summary *s)
{
    ex_heading(opt, "unbiasedness: eq. 10 (<S_0> = K/sqrt N, <S_k> = 0 for k > 0) and eq. 11 "
                    "(<I> = mean of f)");
    s->bias_uniform = s->bias_z = EX_NA;
    for (int p = 0; p < P_COUNT; ++p)
        unbiasedness_rows(opt, p, s);
}

/* The rounding floor of a Var[I] row: 1e-12 of the variance (eq. 13's
 * value where there is one), and at least 1e-15 of E[f^2]/K, the size of the
 * second moments a variance is the difference of, so that a variance of 0
 * that eq. 13 or 14 rounds to 1e-19 reads 0, not a disagreement. */
static double variance_floor(const ex_options *opt, double v13, double vex)
{
    return ex_variance_floor(opt->n, opt->k, f, isnan(v13) ? vex : v13);
}

/* Var[I] of pattern p by eq. 13 and eq. 14, beside the exact and measured. */
static void variance_rows(const ex_options *opt, int p, sec2_summary *s)
{
    const size_t n = opt->n;
    const char *name = mcs_pattern_kind_str(kinds[p]);
    const ex_exact *ex = &exacts[p];
    double v = 0.0;
    const mcs_theory *th = ex_exact_theory(ex); /* eq. 13: N x N moments only */
    s->v13[p] = th != NULL ? ex_or_na(mcs_eq13_variance(th, n, opt->k, f, &v), &v) : EX_NA;
    s->v14[p] = ex_or_na(mcs_eq14_variance(n, opt->k, f, ex->power, &v), &v);
    s->vex[p] = ex_exact_variance(ex, f);
    s->vme[p] = ex_variance(&runs[p].estimate[0], &s->vse[p]);
    double fl = s->floor_[p] = variance_floor(opt, s->v13[p], s->vex[p]);
    ex_row r = ex_row_of("sec2", "Var[I] full double sum", "eq. 13", name, EX_NO_FREQ, EX_NO_FREQ,
                         s->v13[p], s->vex[p], s->vme[p], s->vse[p], fl);
    ex_row_print(opt, &r);
    r = ex_row_of("sec2", "Var[I] diagonal (power)", "eq. 14", name, EX_NO_FREQ, EX_NO_FREQ,
                  s->v14[p], s->vex[p], s->vme[p], s->vse[p], fl);
    ex_row_print(opt, &r);
}

/* ---- eq. 13 and 14: variance ---- */
static void variance_section(const ex_options *opt, sec2_summary *s)
{
    ex_heading(opt, "variance: eq. 13 (all m, n >= 1, with <S_m S_n*>) vs eq. 14 (diagonal "
                    "m = n only, the power spectrum)");
    for (int p = 0; p < P_COUNT; ++p)
        variance_rows(opt, p, s);
    if (opt->n > (size_t)MCS_MAX_COV_N)
        ex_notef(opt, "eq. 13 needs the N x N moments: skipped above MCS_MAX_COV_N = %d",
                 MCS_MAX_COV_N);
}

/* Eq. 13 where it was formed, else the exact variance (N > MCS_MAX_COV_N). */
static double v13_or_exact(const sec2_summary *s, int p)
{
    return isnan(s->v13[p]) ? s->vex[p] : s->v13[p];
}

/* Random and jitter: eq. 14 against eq. 13 (or the exact variance), and the
 * measurement. A gap between two roundings of a variance that is 0 is no
 * gap, so there the row's floor applies. */
static void stationary_note(const ex_options *opt, const sec2_summary *s)
{
    const double *v14 = s->v14, *vme = s->vme, *vse = s->vse, *fl = s->floor_;
    double gap_fl[2];
    for (int i = 0; i < 2; ++i) {
        int p = i == 0 ? P_RANDOM : P_JITTER;
        gap_fl[i] = s->vex[p] == 0.0 ? fl[p] : 1e-300;
    }
    ex_notef(opt,
             "stationary patterns: eq. 14 = %s to %.2g (random) and %.2g (jitter) relative; "
             "both equal the measured variance within %.1f and %.1f stderr",
             isnan(s->v13[P_RANDOM]) ? "the exact variance" : "eq. 13",
             ex_rel_gap(v14[P_RANDOM], v13_or_exact(s, P_RANDOM), gap_fl[0]),
             ex_rel_gap(v14[P_JITTER], v13_or_exact(s, P_JITTER), gap_fl[1]),
             fabs(ex_z(vme[P_RANDOM], v14[P_RANDOM], vse[P_RANDOM], fl[P_RANDOM])),
             fabs(ex_z(vme[P_JITTER], v14[P_JITTER], vse[P_JITTER], fl[P_JITTER])));
}

static void summary_notes(const ex_options *opt, const sec2_summary *s)
{
    ex_heading(opt, "summary (computed from the rows above)");
    if (!(s->vex[P_STRAT] > 0.0) || !(s->vme[P_STRAT] > 0.0) || !(s->vme[P_RANDOM] > 0.0)) {
        ex_note(opt, "(no summary: the variances vanish for this N and K)");
        return;
    }
    stationary_note(opt, s);
    const double *v14 = s->v14, *vme = s->vme, *vse = s->vse, *fl = s->floor_;
    const int have13 = !isnan(s->v13[P_STRAT]);
    const double v13 = v13_or_exact(s, P_STRAT);
    ex_notef(opt,
             "stratified (fixed strata): the off-diagonal terms of %s are %.1f%% of the "
             "variance; eq. 14 misses the measured variance by %.1f%% (z = %.1f), %s is "
             "within %.1f stderr",
             have13 ? "eq. 13" : "the exact variance", 100.0 * (v13 - v14[P_STRAT]) / v13,
             100.0 * (v14[P_STRAT] - vme[P_STRAT]) / vme[P_STRAT],
             ex_z(vme[P_STRAT], v14[P_STRAT], vse[P_STRAT], fl[P_STRAT]),
             have13 ? "eq. 13" : "the exact variance",
             fabs(ex_z(vme[P_STRAT], v13, vse[P_STRAT], fl[P_STRAT])));
    if (have13)
        ex_notef(opt,
                 "uniform: <I> is biased by %.4g (deterministic, z = %.3g); its variance is 0 "
                 "and eq. 13 gives (bias)^2 = %.4g instead (%.4g): the mean squared error",
                 s->bias_uniform, s->bias_z, s->bias_uniform * s->bias_uniform,
                 s->v13[P_UNIFORM]);
    else
        ex_notef(opt,
                 "uniform: <I> is biased by %.4g (deterministic, z = %.3g); its variance is 0 "
                 "(eq. 13, which gives (bias)^2 = %.4g, the mean squared error, is skipped)",
                 s->bias_uniform, s->bias_z, s->bias_uniform * s->bias_uniform);
}

int main(int argc, char **argv)
{
    ex_options opt = {64u, 8u, 200000ul, 1u, 0};
    int rc = ex_parse_options(argc, argv, &opt, MCS_MAX_N, EX_MAX_K, help_text);
    if (rc != EX_PARSE_OK)
        return rc;
    if (!measure_all(&opt))
        return 1;

    sec2_summary summary;
    ex_begin(&opt, "Section 2: discrete Fourier analysis of sampling (eq. 7-14)");
    identity_notes(&opt);                  /* eq. 8 and 9 */
    unbiasedness_section(&opt, &summary);  /* eq. 10 and 11 */
    variance_section(&opt, &summary);      /* eq. 13 and 14 */
    summary_notes(&opt, &summary);
    ex_end(&opt);
    return 0;
}
