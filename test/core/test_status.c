/* Tests for the status module: every code has its own name, and a value that
 * is no code still gets a string. */
#include "mcspec.h"
#include "unity.h"

#include <string.h>

void setUp(void) {}
void tearDown(void) {}

/* Every code of status.h, MCS_OK down to the last error. */
static const mcs_status all_codes[] = {
    MCS_OK,           MCS_ERR_NULL,       MCS_ERR_N_RANGE,    MCS_ERR_K_RANGE,
    MCS_ERR_NOT_FINITE, MCS_ERR_NEGATIVE, MCS_ERR_ZERO_WEIGHT, MCS_ERR_BIN_RANGE,
    MCS_ERR_POINT_RANGE, MCS_ERR_KIND,    MCS_ERR_MISMATCH,   MCS_ERR_BOUND,
    MCS_ERR_EMPTY,    MCS_ERR_DOMAIN,     MCS_ERR_FREQ_RANGE, MCS_ERR_UNINIT,
    MCS_ERR_SPACE,    MCS_ERR_TRUNCATED,  MCS_ERR_MAGIC,      MCS_ERR_VERSION,
    MCS_ERR_CHECKSUM, MCS_ERR_FORMAT,     MCS_ERR_INVARIANT,  MCS_ERR_MAGNITUDE,
    MCS_ERR_COUNT,    MCS_ERR_ALIAS};
#define CODE_COUNT (sizeof all_codes / sizeof all_codes[0])

static void test_the_codes_run_from_ok_down_without_a_gap(void)
{
    /* The list above is complete: the codes are 0, -1, ..., -(count - 1). */
    for (size_t i = 0; i < CODE_COUNT; ++i)
        TEST_ASSERT_EQUAL_INT(-(int)i, (int)all_codes[i]);
}

static void test_every_code_has_a_distinct_non_empty_name(void)
{
    for (size_t i = 0; i < CODE_COUNT; ++i) {
        const char *name = mcs_status_str(all_codes[i]);
        TEST_ASSERT_NOT_NULL(name);
        TEST_ASSERT_TRUE(strlen(name) > 0u);
        TEST_ASSERT_EQUAL_INT(0, strncmp(name, "MCS_", 4u)); /* named as in status.h */
        for (size_t j = 0; j < i; ++j)
            TEST_ASSERT_TRUE_MESSAGE(strcmp(name, mcs_status_str(all_codes[j])) != 0,
                                     "two codes share a name");
    }
    TEST_ASSERT_EQUAL_STRING("MCS_OK", mcs_status_str(MCS_OK));
    TEST_ASSERT_EQUAL_STRING("MCS_ERR_UNINIT", mcs_status_str(MCS_ERR_UNINIT));
}

static void test_an_unknown_code_gets_the_fallback_string(void)
{
    const int unknown[] = {1, -(int)CODE_COUNT, -100, 100}; /* the next code is no code yet */
    for (size_t i = 0; i < sizeof unknown / sizeof unknown[0]; ++i) {
        const char *name = mcs_status_str((mcs_status)unknown[i]);
        TEST_ASSERT_NOT_NULL(name);
        TEST_ASSERT_EQUAL_STRING("MCS_ERR_UNKNOWN", name);
    }
    for (size_t i = 0; i < CODE_COUNT; ++i) /* and no real code is called that */
        TEST_ASSERT_TRUE(strcmp("MCS_ERR_UNKNOWN", mcs_status_str(all_codes[i])) != 0);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_the_codes_run_from_ok_down_without_a_gap);
    RUN_TEST(test_every_code_has_a_distinct_non_empty_name);
    RUN_TEST(test_an_unknown_code_gets_the_fallback_string);
    return UNITY_END();
}
