#include "mcspec/pointset.h"
#include "mcspec/rng.h"
#include "points_ref.h"
#include "unity.h"

#include <math.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define MAXK 512

static mcs_pointset acc, acc2, acc3, snapshot;
static double x[MAXK];

static void fill_stratified(mcs_rng *rng, size_t k, double *p)
{
    for (size_t j = 0; j < k; ++j) {
        double u = 0.0;
        mcs_rng_double(rng, &u);
        p[j] = ((double)j + u) / (double)k;
    }
}

static void test_one_trial_matches_the_direct_sum_at_every_frequency(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 1u, 1u);
    const size_t ks[4] = {1u, 3u, 37u, 500u};
    for (int c = 0; c < 4; ++c) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&acc, 300u));
        points_uniform(&rng, ks[c], x);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add(&acc, ks[c], x));
        for (long f = -300; f <= 300; ++f) {
            double p = 0.0;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_power(&acc, f, &p));
            TEST_ASSERT_DOUBLE_WITHIN(1e-12 * (double)ks[c], points_periodogram(1u, ks[c], x, f, 0), p);
        }
        double p0 = 0.0;
        mcs_pointset_power(&acc, 0, &p0);
        TEST_ASSERT_DOUBLE_WITHIN(1e-13 * (double)ks[c], (double)ks[c], p0);
    }
}

/* <P(f)> over T trials against the exact unbinned spectra, every f in 1..F,
 * within 5 standard errors; T is large enough that sinc instead of sinc^2
 * (or a missing 1) would fail. */
static void test_random_and_stratified_points_match_their_exact_spectra(void)
{
    enum { T = 20000, K = 8, F = 40 };
    mcs_rng rng;
    mcs_rng_seed(&rng, 2u, 3u);
    for (int strat = 0; strat < 2; ++strat) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&acc, F));
        for (int t = 0; t < T; ++t) {
            if (strat)
                fill_stratified(&rng, K, x);
            else
                points_uniform(&rng, K, x);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add(&acc, K, x));
        }
        mcs_pattern_kind kind = strat ? MCS_PATTERN_STRATIFIED : MCS_PATTERN_RANDOM;
        for (long f = 1; f <= F; ++f) {
            double p = 0.0, se = 0.0, ex = 0.0;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_power(&acc, f, &p));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_power_stderr(&acc, f, &se));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_exact_power(kind, K, f, &ex));
            TEST_ASSERT_DOUBLE_WITHIN(5.0 * se + 1e-12, ex, p);
        }
    }
}

static void test_uniform_jitter_points_give_the_exact_comb(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 4u, 4u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&acc, 50u));
    for (int t = 0; t < 20; ++t) {
        double beta = 0.0;
        mcs_rng_double(&rng, &beta);
        for (size_t j = 0; j < 6u; ++j)
            x[j] = ((double)j + beta) / 6.0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add(&acc, 6u, x));
    }
    for (long f = 0; f <= 50; ++f) {
        double p = 0.0, ex = 0.0, ex_u = 0.0;
        mcs_pointset_power(&acc, f, &p);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_exact_power(MCS_PATTERN_JITTER, 6u, f, &ex));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_exact_power(MCS_PATTERN_UNIFORM, 6u, f, &ex_u));
        TEST_ASSERT_EQUAL_DOUBLE(ex, ex_u);
        TEST_ASSERT_DOUBLE_WITHIN(1e-12, ex, p);
        TEST_ASSERT_EQUAL_DOUBLE(f % 6 == 0 ? 6.0 : 0.0, ex);
    }
}

static void test_merge_of_halves_equals_one_pass(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 5u, 5u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&acc, 20u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&acc2, 20u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&acc3, 20u));
    for (int t = 0; t < 300; ++t) {
        size_t k = 1u + (size_t)t % 9u; /* trials of different K */
        points_uniform(&rng, k, x);
        mcs_pointset_add(&acc, k, x);
        mcs_pointset_add(t < 100 ? &acc2 : &acc3, k, x);
    }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_merge(&acc2, &acc3));
    uint64_t n = 0u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_count(&acc2, &n));
    TEST_ASSERT_EQUAL_UINT64(300u, n);
    for (long f = 0; f <= 20; ++f) {
        double a = 0.0, b = 0.0, sa = 0.0, sb = 0.0;
        mcs_pointset_power(&acc, f, &a);
        mcs_pointset_power(&acc2, f, &b);
        mcs_pointset_power_stderr(&acc, f, &sa);
        mcs_pointset_power_stderr(&acc2, f, &sb);
        points_assert_merged(a, sa, b, sb);
    }
    /* Merging an empty accumulator changes nothing; merging into itself doubles the count. */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&acc3, 20u));
    snapshot = acc2;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_merge(&acc2, &acc3));
    TEST_ASSERT_EQUAL_MEMORY(&snapshot, &acc2, sizeof acc2);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_merge(&acc2, &acc2));
    mcs_pointset_count(&acc2, &n);
    TEST_ASSERT_EQUAL_UINT64(600u, n);
}

static void test_bad_input_returns_an_error_and_changes_nothing(void)
{
    double out = -1.0;
    uint64_t n = 0u;
    memset(&acc2, 0, sizeof acc2); /* never initialised */
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pointset_init(NULL, 4u));
    snapshot = acc2;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, mcs_pointset_init(&acc2, 0u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, mcs_pointset_init(&acc2, MCS_MAX_FREQ_1D + 1u));
    TEST_ASSERT_EQUAL_MEMORY(&snapshot, &acc2, sizeof acc2);

    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&acc, 8u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_EMPTY, mcs_pointset_power(&acc, 1, &out));
    x[0] = 0.25;
    x[1] = 0.5;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add(&acc, 2u, x));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_EMPTY, mcs_pointset_power_stderr(&acc, 1, &out));
    snapshot = acc;
    const double bad[4] = {1.0, -0.0 - 1e-300, NAN, INFINITY};
    for (int b = 0; b < 4; ++b) {
        x[1] = bad[b];
        TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_pointset_add(&acc, 2u, x));
    }
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_pointset_add(&acc, 0u, x));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pointset_add(&acc, 2u, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pointset_add(NULL, 2u, x));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_pointset_add(&acc2, 2u, x));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_pointset_merge(&acc, &acc2));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&acc3, 9u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_pointset_merge(&acc, &acc3));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pointset_merge(&acc, NULL));
    TEST_ASSERT_EQUAL_MEMORY(&snapshot, &acc, sizeof acc);

    out = -1.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, mcs_pointset_power(&acc, 9, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, mcs_pointset_power(&acc, -9, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_pointset_power(&acc2, 1, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pointset_power(&acc, 1, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_pointset_count(&acc2, &n));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_pointset_exact_power(MCS_PATTERN_HOMOGENIZED, 4u, 1, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_pointset_exact_power((mcs_pattern_kind)9, 4u, 1, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_pointset_exact_power(MCS_PATTERN_RANDOM, 0u, 1, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pointset_exact_power(MCS_PATTERN_RANDOM, 4u, 1, NULL));
    TEST_ASSERT_EQUAL_DOUBLE(-1.0, out);
}

static uint64_t *count_of(void *a) { return &((mcs_pointset *)a)->count; }
static int add_one(void *a) { return mcs_pointset_add(a, 2u, x); }
static int merge(void *dst, const void *src) { return mcs_pointset_merge(dst, src); }

static void test_the_trial_count_stops_at_mcs_max_count_and_never_wraps(void)
{
    const points_counted kind = {sizeof acc, count_of, add_one, merge};
    for (int j = 0; j < 4; ++j)
        x[j] = 0.125 + 0.25 * j; /* two points in 1D or 2D */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&acc, 8u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&acc2, 8u));
    points_assert_count_bound(&kind, &acc, &acc2, &acc3, &snapshot);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_one_trial_matches_the_direct_sum_at_every_frequency);
    RUN_TEST(test_random_and_stratified_points_match_their_exact_spectra);
    RUN_TEST(test_uniform_jitter_points_give_the_exact_comb);
    RUN_TEST(test_merge_of_halves_equals_one_pass);
    RUN_TEST(test_bad_input_returns_an_error_and_changes_nothing);
    RUN_TEST(test_the_trial_count_stops_at_mcs_max_count_and_never_wraps);
    return UNITY_END();
}
