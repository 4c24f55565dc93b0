#include "mcspec.h"
#include "unity.h"

#include <math.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

static void test_seed_42_54_gives_the_pcg32_reference_vector(void)
{
    /* pcg32-global-demo output for pcg32_srandom_r(&rng, 42u, 54u). */
    static const uint32_t expected[8] = {0xa15c02b7u, 0x7b47f409u, 0xba1d3330u, 0x83d2f293u,
                                         0xbfa4784bu, 0xcbed606eu, 0xbfc6a3adu, 0x812fff6du};
    mcs_rng rng;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, 42u, 54u));
    for (int i = 0; i < 8; ++i) {
        uint32_t v = 0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_u32(&rng, &v));
        TEST_ASSERT_EQUAL_HEX32(expected[i], v);
    }
}

static void test_bounded_draws_pass_a_chi_square_test(void)
{
    enum { BOUND = 10, DRAWS = 200000 };
    unsigned long counts[BOUND] = {0};
    mcs_rng rng;
    mcs_rng_seed(&rng, 7u, 11u);
    for (int i = 0; i < DRAWS; ++i) {
        uint32_t v = 0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_bounded(&rng, BOUND, &v));
        TEST_ASSERT_TRUE(v < BOUND);
        counts[v]++;
    }
    double expected = (double)DRAWS / BOUND, chi2 = 0.0;
    for (int b = 0; b < BOUND; ++b)
        chi2 += ((double)counts[b] - expected) * ((double)counts[b] - expected) / expected;
    /* 9 degrees of freedom: P(chi2 > 27.88) = 0.001. */
    TEST_ASSERT_TRUE_MESSAGE(chi2 < 27.88, "chi-square above the 0.1% critical value");
}

static void test_bounded_draws_have_no_modulo_bias_for_a_large_odd_bound(void)
{
    /* bound = 3 * 2^30: plain r % bound would put [0, 2^30) at probability 1/2,
     * rejection keeps it at 1/3. */
    const uint32_t bound = 3u * (1u << 30);
    const int draws = 60000;
    int low = 0;
    mcs_rng rng;
    mcs_rng_seed(&rng, 2024u, 5u);
    for (int i = 0; i < draws; ++i) {
        uint32_t v = 0;
        mcs_rng_bounded(&rng, bound, &v);
        TEST_ASSERT_TRUE(v < bound);
        low += v < (1u << 30);
    }
    double frac = (double)low / draws, se = sqrt((1.0 / 3.0) * (2.0 / 3.0) / draws);
    TEST_ASSERT_DOUBLE_WITHIN(5.0 * se, 1.0 / 3.0, frac);
}

static void test_doubles_are_in_unit_interval_with_53_bits_and_mean_one_half(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 1u, 2u);
    const int draws = 100000;
    double sum = 0.0;
    int fine_bits = 0;
    for (int i = 0; i < draws; ++i) {
        double x = -1.0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_double(&rng, &x));
        TEST_ASSERT_TRUE(x >= 0.0 && x < 1.0);
        sum += x;
        double scaled = ldexp(x, 32); /* bits below 2^-32 present? */
        fine_bits += scaled != floor(scaled);
        double grid = ldexp(x, 53); /* always a multiple of 2^-53 */
        TEST_ASSERT_EQUAL_DOUBLE(floor(grid), grid);
    }
    TEST_ASSERT_DOUBLE_WITHIN(5.0 * sqrt(1.0 / 12.0 / draws), 0.5, sum / draws);
    TEST_ASSERT_GREATER_THAN_INT(draws * 9 / 10, fine_bits);
}

static void test_bad_input_returns_an_error_and_changes_nothing(void)
{
    mcs_rng rng, copy;
    mcs_rng_seed(&rng, 3u, 4u);
    copy = rng;
    uint32_t u = 0xdeadbeefu;
    double d = 42.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_rng_seed(NULL, 1u, 2u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_rng_u32(NULL, &u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_rng_u32(&rng, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_rng_bounded(NULL, 5u, &u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_rng_bounded(&rng, 5u, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_BOUND, mcs_rng_bounded(&rng, 0u, &u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_rng_double(NULL, &d));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_rng_double(&rng, NULL));
    TEST_ASSERT_EQUAL_HEX32(0xdeadbeefu, u);
    TEST_ASSERT_EQUAL_DOUBLE(42.0, d);
    TEST_ASSERT_EQUAL_MEMORY(&copy, &rng, sizeof rng);
}

/* Issue 10 item 3: a zeroed generator's LCG outputs zeros forever, so a
 * bounded draw that rejects 0 never returned. Seeding makes the increment
 * odd: an even one is refused by every draw, which changes nothing. The u32
 * and double checks come first so that without the fix the test fails
 * rather than hangs in the bounded draw. */
static void test_a_never_seeded_generator_is_refused_by_every_draw_instead_of_hanging(void)
{
    mcs_rng rng, copy;
    memset(&rng, 0, sizeof rng);
    copy = rng;
    uint32_t u = 0xdeadbeefu;
    double d = 42.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_rng_u32(&rng, &u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_rng_double(&rng, &d));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_rng_bounded(&rng, 10u, &u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_rng_bounded(&rng, 0u, &u));
    rng.state = 12345u; /* any state: the increment decides */
    rng.inc = 2u;
    copy = rng;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_rng_bounded(&rng, 3u, &u));
    TEST_ASSERT_EQUAL_HEX32(0xdeadbeefu, u);
    TEST_ASSERT_EQUAL_DOUBLE(42.0, d);
    TEST_ASSERT_EQUAL_MEMORY(&copy, &rng, sizeof rng);
}

/* Any odd increment is a full-period PCG32 stream: a 0xFF-filled generator
 * is accepted and its bounded draws terminate and stay in range. */
static void test_any_odd_increment_is_a_working_stream(void)
{
    mcs_rng rng;
    memset(&rng, 0xFF, sizeof rng);
    uint32_t seen = 0u;
    for (int i = 0; i < 1000; ++i) {
        uint32_t v = 99u;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_bounded(&rng, 7u, &v));
        TEST_ASSERT_TRUE(v < 7u);
        seen |= 1u << v;
    }
    TEST_ASSERT_EQUAL_HEX32(0x7Fu, seen); /* every value drawn */
}

/* Issue 10 item 10: an output inside the generator is refused (the state
 * steps before the output is written, which would overwrite it). */
static void test_an_output_inside_the_generator_is_refused(void)
{
    mcs_rng rng, copy;
    mcs_rng_seed(&rng, 5u, 6u);
    copy = rng;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_rng_u32(&rng, (uint32_t *)(void *)&rng.state));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_rng_bounded(&rng, 7u, (uint32_t *)(void *)&rng.inc));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_rng_double(&rng, (double *)(void *)&rng.state));
    TEST_ASSERT_EQUAL_MEMORY(&copy, &rng, sizeof rng);
}

static void test_status_strings_name_every_code(void)
{
    TEST_ASSERT_EQUAL_STRING("MCS_OK", mcs_status_str(MCS_OK));
    TEST_ASSERT_EQUAL_STRING("MCS_ERR_BOUND", mcs_status_str(MCS_ERR_BOUND));
    for (int code = 0; code >= (int)MCS_ERR_UNINIT; --code) {
        const char *s = mcs_status_str((mcs_status)code);
        TEST_ASSERT_NOT_NULL(s);
        TEST_ASSERT_EQUAL_INT(0, strncmp(s, "MCS_", 4));
        TEST_ASSERT_TRUE(strcmp(s, "MCS_ERR_UNKNOWN") != 0);
    }
    TEST_ASSERT_EQUAL_STRING("MCS_ERR_UNKNOWN", mcs_status_str((mcs_status)1));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_seed_42_54_gives_the_pcg32_reference_vector);
    RUN_TEST(test_bounded_draws_pass_a_chi_square_test);
    RUN_TEST(test_bounded_draws_have_no_modulo_bias_for_a_large_odd_bound);
    RUN_TEST(test_doubles_are_in_unit_interval_with_53_bits_and_mean_one_half);
    RUN_TEST(test_bad_input_returns_an_error_and_changes_nothing);
    RUN_TEST(test_a_never_seeded_generator_is_refused_by_every_draw_instead_of_hanging);
    RUN_TEST(test_any_odd_increment_is_a_working_stream);
    RUN_TEST(test_an_output_inside_the_generator_is_refused);
    RUN_TEST(test_status_strings_name_every_code);
    return UNITY_END();
}
