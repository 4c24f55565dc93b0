/* Section 5: the questions the note leaves open, answered from exact theory
 * (mcspec theory at any N) beside measurement, with verdicts by the rule of
 * the other sections: perfect importance sampling, importance with uniform
 * jitter and uniform sampling, the continuous limit of 1/H, where importance
 * sampling's gain lives, stratified importance sampling with misaligned
 * strata, and the convergence of Var[I] with K. */
#include "exact.h"
#include "fit.h"
#include "importance.h"
#include "mcspec.h"
#include "measure.h"
#include "readout.h"
#include "report.h"

#include <float.h>
#include <math.h>
#include <stdio.h>

static const char help_text[] =
    "Section 5: the note's open questions, exact theory beside measurement.\n"
    "f(x) = 0.5 + 0.3 sin(2 pi x) + 0.4 [x >= 0.3] at the bin centres; importance\n"
    "functions g1 (follows f), g2 = 0.2 + (1 - x)^2 (against f, smooth), gu = 1 +\n"
    "0.6 sin(10 pi x + 1) (unrelated), gs = 0.45 + 0.3 sin(2 pi x) (smooth,\n"
    "periodic), g = f (perfect), g1b (g1 with strata of whole bins).\n"
    "1. g = f: Var[I] = 0 for random, stratified and jitter, while the power\n"
    "   spectrum rises by 1/H (eq. 45, 55).\n"
    "2. g1 with uniform jitter and uniform sampling: their spectra against eq. 37,\n"
    "   stationarity, bias, and Var[I] against random (eq. 52c) and stratified.\n"
    "3. 1/H (eq. 44) against the integral of 1/p for N = 8 .. MCS_MAX_N, for gs\n"
    "   and g2; measured as (N/K) times the mean power over k >= 1.\n"
    "4. Var[I] of random sampling split into its diagonal (power spectrum) and\n"
    "   off-diagonal (Q_{k-l}) parts for no g, g1, gu and g2.\n"
    "5. Stratified with importance when strata do not line up with bins: g\n"
    "   blended from g1b (aligned) to g1; the error of eq. 51 and of eq. 50's\n"
    "   finite-N form against the mean misalignment (in bins) of the strata.\n"
    "6. Exact and measured Var[I] against K = 2 .. N/16 at N = min(32 N,\n"
    "   MCS_MAX_N), for a smooth non-periodic f (0.5 + 0.3 sin(2 pi x) + 0.5 x^2)\n"
    "   and the discontinuous f; the fitted log-log slopes beside the known\n"
    "   rates. --convergence-csv FILE writes that data as CSV.\n"
    "Questions 3 and 6 use a tenth of the trials per point. --n and --k set\n"
    "N and K of questions 1, 2, 4 and 5 (5 needs K dividing N).\n";

static double f[MCS_MAX_N];
static ex_run run, base_run;
static ex_exact ex, base_ex;
static mcs_spectrum spec;
static mcs_importance imp, imp2;
static mcs_theory_spectrum conv_ts;

/* One measured pattern: kind through im (NULL: none) over n bins, k samples. */
typedef struct {
    mcs_pattern_kind kind;
    const mcs_importance *im;
    size_t n, k;
    unsigned long trials;
    uint64_t stream;
    const double *fn; /* its integrand over n bins, or NULL */
} sec5_run;

/* Draws the run with its integrand; its exact moments into e and its
 * spectrum into s unless NULL. 0 (after a message) on failure. */
static int measure(const ex_options *opt, const sec5_run *sr, ex_run *r, ex_exact *e,
                   mcs_spectrum *s)
{
    mcs_status st = ex_run_setup(r, NULL, s, sr->kind, sr->n, sr->k, sr->im, opt->seed, sr->stream);
    if (st == MCS_OK && e != NULL) /* exact at every N from the O(N) route: no cancellation */
        st = ex_exact_init_spectrum(e, &r->pattern);
    if (st == MCS_OK) {
        if (sr->fn != NULL)
            ex_run_integrand(r, sr->fn);
        st = ex_run_go(r, sr->trials, s, NULL);
    }
    if (st != MCS_OK)
        fprintf(stderr, "sec5: %s: %s\n", mcs_pattern_kind_str(sr->kind), mcs_status_str(st));
    return st == MCS_OK;
}

static void row(const ex_options *opt, const char *quantity, const char *eq, const char *pattern,
                long freq, double closed, double exact, double measured, double se, double floor_)
{
    ex_row r = ex_row_of("sec5", quantity, eq, pattern, freq, EX_NO_FREQ, closed, exact, measured,
                         se, floor_);
    ex_row_print(opt, &r);
}

/* ---- 1. perfect importance sampling ------------------------------------ */

static int q1_power_rows(const ex_options *opt, double kn, double h)
{
    const double pfloor = 1e-10 * kn * (double)opt->k;
    const size_t qs[2] = {1u, opt->k};
    for (int i = 0; i < 2; ++i) {
        if (qs[i] >= opt->n || (i == 1 && qs[1] == qs[0]))
            continue;
        double se, meas = ex_spectrum_power(&spec, qs[i], &se);
        row(opt, "<|S_k|^2> g = f", "eq. 45", "random+g=f", (long)qs[i], kn / h,
            ex_exact_power(&ex, qs[i]), meas, se, pfloor);
    }
    double sa, sb, ma = ex_run_mean_power(&run, &sa), mb = ex_run_mean_power(&base_run, &sb);
    row(opt, "mean power rise vs no IS", "eq. 45", "random+g=f", EX_NO_FREQ, kn * (1.0 / h - 1.0),
        ex_exact_mean_power(&ex) - ex_exact_mean_power(&base_ex), ma - mb, sqrt(sa * sa + sb * sb),
        pfloor);
    return 1;
}

static int q1_perfect(const ex_options *opt)
{
    const size_t n = opt->n, k = opt->k;
    ex_heading(opt, "1. g = f (perfect importance sampling): Var[I] = 0, yet every <|S_k|^2> "
                    "rises by 1/H");
    if (ex_importance_for(EX_G_PROPORTIONAL, n, k, &imp) != MCS_OK)
        return 0;
    const double kn = (double)k / (double)n, h = imp.harmonic_mean;
    sec5_run sr = {MCS_PATTERN_RANDOM, &imp, n, k, opt->trials, 0x510u, f};
    sec5_run sb = {MCS_PATTERN_RANDOM, NULL, n, k, opt->trials, 0x511u, f};
    if (!measure(opt, &sr, &run, &ex, &spec) || !measure(opt, &sb, &base_run, &base_ex, NULL))
        return 0;
    q1_power_rows(opt, kn, h);
    double e55 = 0.0, v[3] = {0.0, 0.0, 0.0};
    e55 = ex_or_na(mcs_eq55_variance_convolution(&imp, k, f, &e55), &e55);
    const mcs_pattern_kind kinds[3] = {MCS_PATTERN_RANDOM, MCS_PATTERN_STRATIFIED,
                                       MCS_PATTERN_JITTER};
    for (int i = 0; i < 3; ++i) {
        sr.kind = kinds[i];
        sr.stream = 0x512u + (uint64_t)i;
        if (i > 0 && !measure(opt, &sr, &run, &ex, NULL))
            return 0;
        double se, meas = ex_variance(&run.estimate[0], &se);
        v[i] = ex_exact_variance(&ex, f);
        char pattern[32];
        snprintf(pattern, sizeof pattern, "%s+g=f", mcs_pattern_kind_str(kinds[i]));
        row(opt, "Var[I] g = f", "eq. 55", pattern, EX_NO_FREQ, e55, v[i], meas, se,
            ex_variance_floor(n, k, f, v[i]));
    }
    ex_notef(opt,
             "g = f: exact Var[I] %.3g (random), %.3g (stratified), %.3g (jitter), 0 but for "
             "rounding, while <|S_k|^2> rises by 1/H = %.4f at every k >= 1: the off-diagonal "
             "Q_{k-l} terms cancel the diagonal exactly",
             v[0], v[1], v[2], 1.0 / h);
    return 1;
}

/* ---- 2. importance with uniform jitter and uniform sampling ----------- */

/* Jitter with g1 (in run, spec): spectrum against eq. 37, stationarity.
 * Returns the largest |z| of an off-diagonal <S_1 S_l*> against 0. */
static double q2_jitter_rows(const ex_options *opt)
{
    const size_t n = opt->n, k = opt->k;
    const double kn = (double)k / (double)n, pfloor = 1e-10 * kn * (double)k;
    const size_t qs[3] = {1u, k, k + 1u};
    for (int i = 0; i < 3; ++i) {
        if (qs[i] >= n || (i > 0 && qs[i] == qs[i - 1]))
            continue;
        double v = 0.0, se, meas = ex_spectrum_power(&spec, qs[i], &se);
        row(opt, "<|S_k|^2> jitter+g1", "eq. 37", "jitter+g1", (long)qs[i],
            ex_or_na(mcs_eq37_jitter_power(n, k, qs[i], &v), &v), ex_exact_power(&ex, qs[i]), meas,
            se, pfloor);
    }
    double worst = 0.0;
    const size_t ls[2] = {2u, k + 1u};
    for (int i = 0; i < 2; ++i) {
        int idx = ex_run_probe_pair(&run, 1u, ls[i]);
        if (idx < 0 || (i == 1 && ls[1] == ls[0]))
            continue;
        ex_complex se, meas = ex_run_mean_pair(&run, idx, &se), zero = {0.0, 0.0};
        ex_row_print_complex(opt, "sec5", "<S_k S_l*> if stationary", "eq. 14", "jitter+g1", 1,
                             (long)ls[i], zero, ex_exact_cross(&ex, 1u, ls[i]), meas, se,
                             1e-10 * kn);
        worst = fmax(worst, ex_z_complex(meas, zero, se, 1e-10 * kn));
    }
    return worst;
}

/* Var[I] of a measured run (in run) against a comparison value. */
static double q2_variance_row(const ex_options *opt, const char *quantity, const char *eq,
                              const char *pattern, double closed)
{
    double se, meas = ex_variance(&run.estimate[0], &se), v = ex_exact_variance(&ex, f);
    row(opt, quantity, eq, pattern, EX_NO_FREQ, closed, v, meas, se,
        ex_variance_floor(opt->n, opt->k, f, v));
    return v;
}

static int q2_jitter_uniform(const ex_options *opt)
{
    const size_t n = opt->n, k = opt->k;
    ex_heading(opt, "2. importance g1 with uniform jitter and with uniform sampling: spectra, "
                    "stationarity, Var[I] against random and stratified");
    if (ex_importance_for(EX_G_FOLLOW, n, k, &imp) != MCS_OK)
        return 0;
    double e52 = 0.0, v = 0.0;
    e52 = ex_or_na(mcs_eq52_variance_corrected(&imp, k, f, &e52), &e52);
    sec5_run sr = {MCS_PATTERN_STRATIFIED, &imp, n, k, opt->trials, 0x520u, f};
    if (!measure(opt, &sr, &run, &ex, NULL))
        return 0;
    const double v_strat = q2_variance_row(opt, "Var[I] stratified+g1 vs random", "eq. 52c",
                                           "stratified+g1", e52);
    sr.kind = MCS_PATTERN_JITTER;
    sr.stream = 0x521u;
    if (ex_run_setup(&run, NULL, &spec, sr.kind, n, k, &imp, opt->seed, sr.stream) != MCS_OK ||
        ex_exact_init_spectrum(&ex, &run.pattern) != MCS_OK)
        return 0;
    ex_run_probe_pair(&run, 1u, 2u);
    ex_run_probe_pair(&run, 1u, k + 1u);
    ex_run_integrand(&run, f);
    if (ex_run_go(&run, opt->trials, &spec, NULL) != MCS_OK)
        return 0;
    const double z_off = q2_jitter_rows(opt);
    q2_variance_row(opt, "Var[I] jitter+g1 vs random", "eq. 52c", "jitter+g1", e52);
    const double v_jit = q2_variance_row(opt, "Var[I] jitter+g1 vs stratified", "exact",
                                         "jitter+g1", v_strat);
    sr.kind = MCS_PATTERN_UNIFORM;
    sr.stream = 0x522u;
    if (!measure(opt, &sr, &run, &ex, &spec))
        return 0;
    ex_row r = ex_estimator_mean_row(opt, "sec5", "uniform+g1", &ex, &run, f);
    double se, meas = ex_spectrum_power(&spec, k % n, &se);
    row(opt, "<|S_k|^2> uniform+g1", "eq. 37", "uniform+g1", (long)(k % n),
        ex_or_na(mcs_eq37_jitter_power(n, k, k % n, &v), &v), ex_exact_power(&ex, k % n), meas,
        se, 1e-10 * (double)k * (double)k / (double)n);
    if (!(v_strat > 0.0 && e52 > 0.0)) {
        ex_note(opt, "(no summary: the variances vanish for this N and K)");
        return 1;
    }
    ex_notef(opt,
             "jitter with g1 is not stationary (an off-diagonal <S_1 S_l*> lies %.0f stderr from "
             "0) and its spectrum is not eq. 37's; Var[I] = %.4g, %.3g times stratified+g1's "
             "(%.4g) and %.3g times random+g1's (%.4g); uniform with g1 is biased by %.3g",
             z_off, v_jit, v_jit / v_strat, v_strat, v_jit / e52, e52, r.exact - r.closed_form);
    return 1;
}

/* ---- 3. the continuous limit: 1/H against the integral of 1/p ---------- */

/* 1/H of g over m bins (EX_NA if it cannot be built). */
static double inverse_h(int g, size_t m, size_t k, mcs_importance *im)
{
    return ex_importance_for(g, m, k, im) == MCS_OK ? 1.0 / im->harmonic_mean : EX_NA;
}

/* The rows of one g for N = 8, 16, .. MCS_MAX_N; *rate: the slope of
 * |1/H - integral| against N over N >= 64; *exact_at: the first N where the
 * two agree to rounding, 16 ulps of the integral (0: none). */
static int q3_one_g(const ex_options *opt, int g, const char *pattern, double *rate,
                    size_t *exact_at)
{
    const double integral = ex_g_inverse_integral(g);
    double ns[16], gaps[16];
    size_t count = 0;
    *exact_at = 0u;
    for (size_t m = 8u; m <= (size_t)MCS_MAX_N && count < 16u; m *= 2u) {
        const double ih = inverse_h(g, m, opt->k, &imp);
        const double next =
            2u * m <= (size_t)MCS_MAX_N ? inverse_h(g, 2u * m, opt->k, &imp2) : EX_NA;
        sec5_run sr = {MCS_PATTERN_RANDOM, &imp,  m, opt->k, opt->trials / 10u + 4u,
                       0x530u + (uint64_t)m, NULL};
        if (isnan(ih) || !measure(opt, &sr, &run, NULL, NULL))
            return 0;
        double se, meas = ex_run_mean_power(&run, &se) * (double)m / (double)opt->k;
        char quantity[48];
        snprintf(quantity, sizeof quantity, "1/H at N = %zu", m);
        ex_row r = ex_row_of("sec5", quantity, "eq. 44", pattern, EX_NO_FREQ, EX_NO_FREQ,
                             integral, ih, meas, se * (double)m / (double)opt->k, 1e-13);
        r.limit_gap = isnan(next) ? EX_NA : ex_rel_gap(integral, next, 1e-13);
        ex_row_print(opt, &r);
        ns[count] = (double)m;
        gaps[count++] = fabs(ih - integral);
        /* "Equal to rounding": within a few ulps of the integral, not merely
         * within the row's 1e-13 (at N = 32 the gap of gs is 8.5e-14, a real
         * quadrature gap). */
        if (*exact_at == 0u && fabs(ih - integral) <= 16.0 * DBL_EPSILON * fabs(integral))
            *exact_at = m;
    }
    *rate = ex_loglog_slope(count - 3u, ns + 3u, gaps + 3u, NULL, NULL); /* N >= 64 */
    return 1;
}

static int q3_continuous(const ex_options *opt)
{
    ex_heading(opt, "3. the continuous limit: 1/H = (1/N) sum 1/p_n against the integral of 1/p "
                    "as N grows (measured: (N/K) mean_k>=1 <|S_k|^2>, eq. 45)");
    double rate_s, rate_2;
    size_t at_s, at_2;
    if (!q3_one_g(opt, EX_G_SMOOTH, "random+gs", &rate_s, &at_s) ||
        !q3_one_g(opt, EX_G_MISMATCH, "random+g2", &rate_2, &at_2))
        return 0;
    ex_notef(opt,
             "1/H tends to the integral of 1/p: for g2 (smooth, not periodic) the gap falls as "
             "N^%.2f, the midpoint rule's N^-2; for gs (smooth, periodic) faster than any "
             "power: equal to rounding (16 ulps) from N = %zu (0: not by MCS_MAX_N)",
             rate_2, at_s);
    return 1;
}

/* ---- 4. where importance sampling's gain lives ------------------------- */

static mcs_dft plan;
static double f_re[MCS_MAX_N], f_im[MCS_MAX_N];

/* The diagonal part of Var[I], (1/K^2) sum_k |F_k|^2 Var(S_k), of e, over
 * k >= first (0: all of it; 1: the power terms without k = 0's variance). */
static double diagonal_part(const ex_exact *e, size_t first)
{
    double sum = 0.0;
    for (size_t q = first; q < e->n; ++q)
        sum += (f_re[q] * f_re[q] + f_im[q] * f_im[q]) * ex_exact_covariance(e, q, q).re;
    return sum / ((double)e->k * (double)e->k);
}

/* The same from eq. 45 and 46: Var(S_k) = (K/N)/H for k >= 1 and
 * (K/N)(1/H - 1) at k = 0 (random sampling, importance of harmonic mean h). */
static double diagonal_closed(size_t n, size_t k, double h)
{
    double ac = 0.0;
    for (size_t q = 1; q < n; ++q)
        ac += f_re[q] * f_re[q] + f_im[q] * f_im[q];
    const double kn = (double)k / (double)n, kd = (double)k;
    return (kn / h * ac + (f_re[0] * f_re[0]) * kn * (1.0 / h - 1.0)) / (kd * kd);
}

/* The four rows of one g (im NULL: none); out: total, diagonal, off-diagonal,
 * (in: the run's stream), the diagonal's k >= 1 terms. */
static int q4_rows(const ex_options *opt, const mcs_importance *im, const char *pattern,
                   double *out)
{
    const size_t n = opt->n, k = opt->k;
    sec5_run sr = {MCS_PATTERN_RANDOM, im, n, k, opt->trials, 0x540u + (uint64_t)(out[3]), f};
    if (!measure(opt, &sr, &run, &ex, NULL))
        return 0;
    double v = 0.0, se, meas = ex_variance(&run.estimate[0], &se);
    const double h = im != NULL ? im->harmonic_mean : 1.0;
    double total = im != NULL ? ex_or_na(mcs_eq52_variance_corrected(im, k, f, &v), &v)
                              : ex_or_na(mcs_eq25_random_variance(n, k, f, &v), &v);
    const double var = ex_exact_variance(&ex, f), diag = diagonal_part(&ex, 0u);
    const double dc = diagonal_closed(n, k, h), fl = ex_variance_floor(n, k, f, var);
    row(opt, "Var[I]", im != NULL ? "eq. 52c" : "eq. 25", pattern, EX_NO_FREQ, total, var, meas,
        se, fl);
    row(opt, "  diagonal part", "eq. 45-46", pattern, EX_NO_FREQ, dc, diag, EX_NA, EX_NA, fl);
    row(opt, "  off-diagonal part Q_{k-l}", "eq. 43", pattern, EX_NO_FREQ, total - dc,
        var - diag, EX_NA, EX_NA, fl);
    row(opt, "Var[I] if diagonal only", "eq. 14", pattern, EX_NO_FREQ, diag, var, meas, se, fl);
    out[0] = var;
    out[1] = diag;
    out[2] = var - diag;
    out[4] = diagonal_part(&ex, 1u);
    return 1;
}

static int q4_split(const ex_options *opt)
{
    ex_heading(opt, "4. where the gain of importance sampling lives: Var[I] of random sampling "
                    "= diagonal (power spectrum) + off-diagonal (Q_{k-l}) parts");
    if (mcs_dft_init(&plan, opt->n) != MCS_OK ||
        mcs_dft_real(&plan, opt->n, f, f_re, f_im) != MCS_OK)
        return 0;
    const int gs[4] = {EX_G_NONE, EX_G_FOLLOW, EX_G_UNRELATED, EX_G_MISMATCH};
    const char *names[4] = {"random", "random+g1", "random+gu", "random+g2"};
    double parts[4][5];
    for (int i = 0; i < 4; ++i) {
        parts[i][3] = (double)i; /* the run's stream */
        if (gs[i] != EX_G_NONE && ex_importance_for(gs[i], opt->n, opt->k, &imp) != MCS_OK)
            return 0;
        if (!q4_rows(opt, gs[i] != EX_G_NONE ? &imp : NULL, names[i], parts[i]))
            return 0;
    }
    for (int i = 1; i < 4 && parts[0][0] > 0.0; ++i)
        ex_notef(opt,
                 "%s: the diagonal part %s by %.4g (its k >= 1 power terms by %+.3g, the "
                 "rest is k = 0's variance term), the off-diagonal part adds %+.4g: Var[I] "
                 "%.3g times no g's (%s)",
                 names[i], parts[i][1] > parts[0][1] ? "rises" : "falls",
                 fabs(parts[i][1] - parts[0][1]), parts[i][4] - parts[0][4], parts[i][2],
                 parts[i][0] / parts[0][0],
                 parts[i][0] < parts[0][0] ? "a gain: the off-diagonal part outweighs the rise"
                                           : "a loss");
    return 1;
}

/* ---- 5. stratified with importance, strata off the bins --------------- */

static double moved_w[MCS_MAX_N];

/* g1b (in imp2, every block of N/K bins of mass 1/K) with mass eps moved,
 * at every inner block edge e, from bin e into bin e - 1: the CDF at e rises
 * by eps, so the stratum edge j/K falls inside bin e - 1, delta bins below e
 * (eps = delta/(1 - delta) g_{e-1}, at most half of g_e). */
static int misaligned_g(size_t n, size_t k, double delta)
{
    for (size_t b = 0; b < n; ++b)
        moved_w[b] = imp2.g[b];
    for (size_t e = n / k; e < n; e += n / k) {
        const double eps = fmin(delta / (1.0 - delta) * imp2.g[e - 1u], 0.5 * imp2.g[e]);
        moved_w[e - 1u] += eps;
        moved_w[e] -= eps;
    }
    return mcs_importance_init(&imp, n, moved_w) == MCS_OK;
}

/* Stratified sampling through g1b with strata moved off the bin edges by
 * delta: rows for eq. 51 and eq. 50's finite-N form; out: the misalignment,
 * their relative errors. */
static int q5_rows(const ex_options *opt, double delta, uint64_t stream, double *out)
{
    const size_t n = opt->n, k = opt->k;
    if (!misaligned_g(n, k, delta))
        return 0;
    sec5_run sr = {MCS_PATTERN_STRATIFIED, &imp, n, k, opt->trials, stream, f};
    if (!measure(opt, &sr, &run, &ex, &spec))
        return 0;
    const double kn = (double)k / (double)n, pfloor = 1e-10 * kn * (double)k;
    double v = 0.0, se, closed0 = ex_or_na(mcs_eq46_importance_power0(&imp, k, &v), &v);
    double closed = 0.0;
    for (size_t q = 1; q < n; ++q)
        closed += ex_whole_bin_power_at(n, k, imp.harmonic_mean, q) / (double)(n - 1u);
    char q0[48], qm[48];
    out[0] = ex_strata_misalignment(&imp, k);
    snprintf(q0, sizeof q0, "<|S_0|^2> misaligned %.3f", out[0]);
    snprintf(qm, sizeof qm, "mean_k>=1 <|S_k|^2> mis. %.3f", out[0]);
    const double p0 = ex_exact_power(&ex, 0u), pm = ex_exact_mean_power(&ex);
    double meas = ex_spectrum_power(&spec, 0u, &se);
    row(opt, q0, "eq. 51", "stratified+g", 0, closed0, p0, meas, se, pfloor);
    meas = ex_run_mean_power(&run, &se);
    row(opt, qm, "eq. 50 N", "stratified+g", EX_NO_FREQ, closed, pm, meas, se, pfloor);
    out[1] = fabs(closed0 - p0) / p0;
    out[2] = fabs(closed - pm) / pm;
    return 1;
}

static int q5_misalignment(const ex_options *opt)
{
    const size_t n = opt->n, k = opt->k;
    ex_heading(opt, "5. stratified with importance, strata not on bin edges: g1b with mass moved "
                    "across its block edges; eq. 51 and eq. 50's finite-N form (K/N)/H + eq. 32");
    if (n % k != 0u || k < 2u) {
        ex_note(opt, "(skipped: eq. 50 and 51 need K dividing N, and K >= 2 for a stratum edge)");
        return 1;
    }
    if (ex_importance_for(EX_G_BALANCED, n, k, &imp2) != MCS_OK)
        return 0;
    const double deltas[6] = {0.0, 0.03, 0.06, 0.12, 0.25, 0.45};
    double mis[6], e51[6], e50[6];
    for (int i = 0; i < 6; ++i) {
        double out[3];
        if (!q5_rows(opt, deltas[i], 0x550u + (uint64_t)i, out))
            return 0;
        mis[i] = out[0];
        e51[i] = out[1];
        e50[i] = out[2];
    }
    ex_notef(opt,
             "aligned strata (misalignment %.2g bins): eq. 51 and eq. 50's finite-N form are "
             "exact (relative errors %.2g, %.2g); misaligned, their errors grow as "
             "misalignment^%.2f and ^%.2f, to %.3g and %.3g at %.2f bins",
             mis[0], e51[0], e50[0], ex_loglog_slope(5u, mis + 1, e51 + 1, NULL, NULL),
             ex_loglog_slope(5u, mis + 1, e50 + 1, NULL, NULL), e51[5], e50[5], mis[5]);
    return 1;
}

/* ---- 6. convergence of Var[I] with K ---------------------------------- */

#define CONV_MAX_K 12
static double conv_f[2][MCS_MAX_N];
static const char *const conv_f_name[2] = {"fs", "fe"}; /* smooth, with an edge */
static const mcs_pattern_kind conv_kinds[4] = {MCS_PATTERN_RANDOM, MCS_PATTERN_STRATIFIED,
                                               MCS_PATTERN_JITTER, MCS_PATTERN_HOMOGENIZED};
/* Known rates: random K^-1; stratified K^-3 for smooth f, K^-2 with an edge;
 * jitter and homogenized K^-2: f(1) != f(0) is an edge of the periodized f. */
static const double known_rate[2][4] = {{-1.0, -3.0, -2.0, -2.0}, {-1.0, -2.0, -2.0, -2.0}};

/* Exact and measured Var[I] of one kind and f at K = ks[i]. */
static int q6_point(const ex_options *opt, size_t n, int fi, int ki, size_t k, double *v,
                    double *m, double *se)
{
    mcs_status st = ex_run_init(&run, conv_kinds[ki], n, k, NULL, opt->seed,
                                0x560u + (uint64_t)(16 * fi + 4 * ki) + (uint64_t)k * 64u);
    if (st == MCS_OK && ex_run_integrand(&run, conv_f[fi]) >= 0)
        st = ex_run_go(&run, opt->trials / 10u + 4u, NULL, NULL);
    if (st == MCS_OK)
        st = mcs_theory_spectrum_init(&conv_ts, &run.pattern);
    if (st == MCS_OK)
        st = mcs_theory_spectrum_variance(&conv_ts, n, k, conv_f[fi], v);
    if (st != MCS_OK)
        return 0;
    *m = ex_variance(&run.estimate[0], se);
    return 1;
}

/* The per-K rows and the slope row of one kind and f, and its CSV lines. */
static int q6_series(const ex_options *opt, size_t n, int fi, int ki, FILE *csv)
{
    double ks[CONV_MAX_K], v[CONV_MAX_K], m[CONV_MAX_K], se[CONV_MAX_K];
    size_t count = 0;
    char pattern[32], quantity[32];
    snprintf(pattern, sizeof pattern, "%s %s", mcs_pattern_kind_str(conv_kinds[ki]),
             conv_f_name[fi]);
    for (size_t k = 2u; 16u * k <= n && count < CONV_MAX_K; k *= 2u, ++count) {
        if (!q6_point(opt, n, fi, ki, k, &v[count], &m[count], &se[count]))
            return 0;
        ks[count] = (double)k;
        double e25 = 0.0;
        e25 = ki == 0 ? ex_or_na(mcs_eq25_random_variance(n, k, conv_f[fi], &e25), &e25) : EX_NA;
        snprintf(quantity, sizeof quantity, "Var[I] K = %zu", k);
        row(opt, quantity, ki == 0 ? "eq. 25" : "exact", pattern, EX_NO_FREQ, e25, v[count],
            m[count], se[count], ex_variance_floor(n, k, conv_f[fi], v[count]));
        if (csv != NULL)
            fprintf(csv, "%s,%s,%zu,%zu,%.10g,%.10g,%.10g,%g\n", conv_f_name[fi],
                    mcs_pattern_kind_str(conv_kinds[ki]), n, k, v[count], m[count], se[count],
                    known_rate[fi][ki]);
    }
    /* Both fits weigh each K by the measured relative error, so that the
     * measured slope estimates the same weighted slope as the exact one. */
    double slope_se, se_exact[CONV_MAX_K];
    for (size_t i = 0; i < count; ++i)
        se_exact[i] = se[i] * v[i] / m[i];
    const size_t half = count / 2u;
    const double exact = ex_loglog_slope(count, ks, v, se_exact, NULL);
    const double upper = ex_loglog_slope(count - half, ks + half, v + half, se_exact + half, NULL);
    const double meas = ex_loglog_slope(count, ks, m, se, &slope_se);
    ex_row r = ex_row_of("sec5", "slope of Var[I] vs K", "rate", pattern, EX_NO_FREQ,
                         EX_NO_FREQ, known_rate[fi][ki], exact, meas, slope_se, 1e-12);
    r.limit_gap = ex_rel_gap(known_rate[fi][ki], upper, 1e-12); /* the slope at large K */
    ex_row_print(opt, &r);
    return 1;
}

static int q6_convergence(const ex_options *opt, const char *csv_path)
{
    const size_t n = 32u * opt->n < (size_t)MCS_MAX_N ? 32u * opt->n : (size_t)MCS_MAX_N;
    ex_heading(opt, "6. convergence: exact and measured Var[I] against K on a log-log scale; "
                    "fitted slopes beside the known rates (limit: the slope over the larger "
                    "K is closer)");
    ex_notef(opt, "N = %zu bins, K = 2 .. N/16; fs = 0.5 + 0.3 sin(2 pi x) + 0.5 x^2 (smooth, "
                  "not periodic), fe = the shared f (an edge at 0.3)", n);
    for (size_t b = 0; b < n; ++b) {
        const double x = ((double)b + 0.5) / (double)n;
        conv_f[0][b] = 0.5 + 0.3 * sin(6.283185307179586 * x) + 0.5 * x * x;
        conv_f[1][b] = ex_integrand(x);
    }
    FILE *csv = NULL;
    if (csv_path != NULL) {
        csv = fopen(csv_path, "w");
        if (csv == NULL) {
            fprintf(stderr, "sec5: cannot write %s\n", csv_path);
            return 0;
        }
        fprintf(csv, "f,pattern,n,k,exact_variance,measured_variance,stderr,known_slope\n");
    }
    int ok = 1;
    for (int fi = 0; fi < 2 && ok; ++fi)
        for (int ki = 0; ki < 4 && ok; ++ki)
            ok = q6_series(opt, n, fi, ki, csv);
    if (csv != NULL && fclose(csv) != 0)
        ok = 0;
    return ok;
}

int main(int argc, char **argv)
{
    ex_options opt = {64u, 8u, 20000ul, 1u, 0};
    const char *csv_path = NULL;
    if (ex_take_option(&argc, argv, "--convergence-csv", &csv_path) < 0)
        return EX_PARSE_ERROR;
    int rc = ex_parse_options(argc, argv, &opt, MCS_MAX_N, EX_MAX_K, help_text);
    if (rc != EX_PARSE_OK)
        return rc;
    ex_integrand_bins(opt.n, f);

    ex_begin(&opt, "Section 5: the note's open questions, exact theory beside measurement");
    if (!q1_perfect(&opt) ||             /* g = f */
        !q2_jitter_uniform(&opt) ||      /* uniform jitter and uniform with g */
        !q3_continuous(&opt) ||          /* 1/H against the integral of 1/p */
        !q4_split(&opt) ||               /* diagonal and off-diagonal parts */
        !q5_misalignment(&opt) ||        /* eq. 50-51 off the bins */
        !q6_convergence(&opt, csv_path)) /* Var[I] against K */
        return 1;
    ex_end(&opt);
    return 0;
}
