/* Tests for the scalar Welford accumulator: against two-pass references, the
 * merge of two halves, the standard error of the variance, and bad input. */
#include "mcspec.h"
#include "unity.h"

#include <math.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

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

static void test_merge_of_halves_equals_one_pass(void)
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

/* The call must fail with want and leave acc and v as they were. */
#define EXPECT_UNCHANGED(want, call)                                                         \
    do {                                                                                     \
        const mcs_welford before_ = acc;                                                     \
        const double v_before_ = v;                                                          \
        TEST_ASSERT_EQUAL_INT((want), (call));                                               \
        TEST_ASSERT_EQUAL_MEMORY(&before_, &acc, sizeof acc);                                \
        TEST_ASSERT_EQUAL_MEMORY(&v_before_, &v, sizeof v);                                  \
    } while (0)

static void test_bad_input_returns_an_error_and_leaves_the_accumulator_untouched(void)
{
    mcs_welford acc;
    double v = 5.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_welford_init(NULL));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_init(&acc));
    EXPECT_UNCHANGED(MCS_ERR_EMPTY, mcs_welford_mean(&acc, &v)); /* no values */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_add(&acc, 1.0));
    EXPECT_UNCHANGED(MCS_ERR_NULL, mcs_welford_add(NULL, 1.0));
    EXPECT_UNCHANGED(MCS_ERR_NOT_FINITE, mcs_welford_add(&acc, NAN));
    EXPECT_UNCHANGED(MCS_ERR_NOT_FINITE, mcs_welford_add(&acc, -INFINITY));
    EXPECT_UNCHANGED(MCS_ERR_NULL, mcs_welford_merge(NULL, &acc));
    EXPECT_UNCHANGED(MCS_ERR_NULL, mcs_welford_merge(&acc, NULL));
    EXPECT_UNCHANGED(MCS_ERR_NULL, mcs_welford_mean(NULL, &v));
    EXPECT_UNCHANGED(MCS_ERR_NULL, mcs_welford_mean(&acc, NULL));
    EXPECT_UNCHANGED(MCS_ERR_EMPTY, mcs_welford_variance(&acc, &v)); /* one value */
    EXPECT_UNCHANGED(MCS_ERR_EMPTY, mcs_welford_stderr(&acc, &v));
    EXPECT_UNCHANGED(MCS_ERR_NULL, mcs_welford_variance(NULL, &v));
    EXPECT_UNCHANGED(MCS_ERR_NULL, mcs_welford_variance(&acc, NULL));
    EXPECT_UNCHANGED(MCS_ERR_NULL, mcs_welford_stderr(NULL, &v));
    EXPECT_UNCHANGED(MCS_ERR_NULL, mcs_welford_stderr(&acc, NULL));
    EXPECT_UNCHANGED(MCS_ERR_NULL, mcs_welford_variance_stderr(NULL, &v));
    EXPECT_UNCHANGED(MCS_ERR_NULL, mcs_welford_variance_stderr(&acc, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_add(&acc, 2.0));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_add(&acc, 4.0));
    EXPECT_UNCHANGED(MCS_ERR_EMPTY, mcs_welford_variance_stderr(&acc, &v)); /* three values */
    TEST_ASSERT_EQUAL_DOUBLE(5.0, v);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_welford_matches_a_two_pass_computation_with_a_large_offset);
    RUN_TEST(test_merge_of_halves_equals_one_pass);
    RUN_TEST(test_variance_stderr_matches_the_theory_for_uniform_values);
    RUN_TEST(test_bad_input_returns_an_error_and_leaves_the_accumulator_untouched);
    return UNITY_END();
}
