/* Tests for the limits of the closed forms (issue 10): re == im refused,
 * integrands above MCS_ESTIMATE_MAX_ABS (and powers above
 * MCS_EQ_MAX_POWER) refused rather than read out as inf or NaN, and the
 * variances never negative. The forms themselves are tested in test_eq.c. */
#include "mcspec.h"
#include "theory_ref.h"
#include "unity.h"

#include <float.h>
#include <math.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define SENTINEL (-7.25e300)

static mcs_importance imp, imp_copy;

/* ---- item 10: one double for both parts of a complex result --------------- */

typedef mcs_status (*pair_fn)(size_t, size_t, size_t, size_t, double *, double *);
typedef mcs_status (*imp_pair_fn)(const mcs_importance *, size_t, size_t, size_t, double *,
                                  double *);

/* The call into one double: MCS_ERR_ALIAS and the double untouched; into two
 * it gives (re, im), and into two inside imp (read by the imp forms) the same. */
static void expect_alias_refused(mcs_status both_st, double both)
{
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, both_st);
    TEST_ASSERT_EQUAL_DOUBLE(SENTINEL, both);
}

static void test_a_complex_result_into_one_double_is_refused_and_elsewhere_is_written(void)
{
    const pair_fn pairs[3] = {mcs_eq30_stratified_delta_printed,
                              mcs_eq30_stratified_delta_corrected, mcs_eq30_stratified_cross};
    for (int i = 0; i < 3; ++i) {
        double both = SENTINEL, re = SENTINEL, im = SENTINEL;
        expect_alias_refused(pairs[i](12u, 4u, 1u, 5u, &both, &both), both);
        TEST_ASSERT_EQUAL_INT(MCS_OK, pairs[i](12u, 4u, 1u, 5u, &re, &im));
        TEST_ASSERT_TRUE(im != 0.0); /* so re == im would have lost a part */
    }
    double both = SENTINEL;
    expect_alias_refused(mcs_eq34_uniform_spectrum(8u, 4u, 4u, &both, &both), both);
    expect_alias_refused(mcs_eq35_jitter_mean(8u, 4u, 0u, &both, &both), both);
    /* a bad argument keeps its own status: ALIAS is the last check */
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_eq30_stratified_cross(12u, 5u, 1u, 5u, &both, &both));

    theory_lumpy_importance(&imp, 12u);
    const imp_pair_fn ipairs[2] = {mcs_eq43_importance_cross,
                                   mcs_eq49_importance_stratified_cross};
    for (int i = 0; i < 2; ++i) {
        double re = SENTINEL, im = SENTINEL;
        both = SENTINEL;
        memcpy(&imp_copy, &imp, sizeof imp);
        expect_alias_refused(ipairs[i](&imp, 4u, 1u, 6u, &both, &both), both);
        TEST_ASSERT_EQUAL_MEMORY(&imp_copy, &imp, sizeof imp);
        TEST_ASSERT_EQUAL_INT(MCS_OK, ipairs[i](&imp, 4u, 1u, 6u, &re, &im));
        TEST_ASSERT_TRUE(im != 0.0);
        /* written last: the result may go over the p_n it is formed from */
        TEST_ASSERT_EQUAL_INT(MCS_OK, ipairs[i](&imp, 4u, 1u, 6u, &imp.p[0], &imp.p[1]));
        TEST_ASSERT_EQUAL_DOUBLE(re, imp.p[0]);
        TEST_ASSERT_EQUAL_DOUBLE(im, imp.p[1]);
        memcpy(&imp, &imp_copy, sizeof imp);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_a_complex_result_into_one_double_is_refused_and_elsewhere_is_written);
    return UNITY_END();
}
