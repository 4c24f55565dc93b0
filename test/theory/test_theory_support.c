/* Importance functions with bins of g_n = 0 (issue 23 item 4): the exact
 * moments of every kind against enumeration of every outcome, both exact
 * objects agreeing, the closed forms that stay exact (eq. 41, eq. 52
 * corrected) against them and eq. 58 corrected a bound, and the bias
 * -(1/N) sum over those bins of f_n predicted exactly and measured within
 * 5 standard errors (where a prediction of 0 is rejected). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mcspec.h"
#include "theory_ref.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

#define NMAX 8

static mcs_importance imp;
static mcs_theory th;
static mcs_theory_spectrum ts;
static double bf_mean[NMAX], bf_second[NMAX * NMAX];

/* Weights whose total is a power of two (the CDF exact, on a grid of it),
 * zeros leading, inside, consecutive and trailing, and one support bin. */
typedef struct {
    size_t n;
    double w[NMAX];
    size_t denom;
} support_case;

static const support_case cases[] = {
    {4u, {0.0, 1.0, 1.0, 2.0}, 4u},
    {5u, {1.0, 0.0, 0.0, 2.0, 1.0}, 4u},
    {6u, {0.0, 1.0, 0.0, 1.0, 2.0, 0.0}, 4u},
    {4u, {1.0, 1.0, 0.0, 0.0}, 2u},
    {3u, {0.0, 1.0, 0.0}, 1u},
    {7u, {3.0, 0.0, 1.0, 0.0, 2.0, 0.0, 2.0}, 8u},
};
#define CASES (sizeof cases / sizeof cases[0])

static const mcs_pattern_kind kinds[4] = {MCS_PATTERN_RANDOM, MCS_PATTERN_STRATIFIED,
                                          MCS_PATTERN_UNIFORM, MCS_PATTERN_JITTER};

static void init_both(mcs_pattern_kind kind, size_t n, size_t k)
{
    mcs_pattern pat;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, kind, n, k, &imp));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_init(&th, &pat));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_init(&ts, &pat));
}

/* Every outcome (the CDF on a grid of denom, strata of 1/K): grid^K for
 * random, (grid/K)^K stratified, grid jitter; skipped past 2e5 outcomes. */
static int enumerate(mcs_pattern_kind kind, size_t n, size_t k, size_t denom)
{
    const size_t grid = theory_lcm(denom, k);
    const double outcomes = kind == MCS_PATTERN_RANDOM       ? pow((double)grid, (double)k)
                            : kind == MCS_PATTERN_STRATIFIED ? pow((double)(grid / k), (double)k)
                                                             : (double)grid;
    if (outcomes > 2e5)
        return 0;
    theory_brute_force(kind, n, k, &imp, grid, bf_mean, bf_second);
    return 1;
}

static void test_exact_moments_with_zero_probability_bins_match_enumeration(void)
{
    char what[128];
    for (size_t c = 0; c < CASES; ++c) {
        const size_t n = cases[c].n;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, n, cases[c].w));
        for (size_t k = 1; k <= 5u; ++k)
            for (int i = 0; i < 4; ++i) {
                init_both(kinds[i], n, k);
                if (!enumerate(kinds[i], n, k, cases[c].denom))
                    continue;
                double f[NMAX];
                theory_make_f(n, f, 0.3 * (double)c);
                double bf_var = 0.0, bf_m = 0.0;
                for (size_t a = 0; a < n; ++a) {
                    double v;
                    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_bin_mean(&th, a, &v));
                    (void)snprintf(what, sizeof what, "case %zu %s K=%zu <s_%zu>", c,
                                   mcs_pattern_kind_str(kinds[i]), k, a);
                    theory_assert_close(bf_mean[a], v, 1e-12, what);
                    if (cases[c].w[a] == 0.0)
                        TEST_ASSERT_EQUAL_DOUBLE(0.0, v);
                    bf_m += f[a] * bf_mean[a] / (double)k;
                    for (size_t b = 0; b < n; ++b) {
                        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_bin_second(&th, a, b, &v));
                        (void)snprintf(what, sizeof what, "case %zu %s K=%zu <s_%zu s_%zu>", c,
                                       mcs_pattern_kind_str(kinds[i]), k, a, b);
                        theory_assert_close(bf_second[a * n + b], v, 1e-12, what);
                        bf_var += f[a] * f[b] * bf_second[a * n + b] / ((double)k * (double)k);
                    }
                }
                bf_var -= bf_m * bf_m;
                /* Var[I] by both objects against the enumerated moments, and
                 * the power spectrum of the two objects against each other */
                double v1, v2;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_variance(&th, n, k, f, &v1));
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_variance(&ts, n, k, f, &v2));
                (void)snprintf(what, sizeof what, "case %zu %s K=%zu Var[I]", c,
                               mcs_pattern_kind_str(kinds[i]), k);
                TEST_ASSERT_TRUE_MESSAGE(fabs(v1 - bf_var) <= 1e-11 * (bf_m * bf_m + 1.0), what);
                TEST_ASSERT_TRUE_MESSAGE(fabs(v2 - bf_var) <= 1e-11 * (bf_m * bf_m + 1.0), what);
                for (size_t q = 0; q < n; ++q) {
                    double p1, p2, r1, i1, r2, i2;
                    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_power(&th, q, &p1));
                    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_power(&ts, q, &p2));
                    const double scale = (double)(k * k) / (double)n * 16.0;
                    TEST_ASSERT_TRUE_MESSAGE(fabs(p1 - p2) <= 1e-12 * scale, what);
                    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_covariance(&th, q, (q + 1u) % n, &r1, &i1));
                    TEST_ASSERT_EQUAL_INT(MCS_OK,
                                          mcs_theory_spectrum_covariance(&ts, q, (q + 1u) % n, &r2, &i2));
                    TEST_ASSERT_TRUE_MESSAGE(fabs(r1 - r2) <= 1e-12 * scale, what);
                    TEST_ASSERT_TRUE_MESSAGE(fabs(i1 - i2) <= 1e-12 * scale, what);
                }
            }
    }
}

/* The closed forms over the support (eq.h): eq. 41 and eq. 52 corrected
 * stay exact for random sampling, eq. 58 corrected a bound. */
static void test_the_closed_forms_over_the_support_stay_exact_and_bound(void)
{
    char what[128];
    for (size_t c = 0; c < CASES; ++c) {
        const size_t n = cases[c].n;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, n, cases[c].w));
        for (size_t k = 1; k <= 3u; ++k) {
            init_both(MCS_PATTERN_RANDOM, n, k);
            TEST_ASSERT_TRUE(enumerate(MCS_PATTERN_RANDOM, n, k, cases[c].denom));
            for (size_t a = 0; a < n; ++a)
                for (size_t b = 0; b < n; ++b) {
                    double v;
                    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq41_importance_second(&imp, k, a, b, &v));
                    (void)snprintf(what, sizeof what, "case %zu K=%zu eq. 41 at (%zu, %zu)", c, k,
                                   a, b);
                    theory_assert_close(bf_second[a * n + b], v, 1e-12, what);
                }
            for (int phase = 0; phase < 4; ++phase) {
                double f[NMAX], v, e52, e58;
                theory_make_f(n, f, (double)phase);
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_variance(&th, n, k, f, &v));
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq52_variance_corrected(&imp, k, f, &e52));
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq58_bound_corrected(&imp, k, f, &e58));
                (void)snprintf(what, sizeof what, "case %zu K=%zu: eq. 52c %.17g, exact %.17g", c,
                               k, e52, v);
                theory_assert_close(v, e52, 1e-12, what);
                TEST_ASSERT_TRUE_MESSAGE(e58 >= v * (1.0 - 1e-12), "eq. 58 corrected no bound");
                double printed, conv, b58;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq52_variance_printed(&imp, k, f, &printed));
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq55_variance_convolution(&imp, k, f, &conv));
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq58_bound_printed(&imp, k, f, &b58));
                TEST_ASSERT_TRUE(isfinite(printed) && isfinite(conv) && isfinite(b58));
            }
            double p45, p46, re, im;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq45_importance_power(&imp, k, 1u, &p45));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq46_importance_power0(&imp, k, &p46));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq43_importance_cross(&imp, k, 1u, 2u % n, &re, &im));
            TEST_ASSERT_TRUE(isfinite(p45) && isfinite(p46) && isfinite(re) && isfinite(im));
        }
    }
    /* the case of the header: g = (1, 1, 0, 0)/2, f = (1, 0, 0, 0): Var[I]
     * = 1/(16 K); with 1/N for N_s / N^2 the bound read 0 */
    const double g[4] = {1.0, 1.0, 0.0, 0.0}, f[4] = {1.0, 0.0, 0.0, 0.0};
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, 4u, g));
    init_both(MCS_PATTERN_RANDOM, 4u, 3u);
    double v, e58;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_variance(&th, 4u, 3u, f, &v));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq58_bound_corrected(&imp, 3u, f, &e58));
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 1.0 / 48.0, v);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 1.0 / 24.0, e58);
}

/* Above MCS_MAX_COV_N the eq. 52 forms go by Parseval: still exact over the
 * support, against the O(N) exact variance. */
static void test_eq52_corrected_by_parseval_is_exact_over_the_support(void)
{
    static double w[96], f[96];
    for (size_t b = 0; b < 96u; ++b) {
        w[b] = b % 7u == 3u || b < 2u || b > 90u ? 0.0 : 1.0 + (double)((b * 5u) % 3u);
        f[b] = 1.0 + sin(0.3 * (double)b) + (w[b] == 0.0 ? 40.0 : 0.0);
    }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, 96u, w));
    mcs_pattern pat;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, MCS_PATTERN_RANDOM, 96u, 5u, &imp));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_init(&ts, &pat));
    double v, e52;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_variance(&ts, 96u, 5u, f, &v));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq52_variance_corrected(&imp, 5u, f, &e52));
    theory_assert_close(v, e52, 1e-12, "eq. 52 corrected (Parseval) over the support");
}

/* The bias -(1/N) sum over the bins outside the support of f_n: both
 * objects give it exactly, it is <I> minus the integral, and the measured
 * mean of I minus the integral agrees within 5 standard errors while a
 * prediction of 0 is rejected there. */
static void test_the_bias_is_predicted_exactly_and_measured(void)
{
    const size_t n = 24u;
    double w[24], f[24], out_sum = 0.0, fbar = 0.0;
    for (size_t b = 0; b < n; ++b) {
        w[b] = b % 5u == 1u || b == 23u ? 0.0 : 1.0 + (double)((b * 7u) % 4u);
        f[b] = 0.5 + 0.25 * cos(0.4 * (double)b) + (w[b] == 0.0 ? 0.3 : 0.0);
        fbar += f[b] / (double)n;
        out_sum += w[b] == 0.0 ? f[b] : 0.0;
    }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, n, w));
    const double want = -out_sum / (double)n;
    const mcs_pattern_kind kk[4] = {MCS_PATTERN_RANDOM, MCS_PATTERN_STRATIFIED, MCS_PATTERN_JITTER,
                                    MCS_PATTERN_UNIFORM};
    for (int i = 0; i < 4; ++i) {
        const size_t k = 10u;
        init_both(kk[i], n, k);
        double b1, b2, mean;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_bias(&th, n, k, f, &b1));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_bias(&ts, n, k, f, &b2));
        TEST_ASSERT_EQUAL_DOUBLE(b1, b2);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_estimator_mean(&th, n, k, f, &mean));
        theory_assert_close(mean - fbar, b1, 1e-12, "bias against <I> - integral");
        if (kk[i] != MCS_PATTERN_UNIFORM)
            TEST_ASSERT_EQUAL_DOUBLE(want, b1);
        if (kk[i] == MCS_PATTERN_UNIFORM)
            continue; /* deterministic: its bias is <I> - integral, checked above */
        mcs_pattern pat;
        mcs_rng rng;
        mcs_welford est;
        size_t bins[10];
        double wt[10], x;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, kk[i], n, k, &imp));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, 4242u, (uint64_t)i));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_init(&est));
        for (int t = 0; t < 40000; ++t) {
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_draw(&pat, &rng, k, bins, wt, NULL));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_estimate_bins(n, k, f, bins, wt, &x));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_add(&est, x));
        }
        double m, se;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_mean(&est, &m));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_stderr(&est, &se));
        char what[128];
        (void)snprintf(what, sizeof what, "%s: mean - integral %.6g +- %.2g, bias %.6g",
                       mcs_pattern_kind_str(kk[i]), m - fbar, se, b1);
        TEST_ASSERT_TRUE_MESSAGE(fabs(m - fbar - b1) < 5.0 * se, what);
        TEST_ASSERT_TRUE_MESSAGE(fabs(m - fbar) > 5.0 * se, what); /* bias 0 rejected */
    }
    /* without importance, and with every g_n > 0: no bias, exactly */
    init_both(MCS_PATTERN_JITTER, n, 7u);
    mcs_pattern pat;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, MCS_PATTERN_STRATIFIED, n, 7u, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_init(&th, &pat));
    double b;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_bias(&th, n, 7u, f, &b));
    TEST_ASSERT_TRUE(b == 0.0);
}

static void test_bad_bias_calls_change_nothing(void)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, 4u, cases[0].w));
    init_both(MCS_PATTERN_RANDOM, 4u, 3u);
    theory_check_bad_integrands(&th, mcs_theory_bias, NULL);
    double f[4] = {1.0, 2.0, 3.0, 4.0}, out = 5.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_theory_spectrum_bias(&ts, 5u, 3u, f, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_theory_spectrum_bias(&ts, 4u, 2u, f, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_theory_spectrum_bias(&ts, 4u, 0u, f, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_theory_spectrum_bias(&ts, 4u, 3u, f, NULL));
    f[2] = 1e40;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MAGNITUDE, mcs_theory_spectrum_bias(&ts, 4u, 3u, f, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MAGNITUDE, mcs_theory_bias(&th, 4u, 3u, f, &out));
    TEST_ASSERT_EQUAL_DOUBLE(5.0, out);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_exact_moments_with_zero_probability_bins_match_enumeration);
    RUN_TEST(test_the_closed_forms_over_the_support_stay_exact_and_bound);
    RUN_TEST(test_eq52_corrected_by_parseval_is_exact_over_the_support);
    RUN_TEST(test_the_bias_is_predicted_exactly_and_measured);
    RUN_TEST(test_bad_bias_calls_change_nothing);
    return UNITY_END();
}
