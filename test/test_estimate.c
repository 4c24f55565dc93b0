#include "mcspec.h"
#include "unity.h"

#include <math.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

static mcs_importance imp;

/* A smooth-ish integrand with some structure: f_n = 1 + sin(2 pi n/N) + 0.5 cos(6 pi n/N)^2. */
static void make_f(size_t n, double *f)
{
    const double pi = 3.14159265358979323846;
    for (size_t b = 0; b < n; ++b) {
        double x = (double)b / (double)n;
        f[b] = 1.0 + sin(2.0 * pi * x) + 0.5 * cos(6.0 * pi * x) * cos(6.0 * pi * x);
    }
}

static double mean_of(const double *f, size_t n)
{
    double s = 0.0;
    for (size_t b = 0; b < n; ++b)
        s += f[b];
    return s / (double)n;
}

static void test_estimator_is_unbiased_for_every_kind_except_uniform(void)
{
    const size_t n = 24u, k = 5u;
    double f[24], w[24];
    make_f(n, f);
    for (size_t b = 0; b < n; ++b)
        w[b] = 0.5 + f[b] * f[b]; /* an importance function roughly following f */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, n, w));
    const mcs_pattern_kind kinds[4] = {MCS_PATTERN_RANDOM, MCS_PATTERN_STRATIFIED,
                                       MCS_PATTERN_HOMOGENIZED, MCS_PATTERN_JITTER};
    for (int with_imp = 0; with_imp < 2; ++with_imp) {
        for (int i = 0; i < 4; ++i) {
            if (with_imp && kinds[i] == MCS_PATTERN_HOMOGENIZED)
                continue;
            mcs_pattern pat;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, kinds[i], n, k,
                                                           with_imp ? &imp : NULL));
            mcs_rng rng;
            mcs_rng_seed(&rng, 31u + (uint64_t)i, (uint64_t)with_imp);
            mcs_welford acc;
            mcs_welford_init(&acc);
            size_t bins[5];
            double wts[5];
            for (int t = 0; t < 40000; ++t) {
                double est;
                mcs_pattern_draw(&pat, &rng, k, bins, wts, NULL);
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_estimate_bins(n, f, k, bins, wts, &est));
                mcs_welford_add(&acc, est);
            }
            double mean, se;
            mcs_welford_mean(&acc, &mean);
            mcs_welford_stderr(&acc, &se);
            TEST_ASSERT_TRUE(se > 0.0);
            TEST_ASSERT_DOUBLE_WITHIN(5.0 * se, mean_of(f, n), mean);
        }
    }
}

static void test_uniform_is_biased_for_a_function_that_aliases_with_it(void)
{
    /* N = 64, K = 8: uniform samples land on bins 8j + 4; f is 1 exactly there. */
    double f[64];
    for (size_t b = 0; b < 64u; ++b)
        f[b] = (b % 8u == 4u) ? 1.0 : 0.0;
    mcs_pattern pat;
    mcs_pattern_init(&pat, MCS_PATTERN_UNIFORM, 64u, 8u, NULL);
    mcs_rng rng;
    mcs_rng_seed(&rng, 1u, 1u);
    size_t bins[8];
    double wts[8], est;
    mcs_pattern_draw(&pat, &rng, 8u, bins, wts, NULL);
    mcs_estimate_bins(64u, f, 8u, bins, wts, &est);
    TEST_ASSERT_EQUAL_DOUBLE(1.0, est);
    TEST_ASSERT_EQUAL_DOUBLE(0.125, mean_of(f, 64u)); /* bias 7/8, with zero variance */
    /* Jitter with the same function is unbiased: the offset is random. */
    mcs_pattern_init(&pat, MCS_PATTERN_JITTER, 64u, 8u, NULL);
    mcs_welford acc;
    mcs_welford_init(&acc);
    for (int t = 0; t < 20000; ++t) {
        mcs_pattern_draw(&pat, &rng, 8u, bins, wts, NULL);
        mcs_estimate_bins(64u, f, 8u, bins, wts, &est);
        mcs_welford_add(&acc, est);
    }
    double mean, se;
    mcs_welford_mean(&acc, &mean);
    mcs_welford_stderr(&acc, &se);
    TEST_ASSERT_DOUBLE_WITHIN(5.0 * se, 0.125, mean);
}

static double step_f(double x, void *ctx)
{
    const double *f = (const double *)ctx;
    return f[(size_t)(x * 16.0)];
}

static void test_point_estimator_equals_bin_estimator_for_a_piecewise_constant_f(void)
{
    double f[16], w[16];
    make_f(16u, f);
    for (size_t b = 0; b < 16u; ++b)
        w[b] = 1.0 + (double)(b % 3u);
    mcs_importance_init(&imp, 16u, w);
    mcs_pattern pat;
    mcs_pattern_init(&pat, MCS_PATTERN_STRATIFIED, 16u, 6u, &imp);
    mcs_rng rng;
    mcs_rng_seed(&rng, 4u, 4u);
    size_t bins[6];
    double wts[6], pts[6];
    for (int t = 0; t < 100; ++t) {
        double a, b;
        mcs_pattern_draw(&pat, &rng, 6u, bins, wts, pts);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_estimate_bins(16u, f, 6u, bins, wts, &a));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_estimate_points(step_f, f, 6u, pts, wts, &b));
        TEST_ASSERT_DOUBLE_WITHIN(1e-14, a, b);
    }
    /* Without weights every sample counts 1. */
    const double pts1[2] = {0.0, 0.999};
    double c;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_estimate_points(step_f, f, 2u, pts1, NULL, &c));
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 0.5 * (f[0] + f[15]), c);
}

static void test_welford_matches_a_two_pass_computation_with_a_large_offset(void)
{
    enum { COUNT = 5000 };
    static double x[COUNT];
    mcs_rng rng;
    mcs_rng_seed(&rng, 9u, 9u);
    mcs_welford acc;
    mcs_welford_init(&acc);
    for (int i = 0; i < COUNT; ++i) {
        double u;
        mcs_rng_double(&rng, &u);
        x[i] = 1e9 + u; /* the sum of squares would lose every digit here */
        mcs_welford_add(&acc, x[i]);
    }
    double mean = 0.0, m2 = 0.0, m3 = 0.0, m4 = 0.0;
    for (int i = 0; i < COUNT; ++i)
        mean += x[i] - 1e9; /* exact: the two-pass reference must not lose digits either */
    mean = 1e9 + mean / COUNT;
    for (int i = 0; i < COUNT; ++i) {
        double d = x[i] - mean;
        m2 += d * d;
        m3 += d * d * d;
        m4 += d * d * d * d;
    }
    TEST_ASSERT_DOUBLE_WITHIN(1e-5 * m4, m4, acc.m4);
    TEST_ASSERT_DOUBLE_WITHIN(1e-5 * sqrt(m2 * m4), m3, acc.m3); /* m3 ~ 0: scale by m2, m4 */
    double var, se, wm;
    mcs_welford_mean(&acc, &wm);
    mcs_welford_variance(&acc, &var);
    mcs_welford_stderr(&acc, &se);
    TEST_ASSERT_EQUAL_UINT64(COUNT, acc.count);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12 * mean, mean, wm);
    TEST_ASSERT_DOUBLE_WITHIN(1e-6 * var, m2 / (COUNT - 1), var); /* offset costs ~1e-7 */
    TEST_ASSERT_DOUBLE_WITHIN(1e-6 * se, sqrt(m2 / (COUNT - 1) / COUNT), se);
}

static void test_merge_of_two_halves_equals_one_pass(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 12u, 13u);
    mcs_welford all, a, b, empty;
    mcs_welford_init(&all);
    mcs_welford_init(&a);
    mcs_welford_init(&b);
    mcs_welford_init(&empty);
    for (int i = 0; i < 3001; ++i) {
        double u;
        mcs_rng_double(&rng, &u);
        double v = 3.0 + 10.0 * u * u;
        mcs_welford_add(&all, v);
        mcs_welford_add(i < 1234 ? &a : &b, v);
    }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_merge(&a, &b));
    TEST_ASSERT_EQUAL_UINT64(all.count, a.count);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12 * fabs(all.mean), all.mean, a.mean);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12 * all.m2, all.m2, a.m2);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12 * fabs(all.m3), all.m3, a.m3);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12 * all.m4, all.m4, a.m4);
    /* Merging an empty accumulator either way changes nothing. */
    mcs_welford before = a;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_merge(&a, &empty));
    TEST_ASSERT_EQUAL_MEMORY(&before, &a, sizeof a);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_merge(&empty, &a));
    TEST_ASSERT_EQUAL_MEMORY(&a, &empty, sizeof a);
}

static void test_variance_stderr_matches_the_theory_for_uniform_values(void)
{
    /* U(0,1): sigma^2 = 1/12, mu4 = 1/80, so Var[s^2] ~ (1/80 - 1/144)/c. */
    enum { COUNT = 40000 };
    mcs_rng rng;
    mcs_rng_seed(&rng, 21u, 22u);
    mcs_welford acc;
    mcs_welford_init(&acc);
    for (int i = 0; i < COUNT; ++i) {
        double u;
        mcs_rng_double(&rng, &u);
        mcs_welford_add(&acc, u);
    }
    double se_var, var;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_variance_stderr(&acc, &se_var));
    mcs_welford_variance(&acc, &var);
    double expect = sqrt((1.0 / 80.0 - 1.0 / 144.0) / COUNT);
    TEST_ASSERT_DOUBLE_WITHIN(0.03 * expect, expect, se_var);
    TEST_ASSERT_DOUBLE_WITHIN(5.0 * expect, 1.0 / 12.0, var);
}

static double nan_f(double x, void *ctx)
{
    (void)ctx;
    return x > 0.5 ? (double)NAN : 1.0;
}

static void test_bad_input_returns_an_error_and_leaves_outputs_untouched(void)
{
    const double f[4] = {1.0, 2.0, 3.0, 4.0}, f_nan[4] = {1.0, NAN, 3.0, 4.0};
    const size_t bins[2] = {0u, 3u}, bad_bins[2] = {0u, 4u}, bins1[2] = {0u, 1u};
    const double w[2] = {1.0, 1.0}, w_nan[2] = {1.0, NAN}, w_neg[2] = {1.0, -2.0};
    const double pts[2] = {0.1, 0.9}, bad_pts[2] = {0.1, 1.5};
    double out = 99.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_estimate_bins(4u, NULL, 2u, bins, w, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_estimate_bins(4u, f, 2u, NULL, w, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_estimate_bins(4u, f, 2u, bins, NULL, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_estimate_bins(4u, f, 2u, bins, w, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_N_RANGE, mcs_estimate_bins(0u, f, 2u, bins, w, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_estimate_bins(4u, f, 0u, bins, w, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_BIN_RANGE, mcs_estimate_bins(4u, f, 2u, bad_bins, w, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NOT_FINITE, mcs_estimate_bins(4u, f, 2u, bins, w_nan, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NOT_FINITE, mcs_estimate_bins(4u, f_nan, 2u, bins1, w, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NEGATIVE, mcs_estimate_bins(4u, f, 2u, bins, w_neg, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_estimate_points(NULL, NULL, 2u, pts, w, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_estimate_points(step_f, (void *)(uintptr_t)0, 2u, NULL, w, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_estimate_points(nan_f, NULL, 2u, pts, w, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_estimate_points(nan_f, NULL, 0u, pts, w, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_estimate_points(nan_f, NULL, 2u, bad_pts, w, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NOT_FINITE, mcs_estimate_points(nan_f, NULL, 2u, pts, w_nan, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NEGATIVE, mcs_estimate_points(nan_f, NULL, 2u, pts, w_neg, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NOT_FINITE, mcs_estimate_points(nan_f, NULL, 2u, pts, w, &out));
    TEST_ASSERT_EQUAL_DOUBLE(99.0, out);

    mcs_welford acc, copy;
    mcs_welford_init(&acc);
    mcs_welford_add(&acc, 1.0);
    copy = acc;
    double v = 5.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_welford_init(NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_welford_add(NULL, 1.0));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NOT_FINITE, mcs_welford_add(&acc, NAN));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NOT_FINITE, mcs_welford_add(&acc, -INFINITY));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_welford_merge(NULL, &acc));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_welford_merge(&acc, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_welford_mean(NULL, &v));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_welford_mean(&acc, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_EMPTY, mcs_welford_variance(&acc, &v)); /* one value */
    TEST_ASSERT_EQUAL_INT(MCS_ERR_EMPTY, mcs_welford_stderr(&acc, &v));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_welford_variance(NULL, &v));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_welford_stderr(&acc, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_welford_variance_stderr(NULL, &v));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_welford_variance_stderr(&acc, NULL));
    mcs_welford_add(&acc, 2.0);
    mcs_welford_add(&acc, 4.0);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_EMPTY, mcs_welford_variance_stderr(&acc, &v)); /* three values */
    copy = acc;
    TEST_ASSERT_EQUAL_DOUBLE(5.0, v);
    TEST_ASSERT_EQUAL_MEMORY(&copy, &acc, sizeof acc);
    mcs_welford_init(&acc);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_EMPTY, mcs_welford_mean(&acc, &v));
    TEST_ASSERT_EQUAL_DOUBLE(5.0, v);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_estimator_is_unbiased_for_every_kind_except_uniform);
    RUN_TEST(test_uniform_is_biased_for_a_function_that_aliases_with_it);
    RUN_TEST(test_point_estimator_equals_bin_estimator_for_a_piecewise_constant_f);
    RUN_TEST(test_welford_matches_a_two_pass_computation_with_a_large_offset);
    RUN_TEST(test_merge_of_two_halves_equals_one_pass);
    RUN_TEST(test_variance_stderr_matches_the_theory_for_uniform_values);
    RUN_TEST(test_bad_input_returns_an_error_and_leaves_outputs_untouched);
    return UNITY_END();
}
