/* Section 1 of the note: variance of a gradient (the difference of two
 * neighbouring pixels' integrals) estimated with independent samples
 * (eq. 1-2) and with shared samples (eq. 3-4), for every pattern kind. */
#include "mcspec.h"
#include "report.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static const char help_text[] =
    "Section 1: gradient variance for correlated and uncorrelated sampling.\n"
    "Two neighbouring pixels x0 and x0-1 of an image F(x, y) give integrands\n"
    "f(y) = F(x0, y) and g(y) = F(x0-1, y), a slightly shifted copy of f.\n"
    "Each trial estimates I_f and I_g with K samples each, independently\n"
    "(eq. 1-2: Var = Var[f] + Var[g] ~ 2 Var[f]) and with shared samples\n"
    "(eq. 3-4: Var = Var[h], h = f - g), for every pattern kind.\n"
    "The first table is measured only; the second puts the note's forms\n"
    "beside the exact discrete variance (mcspec theory) and the measurement.\n";

/* A pixel row of an image with a soft gradient and an edge that moves with x. */
static double image(double x, double y)
{
    const double pi = 3.14159265358979323846;
    double edge = y >= 0.3 + 0.02 * x ? 0.4 : 0.0;
    return 0.5 + 0.3 * sin(2.0 * pi * (y + 0.05 * x)) + edge;
}

typedef struct {
    mcs_welford f, g, indep, shared, h_alone;
} sec1_measure;

static double var_of(const mcs_welford *w, double *se)
{
    double v = 0.0;
    mcs_welford_variance(w, &v);
    mcs_welford_variance_stderr(w, se);
    return v;
}

#define SEC1_MAX_K 4096
static size_t bins_a[SEC1_MAX_K], bins_b[SEC1_MAX_K], bins_c[SEC1_MAX_K];
static double w_a[SEC1_MAX_K], w_b[SEC1_MAX_K], w_c[SEC1_MAX_K];
static double f[MCS_MAX_COV_N], g[MCS_MAX_COV_N], h[MCS_MAX_COV_N];
/* Exact variances are differences of second moments of size ~ mean f^2, so
 * anything below 1e-12 of that is rounding, not variance. */
static double noise_floor;

static int measure(const ex_options *opt, mcs_pattern_kind kind, sec1_measure *m)
{
    mcs_pattern pat;
    mcs_rng rng;
    if (mcs_pattern_init(&pat, kind, opt->n, opt->k, NULL) != MCS_OK)
        return 0;
    mcs_rng_seed(&rng, opt->seed, (uint64_t)kind);
    mcs_welford_init(&m->f);
    mcs_welford_init(&m->g);
    mcs_welford_init(&m->indep);
    mcs_welford_init(&m->shared);
    mcs_welford_init(&m->h_alone);
    for (unsigned long t = 0; t < opt->trials; ++t) {
        double fa, ga, gb, hc;
        /* A serves f (and g when shared), B serves g independently, C serves h alone. */
        mcs_pattern_draw(&pat, &rng, opt->k, bins_a, w_a, NULL);
        mcs_pattern_draw(&pat, &rng, opt->k, bins_b, w_b, NULL);
        mcs_pattern_draw(&pat, &rng, opt->k, bins_c, w_c, NULL);
        mcs_estimate_bins(opt->n, opt->k, f, bins_a, w_a, &fa);
        mcs_estimate_bins(opt->n, opt->k, g, bins_a, w_a, &ga);
        mcs_estimate_bins(opt->n, opt->k, g, bins_b, w_b, &gb);
        mcs_estimate_bins(opt->n, opt->k, h, bins_c, w_c, &hc);
        mcs_welford_add(&m->f, fa);
        mcs_welford_add(&m->g, gb);
        mcs_welford_add(&m->indep, fa - gb); /* eq. 1: independent samples */
        mcs_welford_add(&m->shared, fa - ga); /* eq. 3: shared samples */
        mcs_welford_add(&m->h_alone, hc);
    }
    return 1;
}

static void row(const ex_options *opt, const char *quantity, const char *eq,
                mcs_pattern_kind kind, double closed, double exact, const mcs_welford *w)
{
    double se = 0.0, v = var_of(w, &se);
    ex_row r = {"sec1", quantity, eq, mcs_pattern_kind_str(kind), EX_NO_FREQ, EX_NO_FREQ,
                closed, exact, v, se, EX_NA, noise_floor};
    ex_row_print(opt, &r);
}

/* Exact variances of the kind from mcs_theory beside the note's forms. */
static int predict_rows(const ex_options *opt, mcs_pattern_kind kind, const sec1_measure *m)
{
    static mcs_theory th;
    mcs_pattern pat;
    double vf, vg, vh, cov_fg, eq2, eq4;
    if (mcs_pattern_init(&pat, kind, opt->n, opt->k, NULL) != MCS_OK ||
        mcs_theory_init(&th, &pat) != MCS_OK ||
        mcs_theory_variance(&th, opt->n, opt->k, f, &vf) != MCS_OK ||
        mcs_theory_variance(&th, opt->n, opt->k, g, &vg) != MCS_OK ||
        mcs_theory_variance(&th, opt->n, opt->k, h, &vh) != MCS_OK ||
        mcs_theory_estimator_covariance(&th, opt->n, opt->k, f, g, &cov_fg) != MCS_OK ||
        mcs_eq2_uncorrelated_variance(&th, opt->n, opt->k, f, g, &eq2) != MCS_OK ||
        mcs_eq4_correlated_variance(&th, opt->n, opt->k, f, g, &eq4) != MCS_OK)
        return 0;
    /* Independent trials: no covariance, so the exact variance of the
     * difference is Var[f] + Var[g]; eq. 2's "~ 2 Var[f]" is the approximation. */
    row(opt, "Var[If-Ig] independent", "eq. 2", kind, eq2, vf + vg, &m->indep);
    row(opt, "Var[If-Ig] indep ~ 2Var[f]", "eq. 2", kind, 2.0 * vf, vf + vg, &m->indep);
    /* Shared samples: eq. 4 (Var[h]) and eq. 6 (Var[f]+Var[g]-2Cov) against
     * the exact variance of the one-trial difference. */
    row(opt, "Var[If-Ig] shared", "eq. 4", kind, eq4, vf + vg - 2.0 * cov_fg, &m->shared);
    row(opt, "Var[Ih] own trials", "eq. 4", kind, eq4, vh, &m->h_alone);
    row(opt, "Var[If]", "exact", kind, EX_NA, vf, &m->f);
    if (kind == MCS_PATTERN_RANDOM) {
        double e25;
        if (mcs_eq25_random_variance(opt->n, opt->k, f, &e25) != MCS_OK)
            return 0;
        row(opt, "Var[If] population/K", "eq. 25", kind, e25, vf, &m->f);
    }
    return 1;
}

int main(int argc, char **argv)
{
    ex_options opt = {64u, 8u, 100000ul, 1u, 0};
    int rc = ex_parse_options(argc, argv, &opt, MCS_MAX_COV_N, SEC1_MAX_K, help_text);
    if (rc != EX_PARSE_OK)
        return rc == EX_PARSE_HELP ? 0 : 2;

    const double x0 = 10.0;
    for (size_t b = 0; b < opt.n; ++b) {
        double y = ((double)b + 0.5) / (double)opt.n;
        f[b] = image(x0, y);
        g[b] = image(x0 - 1.0, y);
        h[b] = f[b] - g[b];
        noise_floor = fmax(noise_floor, 1e-12 * fmax(f[b] * f[b], g[b] * g[b]));
    }

    static const mcs_pattern_kind kinds[MCS_PATTERN_KIND_COUNT] = {
        MCS_PATTERN_RANDOM, MCS_PATTERN_STRATIFIED, MCS_PATTERN_HOMOGENIZED, MCS_PATTERN_JITTER,
        MCS_PATTERN_UNIFORM};
    static sec1_measure m[MCS_PATTERN_KIND_COUNT];
    for (int i = 0; i < MCS_PATTERN_KIND_COUNT; ++i)
        if (!measure(&opt, kinds[i], &m[i]))
            return 1;

    if (!opt.csv) {
        printf("Section 1: gradient variance, independent (eq. 1-2) vs shared samples (eq. 3-4)\n");
        printf("N = %zu bins, K = %zu samples, %lu trials, seed %llu; all values measured\n\n",
               opt.n, opt.k, opt.trials, (unsigned long long)opt.seed);
        printf("%-12s %22s %12s %12s %22s %12s %9s\n", "pattern", "Var[If-Ig] indep",
               "Var[f]+Var[g]", "2 Var[f]", "Var[If-Ig] shared", "Var[h]", "ratio");
        for (int i = 0; i < MCS_PATTERN_KIND_COUNT; ++i) {
            double se_i, se_s, se_f, se_g, se_h;
            double vi = var_of(&m[i].indep, &se_i), vs = var_of(&m[i].shared, &se_s);
            double vf = var_of(&m[i].f, &se_f), vg = var_of(&m[i].g, &se_g);
            double vh = var_of(&m[i].h_alone, &se_h);
            char ratio[32];
            if (vs > 0.0)
                snprintf(ratio, sizeof ratio, "%9.2f", vi / vs);
            else
                snprintf(ratio, sizeof ratio, "%9s", "-");
            printf("%-12s %11.4e+-%9.2e %12.4e %12.4e %11.4e+-%9.2e %12.4e %s\n",
                   mcs_pattern_kind_str(kinds[i]), vi, se_i, vf + vg, 2.0 * vf, vs, se_s, vh,
                   ratio);
        }
        printf("(ratio = independent / shared; Var[h] is measured on its own trials)\n\n");
    }

    ex_begin(&opt, "Predicted beside measured: the note's form, the exact discrete variance");
    for (int i = 0; i < MCS_PATTERN_KIND_COUNT; ++i) {
        if (!predict_rows(&opt, kinds[i], &m[i]))
            return 1;
    }
    ex_end(&opt);
    return 0;
}
