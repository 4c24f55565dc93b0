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
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_estimate_bins(n, k, f, bins, wts, &est));
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
    mcs_estimate_bins(64u, 8u, f, bins, wts, &est);
    TEST_ASSERT_EQUAL_DOUBLE(1.0, est);
    TEST_ASSERT_EQUAL_DOUBLE(0.125, mean_of(f, 64u)); /* bias 7/8, with zero variance */
    /* Jitter with the same function is unbiased: the offset is random. */
    mcs_pattern_init(&pat, MCS_PATTERN_JITTER, 64u, 8u, NULL);
    mcs_welford acc;
    mcs_welford_init(&acc);
    for (int t = 0; t < 20000; ++t) {
        mcs_pattern_draw(&pat, &rng, 8u, bins, wts, NULL);
        mcs_estimate_bins(64u, 8u, f, bins, wts, &est);
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
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_estimate_bins(16u, 6u, f, bins, wts, &a));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_estimate_points(6u, step_f, f, pts, wts, &b));
        TEST_ASSERT_DOUBLE_WITHIN(1e-14, a, b);
    }
    /* Without weights every sample counts 1. */
    const double pts1[2] = {0.0, 0.999};
    double c;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_estimate_points(2u, step_f, f, pts1, NULL, &c));
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 0.5 * (f[0] + f[15]), c);
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
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_estimate_bins(4u, 2u, NULL, bins, w, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_estimate_bins(4u, 2u, f, NULL, w, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_estimate_bins(4u, 2u, f, bins, NULL, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_estimate_bins(4u, 2u, f, bins, w, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_N_RANGE, mcs_estimate_bins(0u, 2u, f, bins, w, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_estimate_bins(4u, 0u, f, bins, w, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_BIN_RANGE, mcs_estimate_bins(4u, 2u, f, bad_bins, w, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NOT_FINITE, mcs_estimate_bins(4u, 2u, f, bins, w_nan, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NOT_FINITE, mcs_estimate_bins(4u, 2u, f_nan, bins1, w, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NEGATIVE, mcs_estimate_bins(4u, 2u, f, bins, w_neg, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_estimate_points(2u, NULL, NULL, pts, w, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_estimate_points(2u, step_f, (void *)(uintptr_t)0, NULL, w, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_estimate_points(2u, nan_f, NULL, pts, w, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_estimate_points(0u, nan_f, NULL, pts, w, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_estimate_points(2u, nan_f, NULL, bad_pts, w, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NOT_FINITE, mcs_estimate_points(2u, nan_f, NULL, pts, w_nan, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NEGATIVE, mcs_estimate_points(2u, nan_f, NULL, pts, w_neg, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NOT_FINITE, mcs_estimate_points(2u, nan_f, NULL, pts, w, &out));
    TEST_ASSERT_EQUAL_DOUBLE(99.0, out);
}

/* Issue 10 item 5: a term f w above MCS_ESTIMATE_MAX_ABS (2^110), or one
 * that overflows, is refused; the limit itself is accepted, and the result
 * then goes into a mcs_welford. f = 1e300 with a weight of 1e10 used to give
 * I = inf with MCS_OK. */
static double huge_f(double x, void *ctx)
{
    (void)x;
    (void)ctx;
    return 1e300;
}

static void test_a_term_above_the_limit_is_refused_and_the_limit_feeds_a_welford(void)
{
    const double f[2] = {1e300, MCS_ESTIMATE_MAX_ABS};
    const size_t b0[1] = {0u}, b1[2] = {1u, 1u};
    const double w_big[1] = {1e10}, w_one[2] = {1.0, 1.0}, w_tiny[1] = {1e-290};
    const double pts[1] = {0.5};
    double out = 99.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MAGNITUDE, mcs_estimate_bins(2u, 1u, f, b0, w_big, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MAGNITUDE, mcs_estimate_bins(2u, 1u, f, b0, w_one, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MAGNITUDE, mcs_estimate_points(1u, huge_f, NULL, pts, NULL, &out));
    TEST_ASSERT_EQUAL_DOUBLE(99.0, out);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_estimate_bins(2u, 1u, f, b0, w_tiny, &out));
    TEST_ASSERT_DOUBLE_WITHIN(1e-12 * 1e10, 1e10, out);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_estimate_bins(2u, 2u, f, b1, w_one, &out));
    TEST_ASSERT_EQUAL_DOUBLE(MCS_ESTIMATE_MAX_ABS, out);
    mcs_welford acc;
    mcs_welford_init(&acc);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_add(&acc, out));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_add(&acc, -out));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_estimator_is_unbiased_for_every_kind_except_uniform);
    RUN_TEST(test_uniform_is_biased_for_a_function_that_aliases_with_it);
    RUN_TEST(test_point_estimator_equals_bin_estimator_for_a_piecewise_constant_f);
    RUN_TEST(test_bad_input_returns_an_error_and_leaves_outputs_untouched);
    RUN_TEST(test_a_term_above_the_limit_is_refused_and_the_limit_feeds_a_welford);
    return UNITY_END();
}
