/* Section 1 of the note: variance of a gradient (the difference of two
 * neighbouring pixels' integrals) estimated with independent samples
 * (eq. 1-2) and with shared samples (eq. 3-4), for every pattern kind. */
#include "exact.h"
#include "mcspec.h"
#include "measure.h"
#include "readout.h"
#include "report.h"

#include <math.h>
#include <stdio.h>

static const char help_text[] =
    "Section 1: gradient variance for correlated and uncorrelated sampling.\n"
    "Two neighbouring pixels x0 and x0-1 of an image F(x, y) give integrands\n"
    "f(y) = F(x0, y) and g(y) = F(x0-1, y), a slightly shifted copy of f.\n"
    "Each trial estimates I_f and I_g with K samples each, independently\n"
    "(eq. 1-2: Var = Var[f] + Var[g] ~ 2 Var[f]) and with shared samples\n"
    "(eq. 3-4: Var = Var[h], h = f - g), for every pattern kind.\n"
    "The first table is measured only; the second puts the note's forms\n"
    "beside the exact discrete variance (mcspec theory) and the measurement.\n"
    "Any N up to MCS_MAX_N: above MCS_MAX_COV_N the exact variances come from\n"
    "mcs_theory_spectrum, and eq. 2 and 4 are its Var[f] + Var[g] and Var[h].\n";

static const mcs_pattern_kind kinds[MCS_PATTERN_KIND_COUNT] = {
    MCS_PATTERN_RANDOM, MCS_PATTERN_STRATIFIED, MCS_PATTERN_HOMOGENIZED, MCS_PATTERN_JITTER,
    MCS_PATTERN_UNIFORM};

/* Each trial draws three patterns: A serves f (and g when shared), B serves g
 * independently, C serves h alone. The run's estimates, in the order added: */
enum { E_F_ON_A, E_G_ON_A, E_G_ON_B, E_H_ON_C };
/* and its differences: eq. 1 (independent samples), eq. 3 (shared samples). */
enum { D_INDEPENDENT, D_SHARED };

static ex_run runs[MCS_PATTERN_KIND_COUNT];
static double f[MCS_MAX_N], g[MCS_MAX_N], h[MCS_MAX_N];
/* Exact variances are differences of second moments of size ~ mean f^2, so
 * anything below 1e-12 of that is rounding, not variance. */
static double noise_floor;

/* A pixel row of an image with a soft gradient and an edge that moves with x. */
static double image(double x, double y)
{
    const double pi = 3.14159265358979323846;
    double edge = y >= 0.3 + 0.02 * x ? 0.4 : 0.0;
    return 0.5 + 0.3 * sin(2.0 * pi * (y + 0.05 * x)) + edge;
}

/* f and g: pixels x0 and x0 - 1 at the bin centres; h = f - g. */
static void fill_integrands(size_t n)
{
    const double x0 = 10.0;
    for (size_t b = 0; b < n; ++b) {
        double y = ((double)b + 0.5) / (double)n;
        f[b] = image(x0, y);
        g[b] = image(x0 - 1.0, y);
        h[b] = f[b] - g[b];
        noise_floor = fmax(noise_floor, 1e-12 * fmax(f[b] * f[b], g[b] * g[b]));
    }
}

static int measure(const ex_options *opt, int i)
{
    ex_run *run = &runs[i];
    if (ex_run_init(run, kinds[i], opt->n, opt->k, NULL, opt->seed, (uint64_t)kinds[i]) != MCS_OK)
        return 0;
    ex_run_integrand_on(run, f, 0u);
    ex_run_integrand_on(run, g, 0u);
    ex_run_integrand_on(run, g, 1u);
    ex_run_integrand_on(run, h, 2u);
    ex_run_difference(run, E_F_ON_A, E_G_ON_B); /* eq. 1: independent samples */
    ex_run_difference(run, E_F_ON_A, E_G_ON_A); /* eq. 3: shared samples */
    return ex_run_go(run, opt->trials, NULL, NULL) == MCS_OK;
}

/* The first table (not in CSV mode): measured variances only. */
static void measured_table(const ex_options *opt)
{
    if (opt->csv)
        return;
    printf("Section 1: gradient variance, independent (eq. 1-2) vs shared samples (eq. 3-4)\n");
    printf("N = %zu bins, K = %zu samples, %lu trials, seed %llu; all values measured\n\n",
           opt->n, opt->k, opt->trials, (unsigned long long)opt->seed);
    printf("%-12s %22s %12s %12s %22s %12s %9s\n", "pattern", "Var[If-Ig] indep",
           "Var[f]+Var[g]", "2 Var[f]", "Var[If-Ig] shared", "Var[h]", "ratio");
    for (int i = 0; i < MCS_PATTERN_KIND_COUNT; ++i) {
        const ex_run *run = &runs[i];
        double se_i, se_s, se_f, se_g, se_h;
        double vi = ex_variance(&run->difference[D_INDEPENDENT], &se_i);
        double vs = ex_variance(&run->difference[D_SHARED], &se_s);
        double vf = ex_variance(&run->estimate[E_F_ON_A], &se_f);
        double vg = ex_variance(&run->estimate[E_G_ON_B], &se_g);
        double vh = ex_variance(&run->estimate[E_H_ON_C], &se_h);
        char ratio[32];
        if (vs > 0.0)
            snprintf(ratio, sizeof ratio, "%9.2f", vi / vs);
        else
            snprintf(ratio, sizeof ratio, "%9s", "-");
        printf("%-12s %11.4e+-%9.2e %12.4e %12.4e %11.4e+-%9.2e %12.4e %s\n",
               mcs_pattern_kind_str(kinds[i]), vi, se_i, vf + vg, 2.0 * vf, vs, se_s, vh, ratio);
    }
    printf("(ratio = independent / shared; Var[h] is measured on its own trials)\n\n");
}

/* A row whose measurement is the variance of w. */
static void variance_row(const ex_options *opt, const char *quantity, const char *eq,
                         mcs_pattern_kind kind, double closed, double exact, const mcs_welford *w)
{
    double se = 0.0, v = ex_variance(w, &se);
    ex_row r = ex_row_of("sec1", quantity, eq, mcs_pattern_kind_str(kind), EX_NO_FREQ,
                         EX_NO_FREQ, closed, exact, v, se, noise_floor);
    ex_row_print(opt, &r);
}

/* Eq. 2 and eq. 4 from the N x N moments (mcs_eq2, mcs_eq4); above
 * MCS_MAX_COV_N their definitions, Var[f] + Var[g] and Var[h], from
 * mcs_theory_spectrum. 0 if a value is missing. */
static int gradient_forms(const ex_options *opt, const ex_exact *ex, double vf, double vg,
                          double vh, double *eq2, double *eq4)
{
    const mcs_theory *th = ex_exact_theory(ex);
    if (th == NULL) {
        *eq2 = vf + vg;
        *eq4 = vh;
        return !isnan(*eq2) && !isnan(*eq4);
    }
    return mcs_eq2_uncorrelated_variance(th, opt->n, opt->k, f, g, eq2) == MCS_OK &&
           mcs_eq4_correlated_variance(th, opt->n, opt->k, f, g, eq4) == MCS_OK;
}

/* The second table: exact variances of the kind beside the note's forms. */
static int predicted_rows(const ex_options *opt, int i)
{
    static ex_exact ex;
    mcs_pattern_kind kind = kinds[i];
    const ex_run *run = &runs[i];
    double eq2, eq4;
    if (ex_exact_init(&ex, &run->pattern) != MCS_OK)
        return 0;
    double vf = ex_exact_variance(&ex, f), vg = ex_exact_variance(&ex, g);
    double vh = ex_exact_variance(&ex, h), cov_fg = ex_exact_estimator_covariance(&ex, f, g);
    if (isnan(vf) || isnan(vg) || isnan(cov_fg) || !gradient_forms(opt, &ex, vf, vg, vh, &eq2, &eq4))
        return 0;
    const mcs_welford *indep = &run->difference[D_INDEPENDENT], *fa = &run->estimate[E_F_ON_A];
    /* Independent trials: no covariance, so the exact variance of the
     * difference is Var[f] + Var[g]; eq. 2's "~ 2 Var[f]" is the approximation. */
    variance_row(opt, "Var[If-Ig] independent", "eq. 2", kind, eq2, vf + vg, indep);
    variance_row(opt, "Var[If-Ig] indep ~ 2Var[f]", "eq. 2", kind, 2.0 * vf, vf + vg, indep);
    /* Shared samples: eq. 4 (Var[h]) and eq. 6 (Var[f]+Var[g]-2Cov) against
     * the exact variance of the one-trial difference. */
    variance_row(opt, "Var[If-Ig] shared", "eq. 4", kind, eq4, vf + vg - 2.0 * cov_fg,
                 &run->difference[D_SHARED]);
    variance_row(opt, "Var[Ih] own trials", "eq. 4", kind, eq4, vh, &run->estimate[E_H_ON_C]);
    variance_row(opt, "Var[If]", "exact", kind, EX_NA, vf, fa);
    if (kind == MCS_PATTERN_RANDOM) {
        double e25;
        if (mcs_eq25_random_variance(opt->n, opt->k, f, &e25) != MCS_OK)
            return 0;
        variance_row(opt, "Var[If] population/K", "eq. 25", kind, e25, vf, fa);
    }
    return 1;
}

int main(int argc, char **argv)
{
    ex_options opt = {64u, 8u, 100000ul, 1u, 0};
    int rc = ex_parse_options(argc, argv, &opt, MCS_MAX_N, EX_MAX_K, help_text);
    if (rc != EX_PARSE_OK)
        return rc;
    fill_integrands(opt.n);
    for (int i = 0; i < MCS_PATTERN_KIND_COUNT; ++i)
        if (!measure(&opt, i))
            return 1;

    measured_table(&opt); /* eq. 1-4, measured */

    ex_begin(&opt, "Predicted beside measured: the note's form, the exact discrete variance");
    for (int i = 0; i < MCS_PATTERN_KIND_COUNT; ++i)
        if (!predicted_rows(&opt, i)) /* eq. 2, 4, 25 beside mcs_theory */
            return 1;
    ex_end(&opt);
    return 0;
}
